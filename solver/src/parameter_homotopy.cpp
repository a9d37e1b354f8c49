#include "rotlie/solver/parameter_homotopy.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/complex.h>
#include <cln/real.h>

#include "rotlie/solver/critical_points.hpp"
#include "rotlie/solver/rational_polynomial.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace {

constexpr int nodes = interpolation_nodes;
constexpr int max_exponent = 24;  // per unknown, in det = ∇f · (∇P1 × ∇P2): 2·4 − 1 + 2·(2 − 1) + slack
using terms = std::vector<lagrange_polynomials::term>;
// Inside a path the corrector only has to stay in the basin of its solution; the end is polished.
constexpr long double corrector_tolerance = 1e-7L;

std::array<complex_ld, nodes> newton_basis(complex_ld w) {
  std::array<complex_ld, nodes> out;
  out[0] = 1;
  for (int k = 1; k < nodes; ++k) out[k] = out[k - 1] * (w - static_cast<long double>(k));
  return out;
}

terms at_body(const body_polynomial& p, const std::array<complex_ld, nodes>& n1, const std::array<complex_ld, nodes>& n2) {
  terms out;
  out.reserve(p.terms.size());
  for (const auto& t : p.terms) {
    complex_ld c = 0;
    for (int a = 0; a < nodes; ++a) {
      complex_ld inner = 0;
      for (int b = 0; b < nodes; ++b) inner += t.approx[static_cast<std::size_t>(a * nodes + b)] * n2[b];
      c += inner * n1[a];
    }
    if (c != complex_ld(0)) out.push_back({t.x, c});
  }
  return out;
}

// Products accumulate in a dense cube indexed by the exponents, then come back as a term list
// (only the cells touched are visited).
class accumulator {
 public:
  accumulator() : c_(static_cast<std::size_t>(side * side * side)), used_(c_.size(), 0) {}
  void add_product(const terms& a, const terms& b, complex_ld factor) {
    for (const auto& s : a)
      for (const auto& t : b) {
        const int e0 = s.x[0] + t.x[0], e1 = s.x[1] + t.x[1], e2 = s.x[2] + t.x[2];
        if (e0 >= side || e1 >= side || e2 >= side) throw std::invalid_argument("lagrange_at: degree above the bound");
        const std::size_t k = index(e0, e1, e2);
        if (!used_[k]) {
          used_[k] = 1;
          touched_.push_back(k);
        }
        c_[k] += factor * s.c * t.c;
      }
  }
  terms take() {
    std::sort(touched_.begin(), touched_.end());
    terms out;
    out.reserve(touched_.size());
    for (const std::size_t k : touched_) {
      const int e2 = static_cast<int>(k % side), e1 = static_cast<int>((k / side) % side), e0 = static_cast<int>(k / side / side);
      if (c_[k] != complex_ld(0)) out.push_back({{e0, e1, e2}, c_[k]});
      c_[k] = 0;
      used_[k] = 0;
    }
    touched_.clear();
    return out;
  }

 private:
  static constexpr int side = max_exponent + 1;
  static std::size_t index(int a, int b, int c) { return static_cast<std::size_t>((a * side + b) * side + c); }
  std::vector<complex_ld> c_;
  std::vector<char> used_;
  std::vector<std::size_t> touched_;
};

terms derivative(const terms& p, int k) {
  terms out;
  for (const auto& t : p) {
    if (t.x[static_cast<std::size_t>(k)] == 0) continue;
    auto e = t.x;
    e[static_cast<std::size_t>(k)] -= 1;
    out.push_back({e, t.c * static_cast<long double>(t.x[static_cast<std::size_t>(k)])});
  }
  return out;
}

long double size(const complex_point& x) {
  return std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
}
long double distance(const complex_point& a, const complex_point& b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// J⁻¹ F by Gaussian elimination with partial pivoting; false when singular.
bool solve3(std::array<complex_point, 3> J, complex_point F, complex_point& step) {
  for (int c = 0; c < 3; ++c) {
    int p = c;
    for (int r = c + 1; r < 3; ++r)
      if (std::abs(J[r][c]) > std::abs(J[p][c])) p = r;
    if (J[p][c] == complex_ld(0)) return false;
    std::swap(J[p], J[c]);
    std::swap(F[p], F[c]);
    for (int r = c + 1; r < 3; ++r) {
      const complex_ld f = J[r][c] / J[c][c];
      for (int k = c; k < 3; ++k) J[r][k] -= f * J[c][k];
      F[r] -= f * F[c];
    }
  }
  for (int r = 2; r >= 0; --r) {
    complex_ld v = F[r];
    for (int k = r + 1; k < 3; ++k) v -= J[r][k] * step[k];
    step[r] = v / J[r][r];
  }
  return std::isfinite(std::abs(step[0]) + std::abs(step[1]) + std::abs(step[2]));
}

// One Newton iteration: x ← x − J⁻¹F; the size of the step, or infinity when J is singular.
long double newton_step(const lagrange_polynomials& p, complex_point& x) {
  complex_point F, step{};
  std::array<complex_point, 3> J;
  lagrange_residual(p, x, F, J);
  if (!solve3(J, F, step)) return INFINITY;
  for (int k = 0; k < 3; ++k) x[k] -= step[k];
  return size(step);
}

// The corrector at one step of a path: converged to 1e-9 relative in at most 5 iterations, each
// correction at most a quarter of the one before after the first (inside Newton's quadratic basin).
bool correct(const lagrange_polynomials& p, complex_point& x, long double max_first, tracking_stats& stats) {
  long double before = INFINITY;
  for (int it = 0; it < 5; ++it) {
    const long double d = newton_step(p, x);
    ++stats.newton_iterations;
    if (!std::isfinite(d)) return false;
    if (it == 0 && d > max_first) return false;
    if (d <= corrector_tolerance * (1 + size(x))) return true;  // before the contraction test: rounding noise does not contract
    if (it > 0 && d > 0.25L * before) return false;
    before = d;
  }
  return false;
}

// Every path carried along w(τ), τ: 0 → 1, with common steps.
template <class Path>
bool track_path(const body_system& system, std::vector<complex_point>& x, const Path& path, tracking_stats& stats,
                long double first_step = 0.125L) {
  const std::size_t m = x.size();
  if (m == 0) return true;
  std::vector<complex_point> previous = x, next(m);
  std::vector<long double> nearest(m);
  long double tau = 0, h = first_step, h_previous = 0;
  int good = 0;
  while (tau < 1) {
    h = std::min(h, 1 - tau);
    const auto p = lagrange_at(system, path(tau + h));
    ++stats.assemblies;
    for (std::size_t i = 0; i < m; ++i) {
      nearest[i] = 1 + size(x[i]);
      for (std::size_t j = 0; j < m; ++j)
        if (j != i) nearest[i] = std::min(nearest[i], distance(x[i], x[j]));
    }
    bool held = true;
    for (std::size_t i = 0; i < m && held; ++i) {
      next[i] = x[i];
      if (h_previous > 0)
        for (int k = 0; k < 3; ++k) next[i][k] += (x[i][k] - previous[i][k]) * (h / h_previous);
      held = correct(p, next[i], 0.25L * nearest[i], stats) && distance(next[i], x[i]) <= 0.5L * nearest[i];
    }
    if (!held) {
      ++stats.refused_steps;
      h /= 2;
      good = 0;
      if (h < 1e-9L) return false;
      continue;
    }
    previous.swap(x);
    x.swap(next);
    tau += h;
    h_previous = h;
    if (++good >= 2) h = std::min(2 * h, 1.0L);
  }
  return true;
}

bool all_distinct(const std::vector<complex_point>& x) {
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j)
      if (distance(x[i], x[j]) <= 1e-7L * (1 + size(x[i]))) return false;
  return true;
}

}  // namespace

lagrange_polynomials lagrange_at(const body_system& system, const complex_body& w) {
  const auto n1 = newton_basis(w[0]), n2 = newton_basis(w[1]);
  const terms g1 = at_body(system.p1, n1, n2), g2 = at_body(system.p2, n1, n2);
  accumulator acc;
  for (const auto& q : system.h5) {
    const terms t = at_body(q, n1, n2);
    acc.add_product(t, t, 1);
  }
  const terms f = acc.take();
  std::array<terms, 3> df, dg1, dg2;
  for (int k = 0; k < 3; ++k) {
    df[k] = derivative(f, k);
    dg1[k] = derivative(g1, k);
    dg2[k] = derivative(g2, k);
  }
  // det[∇f; ∇g1; ∇g2] = Σ_k ∂_k f (∇g1 × ∇g2)_k, as critical_points.cpp's determinant3.
  for (int k = 0; k < 3; ++k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    accumulator cross;
    cross.add_product(dg1[a], dg2[b], 1);
    cross.add_product(dg1[b], dg2[a], -1);
    acc.add_product(df[k], cross.take(), 1);
  }
  lagrange_polynomials out;
  out.equations = {g1, g2, acc.take()};
  for (const auto& e : out.equations)
    for (const auto& t : e) out.max_degree = std::max({out.max_degree, t.x[0], t.x[1], t.x[2]});
  return out;
}

void lagrange_residual(const lagrange_polynomials& p, const complex_point& x, complex_point& F,
                       std::array<complex_point, 3>& J) {
  std::array<std::array<complex_ld, max_exponent + 1>, 3> power;  // no allocation in the inner loop
  for (int k = 0; k < 3; ++k) {
    power[k][0] = 1;
    for (int e = 1; e <= p.max_degree; ++e) power[k][e] = power[k][e - 1] * x[k];
  }
  for (int r = 0; r < 3; ++r) {
    complex_ld v = 0, d0 = 0, d1 = 0, d2 = 0;
    for (const auto& t : p.equations[r]) {
      const auto& e = t.x;
      const complex_ld m1 = power[1][e[1]], m2 = power[2][e[2]], m12 = m1 * m2;
      const complex_ld cm0 = t.c * power[0][e[0]];
      v += cm0 * m12;
      if (e[0] > 0) d0 += (t.c * static_cast<long double>(e[0])) * power[0][e[0] - 1] * m12;
      if (e[1] > 0) d1 += cm0 * (static_cast<long double>(e[1]) * power[1][e[1] - 1]) * m2;
      if (e[2] > 0) d2 += cm0 * m1 * (static_cast<long double>(e[2]) * power[2][e[2] - 1]);
    }
    F[r] = v;
    J[r] = {d0, d1, d2};
  }
}

polished_point polish(const lagrange_polynomials& p, complex_point x, int iterations) {
  polished_point out;
  for (int it = 0; it < iterations; ++it) {
    const long double d = newton_step(p, x);
    if (!std::isfinite(d)) break;
    out.correction = d / (1 + size(x));
    if (out.correction <= 1e-17L) break;
  }
  out.x = x;
  out.converged = std::isfinite(out.correction) && out.correction <= 1e-12L;
  return out;
}

bool track_all(const body_system& system, std::vector<complex_point>& x, const complex_body& w_from,
               const complex_body& w_to, complex_ld gamma, tracking_stats& stats, long double first_step) {
  // w(τ) = w_from + s(τ)(w_to − w_from), s = τ + γτ(1 − τ): complex inside, real at both ends.
  const auto path = [&](long double tau) {
    const complex_ld s = tau + gamma * tau * (1 - tau);
    return complex_body{w_from[0] + s * (w_to[0] - w_from[0]), w_from[1] + s * (w_to[1] - w_from[1])};
  };
  if (!track_path(system, x, path, stats, first_step)) return false;
  const auto end = lagrange_at(system, w_to);
  for (auto& xi : x) {
    const auto r = polish(end, xi, 4);
    if (!r.converged) return false;
    xi = r.x;
  }
  return all_distinct(x);
}

std::vector<complex_point> monodromy_solutions(const body_system& system, std::vector<complex_point> seeds,
                                               const complex_body& w, std::size_t target, int max_loops,
                                               unsigned seed, tracking_stats& stats, long double radius) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<long double> unit(-1, 1);
  const auto at_w = lagrange_at(system, w);
  std::vector<complex_point> known;
  const auto add = [&](const complex_point& y) {
    const auto r = polish(at_w, y);
    if (!r.converged) return false;
    for (const auto& k : known)
      if (distance(k, r.x) <= 1e-7L * (1 + size(k))) return false;
    known.push_back(r.x);
    return true;
  };
  for (const auto& s : seeds) add(s);
  const long double scale = radius * std::max(std::abs(w[0]), std::abs(w[1]));
  for (int fruitless = 0; known.size() < target && fruitless < max_loops;) {
    // A triangle 0 → a → b → 0 in the complex line w + s·D (D a random real direction).
    const long double angle = 3.14159265358979L * unit(random);
    const complex_body D{scale * std::cos(angle), scale * std::sin(angle)};
    const complex_ld a(2 * unit(random), 2 * unit(random)), b(2 * unit(random), 2 * unit(random));
    const std::array<complex_ld, 4> corners{0, a, b, 0};
    // Each solution on its own: a path that jumps to another still ends at a solution at w.
    std::size_t found = 0;
    const std::vector<complex_point> starts = known;
    for (const auto& start : starts) {
      std::vector<complex_point> x{start};
      bool held = true;
      for (int leg = 0; leg < 3 && held; ++leg) {
        const complex_ld s0 = corners[leg], s1 = corners[leg + 1];
        const auto path = [&](long double tau) {
          const complex_ld s = s0 + tau * (s1 - s0);
          return complex_body{w[0] + s * D[0], w[1] + s * D[1]};
        };
        held = track_path(system, x, path, stats);
      }
      if (held && add(x[0])) ++found;
    }
    fruitless = found > 0 ? 0 : fruitless + 1;
    ++stats.loops;
  }
  return known;
}

}  // namespace rotlie::solver

namespace rotlie::solver {
namespace {

// A rational as a long double of any exponent (53 bits of mantissa): the eliminant's coefficients
// overflow a double.
long double to_long_double(const cln::cl_RA& c) {
  if (cln::zerop(c)) return 0;
  const long e = static_cast<long>(cln::integer_length(cln::numerator(c))) -
                 static_cast<long>(cln::integer_length(cln::denominator(c)));
  const cln::cl_RA scaled = c * cln::expt(cln::cl_RA(2), static_cast<int>(-e));
  const double high = cln::double_approx(scaled);  // and the rest: the full long double mantissa
  const double low = cln::double_approx(scaled - cln::rational(cln::cl_DF(high)));
  return std::ldexp(static_cast<long double>(high) + static_cast<long double>(low), static_cast<int>(e));
}

complex_ld horner(const std::vector<complex_ld>& c, complex_ld z, complex_ld& derivative) {
  complex_ld p = 0;
  derivative = 0;
  for (std::size_t k = c.size(); k-- > 0;) {
    derivative = derivative * z + p;
    p = p * z + c[k];
  }
  return p;
}

// Every complex root of Σ c_k z^k (simple roots), by Aberth–Ehrlich iteration from a circle of the
// Fujiwara radius.
std::vector<complex_ld> aberth_roots(const std::vector<complex_ld>& c) {
  const std::size_t n = c.size() - 1;
  if (n == 0) return {};
  long double radius = 0;
  for (std::size_t k = 0; k < n; ++k)
    radius = std::max(radius, std::pow(std::abs(c[k] / c[n]), 1.0L / static_cast<long double>(n - k)));
  radius = std::max(radius, 1e-6L);
  std::vector<complex_ld> z(n);
  for (std::size_t k = 0; k < n; ++k)
    z[k] = std::polar(radius, 6.283185307179586L * static_cast<long double>(k) / static_cast<long double>(n) + 0.4L);
  for (int it = 0; it < 800; ++it) {
    long double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      complex_ld d;
      const complex_ld p = horner(c, z[i], d);
      if (p == complex_ld(0)) continue;
      const complex_ld ratio = p / d;
      complex_ld sum = 0;
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) sum += 1.0L / (z[i] - z[j]);
      const complex_ld w = ratio / (1.0L - ratio * sum);
      z[i] -= w;
      worst = std::max(worst, std::abs(w) / (1 + std::abs(z[i])));
    }
    if (worst < 1e-17L) break;
  }
  return z;
}

// A root refined by Newton on the exact polynomial in 40-digit complex arithmetic: near-multiple roots
// of the eliminant lose most of their digits in long double.
complex_ld refine_exactly(const rational_polynomial& p, complex_ld z) {
  const cln::float_format_t format = cln::float_format(40);
  const auto to_float = [&](long double x) {
    const double high = static_cast<double>(x);
    return cln::cl_float(cln::rational(cln::cl_DF(high)) + cln::rational(cln::cl_DF(static_cast<double>(x - high))), format);
  };
  const auto to_ld = [](const cln::cl_R& x) {
    const double high = cln::double_approx(x);
    return static_cast<long double>(high) + static_cast<long double>(cln::double_approx(x - cln::rational(cln::cl_DF(high))));
  };
  std::vector<cln::cl_N> c;
  for (const auto& k : p.coefficients()) c.push_back(cln::cl_float(k, format));
  cln::cl_N x = cln::complex(to_float(z.real()), to_float(z.imag()));
  for (int it = 0; it < 6; ++it) {
    cln::cl_N value = cln::cl_float(0, format), slope = cln::cl_float(0, format);
    for (std::size_t k = c.size(); k-- > 0;) {
      slope = slope * x + value;
      value = value * x + c[k];
    }
    if (cln::zerop(slope)) break;
    x = x - value / slope;
  }
  return {to_ld(cln::realpart(x)), to_ld(cln::imagpart(x))};
}

// A polynomial of the planar system in v at a complex u: its coefficients, by power of v.
std::vector<complex_ld> in_v_at(const lie::coefficient_polynomial& p, int u, int v, complex_ld at_u) {
  std::vector<complex_ld> c(static_cast<std::size_t>(std::max(0, p.degree(v)) + 1), 0);
  for (const auto& t : p.terms()) {
    const auto e = lie::coefficient_polynomial::unpack(t.key);
    c[static_cast<std::size_t>(e[static_cast<std::size_t>(v)])] +=
        to_long_double(t.c) * std::pow(at_u, e[static_cast<std::size_t>(u)]);
  }
  while (c.size() > 1 && c.back() == complex_ld(0)) c.pop_back();
  return c;
}

complex_ld value_at(const lie::coefficient_polynomial& p, const complex_point& x, long double& size) {
  complex_ld s = 0;
  size = 0;
  for (const auto& t : p.terms()) {
    const auto e = lie::coefficient_polynomial::unpack(t.key);
    const complex_ld term = to_long_double(t.c) * std::pow(x[0], e[0]) * std::pow(x[1], e[1]) * std::pow(x[2], e[2]);
    s += term;
    size += std::abs(term);
  }
  return s;
}

}  // namespace

eliminant_start start_from_eliminant(const body_system& system, const cln::cl_RA& w1, const cln::cl_RA& w2) {
  eliminant_start out;
  lie::coefficient_polynomial f;
  for (const auto& q : system.h5) {
    const auto e = q.at(w1, w2);
    f += e * e;
  }
  const auto reduced = reduce_lagrange_system(f, system.p1.at(w1, w2), system.p2.at(w1, w2));
  if (reduced.degenerate) return out;
  const int u = reduced.rest[0], v = reduced.rest[1];
  const rational_polynomial R = resultant_in(reduced.reduced_other, reduced.reduced_det, v, u);
  out.eliminant_degree = R.degree();
  const rational_polynomial simple = quotient(R, modular_gcd(R, R.derivative()));
  out.distinct_roots = simple.degree();
  std::vector<complex_ld> c;
  for (const auto& k : simple.coefficients()) c.push_back(to_long_double(k));
  const auto numeric = lagrange_at(system, {static_cast<long double>(cln::double_approx(w1)),
                                            static_cast<long double>(cln::double_approx(w2))});
  const complex_ld a_value = reduced.A.is_constant() ? complex_ld(to_long_double(reduced.A.terms().empty() ? cln::cl_RA(0) : reduced.A.terms()[0].c)) : complex_ld(0);
  for (const complex_ld rough : aberth_roots(c)) {
    const complex_ld root = refine_exactly(simple, rough);
    // v: the roots of the lower-degree planar equation at u where the other one vanishes too.
    // Candidates for v: the roots of both planar equations at u (an ill-conditioned u spoils one of them).
    std::vector<complex_ld> candidates = aberth_roots(in_v_at(reduced.reduced_other, u, v, root));
    for (const complex_ld c2 : aberth_roots(in_v_at(reduced.reduced_det, u, v, root))) candidates.push_back(c2);
    for (const complex_ld vr : candidates) {
      complex_point x{};
      x[static_cast<std::size_t>(u)] = root;
      x[static_cast<std::size_t>(v)] = vr;
      long double size_a = 0, size_b = 0;
      const complex_ld A = reduced.A.is_constant() ? a_value : value_at(reduced.A, x, size_a);
      const complex_ld B = value_at(reduced.B, x, size_b);
      if (std::abs(A) <= 1e-12L * std::max(size_a, 1e-300L)) {
        ++out.at_infinity;  // the linear solve is undefined: no finite solution here
        continue;
      }
      x[static_cast<std::size_t>(reduced.eliminated)] = -B / A;
      const auto r = polish(numeric, x, 40);
      if (!r.converged) {
        ++out.unpolished;
        continue;
      }
      // A regular solution only: Newton also "converges" onto a curve of solutions (det[∇f; ∇g1; ∇g2]
      // vanishes along it), where the Jacobian is singular. Hadamard ratio |det J| / Π ‖row‖.
      {
        complex_point F;
        std::array<complex_point, 3> J;
        lagrange_residual(numeric, r.x, F, J);
        const complex_ld det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                               J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                               J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
        long double rows = 1;
        for (const auto& row : J) rows *= std::sqrt(std::norm(row[0]) + std::norm(row[1]) + std::norm(row[2]));
        if (!(std::abs(det) > 1e-10L * rows)) {
          ++out.singular;
          continue;
        }
      }
      // A point where A vanishes lies on the line A = B = 0 (x_z free) that the exact solver discards:
      // not an isolated solution, whatever Newton says.
      long double size_after = 0;
      if (!reduced.A.is_constant() && std::abs(value_at(reduced.A, r.x, size_after)) <= 1e-8L * size_after) {
        ++out.at_infinity;
        continue;
      }
      bool known = false;
      for (const auto& y : out.x)
        known = known || std::max({std::abs(y[0] - r.x[0]), std::abs(y[1] - r.x[1]), std::abs(y[2] - r.x[2])}) <=
                             1e-7L * (1 + std::max({std::abs(y[0]), std::abs(y[1]), std::abs(y[2])}));
      if (!known) out.x.push_back(r.x);
    }
  }
  return out;
}

}  // namespace rotlie::solver
