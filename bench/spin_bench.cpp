// Issue 24's question: in the spin–orbit scene, where the torque costs a handful of flops and the free
// rotation is most of the work, does a dedicated rotor pay against the exact rotor, the general
// 4th-order compositions and Boost.Odeint? Error of the final attitude (against RKF78 in long double)
// against CPU time for the Moon, Mercury and Hyperion (runs::spin_cost_cases), then per body the CPU
// each method needs for a given error and the error it reaches for a given CPU time, as ratios to the
// exact rotor (SIER4) and to the best reference composition. The best R, P and N rotors are those
// `rotlie best --analytic-only` ranks first for each body.
//   spin_bench [--quick]    CSV rows on stdout, then the summary tables
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "rotlie/runs/spin_orbit_cost.hpp"

namespace runs = rotlie::runs;

namespace {

// The integrators of each body: the exact rotor, the general compositions in the permutations that
// `rotlie best` ranks first for the body, its best dedicated rotors (R and P by ||H_R5||), 2nd order.
std::vector<std::string> methods_for(const std::string& body) {
  std::vector<std::string> m = {"SIER4", "SIER4/RS4-S5-McLachlan:ABC", "SIER4/RS4-S5-McLachlan:CBA", "SIER4/ABC4-S5-McLachlan:CBA", "SIER2", "MRDL"};
  if (body == "Hyperion") {
    m.push_back("SIER4/R:ABC:4");
    m.push_back("SIER4/P12:ABC:4");
    m.push_back("SIER4/N4:ABC:3");  // the cheapest family (9 rotations), best N by ||H_R5||
  } else {
    m.push_back("SIER4/R:CBA:4");
    m.push_back("SIER4/P9:BCA:3");
    m.push_back("SIER4/N3:BCA:3");
  }
  return m;
}

double error_at_cpu(const std::vector<runs::spin_cost_point>& curve, double cpu) {
  std::vector<runs::spin_cost_point> pts = curve;
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.cpu_s < b.cpu_s; });
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const auto &a = pts[i], &b = pts[i + 1];
    if (a.cpu_s <= cpu && cpu <= b.cpu_s && a.error > 0 && b.error > 0) {
      const double u = std::log(cpu / a.cpu_s) / std::log(b.cpu_s / a.cpu_s);
      return std::exp(std::log(a.error) + u * std::log(b.error / a.error));
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::string(argv[1]) == "--quick";
  const std::vector<double> steps_per_orbit = quick ? std::vector<double>{25, 100, 400} : std::vector<double>{25, 50, 100, 200, 400, 800, 1600};
  const std::vector<std::string> tolerances = quick ? std::vector<std::string>{"1e-7", "1e-10", "1e-13"}
                                                    : std::vector<std::string>{"1e-6", "1e-7", "1e-8", "1e-9", "1e-10", "1e-11", "1e-12", "1e-13"};
  const double min_cpu = quick ? 0.005 : 0.05;
  std::printf("case,method,h_or_tol,error,cpu_s,evaluations\n");
  for (const auto& c : runs::spin_cost_cases()) {
    const auto ref = runs::spin_cost_reference(c);
    std::map<std::string, std::vector<runs::spin_cost_point>> curves;
    auto methods = methods_for(c.body);
    for (const auto& tol : tolerances) {
      methods.push_back("odeint-dopri5:" + tol);
      methods.push_back("odeint-rkf78:" + tol);
    }
    for (const auto& name : methods) {
      const bool adaptive = name.rfind("odeint-", 0) == 0;
      const std::string family = adaptive ? name.substr(0, name.find(':')) : name;
      for (double n : adaptive ? std::vector<double>{1} : steps_per_orbit) {
        const auto p = runs::spin_cost_point_of(c, ref, name, 1 / n, min_cpu);
        curves[family].push_back(p);
        std::printf("\"%s\",%s,%.3g,%.4e,%.4e,%.0f\n", c.label.c_str(), family.c_str(), p.h, p.error, p.cpu_s, p.evaluations);
      }
    }
    // per body: CPU for a given error, error for a given CPU, as ratios
    std::printf("\n# %s: CPU (s) needed for an attitude error, and the error at a CPU time\n", c.label.c_str());
    const std::vector<double> errors = {1e-6, 1e-9, 1e-11};
    const double exact_cpu = runs::cpu_at_error(curves["SIER4"], 1e-9);
    std::printf("# %-30s %12s %12s %12s %14s\n", "method", "cpu@1e-6", "cpu@1e-9", "cpu@1e-11", "err@SIER4cpu(1e-9)");
    for (const auto& [family, curve] : curves) {
      std::printf("# %-30s", family.c_str());
      for (double e : errors) std::printf(" %12.3e", runs::cpu_at_error(curve, e));
      std::printf(" %14.3e\n", error_at_cpu(curve, exact_cpu));
    }
    std::printf("\n");
  }
  return 0;
}
