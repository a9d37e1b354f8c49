#include "rotlie/solver/resultant.hpp"

#include <cln/integer.h>

#include <optional>
#include <stdexcept>

namespace rotlie::solver {
namespace {

// coefficient[j][i] of v^j u^i, integers after clearing denominators.
using bivariate_integer = std::vector<std::vector<cln::cl_I>>;

bivariate_integer integer_coefficients(const lie::coefficient_polynomial& p, int v, int u) {
  for (const auto& t : p.terms()) {
    const auto e = lie::coefficient_polynomial::unpack(t.key);
    for (int k = 0; k < lie::coefficient_polynomial::max_unknowns; ++k)
      if (k != u && k != v && e[static_cast<std::size_t>(k)] != 0)
        throw std::invalid_argument("resultant: a third unknown appears");
  }
  bivariate_integer out(static_cast<std::size_t>(std::max(p.degree(v), 0)) + 1);
  cln::cl_I denominators = 1;
  for (const auto& t : p.terms()) denominators = cln::lcm(denominators, cln::denominator(t.c));
  for (const auto& t : p.terms()) {
    const auto e = lie::coefficient_polynomial::unpack(t.key);
    auto& row = out[static_cast<std::size_t>(e[static_cast<std::size_t>(v)])];
    const auto i = static_cast<std::size_t>(e[static_cast<std::size_t>(u)]);
    if (row.size() <= i) row.resize(i + 1, 0);
    row[i] = cln::the<cln::cl_I>(t.c * denominators);
  }
  for (auto& row : out)
    if (row.empty()) row.push_back(0);
  return out;
}

int degree_in_u(const bivariate_integer& p) {
  int d = 0;
  for (const auto& row : p) d = std::max(d, static_cast<int>(row.size()) - 1);
  return d;
}

std::vector<cln::cl_I> at_u(const bivariate_integer& p, const cln::cl_I& x) {
  std::vector<cln::cl_I> out;
  for (const auto& row : p) {
    cln::cl_I s = 0;
    for (auto it = row.rbegin(); it != row.rend(); ++it) s = s * x + *it;
    out.push_back(s);
  }
  return out;
}

// Sylvester matrix of a (degree m) and b (degree n) with formal degrees kept even when the leading
// coefficients vanish at this point, so the determinant is the specialisation of the resultant.
std::vector<std::vector<cln::cl_I>> sylvester(const std::vector<cln::cl_I>& a, const std::vector<cln::cl_I>& b) {
  const std::size_t m = a.size() - 1, n = b.size() - 1, size = m + n;
  std::vector<std::vector<cln::cl_I>> s(size, std::vector<cln::cl_I>(size, 0));
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = 0; k <= m; ++k) s[r][r + k] = a[m - k];
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t k = 0; k <= n; ++k) s[n + r][r + k] = b[n - k];
  return s;
}

// Res(a, b) of univariate integer polynomials with formal degrees m = a.size() − 1, n = b.size() − 1,
// in the Sylvester convention (n rows of a first): α^n Π b(ξ) over the roots ξ of a, α = lc(a).
// With b = q a + r, b(ξ) = r(ξ), so Res(a, b) = α^(n − deg r) Res(a, r): one division and an
// (m + deg r)-square determinant instead of (m + n)-square. nullopt when the lower-degree
// polynomial's leading coefficient vanishes (the caller picks another point).
std::optional<cln::cl_RA> resultant_at(const std::vector<cln::cl_I>& a, const std::vector<cln::cl_I>& b) {
  const std::size_t m = a.size() - 1, n = b.size() - 1;
  if (m > n) {  // Res(a, b) = (−1)^(mn) Res(b, a)
    const auto swapped = resultant_at(b, a);
    if (!swapped) return std::nullopt;
    return (m * n) % 2 == 0 ? *swapped : -*swapped;
  }
  const cln::cl_I alpha = a.back();
  if (cln::zerop(alpha)) return std::nullopt;
  if (m == 0) return cln::expt(cln::cl_RA(alpha), static_cast<int>(n));
  // Pseudo-remainder over the integers: r = α^(n−m+1) b mod a, no rational normalisation.
  std::vector<cln::cl_I> r = b;
  for (std::size_t top = n + 1; top-- > m;) {
    const cln::cl_I lead = r[top];
    for (std::size_t j = 0; j < top; ++j) r[j] = r[j] * alpha;
    if (!cln::zerop(lead))
      for (std::size_t j = 0; j < m; ++j) r[top - m + j] = r[top - m + j] - lead * a[j];
    r.pop_back();
  }
  while (!r.empty() && cln::zerop(r.back())) r.pop_back();
  if (r.empty()) return cln::cl_RA(0);
  const int rho = static_cast<int>(r.size()) - 1;
  // Res(a, α^k r) = α^(k m) Res(a, r) with k = n − m + 1
  const cln::cl_I scale = cln::expt_pos(alpha, static_cast<uintL>((n - m + 1) * m));
  const cln::cl_RA small = cln::cl_RA(bareiss_determinant(sylvester(a, r))) / scale;
  return cln::expt(cln::cl_RA(alpha), static_cast<int>(n) - rho) * small;
}

}  // namespace

cln::cl_I bareiss_determinant(std::vector<std::vector<cln::cl_I>> m) {
  const std::size_t n = m.size();
  if (n == 0) return 1;
  cln::cl_I previous = 1;
  int sign = 1;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (cln::zerop(m[k][k])) {
      std::size_t r = k + 1;
      while (r < n && cln::zerop(m[r][k])) ++r;
      if (r == n) return 0;
      std::swap(m[k], m[r]);
      sign = -sign;
    }
    for (std::size_t i = k + 1; i < n; ++i) {
      for (std::size_t j = k + 1; j < n; ++j) m[i][j] = cln::exquo(m[i][j] * m[k][k] - m[i][k] * m[k][j], previous);
    }
    previous = m[k][k];
  }
  return sign > 0 ? m[n - 1][n - 1] : -m[n - 1][n - 1];
}

rational_polynomial resultant_in(const lie::coefficient_polynomial& p, const lie::coefficient_polynomial& q, int eliminated,
                                 int kept) {
  const auto a = integer_coefficients(p, eliminated, kept), b = integer_coefficients(q, eliminated, kept);
  const std::size_t m = a.size() - 1, n = b.size() - 1;
  if (m == 0 && n == 0) return rational_polynomial({1});
  // Each of the n rows of a has entries of degree ≤ deg_u a, each of the m rows of b ≤ deg_u b.
  const int bound = static_cast<int>(n) * degree_in_u(a) + static_cast<int>(m) * degree_in_u(b);
  std::vector<cln::cl_RA> xs, divided;  // Newton's divided differences, built incrementally
  for (int k = 0; static_cast<int>(xs.size()) <= bound; ++k) {
    const cln::cl_I x = (k % 2 == 0) ? cln::cl_I(k / 2) : cln::cl_I(-(k + 1) / 2);  // 0, −1, 1, −2, 2, …
    const auto value = resultant_at(at_u(a, x), at_u(b, x));
    if (!value) continue;  // the lower-degree leading coefficient vanishes here: another point serves
    cln::cl_RA y = *value;
    for (std::size_t i = 0; i < xs.size(); ++i) y = (y - divided[i]) / (x - xs[i]);
    xs.push_back(x);
    divided.push_back(y);
  }
  // Newton form → monomial coefficients: Horner over (u − x_k).
  std::vector<cln::cl_RA> c{divided.back()};
  for (std::size_t k = divided.size() - 1; k-- > 0;) {
    std::vector<cln::cl_RA> next(c.size() + 1, 0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i + 1] = next[i + 1] + c[i];
      next[i] = next[i] - xs[k] * c[i];
    }
    next[0] = next[0] + divided[k];
    c = std::move(next);
  }
  return rational_polynomial(std::move(c));
}

}  // namespace rotlie::solver
