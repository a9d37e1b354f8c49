// `rotlie bch`: a BCH-type series in the free Lie algebra, every Lyndon basis element with its exact
// coefficient, as text or JSON.
#include <functional>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

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
  // Each term's line (the gcd of its fraction and the bracket) is formatted independently, so the
  // terms are shared among the threads in contiguous ranges and written in order.
  auto format_range = [&](std::size_t begin, std::size_t end, std::string& text) {
    for (std::size_t i = begin; i < end; ++i) {
      if (options.json) {
        text += i ? ",\n" : "\n";
        text += "{\"word\":\"" + basis.foliage(i) + "\",\"coefficient\":\"" + s.coefficient_text(i) + "\"}";
      } else {
        text += basis.foliage(i) + "\t";
        append_bracket(basis, i, text);
        text += "\t" + s.coefficient_text(i) + "\n";
      }
    }
  };
  std::vector<std::string> parts(static_cast<std::size_t>(threads));
  {
    std::vector<std::thread> workers;
    const std::size_t n = s.size(), k = parts.size();
    for (std::size_t t = 1; t < k; ++t)
      workers.emplace_back(format_range, n * t / k, n * (t + 1) / k, std::ref(parts[t]));
    format_range(0, n / k, parts[0]);
    for (auto& w : workers) w.join();
  }
  std::string out;
  if (options.json)
    out += "{\"series\":\"" + std::string(bch::series_name(*series)) + "\",\"degree\":" + std::to_string(degree) + ",\"terms\":[";
  else
    out += "# " + std::string(bch::series_name(*series)) + " to degree " + std::to_string(degree) +
           ": Lyndon word, basis element (standard bracketing), coefficient\n";
  for (const auto& part : parts) out += part;
  if (options.json) out += "\n]}\n";
  std::cout << out;
  return 0;
}

}  // namespace rotlie::app
