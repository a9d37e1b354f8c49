#include "rotlie/solver/rational_polynomial.hpp"

#include "bivariate_rows.hpp"

#include <cln/integer.h>

#include <algorithm>
#include <stdexcept>

namespace rotlie::solver {

rational_polynomial::rational_polynomial(std::vector<cln::cl_RA> coefficients) : c_(std::move(coefficients)) { trim(); }

void rational_polynomial::trim() {
  while (!c_.empty() && cln::zerop(c_.back())) c_.pop_back();
}

cln::cl_RA rational_polynomial::operator()(const cln::cl_RA& x) const {
  cln::cl_RA v = 0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) v = v * x + *it;  // Horner
  return v;
}

rational_polynomial rational_polynomial::derivative() const {
  std::vector<cln::cl_RA> d;
  for (std::size_t i = 1; i < c_.size(); ++i) d.push_back(c_[i] * static_cast<long>(i));
  return rational_polynomial(std::move(d));
}

namespace {
// a = q b + r
void divide(const rational_polynomial& a, const rational_polynomial& b, rational_polynomial& q, rational_polynomial& r) {
  if (b.is_zero()) throw std::domain_error("division by the zero polynomial");
  std::vector<cln::cl_RA> rem = a.coefficients();
  const auto& bc = b.coefficients();
  const int db = b.degree();
  std::vector<cln::cl_RA> quo(rem.size() >= bc.size() ? rem.size() - bc.size() + 1 : 0, 0);
  for (int i = static_cast<int>(rem.size()) - 1; i >= db; --i) {
    const cln::cl_RA f = rem[static_cast<std::size_t>(i)] / bc.back();
    if (cln::zerop(f)) continue;
    quo[static_cast<std::size_t>(i - db)] = f;
    for (int j = 0; j <= db; ++j) rem[static_cast<std::size_t>(i - db + j)] = rem[static_cast<std::size_t>(i - db + j)] - f * bc[static_cast<std::size_t>(j)];
  }
  q = rational_polynomial(std::move(quo));
  rem.resize(static_cast<std::size_t>(std::max(db, 0)));
  r = rational_polynomial(std::move(rem));
}
}  // namespace

rational_polynomial operator+(const rational_polynomial& a, const rational_polynomial& b) {
  std::vector<cln::cl_RA> c(std::max(a.c_.size(), b.c_.size()), 0);
  for (std::size_t i = 0; i < a.c_.size(); ++i) c[i] = a.c_[i];
  for (std::size_t i = 0; i < b.c_.size(); ++i) c[i] = c[i] + b.c_[i];
  return rational_polynomial(std::move(c));
}

rational_polynomial operator-(const rational_polynomial& a, const rational_polynomial& b) {
  std::vector<cln::cl_RA> c(std::max(a.c_.size(), b.c_.size()), 0);
  for (std::size_t i = 0; i < a.c_.size(); ++i) c[i] = a.c_[i];
  for (std::size_t i = 0; i < b.c_.size(); ++i) c[i] = c[i] - b.c_[i];
  return rational_polynomial(std::move(c));
}

rational_polynomial operator*(const rational_polynomial& a, const rational_polynomial& b) {
  if (a.is_zero() || b.is_zero()) return {};
  std::vector<cln::cl_RA> c(a.c_.size() + b.c_.size() - 1, 0);
  for (std::size_t i = 0; i < a.c_.size(); ++i)
    for (std::size_t j = 0; j < b.c_.size(); ++j) c[i + j] = c[i + j] + a.c_[i] * b.c_[j];
  return rational_polynomial(std::move(c));
}

rational_polynomial remainder(const rational_polynomial& a, const rational_polynomial& b) {
  rational_polynomial q, r;
  divide(a, b, q, r);
  return r;
}

rational_polynomial quotient(const rational_polynomial& a, const rational_polynomial& b) {
  rational_polynomial q, r;
  divide(a, b, q, r);
  return q;
}

rational_polynomial gcd(rational_polynomial a, rational_polynomial b) {
  while (!b.is_zero()) {
    rational_polynomial r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  if (a.is_zero()) return a;
  std::vector<cln::cl_RA> c = a.coefficients();
  const cln::cl_RA lead = c.back();
  for (auto& x : c) x = x / lead;
  return rational_polynomial(std::move(c));
}

rational_polynomial rational_polynomial::square_free() const {
  if (degree() < 1) return *this;
  return quotient(*this, gcd(*this, derivative()));
}

namespace {

std::vector<rational_polynomial> sturm_sequence(const rational_polynomial& p) {
  std::vector<rational_polynomial> s{p, p.derivative()};
  while (!s.back().is_zero() && s.back().degree() > 0) {
    rational_polynomial r = remainder(s[s.size() - 2], s.back());
    std::vector<cln::cl_RA> c = r.coefficients();
    for (auto& x : c) x = -x;
    s.emplace_back(std::move(c));
  }
  if (s.back().is_zero()) s.pop_back();
  return s;
}

int sign_changes(const std::vector<rational_polynomial>& s, const cln::cl_RA& x) {
  int changes = 0, last = 0;
  for (const auto& p : s) {
    const int sg = cln::signum(p(x)) == 0 ? 0 : (cln::plusp(p(x)) ? 1 : -1);
    if (sg == 0) continue;
    if (last != 0 && sg != last) ++changes;
    last = sg;
  }
  return changes;
}

// Cauchy's bound: every root has |x| < 1 + max |a_i / a_n|.
cln::cl_RA root_bound(const rational_polynomial& p) {
  cln::cl_RA m = 0;
  const auto& c = p.coefficients();
  for (std::size_t i = 0; i + 1 < c.size(); ++i) m = cln::max(m, cln::abs(c[i] / c.back()));
  return m + 1;
}

}  // namespace

std::vector<root_interval> isolate_real_roots_sturm(const rational_polynomial& p) {
  if (p.is_zero()) throw std::invalid_argument("the zero polynomial has every number as a root");
  const rational_polynomial q = p.square_free();
  std::vector<root_interval> roots;
  if (q.degree() < 1) return roots;
  const auto s = sturm_sequence(q);
  const cln::cl_RA b = root_bound(q);
  // (lo, hi] with count = V(lo) − V(hi) distinct roots, lo and hi never roots (checked when split)
  struct piece {
    cln::cl_RA lo, hi;
    int count;
  };
  std::vector<piece> stack{{-b, b, sign_changes(s, -b) - sign_changes(s, b)}};
  while (!stack.empty()) {
    piece c = stack.back();
    stack.pop_back();
    if (c.count == 0) continue;
    if (c.count == 1) {
      roots.push_back({c.lo, c.hi});
      continue;
    }
    const cln::cl_RA mid = (c.lo + c.hi) / 2;
    if (cln::zerop(q(mid))) {
      roots.push_back({mid, mid});
      // exclude the exact root from both halves by stepping a hair away on each side
      cln::cl_RA eps = (c.hi - c.lo) / 1024;
      while (sign_changes(s, mid - eps) - sign_changes(s, mid + eps) != 1) eps = eps / 2;
      const cln::cl_RA l = mid - eps, r = mid + eps;
      stack.push_back({c.lo, l, sign_changes(s, c.lo) - sign_changes(s, l)});
      stack.push_back({r, c.hi, sign_changes(s, r) - sign_changes(s, c.hi)});
      continue;
    }
    const int vmid = sign_changes(s, mid);
    stack.push_back({c.lo, mid, sign_changes(s, c.lo) - vmid});
    stack.push_back({mid, c.hi, vmid - sign_changes(s, c.hi)});
  }
  std::sort(roots.begin(), roots.end(), [](const root_interval& x, const root_interval& y) { return x.lo < y.lo; });
  return roots;
}

namespace {
// sign of p(num/den), den > 0, from the integer Σ c_i num^i den^(n−i) (no rational normalisation).
int integer_sign_at(const std::vector<cln::cl_I>& c, const cln::cl_RA& x) {
  const cln::cl_I num = cln::numerator(x), den = cln::denominator(x);
  cln::cl_I s = c.back(), den_power = 1;
  for (std::size_t i = c.size() - 1; i-- > 0;) {
    den_power = den_power * den;
    s = s * num + c[i] * den_power;
  }
  return cln::zerop(s) ? 0 : (cln::plusp(s) ? 1 : -1);
}
}  // namespace

cln::cl_RA refine_root(const rational_polynomial& p, root_interval r, const cln::cl_RA& width) {
  if (r.lo == r.hi) return r.lo;
  cln::cl_I denominators = 1;
  for (const auto& c : p.coefficients()) denominators = cln::lcm(denominators, cln::denominator(c));
  std::vector<cln::cl_I> c;
  for (const auto& x : p.coefficients()) c.push_back(cln::the<cln::cl_I>(x * denominators));
  // On (lo, hi] a square-free p changes sign exactly once (hi may be the root itself).
  const int at_hi = integer_sign_at(c, r.hi);
  if (at_hi == 0) return r.hi;
  while (r.hi - r.lo > width) {
    const cln::cl_RA mid = (r.lo + r.hi) / 2;
    const int v = integer_sign_at(c, mid);
    if (v == 0) return mid;
    if (v == at_hi)
      r.hi = mid;
    else
      r.lo = mid;
  }
  return (r.lo + r.hi) / 2;
}

root_polisher::root_polisher(const rational_polynomial& p, int digits)
    : p_(p), digits_(digits), width_(cln::recip(cln::expt(cln::cl_RA(10), digits + 10))) {
  cln::cl_I denominators = 1;
  for (const auto& c : p.coefficients()) denominators = cln::lcm(denominators, cln::denominator(c));
  const cln::float_format_t format = cln::float_format(digits + 40);
  for (const auto& c : p.coefficients()) {
    integer_.push_back(cln::the<cln::cl_I>(c * denominators));
    value_.push_back(cln::cl_float(integer_.back(), format));
  }
  for (std::size_t i = 1; i < value_.size(); ++i) slope_.push_back(value_[i] * cln::cl_float(cln::cl_I(static_cast<long>(i)), format));
}

int root_polisher::sign_at(const cln::cl_RA& x) const { return integer_sign_at(integer_, x); }

cln::cl_RA root_polisher::polish(const root_interval& r) const {
  if (r.lo == r.hi) return r.lo;
  const int sign_hi = sign_at(r.hi);
  if (sign_hi == 0) return r.hi;
  const cln::float_format_t format = cln::float_format(digits_ + 40);
  using detail::horner;
  cln::cl_F lo = cln::cl_float(r.lo, format), hi = cln::cl_float(r.hi, format);
  cln::cl_F x = (lo + hi) / 2;
  const cln::cl_F step_goal = cln::cl_float(width_ / 1000, format);
  for (int iteration = 0; iteration < 400; ++iteration) {
    const cln::cl_F value = horner(value_, x);
    if (cln::zerop(value)) break;
    // Keep the bracket: the sign at hi is the exact one; a rounding error here only costs a step.
    if ((cln::plusp(value) ? 1 : -1) == sign_hi)
      hi = x;
    else
      lo = x;
    const cln::cl_F slope = slope_.empty() ? cln::cl_float(0, format) : horner(slope_, x);
    cln::cl_F next = (lo + hi) / 2;
    if (!cln::zerop(slope)) {
      const cln::cl_F newton = x - value / slope;
      if (newton > lo && newton < hi) next = newton;
    }
    const cln::cl_F step = cln::abs(next - x);
    x = next;
    if (step <= step_goal * (1 + cln::abs(x))) break;
  }
  // Certificate: a sign change of p across (x − width/2, x + width/2], inside the isolating interval.
  const cln::cl_RA xr = cln::rational(x), a = xr - width_ / 2, b = xr + width_ / 2;
  if (a >= r.lo && b <= r.hi) {
    const int sa = sign_at(a), sb = sign_at(b);
    if (sa == 0) return a;
    if (sb == 0) return b;
    if (sa != sb) return xr;
  }
  ++uncertified_;
  return refine_root(p_, r, width_);
}

}  // namespace rotlie::solver
