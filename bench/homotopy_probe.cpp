// Probe of the parameter homotopy on one system along one grid row: monodromy from the exact real
// solutions at the first body, then every complex solution carried body to body, the real ones
// compared with the exact solver's at each body. CPU time of this process.
//   homotopy_probe FAMILY SYSTEM_INDEX K ROW J0 BODIES
#include <cln/float.h>

#include <cstdlib>
#include <ctime>
#include <iostream>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/critical_points.hpp"
#include "rotlie/solver/resultant.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/family_systems.hpp"
#include "rotlie/solver/parameter_homotopy.hpp"

namespace {
// A polynomial in x_u only as a univariate polynomial.
rotlie::solver::rational_polynomial univariate(const rotlie::lie::coefficient_polynomial& p, int u) {
  std::vector<cln::cl_RA> c(static_cast<std::size_t>(std::max(0, p.degree(u)) + 1), 0);
  for (const auto& t : p.terms()) c[static_cast<std::size_t>(rotlie::lie::coefficient_polynomial::unpack(t.key)[static_cast<std::size_t>(u)])] += t.c;
  return rotlie::solver::rational_polynomial(c);
}
double cpu() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }
}  // namespace

int main(int argc, char** argv) {
  using namespace rotlie::solver;
  if (argc < 7) return 2;
  const std::string family = argv[1];
  const std::size_t index = std::stoul(argv[2]);
  const int K = std::stoi(argv[3]), i = std::stoi(argv[4]), j0 = std::stoi(argv[5]), count = std::stoi(argv[6]);
  const auto& sys = family_systems(family).at(index);
  const auto body_w = [&](int j) {
    const auto unit = scaled_to_unit_I3(grid_point(K, i, j).body);
    return complex_body{1.0L / static_cast<long double>(cln::double_approx(unit.I[0])),
                        1.0L / static_cast<long double>(cln::double_approx(unit.I[1]))};
  };
  const auto exact = [&](int j, int& degree, int& discarded) {
    const auto r = solve_dedicated(grid_point(K, i, j).body, {sys.scheme}, {sys.permutation}, 40);
    degree = r.systems.at(0).eliminant_degree;
    discarded = r.systems.at(0).discarded;
    std::vector<std::array<long double, 3>> out;
    for (const auto& s : r.solutions) {
      std::array<long double, 3> x{0, 0, 0};
      for (std::size_t k = 0; k < s.free.size(); ++k)
        for (const auto& [name, value] : s.coefficients)
          if (name == s.free[k]) x[k] = static_cast<long double>(cln::double_approx(value));
      out.push_back(x);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  int degree = 0, discarded = 0;
  double t = cpu();
  auto reals = exact(j0, degree, discarded);
  const double t_exact = cpu() - t;
  {  // the count of finite solutions: distinct roots of the eliminant, less those where both leading coefficients vanish
    const auto unit = scaled_to_unit_I3(grid_point(K, i, j0).body);
    const cln::cl_RA w1 = cln::recip(unit.I[0]), w2 = cln::recip(unit.I[1]);
    rotlie::lie::coefficient_polynomial f;
    for (const auto& q : sys.h5) {
      const auto e = q.at(w1, w2);
      f += e * e;
    }
    const auto red = reduce_lagrange_system(f, sys.p1.at(w1, w2), sys.p2.at(w1, w2));
    const int u = red.rest[0], v = red.rest[1];
    const auto R = resultant_in(red.reduced_other, red.reduced_det, v, u);
    const auto distinct = modular_gcd(R, R.derivative());
    const auto lc1 = univariate(red.reduced_other.coefficient(v, red.reduced_other.degree(v)), u);
    const auto lc2 = univariate(red.reduced_det.coefficient(v, red.reduced_det.degree(v)), u);
    const auto both = modular_gcd(lc1, lc2);
    std::cout << "eliminant: degree " << R.degree() << ", distinct roots " << R.degree() - distinct.degree()
              << "; A constant " << red.A.is_constant() << "; degrees in v " << red.reduced_other.degree(v) << ", "
              << red.reduced_det.degree(v) << "; common roots of the leading coefficients " << both.degree()
              << " (of which roots of the eliminant " << modular_gcd(both, R).degree() << ")\n";
  }
  std::vector<complex_point> seeds;
  for (const auto& x : reals) seeds.push_back({x[0], x[1], x[2]});
  tracking_stats stats;
  t = cpu();
  const auto unit0 = scaled_to_unit_I3(grid_point(K, i, j0).body);
  const auto start = start_from_eliminant(sys, cln::recip(unit0.I[0]), cln::recip(unit0.I[1]));
  std::cout << "start from the eliminant: " << start.x.size() << " solutions (eliminant degree " << start.eliminant_degree
            << ", distinct roots " << start.distinct_roots << ", linear solve undefined " << start.at_infinity
            << ", not polished " << start.unpolished << ", singular " << start.singular << ") in " << cpu() - t << " s CPU\n";
  std::vector<complex_point> all = start.x;
  const int loops = argc > 7 ? std::stoi(argv[7]) : 0;
  if (loops > 0) {
    t = cpu();
    all = monodromy_solutions(sys, seeds, body_w(j0), static_cast<std::size_t>(degree - discarded), loops, 14, stats,
                              argc > 8 ? std::stold(argv[8]) : 0.2L);
    std::cout << "monodromy found " << all.size() << " in " << cpu() - t << " s CPU (" << stats.newton_iterations
              << " Newton, " << stats.assemblies << " assemblies, " << stats.loops << " loops)\n";
  }
  std::cout << sys.scheme << " " << sys.permutation << " row " << i << " body " << j0 << ": eliminant degree " << degree
            << ", discarded " << discarded << ", real " << reals.size() << "; det terms "
            << lagrange_at(sys, body_w(j0)).equations[2].size() << "; exact solve " << t_exact << " s\n";
  int real_start = 0;
  for (const auto& x : all)
    real_start += std::max({std::abs(x[0].imag()), std::abs(x[1].imag()), std::abs(x[2].imag())}) <= 1e-9L * (1 + std::abs(x[0])) ? 1 : 0;
  std::cout << "real among the start solutions: " << real_start << "\n";
  {  // the unit costs: one assembly, one residual + Jacobian
    t = cpu();
    for (int k = 0; k < 200; ++k) lagrange_at(sys, body_w(j0));
    const double assembly = (cpu() - t) / 200;
    const auto p = lagrange_at(sys, body_w(j0));
    complex_point F;
    std::array<complex_point, 3> J;
    complex_ld sink = 0;
    t = cpu();
    for (int k = 0; k < 20000; ++k) {
      lagrange_residual(p, all[static_cast<std::size_t>(k) % all.size()], F, J);
      sink += F[2];
    }
    std::cout << "one assembly " << assembly * 1e3 << " ms, one residual + Jacobian " << (cpu() - t) / 20000 * 1e6
              << " us CPU" << (std::abs(sink) < 0 ? "" : "") << "\n";
  }
  const long double first_step = std::getenv("FIRST_STEP") ? std::stold(std::getenv("FIRST_STEP")) : 0.125L;
  const complex_ld gamma(0.37L, 0.81L);
  int disagreements = 0;
  double t_track = 0;
  for (int j = j0 + 1; j < j0 + count && j < K; ++j) {
    tracking_stats s;
    t = cpu();
    const bool ok = track_all(sys, all, body_w(j - 1), body_w(j), gamma, s, first_step);
    t_track += cpu() - t;
    std::vector<std::array<long double, 3>> fast;
    int near_real = 0;
    for (const auto& x : all) {
      const long double im = std::max({std::abs(x[0].imag()), std::abs(x[1].imag()), std::abs(x[2].imag())});
      const long double re = 1 + std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
      if (im <= 1e-9L * re) fast.push_back({x[0].real(), x[1].real(), x[2].real()});
      else if (im <= 1e-3L * re) ++near_real;
    }
    std::sort(fast.begin(), fast.end());
    int d2 = 0, disc2 = 0;
    const auto ex = exact(j, d2, disc2);
    bool same = ex.size() == fast.size();
    for (std::size_t k = 0; same && k < ex.size(); ++k)
      for (int c = 0; c < 3; ++c) same = same && std::fabs(ex[k][c] - fast[k][c]) <= 1e-8L * (1 + std::fabs(ex[k][c]));
    disagreements += same ? 0 : 1;
    std::cout << "  body " << j << ": tracked " << (ok ? "ok" : "REFUSED") << " " << all.size() << " paths, "
              << s.newton_iterations << " Newton, " << s.assemblies << " assemblies, " << s.refused_steps
              << " refused steps; real fast " << fast.size() << " exact " << ex.size() << " (eliminant " << d2 << ", discarded "
              << disc2 << "), near-real " << near_real << (same ? "" : "  DIFFERENT") << "\n";
  }
  std::cout << "tracking: " << t_track / std::max(1, count - 1) << " s CPU per body step for this system; "
            << disagreements << " bodies differ\n";
}
