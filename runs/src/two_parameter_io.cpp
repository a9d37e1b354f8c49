#include "rotlie/runs/two_parameter_io.hpp"

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/family_names.hpp"

namespace rotlie::runs {

nlohmann::ordered_json two_parameter_json(const solver::two_parameter_result& result, const std::string& family,
                                          const lie::moments_of_inertia& body, int digits, int starts) {
  const auto decimal = [](const cln::cl_RA& x) { return lie::to_decimal(x, 2); };
  nlohmann::ordered_json j;
  j["family"] = family;
  j["inertia"] = lie::inertia_text(body);
  j["digits"] = digits;
  j["starts"] = starts;
  j["cpu_seconds"] = result.seconds;
  j["systems"] = nlohmann::ordered_json::array();
  for (const auto& e : result.entries) {
    nlohmann::ordered_json s;
    s["name"] = runs::two_parameter_name(e);
    s["on_surface"] = e.search.on_surface;
    s["converged"] = e.search.converged;
    s["distinct_minima"] = e.search.minima.size();
    s["polished"] = e.polished;
    if (e.polished) {
      s["remainder"] = e.best.remainder;
      s["order_residual"] = decimal(e.best.order_residual);
      s["projected_gradient"] = decimal(e.best.projected_gradient);
      s["reduced_hessian"] = e.best.reduced_hessian;
      nlohmann::ordered_json c;
      for (const auto& [name, v] : e.best.values) c[name] = lie::to_decimal(v, digits);
      s["coefficients"] = c;
    } else {
      s["note"] = e.note;
    }
    j["systems"].push_back(s);
  }
  return j;
}

}  // namespace rotlie::runs
