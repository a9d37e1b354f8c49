// Every system of an R/P family along a stretch of one grid row by the parameter homotopy: start
// solutions from the exact eliminant at the first body, then every complex solution carried body to
// body; at each body the real ones (imaginary part ≤ 1e-9 relative) are compared with the exact
// solver's, system by system. CPU time of this process (the machine is shared: wall time means little).
//   homotopy_row_bench FAMILY K ROW J0 BODIES [FIRST_STEP] [--no-check]
#include <cln/float.h>

#include <algorithm>
#include <ctime>
#include <iostream>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/family_systems.hpp"
#include "rotlie/solver/parameter_homotopy.hpp"

namespace {
double cpu() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }
using real_point = std::array<long double, 3>;
}  // namespace

int main(int argc, char** argv) {
  using namespace rotlie::solver;
  if (argc < 6) {
    std::cerr << "usage: homotopy_row_bench FAMILY K ROW J0 BODIES [FIRST_STEP] [--no-check]\n";
    return 2;
  }
  const std::string family = argv[1];
  const int K = std::stoi(argv[2]), i = std::stoi(argv[3]), j0 = std::stoi(argv[4]), count = std::stoi(argv[5]);
  const long double first_step = argc > 6 ? std::stold(argv[6]) : 1.0L;
  const bool check = !(argc > 7 && std::string(argv[7]) == "--no-check");
  double t = cpu();
  const auto& systems = family_systems(family);
  std::cout << "systems interpolated in " << cpu() - t << " s CPU\n";
  const auto body_w = [&](int j) {
    const auto unit = scaled_to_unit_I3(grid_point(K, i, j).body);
    return complex_body{1.0L / static_cast<long double>(cln::double_approx(unit.I[0])),
                        1.0L / static_cast<long double>(cln::double_approx(unit.I[1]))};
  };
  const auto unit0 = scaled_to_unit_I3(grid_point(K, i, j0).body);
  std::vector<std::vector<complex_point>> paths;
  t = cpu();
  long total_paths = 0;
  int expected_mismatch = 0;
  for (const auto& sys : systems) {
    const auto s = start_from_eliminant(sys, cln::recip(unit0.I[0]), cln::recip(unit0.I[1]));
    paths.push_back(s.x);
    total_paths += static_cast<long>(s.x.size());
    expected_mismatch += (s.unpolished > 0 || s.at_infinity > 0) ? 1 : 0;
  }
  const double t_start = cpu() - t;
  std::cout << "start: " << total_paths << " complex solutions of " << systems.size() << " systems in " << t_start
            << " s CPU (" << expected_mismatch << " systems with roots that do not lift to finite solutions)\n";
  const complex_ld gamma(0.37L, 0.81L);
  double t_track = 0, t_exact = 0;
  int refused = 0, differ = 0, real_fast_total = 0, real_exact_total = 0, near_real = 0;
  long long newton = 0, assemblies = 0;
  for (int j = j0 + 1; j < j0 + count && j < K; ++j) {
    int body_differ = 0, body_refused = 0, rf = 0, re = 0;
    for (std::size_t k = 0; k < systems.size(); ++k) {
      tracking_stats s;
      t = cpu();
      const bool ok = track_all(systems[k], paths[k], body_w(j - 1), body_w(j), gamma, s, first_step);
      t_track += cpu() - t;
      newton += s.newton_iterations;
      assemblies += s.assemblies;
      if (!ok) {
        ++body_refused;
        const auto unit = scaled_to_unit_I3(grid_point(K, i, j).body);
        paths[k] = start_from_eliminant(systems[k], cln::recip(unit.I[0]), cln::recip(unit.I[1])).x;
      }
      std::vector<real_point> fast;
      for (const auto& x : paths[k]) {
        const long double im = std::max({std::abs(x[0].imag()), std::abs(x[1].imag()), std::abs(x[2].imag())});
        const long double re_size = 1 + std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])});
        if (im <= 1e-9L * re_size) fast.push_back({x[0].real(), x[1].real(), x[2].real()});
        else if (im <= 1e-4L * re_size) ++near_real;
      }
      std::sort(fast.begin(), fast.end());
      rf += static_cast<int>(fast.size());
      if (!check) continue;
      t = cpu();
      const auto r = solve_dedicated(grid_point(K, i, j).body, {systems[k].scheme}, {systems[k].permutation}, 40);
      t_exact += cpu() - t;
      std::vector<real_point> exact;
      for (const auto& sol : r.solutions) {
        real_point x{0, 0, 0};
        for (std::size_t c = 0; c < sol.free.size(); ++c)
          for (const auto& [name, value] : sol.coefficients)
            if (name == sol.free[c]) x[c] = static_cast<long double>(cln::double_approx(value));
        exact.push_back(x);
      }
      std::sort(exact.begin(), exact.end());
      re += static_cast<int>(exact.size());
      bool same = exact.size() == fast.size();
      for (std::size_t a = 0; same && a < exact.size(); ++a)
        for (int c = 0; c < 3; ++c) same = same && std::fabs(exact[a][c] - fast[a][c]) <= 1e-8L * (1 + std::fabs(exact[a][c]));
      if (!same) {
        ++body_differ;
        std::cout << "    " << systems[k].scheme << " " << systems[k].permutation << ": fast " << fast.size() << " real, exact "
                  << exact.size() << "\n";
      }
    }
    std::cout << "  body " << j << ": " << rf << " real (exact " << re << "), " << body_refused << " systems refused, "
              << body_differ << " systems differ\n" << std::flush;
    refused += body_refused;
    differ += body_differ;
    real_fast_total += rf;
    real_exact_total += re;
  }
  const int steps = std::max(1, std::min(count, K - j0) - 1);
  std::cout << "tracking: " << t_track / steps << " s CPU per body (" << static_cast<double>(newton) / steps
            << " Newton iterations, " << static_cast<double>(assemblies) / steps << " assemblies per body); "
            << refused << " refused (system, body) steps; " << near_real << " near-real solutions seen; " << differ
            << " (system, body) pairs differ from the exact solver";
  if (check) std::cout << " (exact solver: " << t_exact / steps << " s CPU per body)";
  std::cout << "\n";
}
