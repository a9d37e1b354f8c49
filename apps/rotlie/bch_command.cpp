// `rotlie bch`: a BCH-type series in the free Lie algebra, every Lyndon basis element with its exact
// coefficient, as text or JSON.
#include <iostream>
#include <string>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/bch/free_bch.hpp"

namespace rotlie::app {
namespace {

// "[A,[A,B]]" from the standard factorisations stored in the basis.
void append_bracket(const bch::lyndon_basis& basis, std::size_t i, std::string& out) {
  if (basis.length(i) == 1) {
    out.push_back(static_cast<char>('A' + basis.letter(i, 0)));
    return;
  }
  out.push_back('[');
  append_bracket(basis, basis.left(i), out);
  out.push_back(',');
  append_bracket(basis, basis.right(i), out);
  out.push_back(']');
}

}  // namespace

int run_bch(const bch_options& options) {
  const auto series = bch::parse_free_series(options.series);
  if (!series)
    throw usage_error("unknown series '" + one_line(options.series) + "' for --series (expected XY, XYX, SYM or XYZ)");
  const int degree = static_cast<int>(parse_integer_in_range(options.degree, "--degree", 1, bch::max_series_degree(*series)));
  const int threads = static_cast<int>(parse_integer_in_range(options.threads, "--threads", 1, 64));
  const auto s = bch::compute_free_series(*series, degree, {threads, false});
  const auto& basis = *s.basis;
  std::string out;
  if (options.json) {
    out += "{\"series\":\"" + std::string(bch::series_name(*series)) + "\",\"degree\":" + std::to_string(degree) + ",\"terms\":[";
    for (std::size_t i = 0; i < s.size(); ++i) {
      out += i ? ",\n" : "\n";
      out += "{\"word\":\"" + basis.foliage(i) + "\",\"coefficient\":\"" + s.coefficient_text(i) + "\"}";
    }
    out += "\n]}\n";
  } else {
    out += "# " + std::string(bch::series_name(*series)) + " to degree " + std::to_string(degree) +
           ": Lyndon word, basis element (standard bracketing), coefficient\n";
    for (std::size_t i = 0; i < s.size(); ++i) {
      out += basis.foliage(i) + "\t";
      append_bracket(basis, i, out);
      out += "\t" + s.coefficient_text(i) + "\n";
    }
  }
  std::cout << out;
  return 0;
}

}  // namespace rotlie::app
