#pragma once
// Internal to the solver: a bivariate polynomial as rows in u, evaluated exactly or in floating point;
// its coefficients in v as univariate polynomials in u; Horner and the derivative of a univariate
// polynomial in floating point; the double-precision complex roots of a univariate polynomial.
#include <cln/float.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>
#include <optional>
#include <type_traits>
#include <vector>

#include "rotlie/lie/coefficient_polynomial.hpp"
#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver::detail {

using lie::coefficient_polynomial;
inline cln::cl_RA ten_to_minus(int n) { return cln::recip(cln::expt(cln::cl_RA(10), n)); }

/// The coefficients of e in v (index = power of v), each a polynomial in the unknown u; e holds no
/// other unknown.
inline std::vector<rational_polynomial> rows_in_u(const coefficient_polynomial& e, int u, int v) {
  std::vector<rational_polynomial> rows;
  for (int j = 0; j <= e.degree(v); ++j) {
    const coefficient_polynomial cj = e.coefficient(v, j);
    std::vector<cln::cl_RA> c(static_cast<std::size_t>(std::max(cj.degree(u), 0)) + 1, 0);
    for (const auto& t : cj.terms()) c[static_cast<std::size_t>(coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(u)])] = t.c;
    rows.emplace_back(std::move(c));
  }
  return rows;
}

/// Σ c_i x^i by Horner (c: index = power), in the precision of x.
inline cln::cl_F horner(const std::vector<cln::cl_F>& c, const cln::cl_F& x) {
  cln::cl_F r = cln::cl_float(0, x);
  for (auto it = c.rbegin(); it != c.rend(); ++it) r = r * x + *it;
  return r;
}

/// The derivative's coefficients.
inline std::vector<cln::cl_F> derivative(const std::vector<cln::cl_F>& c) {
  std::vector<cln::cl_F> d;
  for (std::size_t j = 1; j < c.size(); ++j) d.push_back(c[j] * cln::cl_float(cln::cl_I(static_cast<long>(j)), c[j]));
  return d;
}

// A bivariate polynomial as rows c[i][j] of u^i v^j, evaluated first in u (once per root u), then in v
// by Horner: exactly (T = cl_RA) or in floating point of a fixed precision (T = cl_F).
template <class T>
class bivariate_in {
 public:
  bivariate_in(const coefficient_polynomial& p, int u, int v, const cln::float_format_t& format = cln::float_format_t(0))
      : zero_(convert(0, format)), one_(convert(1, format)) {
    for (const auto& t : p.terms()) {
      const auto e = coefficient_polynomial::unpack(t.key);
      const auto i = static_cast<std::size_t>(e[static_cast<std::size_t>(u)]);
      const auto j = static_cast<std::size_t>(e[static_cast<std::size_t>(v)]);
      if (c_.size() <= i) c_.resize(i + 1);
      if (c_[i].size() <= j) c_[i].resize(j + 1, zero_);
      c_[i][j] = convert(t.c, format);
      degree_v_ = std::max(degree_v_, static_cast<int>(j));
    }
  }
  int degree_v() const { return degree_v_; }
  /// (value, magnitude) at u fixed, as polynomials in v: value Σ c_ij u^i v^j and Σ |c_ij| max(1,|u|)^i.
  struct in_v {
    std::vector<T> value, magnitude;
  };
  in_v at_u(const T& x) const {
    in_v r{std::vector<T>(static_cast<std::size_t>(degree_v_) + 1, zero_), std::vector<T>(static_cast<std::size_t>(degree_v_) + 1, zero_)};
    const T ax = cln::max(one_, cln::abs(x));
    for (std::size_t i = c_.size(); i-- > 0;)
      for (std::size_t j = 0; j < r.value.size(); ++j) {
        const T& c = j < c_[i].size() ? c_[i][j] : zero_;
        r.value[j] = r.value[j] * x + c;
        r.magnitude[j] = r.magnitude[j] * ax + cln::abs(c);
      }
    return r;
  }
  /// The degree in v at the root u* known to lie in (x − h, x + h): leading coefficients c_j(u) that
  /// change sign (or vanish) across that interval vanish at u* and are dropped.
  int degree_v_at_root(const T& x, const T& h) const {
    const auto coefficient_at = [&](int j, const T& at) {
      T s = zero_;
      for (std::size_t i = c_.size(); i-- > 0;) s = s * at + (static_cast<std::size_t>(j) < c_[i].size() ? c_[i][static_cast<std::size_t>(j)] : zero_);
      return s;
    };
    int d = degree_v_;
    const auto sign = [](const T& y) { return cln::zerop(y) ? 0 : (cln::minusp(y) ? -1 : 1); };
    while (d > 0 && sign(coefficient_at(d, x - h)) * sign(coefficient_at(d, x + h)) <= 0) --d;
    return d;
  }
  T horner(const std::vector<T>& c, const T& y) const {
    T s = zero_;
    for (auto it = c.rbegin(); it != c.rend(); ++it) s = s * y + *it;
    return s;
  }
  /// |e(x, y)| / (size of the terms) when it is below tolerance, i.e. (x, y) is a root to that width.
  /// Relative to the equation's own size, never to 1: the same verdict for e and 10^k e at any k. The
  /// size bounds Σ |c_ij| |x|^i |y|^j with |x|, |y| raised to 1, the width the unknowns are known to.
  std::optional<T> vanishes(const in_v& at_x, const T& y, const T& tolerance) const {
    const T ay = cln::max(one_, cln::abs(y));
    const T r = cln::abs(horner(at_x.value, y));
    const T size = horner(at_x.magnitude, ay);
    if (cln::zerop(size)) return cln::zerop(r) ? std::optional<T>(r) : std::nullopt;
    if (r <= tolerance * size) return r / size;
    return std::nullopt;
  }
  T convert(const cln::cl_RA& x) const { return convert(x, format_of(one_)); }

 private:
  static cln::float_format_t format_of(const cln::cl_RA&) { return cln::float_format_t(0); }
  static cln::float_format_t format_of(const cln::cl_F& x) { return cln::float_format(x); }
  static T convert(const cln::cl_RA& x, const cln::float_format_t& format) {
    if constexpr (std::is_same_v<T, cln::cl_F>)
      return cln::cl_float(x, format);
    else
      return x;
  }
  T zero_, one_;
  std::vector<std::vector<T>> c_;
  int degree_v_ = 0;
};
using bivariate = bivariate_in<cln::cl_RA>;
using float_bivariate_rows = bivariate_in<cln::cl_F>;

// All complex roots of a univariate polynomial (exact coefficients, index = power), in double, as the
// eigenvalues of its companion matrix: starting points only, every one is polished and checked. The
// coefficients are divided by the largest first, so that no size of the polynomial overflows a double.
template <class T>
inline std::vector<std::complex<double>> complex_roots(const std::vector<T>& exact) {
  if (exact.empty()) return {};
  T largest = cln::abs(exact.front());
  for (const auto& x : exact) largest = cln::max(largest, cln::abs(x));
  if (cln::zerop(largest)) return {};
  // Ratios below 10^-300 are 0 here: converting them would underflow a double.
  static const cln::cl_RA negligible = cln::recip(cln::expt(cln::cl_RA(10), 300));
  std::vector<double> c;
  for (const auto& x : exact) {
    const T ratio = x / largest;
    c.push_back(cln::cl_R(cln::abs(ratio)) < cln::cl_R(negligible) ? 0.0 : cln::double_approx(ratio));
  }
  while (!c.empty() && c.back() == 0) c.pop_back();
  if (c.size() < 2) return {};
  const auto n = static_cast<Eigen::Index>(c.size() - 1);
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 1; i < n; ++i) companion(i, i - 1) = 1;
  for (Eigen::Index i = 0; i < n; ++i) companion(i, n - 1) = -c[static_cast<std::size_t>(i)] / c.back();
  const Eigen::VectorXcd eigenvalues = companion.eigenvalues();
  return {eigenvalues.begin(), eigenvalues.end()};
}

}  // namespace rotlie::solver::detail
