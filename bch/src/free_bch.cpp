#include "rotlie/bch/free_bch.hpp"

#include <cln/integer.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <thread>

#include "rotlie/bch/lyndon_projection.hpp"
#include "rotlie/bch/word_coefficients.hpp"
#include "rotlie/lie/stop_request.hpp"

namespace rotlie::bch {
namespace {

cln::cl_I to_cln(int128 x) {
  const uint128 m = magnitude(x);
  const cln::cl_I hi(static_cast<unsigned long long>(m >> 64)), lo(static_cast<unsigned long long>(m));
  const cln::cl_I v = cln::ash(hi, 64) + lo;
  return x < 0 ? -v : v;
}

int128 lcm(int128 a, int128 b) { return checked_mul(a / gcd(a, b), b); }

// Divides degree d's numerators and denominator by their common factor.
void reduce(exact_lie_series& s, int d) {
  int128 g = s.denominator[static_cast<std::size_t>(d)];
  for (std::size_t i = s.basis->begin(d); i < s.basis->end(d) && g != 1; ++i) g = gcd(g, s.numerator[i]);
  s.denominator[static_cast<std::size_t>(d)] /= g;
  for (std::size_t i = s.basis->begin(d); i < s.basis->end(d); ++i) s.numerator[i] /= g;
}

// log(e^{X_g1} … e^{X_gm}) projected at the degrees asked (the others left zero).
exact_lie_series project(free_series name, const std::vector<std::uint8_t>& factors, int letters, int max_degree,
                         bool odd_only, int threads) {
  exact_lie_series s;
  s.series = name;
  s.max_degree = max_degree;
  s.basis = std::make_shared<const lyndon_basis>(letters, max_degree);
  // Room for every degree, but each one's pages are touched only when it is reached: the top
  // degree, half of the basis, is not written at all when only the odd ones are solved.
  s.numerator.reserve(s.basis->size());
  s.denominator.assign(static_cast<std::size_t>(max_degree) + 1, 1);
  const auto& basis = *s.basis;
  for (int d = 1; d <= max_degree; ++d) {
    if (odd_only && d % 2 == 0) continue;
    lie::stop_point();
    check_word_coefficient_bound(d, factors.size());
    s.numerator.resize(basis.end(d), 0);
    s.denominator[static_cast<std::size_t>(d)] = word_denominator(d);
    const std::size_t first = basis.begin(d), count = basis.end(d) - first;
    auto fill = [&](std::size_t from, std::size_t to) {
      word_coefficients z(factors);
      std::array<std::uint8_t, 64> w{};
      for (std::size_t i = from; i < to; ++i) {
        basis.copy_letters(i, w.data());
        s.numerator[i] = z(w.data(), d);
      }
    };
    const int t = std::max(1, std::min<int>(threads, static_cast<int>(count / 512) + 1));
    std::vector<std::thread> pool;
    for (int k = 1; k < t; ++k)
      pool.emplace_back(fill, first + count * static_cast<std::size_t>(k) / static_cast<std::size_t>(t),
                        first + count * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(t));
    fill(first, first + count / static_cast<std::size_t>(t));
    for (auto& p : pool) p.join();
    reduce(s, d);  // smaller numbers in the solve
    solve_lyndon_coordinates(basis, d, s.numerator, threads);
    reduce(s, d);
  }
  s.numerator.resize(basis.size(), 0);
  return s;
}

int count_of_a(const lyndon_basis& b, std::size_t i) { return static_cast<int>(b.content(i) & 0xffu); }

// SYM(X, Y) = XYX(X/2, Y): each coefficient times 2^{−#A}.
exact_lie_series sym_from_xyx(exact_lie_series s) {
  s.series = free_series::sym;
  for (int d = 1; d <= s.max_degree; ++d) {
    s.denominator[static_cast<std::size_t>(d)] = checked_mul(s.denominator[static_cast<std::size_t>(d)], int128(1) << d);
    for (std::size_t i = s.basis->begin(d); i < s.basis->end(d); ++i)
      s.numerator[i] = checked_mul(s.numerator[i], int128(1) << (d - count_of_a(*s.basis, i)));
    reduce(s, d);
  }
  return s;
}

// Indices of words of one degree asked for in increasing order: a cursor that only moves forward.
class ascending_finder {
 public:
  ascending_finder(const lyndon_basis& basis, int d) : basis_(basis), at_(basis.begin(d)), end_(basis.end(d)) {}
  std::size_t find(std::uint64_t code) {
    while (at_ < end_ && basis_.code(at_) < code) ++at_;
    return at_ < end_ && basis_.code(at_) == code ? at_ : basis_.size();
  }

 private:
  const lyndon_basis& basis_;
  std::size_t at_, end_;
};

// XY = Σ_k ad_A^k SYM / (2^k k!): the coefficient of P_w, w = A^k l (l Lyndon, l ≠ A), collects
// SYM's coefficient of P_l over every such split. In place, from the top degree down: degree d
// reads SYM at degree d (its own word) and below, which are still SYM's.
exact_lie_series xy_from_sym(exact_lie_series s) {
  s.series = free_series::xy;
  const std::vector<int128> sym_denominator = s.denominator;
  const auto& basis = *s.basis;
  const int bits = basis.bits_per_letter();
  for (int d = s.max_degree; d >= 1; --d) {
    // factor[k] = common / (2^k k! · SYM's denominator at degree d − k)
    std::vector<int128> factor(static_cast<std::size_t>(d), 0);
    int128 common = 1, factorial = 1;
    for (int k = 0; k < d; ++k) {
      if (k > 0) factorial *= k;
      factor[static_cast<std::size_t>(k)] =
          checked_mul(checked_mul(factorial, int128(1) << k), sym_denominator[static_cast<std::size_t>(d - k)]);
      common = lcm(common, factor[static_cast<std::size_t>(k)]);
    }
    for (auto& f : factor) f = common / f;
    s.denominator[static_cast<std::size_t>(d)] = common;
    // For a fixed k, the words A^k… come first in the degree and their suffixes l increase.
    std::vector<ascending_finder> suffixes;
    for (int k = 1; k < d; ++k) suffixes.emplace_back(basis, d - k);
    for (std::size_t i = basis.begin(d); i < basis.end(d); ++i) {
      const std::uint64_t w = basis.code(i);
      int128 sum = s.numerator[i] == 0 ? 0 : checked_mul(s.numerator[i], factor[0]);
      for (int k = 1; k < d && ((w >> (bits * (d - k))) & ((1u << bits) - 1)) == 0; ++k) {
        const std::uint64_t l = basis.suffix_code(w, d - k);
        if (d - k == 1 && l == basis.code(0)) break;  // ad_A A = 0
        const std::size_t j = suffixes[static_cast<std::size_t>(k - 1)].find(l);
        if (j == basis.size() || s.numerator[j] == 0) continue;
        sum = checked_add(sum, checked_mul(s.numerator[j], factor[static_cast<std::size_t>(k)]));
      }
      s.numerator[i] = sum;
    }
    reduce(s, d);
  }
  return s;
}

}  // namespace

std::string_view series_name(free_series s) {
  switch (s) {
    case free_series::xy: return "XY";
    case free_series::xyx: return "XYX";
    case free_series::sym: return "SYM";
    case free_series::xyz: return "XYZ";
  }
  return "?";
}

std::optional<free_series> parse_free_series(std::string_view name) {
  for (const auto s : {free_series::xy, free_series::xyx, free_series::sym, free_series::xyz})
    if (series_name(s) == name) return s;
  return std::nullopt;
}

int series_letters(free_series s) { return s == free_series::xyz ? 3 : 2; }
int max_series_degree(free_series s) { return s == free_series::xyz ? 14 : 20; }

cln::cl_RA exact_lie_series::coefficient(std::size_t i) const {
  return cln::cl_RA(to_cln(numerator[i])) / to_cln(denominator[static_cast<std::size_t>(basis->length(i))]);
}

std::string exact_lie_series::coefficient_text(std::size_t i) const {
  return fraction_text(numerator[i], denominator[static_cast<std::size_t>(basis->length(i))]);
}

std::size_t exact_lie_series::nonzero_at_degree(int d) const {
  return static_cast<std::size_t>(std::count_if(numerator.begin() + static_cast<long>(basis->begin(d)),
                                                numerator.begin() + static_cast<long>(basis->end(d)),
                                                [](int128 x) { return x != 0; }));
}

exact_lie_series compute_free_series(free_series s, int max_degree, const series_options& options) {
  if (max_degree < 1 || max_degree > max_series_degree(s))
    throw std::invalid_argument("the degree of " + std::string(series_name(s)) + " must be between 1 and " +
                                std::to_string(max_series_degree(s)));
  const int threads = std::max(1, options.threads);
  switch (s) {
    case free_series::xyz: return project(s, {0, 1, 2}, 3, max_degree, false, threads);
    case free_series::xyx: return project(s, {0, 1, 0}, 2, max_degree, !options.direct, threads);
    case free_series::sym: return sym_from_xyx(project(free_series::xyx, {0, 1, 0}, 2, max_degree, !options.direct, threads));
    case free_series::xy:
      if (options.direct) return project(s, {0, 1}, 2, max_degree, false, threads);
      return xy_from_sym(sym_from_xyx(project(free_series::xyx, {0, 1, 0}, 2, max_degree, true, threads)));
  }
  throw std::logic_error("unknown series");
}

lie_series to_lie_series(const exact_lie_series& s) {
  lie_series out;
  out.letters = s.basis->letters();
  out.max_degree = s.max_degree;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.numerator[i] != 0) out.coefficients.emplace(s.basis->word_at(i), s.coefficient(i));
  return out;
}

}  // namespace rotlie::bch
