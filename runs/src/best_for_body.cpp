#include "rotlie/runs/best_for_body.hpp"

#include <algorithm>
#include <limits>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/bch/families.hpp"
#include "rotlie/lie/stop_request.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {
namespace {

measured_family measure_family(const fixed_reduced_step_protocol& protocol, const lie::moments_of_inertia& body,
                               const solver::family_result& solved, const solver::map_point& point) {
  measured_family m;
  for (const auto& x : solved.solutions) {
    lie::stop_point();
    const double e = protocol.error(solver::scheme_table_of(x, body));
    m.candidates.push_back({solver::scheme_table_name(x), x.analytic_remainder, e});
    if (point.best && solver::scheme_table_name(x) == solver::scheme_table_name(*point.best)) m.analytic_best_error = e;
  }
  std::stable_sort(m.candidates.begin(), m.candidates.end(), [](const auto& a, const auto& b) { return a.error < b.error; });
  return m;
}


}  // namespace

lie::moments_of_inertia best_body(const std::string& text) {
  if (text.empty()) throw bad_input("--inertia is required (I1,I2,I3, or water)");
  lie::moments_of_inertia body;
  try {
    body = lie::parse_moments(text);
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--inertia: ") + e.what() + " (the body must lie in the set of rigid bodies, eq. 77)");
  }
  if (const auto symmetry = lie::symmetry_of(body); !symmetry.empty())
    throw bad_input("--inertia: a symmetric top (" + symmetry +
                    ") is outside the maps: its dedicated systems are singular; use `rotlie solve` for it");
  return body;
}

best_result best_for_body(const lie::moments_of_inertia& body, bool analytic_only,
                          const std::function<void(const std::string&)>& progress) {
  best_result r;
  r.body = body;
  std::tie(r.s, r.t) = solver::triangle_coordinates(body);
  r.measured = !analytic_only;
  const double start = models::thread_cpu_seconds();
  const fixed_reduced_step_protocol protocol(body);
  const auto show = [&](const std::string& line) {
    lie::stop_point();  // between the phases, each a minute at most
    if (progress) progress(line);
  };
  for (const auto& f : bch::families()) {
    if (f.kind != bch::family_kind::one_free_parameter) continue;  // the maps' families: N, R, P
    const std::string family(f.name);
    show("best: solving the " + family + " family at every permutation");
    const auto solved = solver::solve_dedicated(body, solver::family_schemes(family), bch::permutation_names(), 40);
    r.points.push_back(solver::summarize_family(body, family, solved));
    if (r.measured) {
      show("best: measuring every " + family + " solution");
      r.measured_families.push_back(measure_family(protocol, body, solved, r.points.back()));
    }
  }
  if (r.measured) {
    show("best: measuring every reference scheme at every permutation");
    r.references = measure_references(protocol);
  }
  r.cpu_seconds = models::thread_cpu_seconds() - start;
  // The measured reference of the gains: RS4 S5 McLachlan at its best measured permutation.
  for (const auto& x : r.references) {
    if (x.name.rfind(std::string(solver::map_reference_scheme) + ":", 0) == 0) r.rs4 = x;
    if (!r.best_reference || x.error < r.best_reference->error) r.best_reference = x;
  }
  double smallest_error = std::numeric_limits<double>::infinity();
  for (const auto& m : r.measured_families)
    if (!m.candidates.empty() && m.candidates.front().error < smallest_error)
      smallest_error = m.candidates.front().error, r.recommended_measured = m.candidates.front().name;
  if (r.best_reference && r.best_reference->error < smallest_error) r.recommended_measured = r.best_reference->name;
  r.reference = std::string(solver::map_reference_scheme) + ":" + r.points.front().reference_permutation;
  // The recommendation: the largest predicted gain, or the reference when no family beats it.
  r.recommended = r.reference;
  double best_gain = 1;
  for (const auto& p : r.points)
    if (p.ratio && *p.ratio > best_gain) best_gain = *p.ratio, r.recommended = solver::scheme_table_name(*p.best);
  return r;
}

}  // namespace rotlie::runs
