// `rotlie bch`: a BCH-type series in the free Lie algebra, every Lyndon basis element with its exact
// coefficient, as text or JSON.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/bch/free_bch.hpp"

namespace rotlie::app {
namespace {

// "[A,[A,B]]" from the standard factorisations stored in the basis. The texts of the first few
// thousand words (the short ones, every factor of a long word ends in them) are kept, so a long
// word's text is a few copies.
class bracket_texts {
 public:
  explicit bracket_texts(const bch::lyndon_basis& basis) : basis_(basis) {
    for (int d = 1; d <= basis.max_degree() && basis.end(d) <= 4096; ++d) kept_ = basis.end(d);
    offset_.push_back(0);
    for (std::size_t i = 0; i < kept_; ++i) {
      char text[4 * 32];
      text_.append(text, build(i, text));
      offset_.push_back(text_.size());
    }
  }
  /// Writes word i's text at out; returns the end. At most 4 · length − 3 characters.
  char* write(std::size_t i, char* out) const {
    if (i < kept_) {
      const std::size_t n = offset_[i + 1] - offset_[i];
      std::memcpy(out, text_.data() + offset_[i], n);
      return out + n;
    }
    return build(i, out);
  }

 private:
  char* build(std::size_t i, char* out) const {
    if (basis_.length(i) == 1) {
      *out++ = static_cast<char>('A' + basis_.letter(i, 0));
      return out;
    }
    *out++ = '[';
    out = write(basis_.left(i), out);
    *out++ = ',';
    out = write(basis_.right(i), out);
    *out++ = ']';
    return out;
  }

  const bch::lyndon_basis& basis_;
  std::size_t kept_ = 0;
  std::string text_;
  std::vector<std::size_t> offset_;
};

// One term's line (text) or object (JSON, after its separator) at out; returns the end.
char* write_term(const bch::exact_lie_series& s, const bracket_texts& brackets, bool json, std::size_t i, char* out) {
  const auto& basis = *s.basis;
  const auto put = [&out](const char* text) {
    const std::size_t n = std::strlen(text);
    std::memcpy(out, text, n);
    out += n;
  };
  const int n = basis.length(i);
  std::uint8_t foliage[64];
  basis.copy_letters(i, foliage);
  if (json) put(i ? ",\n{\"word\":\"" : "\n{\"word\":\"");
  for (int k = 0; k < n; ++k) *out++ = static_cast<char>('A' + foliage[k]);
  if (json) {
    put("\",\"coefficient\":\"");
  } else {
    *out++ = '\t';
    out = brackets.write(i, out);
    *out++ = '\t';
  }
  out = bch::write_fraction(out, s.numerator[i], s.denominator[static_cast<std::size_t>(n)]);
  if (json)
    put("\"}");
  else
    *out++ = '\n';
  return out;
}

constexpr std::size_t longest_term = 512;  // 29 letters, their bracketing, two 40-character numbers, the JSON keys

// Terms [begin, end) appended to text.
void format_terms(const bch::exact_lie_series& s, const bracket_texts& brackets, bool json, std::size_t begin,
                  std::size_t end, std::string& text) {
  char line[longest_term];
  for (std::size_t i = begin; i < end; ++i) text.append(line, write_term(s, brackets, json, i, line));
}

}  // namespace

int run_bch(const bch_options& options) {
  const auto series = bch::parse_free_series(options.series);
  if (!series)
    throw usage_error("unknown series '" + one_line(options.series) + "' for --series (expected XY, XYX, SYM or XYZ)");
  const int degree = static_cast<int>(parse_integer_in_range(options.degree, "--degree", 1, bch::max_series_degree(*series)));
  const int threads = static_cast<int>(parse_integer_in_range(options.threads, "--threads", 1, 64));
  const auto s = bch::compute_free_series(*series, degree, {threads, false});
  const bracket_texts brackets(*s.basis);
  if (options.json)
    std::cout << "{\"series\":\"" << bch::series_name(*series) << "\",\"degree\":" << degree << ",\"terms\":[";
  else
    std::cout << "# " << bch::series_name(*series) << " to degree " << degree
              << ": Lyndon word, basis element (standard bracketing), coefficient\n";
  // The terms go out in rounds: each thread formats one contiguous range (its own buffer), then the
  // buffers are written in order, so the memory stays that of one round whatever the series' size.
  constexpr std::size_t range = 1024;
  std::vector<std::string> parts(static_cast<std::size_t>(threads));
  const std::size_t n = s.size();
  for (std::size_t first = 0; first < n && std::cout; first += range * parts.size()) {
    auto format = [&](std::size_t t) {
      const std::size_t begin = std::min(n, first + t * range), end = std::min(n, begin + range);
      parts[t].clear();
      format_terms(s, brackets, options.json, begin, end, parts[t]);
    };
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < parts.size() && first + t * range < n; ++t) workers.emplace_back(format, t);
    format(0);
    for (auto& w : workers) w.join();
    for (std::size_t t = 0; t < parts.size() && first + t * range < n; ++t)
      std::cout.write(parts[t].data(), static_cast<std::streamsize>(parts[t].size()));
  }
  if (options.json) std::cout << "\n]}\n";
  return 0;
}

}  // namespace rotlie::app
