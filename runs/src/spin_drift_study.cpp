#include "rotlie/runs/spin_drift_study.hpp"

namespace rotlie::runs {

spin_drift_result spin_drift_study(long last, const std::function<void(const std::string&)>& progress) {
  spin_drift_result out;
  for (long n = 100; n <= last; n *= 10) out.checkpoints.push_back(n);
  for (const auto& c : spin_drift_cases()) {
    if (c.body == "Hyperion") continue;
    if (progress) progress("Spin-orbit: long runs, " + c.label);
    const std::string tol = rkf78_tolerance_at_equal_cpu(c, 100);
    const auto ref = spin_track_of(c, "odeint-rkf78:1e-18", true, 1, out.checkpoints);
    spin_drift_table table{c, {}};
    for (const std::string& m : std::vector<std::string>{"SIER4", "SIER4/R:CBA:4", "SIER4/RS4-S5-McLachlan:ABC", "odeint-rkf78:" + tol}) {
      const auto t = spin_track_of(c, m, false, c.steps_per_orbit, out.checkpoints);
      spin_drift_row row{m, {}, t.cpu_s.back()};
      for (std::size_t i = 0; i < t.orbits.size(); ++i) row.error.push_back(static_cast<double>(attitude_angle(ref.Q[i], t.Q[i])));
      table.rows.push_back(std::move(row));
    }
    out.tables.push_back(std::move(table));
  }
  return out;
}

}  // namespace rotlie::runs
