#include "rotlie/bch/word_coefficients.hpp"

#include <array>
#include <cmath>
#include <numeric>

namespace rotlie::bch {
namespace {

constexpr int max_n = 31;  // as word_coefficients::max_n

// Binomial coefficients up to max_n (exact in 64 bits).
const std::array<std::array<std::int64_t, max_n + 1>, max_n + 1>& binomials() {
  static const auto table = [] {
    std::array<std::array<std::int64_t, max_n + 1>, max_n + 1> c{};
    for (int n = 0; n <= max_n; ++n) {
      c[static_cast<std::size_t>(n)][0] = 1;
      for (int k = 1; k <= n; ++k)
        c[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)] =
            c[static_cast<std::size_t>(n - 1)][static_cast<std::size_t>(k - 1)] +
            (k < n ? c[static_cast<std::size_t>(n - 1)][static_cast<std::size_t>(k)] : 0);
    }
    return c;
  }();
  return table;
}

std::int64_t binomial(int n, int k) { return binomials()[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)]; }

// u[q] = (p − q)! · <e^{X_g1} … e^{X_gm}, w[q : p]> for every q in [first, p) at once, from the
// last exponential back: with u_j(q) for the factors j … m, u_j(q) = Σ_e C(p − q, e) u_{j+1}(q + e)
// over the powers w[q : q+e] = g_j^e (e = 0 included), u_m(q) = [q = p].
void factor_values(const std::uint8_t* w, int first, int p, const std::vector<std::uint8_t>& g,
                   std::array<std::int64_t, max_n + 1>& u) {
  for (int q = first; q <= p; ++q) u[static_cast<std::size_t>(q)] = q == p;
  for (auto j = g.size(); j-- > 0;) {
    const std::uint8_t letter = g[j];
    for (int q = first; q < p; ++q) {  // ascending: u[q + e], e ≥ 1, still u_{j+1}
      if (w[q] != letter) continue;
      std::int64_t s = u[static_cast<std::size_t>(q)];
      for (int e = 1; q + e <= p && w[q + e - 1] == letter; ++e) s += binomial(p - q, e) * u[static_cast<std::size_t>(q + e)];
      u[static_cast<std::size_t>(q)] = s;
    }
  }
}

}  // namespace

int128 word_denominator(int n) {
  int128 factorial = 1, l = 1;
  for (int k = 1; k <= n; ++k) {
    factorial *= k;
    l = l / gcd(l, k) * k;
  }
  return checked_mul(factorial, l);
}

void check_word_coefficient_bound(int n, std::size_t factors) {
  // Fubini numbers a(p) = Σ_k C(p,k) a(p−k): compositions weighted by multinomials.
  std::vector<long double> a(static_cast<std::size_t>(n) + 1, 0);
  a[0] = 1;
  for (int p = 1; p <= n; ++p)
    for (int k = 1; k <= p; ++k) a[static_cast<std::size_t>(p)] += static_cast<long double>(binomial(p, k)) * a[static_cast<std::size_t>(p - k)];
  long double l = 1;
  for (int k = 1; k <= n; ++k) l = static_cast<long double>(std::lcm(static_cast<long long>(l), static_cast<long long>(k)));
  const long double bound = a[static_cast<std::size_t>(n)] * std::pow(static_cast<long double>(factors), n) * l;
  if (!(bound < std::ldexp(1.0L, 126)))
    throw std::overflow_error("degree " + std::to_string(n) + " is beyond the proven 128-bit range of the word coefficients");
}

word_coefficients::word_coefficients(std::vector<std::uint8_t> factors) : factors_(std::move(factors)) {
  e_[0][0] = 1;
}

int128 word_coefficients::operator()(const std::uint8_t* w, int n) {
  // Rows 0 … common stay valid: they depend on w[0 : p] only.
  int common = 0;
  if (n == previous_n_)
    while (common < n && previous_[static_cast<std::size_t>(common)] == w[common]) ++common;
  std::copy(w, w + n, previous_.begin());
  if (n != previous_n_) set_log_weights(n);
  previous_n_ = n;
  const int m = static_cast<int>(factors_.size());
  std::array<std::int64_t, max_n + 1> value;
  for (int p = common + 1; p <= n; ++p) {
    const auto up = static_cast<std::size_t>(p);
    // run_start_[p]: where the run containing w[p−1] begins.
    run_start_[up] = (p > 1 && w[p - 1] == w[p - 2]) ? run_start_[up - 1] : p - 1;
    // e_[p][k] = p! · Σ over cuts of w[0:p] into k non-empty factors of the product of their values;
    // a factor spanning more runs than there are exponentials vanishes.
    auto& row = e_[up];
    std::fill(row.begin(), row.begin() + p + 1, 0);
    int earliest = p;
    for (int r = 0; r < m && earliest > 0; ++r) earliest = run_start_[static_cast<std::size_t>(earliest)];
    factor_values(w, earliest, p, factors_, value);
    for (int q = earliest; q < p; ++q) {
      const std::int64_t v = value[static_cast<std::size_t>(q)];
      if (v == 0) continue;
      const int128 weight = static_cast<int128>(binomial(p, q)) * v;
      const auto& before = e_[static_cast<std::size_t>(q)];
      for (int k = 1; k <= q + 1; ++k) row[static_cast<std::size_t>(k)] += before[static_cast<std::size_t>(k - 1)] * weight;
    }
  }
  // log(1 + Y) = Σ_k (−1)^{k+1} Y^k / k
  int128 z = 0;
  for (int k = 1; k <= n; ++k) z += e_[static_cast<std::size_t>(n)][static_cast<std::size_t>(k)] * log_weight_[static_cast<std::size_t>(k)];
  return z;
}

void word_coefficients::set_log_weights(int n) {
  // with D_n = n! · lcm(1 … n), the k-th term carries (−1)^{k+1} lcm / k
  int128 l = 1;
  for (int k = 1; k <= n; ++k) l = l / gcd(l, k) * k;
  for (int k = 1; k <= n; ++k) log_weight_[static_cast<std::size_t>(k)] = k % 2 ? l / k : -(l / k);
}

}  // namespace rotlie::bch
