#include "rotlie/runs/spin_cost_study.hpp"

namespace rotlie::runs {

std::string best_spin_rotor(const std::string& body) { return body == "Hyperion" ? "SIER4/N4:ABC:3" : "SIER4/R:CBA:4"; }

std::vector<spin_cost_panel> spin_cost_study(const std::vector<double>& steps, const std::vector<std::string>& tolerances, double min_cpu_s,
                                             const std::function<void(const std::string&)>& progress) {
  std::vector<spin_cost_panel> out;
  for (const auto& cs : spin_cost_cases()) {
    if (progress) progress("Spin-orbit: error against CPU time, " + cs.label);
    const auto ref = spin_cost_reference(cs);
    spin_cost_panel panel{cs, {}};
    const auto add = [&](const std::string& method, std::vector<spin_cost_point> pts) {
      const double cpu = cpu_at_error(pts, 1e-9);
      panel.curves.push_back({method, std::move(pts), cpu});
    };
    const double finer = cs.body == "Hyperion" ? 4 : 1;  // Hyperion's run is 5 orbits
    for (const auto& m : {std::string("SIER4"), std::string("SIER4/RS4-S5-McLachlan:ABC"), best_spin_rotor(cs.body)}) {
      std::vector<spin_cost_point> pts;
      for (const double n : steps) pts.push_back(spin_cost_point_of(cs, ref, m, 1 / (finer * n), min_cpu_s));
      add(m, std::move(pts));
    }
    for (const std::string family : {"odeint-dopri5", "odeint-rkf78"}) {
      std::vector<spin_cost_point> pts;
      for (const auto& t : tolerances) pts.push_back(spin_cost_point_of(cs, ref, family + ":" + t, 0, min_cpu_s));
      add(family, std::move(pts));
    }
    out.push_back(std::move(panel));
  }
  return out;
}

}  // namespace rotlie::runs
