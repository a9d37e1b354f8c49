#include "rotlie/runs/spin_io.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "stepping_fields.hpp"

namespace rotlie::runs {
namespace {

nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json spin_json(const runs::spin_result& r) {
  const auto& s = r.setup;
  const auto I = runs::spin_moments(s.body);
  nlohmann::json Q = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) Q.push_back({r.Q(i, 0), r.Q(i, 1), r.Q(i, 2)});
  nlohmann::json j = {{"body", s.body.name},
          {"moments", {I[0], I[1], I[2]}},
          {"e", s.e},
          {"scalar", s.scalar},
          {"Q", Q},
          {"omega_body", {r.omega_body[0], r.omega_body[1], r.omega_body[2]}},
          {"theta", r.theta},
          {"energy_start", r.energy_start},
          {"energy_end", r.energy_end},
          {"cpu_s", r.cpu_s},
          {"conserved",
           {{"quantity", r.check.quantity},
            {"start", r.check.start},
            {"max_change", finite_or_null(r.check.max_change)},
            {"potential_fluctuation", r.check.potential_fluctuation},
            {"change_percent", finite_or_null(r.check.change_percent)}}},
          {"unstable", r.check.unstable},
          {"round_off_floor", r.check.round_off_floor}};
  j["inaccurate"] = r.check.inaccurate;
  j["accuracy"] = {{"relative", s.accuracy_rel}, {"angle_rad", s.accuracy_rad}};
  if (r.error_estimate) {
    const auto& e = *r.error_estimate;
    j["error_estimate"] = {{"attitude_rad", e.attitude_rad}, {"spin_rate_rel", e.spin_rate_rel}, {"order", e.order},
                           {"observed_order", e.observed_order}, {"step_ratio", e.step_ratio}, {"cpu_s", e.cpu_s}};
  } else {
    j["error_estimate"] = nullptr;
  }
  j.update(stepping_fields(s, r.evaluations));
  if (s.every > 0) {
    const auto& tr = r.trajectory;
    nlohmann::json Qs = nlohmann::json::array(), ws = nlohmann::json::array();
    for (const auto& q : tr.Q) Qs.push_back({{q[0], q[1], q[2]}, {q[3], q[4], q[5]}, {q[6], q[7], q[8]}});
    for (const auto& w : tr.omega_body) ws.push_back({w[0], w[1], w[2]});
    j["trajectory"] = {{"every", s.every}, {"t", tr.t}, {"Q", Qs}, {"omega_body", ws}, {"energy", tr.energy}};
  }
  return j;
}

std::string spin_text(const runs::spin_result& r) {
  const auto& setup = r.setup;
  const auto I = runs::spin_moments(setup.body);
  std::ostringstream out;
  out << std::setprecision(10) << "spin-orbit: " << setup.body.name << " (A, B, C = " << I[0] << ", " << I[1] << ", " << I[2]
      << "), e = " << setup.e << ", " << setup.method.name << ", h = " << setup.h << " orbit, " << setup.steps << " steps ("
      << setup.T << " orbits), " << setup.scalar << "\n  Q =";
  for (int i = 0; i < 3; ++i) out << (i ? "\n     " : " ") << r.Q(i, 0) << "  " << r.Q(i, 1) << "  " << r.Q(i, 2);
  out << "\n  omega_body = " << r.omega_body[0] << ", " << r.omega_body[1] << ", " << r.omega_body[2] << " n\n  theta = " << r.theta
      << " rad\n  energy " << r.energy_start << " -> " << r.energy_end << "\n  " << r.check.quantity << " changed by at most "
      << r.check.max_change << " (" << r.check.change_percent << " % of the potential's fluctuation)" << (r.check.unstable ? ": UNSTABLE" : "")
      << "\n  CPU " << r.cpu_s << " s, " << r.evaluations << " torque evaluations\n";
  if (r.error_estimate)
    out << "  estimated error at the end: attitude " << r.error_estimate->attitude_rad << " rad, spin rate " << r.error_estimate->spin_rate_rel
        << " relative" << (r.check.inaccurate ? ": INACCURATE" : "") << "\n";
  return out.str();
}

}  // namespace rotlie::runs
