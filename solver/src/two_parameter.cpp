#include "rotlie/solver/two_parameter.hpp"

#include "dense_linear_solve.hpp"

#include <cln/float.h>
#include <cln/real.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>

#include "rotlie/bch/stage_hamiltonian.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/lie/stop_request.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/sixth_order_search.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "rotlie/solver/table_certificate.hpp"

namespace rotlie::solver {
namespace {

using poly = lie::multivariate_polynomial;
constexpr int max_free = 4;

// ∂p/∂x_k, exactly.
poly derivative(const poly& p, int k) {
  std::vector<poly> monomials;
  std::vector<cln::cl_RA> factors;
  for (const auto& [key, c] : p.rational_terms()) {
    const int e = poly::exponent(key, k);
    if (e == 0) continue;
    poly m(1);
    for (int j = 0; j < max_free; ++j)
      for (int i = 0; i < poly::exponent(key, j) - (j == k ? 1 : 0); ++i) m = m * poly::unknown(j);
    monomials.push_back(std::move(m));
    factors.push_back(c * e);
  }
  std::vector<poly::product_term> summands;
  for (std::size_t i = 0; i < monomials.size(); ++i) summands.push_back({factors[i], &monomials[i], nullptr});
  return poly::sum_of_products(summands);
}

// A polynomial in n ≤ 4 unknowns compiled for evaluation with its gradient and Hessian in T.
template <class T>
struct compiled {
  int n = 0;
  std::vector<std::array<int, max_free>> exponent;
  std::vector<T> coefficient;
};

template <class T, class Convert>
compiled<T> compile(const poly& p, int n, Convert convert) {
  compiled<T> out;
  out.n = n;
  for (const auto& [key, c] : p.rational_terms()) {
    std::array<int, max_free> e{};
    for (int k = 0; k < n; ++k) e[static_cast<std::size_t>(k)] = poly::exponent(key, k);
    out.exponent.push_back(e);
    out.coefficient.push_back(convert(c));
  }
  return out;
}

using detail::abs_of;
using detail::solve_linear;
long double times(long double x, int e) { return x * e; }
cln::cl_F times(const cln::cl_F& x, int e) { return x * cln::cl_float(e, x); }

// Value, gradient, Hessian (row-major n×n) and the gradient's term sizes Σ|terms of ∂p/∂x_k| at the
// powers power[k][e] = x_k^e.
template <class T>
struct evaluation {
  T value;
  std::vector<T> gradient, hessian, gradient_size;
  T size;  // Σ|terms|
};

template <class T>
evaluation<T> evaluate(const compiled<T>& p, const std::vector<std::vector<T>>& power, const T& zero) {
  const int n = p.n;
  evaluation<T> r{zero, std::vector<T>(static_cast<std::size_t>(n), zero),
                  std::vector<T>(static_cast<std::size_t>(n * n), zero), std::vector<T>(static_cast<std::size_t>(n), zero), zero};
  for (std::size_t t = 0; t < p.coefficient.size(); ++t) {
    const auto& e = p.exponent[t];
    const T& c = p.coefficient[t];
    // other[k] = c · Π_{j≠k} x_j^{e_j}; all = c · Π_j x_j^{e_j}
    T all = c;
    for (int k = 0; k < n; ++k) all = all * power[static_cast<std::size_t>(k)][static_cast<std::size_t>(e[static_cast<std::size_t>(k)])];
    r.value = r.value + all;
    r.size = r.size + abs_of(all);
    for (int k = 0; k < n; ++k) {
      const int ek = e[static_cast<std::size_t>(k)];
      if (ek == 0) continue;
      T without_k = c;
      for (int j = 0; j < n; ++j)
        if (j != k) without_k = without_k * power[static_cast<std::size_t>(j)][static_cast<std::size_t>(e[static_cast<std::size_t>(j)])];
      const T gk = times(without_k, ek) * power[static_cast<std::size_t>(k)][static_cast<std::size_t>(ek - 1)];
      r.gradient[static_cast<std::size_t>(k)] = r.gradient[static_cast<std::size_t>(k)] + gk;
      r.gradient_size[static_cast<std::size_t>(k)] = r.gradient_size[static_cast<std::size_t>(k)] + abs_of(gk);
      if (ek >= 2) {
        const std::size_t kk = static_cast<std::size_t>(k * n + k);
        r.hessian[kk] = r.hessian[kk] + times(without_k, ek * (ek - 1)) * power[static_cast<std::size_t>(k)][static_cast<std::size_t>(ek - 2)];
      }
      for (int l = k + 1; l < n; ++l) {
        const int el = e[static_cast<std::size_t>(l)];
        if (el == 0) continue;
        T h = times(c, ek * el) * power[static_cast<std::size_t>(k)][static_cast<std::size_t>(ek - 1)] *
              power[static_cast<std::size_t>(l)][static_cast<std::size_t>(el - 1)];
        for (int j = 0; j < n; ++j)
          if (j != k && j != l) h = h * power[static_cast<std::size_t>(j)][static_cast<std::size_t>(e[static_cast<std::size_t>(j)])];
        r.hessian[static_cast<std::size_t>(k * n + l)] = r.hessian[static_cast<std::size_t>(k * n + l)] + h;
        r.hessian[static_cast<std::size_t>(l * n + k)] = r.hessian[static_cast<std::size_t>(l * n + k)] + h;
      }
    }
  }
  return r;
}

template <class T>
std::vector<std::vector<T>> powers(const std::vector<T>& x, const T& one) {
  std::vector<std::vector<T>> p(x.size(), std::vector<T>(16, one));
  for (std::size_t k = 0; k < x.size(); ++k)
    for (std::size_t e = 1; e < 16; ++e) p[k][e] = p[k][e - 1] * x[k];
  return p;
}

using real = long double;

struct compiled_system {
  compiled<real> f, p1, p2;
  int n = 0;
};

compiled_system compile_long_double(const two_parameter_system& s) {
  const auto to_real = [](const cln::cl_RA& c) { return static_cast<real>(cln::double_approx(c)); };
  const int n = s.free_count();
  return {compile<real>(s.norm_squared, n, to_real), compile<real>(s.p1, n, to_real), compile<real>(s.p2, n, to_real), n};
}

// The local picture at a point of the surface: multipliers, reduced gradient and Hessian.
struct local_model {
  real f = 0;
  std::array<real, 2> lambda{};
  std::vector<real> z;         // n × r tangent basis, column-major
  std::vector<real> gradient;  // r: Zᵀ(∇f − Aᵀλ)
  std::vector<real> hessian;   // r × r: Zᵀ(∇²f − λ1∇²P1 − λ2∇²P2)Z
  real gradient_scale = 0;     // max_k Σ|terms of ∂f/∂x_k|
  bool valid = false;
};

// Eigenvalues of a symmetric r × r matrix, r ≤ 2, ascending.
std::vector<real> symmetric_eigenvalues(const std::vector<real>& h, int r) {
  if (r == 1) return {h[0]};
  const real m = (h[0] + h[3]) / 2, d = std::sqrt((h[0] - h[3]) * (h[0] - h[3]) / 4 + h[1] * h[1]);
  return {m - d, m + d};
}

local_model model_at(const compiled_system& c, const std::vector<real>& x) {
  const int n = c.n, r = n - 2;
  const auto pw = powers<real>(x, 1);
  const auto f = evaluate(c.f, pw, real(0)), a = evaluate(c.p1, pw, real(0)), b = evaluate(c.p2, pw, real(0));
  local_model m;
  m.f = f.value;
  for (real v : f.gradient_size) m.gradient_scale = std::max(m.gradient_scale, v);
  // λ from the normal equations (A Aᵀ) λ = A ∇f.
  real aa = 0, ab = 0, bb = 0, af = 0, bf = 0;
  for (int k = 0; k < n; ++k) {
    const real ak = a.gradient[static_cast<std::size_t>(k)], bk = b.gradient[static_cast<std::size_t>(k)];
    aa += ak * ak, ab += ak * bk, bb += bk * bk;
    af += ak * f.gradient[static_cast<std::size_t>(k)], bf += bk * f.gradient[static_cast<std::size_t>(k)];
  }
  const real det = aa * bb - ab * ab;
  if (!(det > 1e-24L * aa * bb)) return m;  // the constraints' gradients are dependent: a singular point
  m.lambda = {(bb * af - ab * bf) / det, (aa * bf - ab * af) / det};
  // Orthonormal basis of the constraints' gradients, then of its complement (greedy Gram–Schmidt).
  std::vector<std::vector<real>> q{a.gradient, b.gradient};
  const auto orthonormalise = [&](std::vector<real>& v, const std::vector<std::vector<real>>& basis) {
    for (const auto& u : basis) {
      real d = 0;
      for (int k = 0; k < n; ++k) d += u[static_cast<std::size_t>(k)] * v[static_cast<std::size_t>(k)];
      for (int k = 0; k < n; ++k) v[static_cast<std::size_t>(k)] -= d * u[static_cast<std::size_t>(k)];
    }
    real norm = 0;
    for (real e : v) norm += e * e;
    return std::sqrt(norm);
  };
  std::vector<std::vector<real>> basis;
  for (auto& v : q) {
    const real norm = orthonormalise(v, basis);
    for (auto& e : v) e /= norm;
    basis.push_back(v);
  }
  std::vector<std::vector<real>> tangent;
  while (static_cast<int>(tangent.size()) < r) {
    std::vector<real> best;
    real best_norm = 0;
    for (int k = 0; k < n; ++k) {
      std::vector<real> v(static_cast<std::size_t>(n), 0);
      v[static_cast<std::size_t>(k)] = 1;
      const real norm = orthonormalise(v, basis);
      if (norm > best_norm) best_norm = norm, best = v;
    }
    for (auto& e : best) e /= best_norm;
    basis.push_back(best);
    tangent.push_back(best);
  }
  std::vector<real> g(static_cast<std::size_t>(n)), h(static_cast<std::size_t>(n * n));
  for (int k = 0; k < n; ++k)
    g[static_cast<std::size_t>(k)] = f.gradient[static_cast<std::size_t>(k)] - m.lambda[0] * a.gradient[static_cast<std::size_t>(k)] -
                                     m.lambda[1] * b.gradient[static_cast<std::size_t>(k)];
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = f.hessian[i] - m.lambda[0] * a.hessian[i] - m.lambda[1] * b.hessian[i];
  m.gradient.assign(static_cast<std::size_t>(r), 0);
  m.hessian.assign(static_cast<std::size_t>(r * r), 0);
  for (int i = 0; i < r; ++i) {
    const auto& zi = tangent[static_cast<std::size_t>(i)];
    for (int k = 0; k < n; ++k) m.gradient[static_cast<std::size_t>(i)] += zi[static_cast<std::size_t>(k)] * g[static_cast<std::size_t>(k)];
    for (int j = 0; j < r; ++j) {
      const auto& zj = tangent[static_cast<std::size_t>(j)];
      real sum = 0;
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l)
          sum += zi[static_cast<std::size_t>(k)] * h[static_cast<std::size_t>(k * n + l)] * zj[static_cast<std::size_t>(l)];
      m.hessian[static_cast<std::size_t>(i * r + j)] = sum;
    }
  }
  for (const auto& zi : tangent) m.z.insert(m.z.end(), zi.begin(), zi.end());
  m.valid = true;
  return m;
}

// Moves x onto P1 = P2 = 0 by minimum-norm Gauss–Newton steps; false when it fails or leaves the box.
bool restore(const compiled_system& c, std::vector<real>& x, double bound) {
  const int n = c.n;
  for (int it = 0; it < 40; ++it) {
    const auto pw = powers<real>(x, 1);
    const auto a = evaluate(c.p1, pw, real(0)), b = evaluate(c.p2, pw, real(0));
    const real ra = a.value / std::max(a.size, real(1e-300)), rb = b.value / std::max(b.size, real(1e-300));
    if (std::abs(ra) < 1e-17L && std::abs(rb) < 1e-17L) return true;
    real aa = 0, ab = 0, bb = 0;
    for (int k = 0; k < n; ++k) {
      const real ak = a.gradient[static_cast<std::size_t>(k)], bk = b.gradient[static_cast<std::size_t>(k)];
      aa += ak * ak, ab += ak * bk, bb += bk * bk;
    }
    const real det = aa * bb - ab * ab;
    if (!(det > 1e-24L * aa * bb)) return false;
    const real ya = (bb * a.value - ab * b.value) / det, yb = (aa * b.value - ab * a.value) / det;
    real step = 0;
    for (int k = 0; k < n; ++k) {
      const real d = ya * a.gradient[static_cast<std::size_t>(k)] + yb * b.gradient[static_cast<std::size_t>(k)];
      x[static_cast<std::size_t>(k)] -= d;
      step = std::max(step, std::abs(d));
      if (!(std::abs(x[static_cast<std::size_t>(k)]) <= bound)) return false;
    }
  }
  return false;
}

real norm_squared_at(const compiled_system& c, const std::vector<real>& x) {
  return evaluate(c.f, powers<real>(x, 1), real(0)).value;
}

bool positive_definite(const local_model& m, int r) {
  const auto e = symmetric_eigenvalues(m.hessian, r);
  return e.front() > 0;
}

real reduced_gradient_size(const local_model& m) {
  real g = 0;
  for (real v : m.gradient) g = std::max(g, std::abs(v));
  return g / std::max(m.gradient_scale, real(1e-300));
}

// Descent on the surface from x (on it): reduced Newton steps, shifted to descent directions where
// the reduced Hessian is not positive definite, each restored onto the surface and kept only when f
// decreases. True when it ends at a local minimum.
bool descend(const compiled_system& c, std::vector<real>& x, const minimum_search_options& o, local_model& m) {
  const int n = c.n, r = n - 2;
  m = model_at(c, x);
  for (int it = 0; it < o.max_iterations && m.valid; ++it) {
    if (reduced_gradient_size(m) < 1e-13L && positive_definite(m, r)) return true;
    const auto eig = symmetric_eigenvalues(m.hessian, r);
    const real spread = std::max(std::abs(eig.front()), std::abs(eig.back())) + 1e-30L;
    real mu = eig.front() > 0 ? 0 : -eig.front() + 1e-6L * spread;
    bool accepted = false;
    real last_step = 0;
    for (int attempt = 0; attempt < 40 && !accepted; ++attempt) {
      std::vector<real> h = m.hessian, dr(static_cast<std::size_t>(r));
      for (int i = 0; i < r; ++i) h[static_cast<std::size_t>(i * r + i)] += mu, dr[static_cast<std::size_t>(i)] = -m.gradient[static_cast<std::size_t>(i)];
      if (!solve_linear(h, dr, static_cast<std::size_t>(r))) {
        mu = std::max(mu * 4, 1e-8L * spread);
        continue;
      }
      std::vector<real> d(static_cast<std::size_t>(n), 0);
      real length = 0;
      for (int i = 0; i < r; ++i)
        for (int k = 0; k < n; ++k) d[static_cast<std::size_t>(k)] += m.z[static_cast<std::size_t>(i * n + k)] * dr[static_cast<std::size_t>(i)];
      for (real v : d) length += v * v;
      length = std::sqrt(length);
      const real trust = 0.25L;
      if (length > trust)
        for (auto& v : d) v *= trust / length;
      std::vector<real> y = x;
      for (int k = 0; k < n; ++k) y[static_cast<std::size_t>(k)] += d[static_cast<std::size_t>(k)];
      if (restore(c, y, o.bound)) {
        const real fy = norm_squared_at(c, y);
        // Near the minimum f changes below its rounding: a Newton step (μ = 0) is kept if f does not grow.
        if (fy < m.f || (mu == 0 && fy <= m.f * (1 + 1e-16L))) {
          last_step = std::min(length, trust);
          x = y;
          accepted = true;
          break;
        }
      }
      mu = std::max(mu * 4, 1e-8L * spread);
    }
    if (!accepted) break;
    m = model_at(c, x);
    if (last_step < 1e-16L) break;
  }
  return m.valid && reduced_gradient_size(m) < 1e-9L && positive_definite(m, r);
}

}  // namespace

two_parameter_system two_parameter_conditions(const bch::scheme_layout& layout, const lie::moments_of_inertia& body) {
  if (!layout.symmetric) throw std::invalid_argument("a two-parameter family needs a palindromic word");
  const int n = static_cast<int>(layout.free_coefficients.size());
  if (n != 3 && n != 4)
    throw std::invalid_argument(layout.word + " has " + std::to_string(n) + " free coefficients; this search takes 3 or 4");
  two_parameter_system s;
  s.layout = layout;
  s.body = scaled_to_unit_I3(body);
  const std::array<cln::cl_RA, 3> w{cln::recip(s.body.I[0]), cln::recip(s.body.I[1]), cln::cl_RA(1)};
  const auto k = bch::compute_stage_hamiltonian(layout, w, 5);
  s.p1 = k.remainder[3].coefficient(lie::monomial(2, 2, 0));
  s.p2 = k.remainder[3].coefficient(lie::monomial(2, 0, 2));
  std::vector<poly::product_term> squares;
  for (const auto& [m, q] : k.remainder[5].terms()) s.h5.push_back(q);
  for (const auto& q : s.h5) squares.push_back({cln::cl_RA(1), &q, &q});
  s.norm_squared = poly::sum_of_products(squares);
  for (int j = 0; j < n; ++j) {
    s.gradient.push_back(derivative(s.norm_squared, j));
    s.p1_gradient.push_back(derivative(s.p1, j));
    s.p2_gradient.push_back(derivative(s.p2, j));
  }
  return s;
}

minimum_search search_minima(const two_parameter_system& s, const minimum_search_options& o) {
  const auto c = compile_long_double(s);
  const int n = c.n;
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> start(-o.box, o.box);
  minimum_search out;
  for (int trial = 0; trial < o.starts; ++trial) {
    ++out.starts;
    std::vector<real> x(static_cast<std::size_t>(n));
    for (auto& v : x) v = start(rng);
    if (!restore(c, x, o.bound)) continue;
    ++out.on_surface;
    local_model m;
    if (!descend(c, x, o, m)) continue;
    ++out.converged;
    bool known = false;
    for (auto& r : out.minima) {
      real distance = 0;
      for (int k = 0; k < n; ++k) distance = std::max(distance, std::abs(r.x[static_cast<std::size_t>(k)] - x[static_cast<std::size_t>(k)]));
      // The descent stops at a reduced gradient of 1e-9 of its terms: in a flat valley that leaves
      // x good to about 1e-5, so two ends that close with the same value are one minimum.
      const double values_differ = std::abs(r.remainder - static_cast<double>(std::sqrt(std::max(m.f, real(0)))));
      if (distance < 1e-4L && values_differ <= 1e-8 * r.remainder) {
        ++r.hits;
        known = true;
        break;
      }
    }
    if (!known) out.minima.push_back({x, m.lambda, static_cast<double>(std::sqrt(std::max(m.f, real(0)))), 1});
  }
  std::sort(out.minima.begin(), out.minima.end(), [](const auto& a, const auto& b) { return a.remainder < b.remainder; });
  return out;
}

bool certified_minimum::is_minimum() const {
  return !reduced_hessian.empty() && reduced_hessian.front() > 0;
}

cln::cl_RA projected_gradient(const two_parameter_system& s, const std::vector<cln::cl_RA>& x) {
  const std::size_t n = x.size();
  std::vector<cln::cl_RA> g(n), a(n), b(n);
  cln::cl_RA scale = 0;
  for (std::size_t k = 0; k < n; ++k) {
    g[k] = s.gradient[k](x), a[k] = s.p1_gradient[k](x), b[k] = s.p2_gradient[k](x);
    scale = cln::max(scale, s.gradient[k].term_size(x));
  }
  cln::cl_RA aa = 0, ab = 0, bb = 0, ag = 0, bg = 0;
  for (std::size_t k = 0; k < n; ++k) aa += a[k] * a[k], ab += a[k] * b[k], bb += b[k] * b[k], ag += a[k] * g[k], bg += b[k] * g[k];
  const cln::cl_RA det = aa * bb - ab * ab;
  if (cln::zerop(det) || cln::zerop(scale)) return 1;
  const cln::cl_RA l1 = (bb * ag - ab * bg) / det, l2 = (aa * bg - ab * ag) / det;
  cln::cl_RA worst = 0;
  for (std::size_t k = 0; k < n; ++k) worst = cln::max(worst, cln::abs(g[k] - l1 * a[k] - l2 * b[k]));
  return worst / scale;
}

certified_minimum polish_minimum(const two_parameter_system& s, const local_minimum& start, int digits) {
  const int n = s.free_count();
  const std::size_t unknowns = static_cast<std::size_t>(n + 2);
  const cln::float_format_t format = cln::float_format(static_cast<unsigned>(digits + 25));
  const auto to_float = [&](const cln::cl_RA& c) { return cln::cl_float(c, format); };
  const compiled<cln::cl_F> f = compile<cln::cl_F>(s.norm_squared, n, to_float), p1 = compile<cln::cl_F>(s.p1, n, to_float),
                            p2 = compile<cln::cl_F>(s.p2, n, to_float);
  const cln::cl_F zero = cln::cl_float(0, format), one = cln::cl_float(1, format);
  const auto from_long_double = [&](long double v) {  // exactly: the high and low double halves
    const double hi = static_cast<double>(v), lo = static_cast<double>(v - static_cast<long double>(hi));
    return cln::cl_F(cln::cl_float(hi, format) + cln::cl_float(lo, format));
  };
  std::vector<cln::cl_F> z;
  for (long double v : start.x) z.push_back(from_long_double(v));
  z.push_back(from_long_double(start.lambda[0]));
  z.push_back(from_long_double(start.lambda[1]));
  bool converged = false;
  for (int iteration = 0; iteration < 30 && !converged; ++iteration) {
    const std::vector<cln::cl_F> x(z.begin(), z.begin() + n);
    const auto pw = powers<cln::cl_F>(x, one);
    const auto ef = evaluate(f, pw, zero), ea = evaluate(p1, pw, zero), eb = evaluate(p2, pw, zero);
    const cln::cl_F& l1 = z[static_cast<std::size_t>(n)];
    const cln::cl_F& l2 = z[static_cast<std::size_t>(n + 1)];
    std::vector<cln::cl_F> value(unknowns, zero), jac(unknowns * unknowns, zero);
    for (int k = 0; k < n; ++k) {
      const auto ks = static_cast<std::size_t>(k);
      value[ks] = ef.gradient[ks] - l1 * ea.gradient[ks] - l2 * eb.gradient[ks];
      for (int l = 0; l < n; ++l) {
        const auto kl = static_cast<std::size_t>(k * n + l);
        jac[ks * unknowns + static_cast<std::size_t>(l)] = ef.hessian[kl] - l1 * ea.hessian[kl] - l2 * eb.hessian[kl];
      }
      jac[ks * unknowns + static_cast<std::size_t>(n)] = -ea.gradient[ks];
      jac[ks * unknowns + static_cast<std::size_t>(n + 1)] = -eb.gradient[ks];
      jac[static_cast<std::size_t>(n) * unknowns + ks] = ea.gradient[ks];
      jac[static_cast<std::size_t>(n + 1) * unknowns + ks] = eb.gradient[ks];
    }
    value[static_cast<std::size_t>(n)] = ea.value;
    value[static_cast<std::size_t>(n + 1)] = eb.value;
    std::vector<cln::cl_F> d(unknowns);
    for (std::size_t i = 0; i < unknowns; ++i) d[i] = -value[i];
    if (!solve_linear(jac, d, unknowns)) throw std::runtime_error("polishing: singular Lagrange system");
    cln::cl_F step = zero, size = zero;
    for (std::size_t i = 0; i < unknowns; ++i) {
      z[i] = z[i] + d[i];
      step = cln::max(step, cln::abs(d[i]));
      size = cln::max(size, cln::abs(z[i]));
    }
    if (cln::zerop(step) || cln::float_exponent(step) - cln::float_exponent(size + one) < -static_cast<long>(3.33 * (digits + 20)))
      converged = true;
  }
  if (!converged) throw std::runtime_error("polishing: Newton on the Lagrange system did not converge");
  certified_minimum out;
  for (int k = 0; k < n; ++k) out.x.push_back(written_value(cln::rational(z[static_cast<std::size_t>(k)]), digits));
  for (std::size_t k = 0; k < out.x.size(); ++k) out.values.emplace(s.layout.free_coefficients[k], out.x[k]);
  bch::solve_first_order_conditions(s.layout, out.values, [](const cln::cl_RA& v, int m) { return v / m; });
  for (const auto& name : s.layout.eliminated) out.values[name] = written_value(out.values.at(name), digits);
  const auto certificate = certify_order_four(s.layout, s.body, out.values, digits);
  out.order = certificate.order;
  out.order_residual = certificate.residual;
  out.projected_gradient = projected_gradient(s, out.x);
  out.remainder = std::sqrt(cln::double_approx(s.norm_squared(out.x)));
  std::vector<real> xl;
  for (const auto& v : out.x) xl.push_back(static_cast<real>(cln::double_approx(v)));
  const auto m = model_at(compile_long_double(s), xl);
  if (m.valid)
    for (real e : symmetric_eigenvalues(m.hessian, n - 2)) out.reduced_hessian.push_back(static_cast<double>(e));
  return out;
}

std::string two_parameter_table_text(const two_parameter_system& s, const certified_minimum& m, int digits,
                                     const lie::moments_of_inertia& body, const std::string& name, const std::string& source) {
  std::ostringstream remainder;
  remainder << m.remainder;
  return searched_table_text(s.layout, body, m.values,
                             {name, 4, digits, m.order_residual,
                              " a local minimum of ||H_R5|| on the surface H_R3 = 0; projected gradient " +
                                  lie::to_decimal(m.projected_gradient, 3) + " of its terms",
                              remainder.str(), source});
}

std::vector<std::string> two_parameter_words(bch::splitting split) {
  if (split == bch::splitting::rs) return {"RSRSRSRSRSR", "SRSRSRSRSRS"};
  return palindromic_words(13, bch::splitting::abc);
}

two_parameter_result solve_two_parameter(const lie::moments_of_inertia& body, bch::splitting split,
                                         const std::vector<std::string>& words, const std::vector<std::string>& permutations,
                                         const minimum_search_options& o, int digits, int polish) {
  const std::clock_t begin = std::clock();
  two_parameter_result result;
  std::vector<two_parameter_system> systems;
  for (const auto& word : words)
    for (const auto& perm : permutations) {
      lie::stop_point();
      two_parameter_entry e;
      e.word = word;
      e.permutation = perm;
      e.split = split;
      systems.push_back(two_parameter_conditions(bch::layout_scheme(word, split, perm), body));
      e.search = search_minima(systems.back(), o);
      if (e.search.minima.empty()) e.note = "no local minimum reached from " + std::to_string(o.starts) + " starts";
      result.entries.push_back(std::move(e));
    }
  // Polishing (long floats) costs more than the search: the systems in the order of their best minimum.
  std::vector<std::size_t> order(result.entries.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const auto best_of = [&](std::size_t i) {
    const auto& m = result.entries[i].search.minima;
    return m.empty() ? std::numeric_limits<double>::infinity() : m.front().remainder;
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return best_of(a) < best_of(b); });
  int polished = 0;
  for (std::size_t i : order) {
    auto& e = result.entries[i];
    if (e.search.minima.empty()) continue;
    if (polish >= 0 && polished >= polish) {
      e.note = "not polished (only the best " + std::to_string(polish) + " systems are)";
      continue;
    }
    ++polished;
    lie::stop_point();
    try {
      e.best = polish_minimum(systems[i], e.search.minima.front(), digits);
      e.polished = e.best.order >= 4;
      if (!e.polished) e.note = "the polished minimum does not certify order 4";
    } catch (const std::runtime_error& err) {
      e.note = err.what();
    }
  }
  std::stable_sort(result.entries.begin(), result.entries.end(), [](const auto& a, const auto& b) {
    if (a.polished != b.polished) return a.polished;
    return a.polished && a.best.remainder < b.best.remainder;
  });
  result.seconds = static_cast<double>(std::clock() - begin) / CLOCKS_PER_SEC;
  return result;
}

}  // namespace rotlie::solver
