// Real-root isolation by Descartes' rule of signs with bisection (Vincent–Collins–Akritas) on a
// primitive integer polynomial. Only integer additions and shifts: far cheaper than Sturm
// sequences over Q once the degree reaches a few dozen and the coefficients hundreds of digits.
#include <cln/integer.h>

#include <algorithm>
#include <stdexcept>

#include "rotlie/solver/rational_polynomial.hpp"

namespace rotlie::solver {
namespace {

using integer_poly = std::vector<cln::cl_I>;  // index = power

integer_poly primitive_integer(const rational_polynomial& p) {
  cln::cl_I common_denominator = 1;
  for (const auto& c : p.coefficients()) common_denominator = cln::lcm(common_denominator, cln::denominator(c));
  integer_poly out;
  cln::cl_I g = 0;
  for (const auto& c : p.coefficients()) {
    out.push_back(cln::the<cln::cl_I>(c * common_denominator));
    g = cln::gcd(g, out.back());
  }
  for (auto& c : out) c = cln::exquo(c, g);
  return out;
}

// a(x) ← a(x + 1), in place (Horner-like repeated synthetic division).
void taylor_shift_by_one(integer_poly& a) {
  const std::size_t n = a.size();
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (std::size_t j = n - 1; j-- > i;) a[j] = a[j] + a[j + 1];
}

// Sign variations of (x + 1)^n a(1/(x + 1)): a bound on the roots of a in (0, 1), exact when 0 or 1.
int descartes_bound_on_unit_interval(const integer_poly& a) {
  integer_poly r(a.rbegin(), a.rend());
  taylor_shift_by_one(r);
  int changes = 0, last = 0;
  for (const auto& c : r) {
    const int s = cln::signum(c) == 0 ? 0 : (cln::plusp(c) ? 1 : -1);
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

cln::cl_I sum_of(const integer_poly& a) {  // a(1)
  cln::cl_I s = 0;
  for (const auto& c : a) s = s + c;
  return s;
}

cln::cl_I value_at_half_scaled(const integer_poly& a) {  // 2^n a(1/2)
  cln::cl_I v = 0;
  const std::size_t n = a.size() - 1;
  for (std::size_t i = 0; i <= n; ++i) v = v + a[i] * cln::ash(cln::cl_I(1), static_cast<sintC>(n - i));
  return v;
}

// Roots of a in (0, 2^k) with a(0) ≠ 0, as intervals scaled back by `sign`.
void isolate_positive(integer_poly a, long k, int sign, bool zero_is_root, std::vector<root_interval>& out) {
  // a(x) ← a(2^k x): the roots move into (0, 1).
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = cln::ash(a[i], static_cast<sintC>(static_cast<std::size_t>(k) * i));
  struct node {
    integer_poly q;   // q(x) ∝ a((c + x) / 2^j)
    cln::cl_I c;
    long j;
    bool root_at_left_end;  // recorded already (zero, or an ancestor's midpoint)
  };
  std::vector<node> stack{{std::move(a), 0, 0, zero_is_root}};
  auto to_original = [&](const cln::cl_RA& t) { return sign * t * cln::expt(cln::cl_RA(2), static_cast<sintL>(k)); };
  while (!stack.empty()) {
    node nd = std::move(stack.back());
    stack.pop_back();
    const bool root_at_left_end = nd.root_at_left_end || cln::zerop(nd.q.front());
    while (nd.q.size() > 1 && cln::zerop(nd.q.front())) nd.q.erase(nd.q.begin());
    if (nd.q.size() <= 1) continue;
    const int v = descartes_bound_on_unit_interval(nd.q);
    const cln::cl_RA scale = cln::expt(cln::cl_RA(2), static_cast<sintL>(-nd.j));
    const cln::cl_RA lo = nd.c * scale, hi = (nd.c + 1) * scale;
    if (v == 0) continue;
    // Exactly one root inside; accepted only when neither end is itself a root, so that refinement
    // can rely on a sign change across the interval (the negative side flips the ends).
    if (v == 1 && !root_at_left_end && !cln::zerop(sum_of(nd.q))) {
      cln::cl_RA l = to_original(lo), h = to_original(hi);
      if (l > h) std::swap(l, h);
      out.push_back({l, h});
      continue;
    }
    const bool root_at_midpoint = cln::zerop(value_at_half_scaled(nd.q));
    if (root_at_midpoint) {
      const cln::cl_RA m = to_original((2 * nd.c + 1) * scale / 2);
      out.push_back({m, m});
    }
    // Left half: 2^n q(x/2); right half: the same shifted by one.
    const std::size_t n = nd.q.size() - 1;
    integer_poly left(nd.q.size());
    for (std::size_t i = 0; i <= n; ++i) left[i] = cln::ash(nd.q[i], static_cast<sintC>(n - i));
    integer_poly right = left;
    taylor_shift_by_one(right);
    stack.push_back({std::move(right), 2 * nd.c + 1, nd.j + 1, root_at_midpoint});
    stack.push_back({std::move(left), 2 * nd.c, nd.j + 1, root_at_left_end});
  }
}

// k with 2^k above every root's modulus (Cauchy: 1 + max |a_i / a_n|).
long root_bound_exponent(const integer_poly& a) {
  cln::cl_RA m = 0;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) m = cln::max(m, cln::abs(cln::cl_RA(a[i]) / a.back()));
  const cln::cl_I ceiling = cln::ceiling1(m + 1);
  return static_cast<long>(cln::integer_length(ceiling));
}

}  // namespace

std::vector<root_interval> isolate_real_roots(const rational_polynomial& p) {
  if (p.is_zero()) throw std::invalid_argument("the zero polynomial has every number as a root");
  return isolate_real_roots_of_square_free(p.square_free());
}

std::vector<root_interval> isolate_real_roots_of_square_free(const rational_polynomial& p) {
  if (p.is_zero()) throw std::invalid_argument("the zero polynomial has every number as a root");
  integer_poly a = primitive_integer(p);
  std::vector<root_interval> roots;
  if (a.size() <= 1) return roots;
  const bool zero_is_root = cln::zerop(a.front());
  if (zero_is_root) {  // square-free: x divides it once
    roots.push_back({0, 0});
    a.erase(a.begin());
  }
  if (a.size() > 1) {
    const long k = root_bound_exponent(a);
    integer_poly negated = a;
    for (std::size_t i = 1; i < negated.size(); i += 2) negated[i] = -negated[i];
    isolate_positive(a, k, 1, zero_is_root, roots);
    isolate_positive(negated, k, -1, zero_is_root, roots);
  }
  std::sort(roots.begin(), roots.end(), [](const root_interval& x, const root_interval& y) { return x.lo < y.lo; });
  return roots;
}

}  // namespace rotlie::solver
