// rotlie best: for one body, the best N, R and P integrators by analytic remainder ‖H_R5‖ (eq. 64),
// the reference RS4 S5 McLachlan at its best permutation, and the gain predicted at equal cost — the
// map's answer (LV section 5) for a body off the grid. Every name is one that `integrate` accepts
// with the same --inertia. The measured column (unless --analytic-only): every real solution of
// every system of each family and every reference scheme at every permutation, run with the
// numeric protocol at the fixed reduced step h/C = 1/1980 (runs/measured_best.hpp).
#include <cmath>
#include <ctime>
#include <limits>
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/bch/families.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/measured_best.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::app {
namespace {

std::string scientific(double x, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << std::scientific << x;
  return s.str();
}

struct measured_candidate {
  std::string name;
  double remainder = 0, error = 0;
};

struct measured_family {
  std::vector<measured_candidate> candidates;  ///< every real solution, by ascending measured error
  double analytic_best_error = 0;              ///< the measured error of the analytic best
};

measured_family measure_family(const runs::fixed_reduced_step_protocol& protocol, const lie::moments_of_inertia& body,
                               const solver::family_result& solved, const solver::map_point& point) {
  measured_family m;
  for (const auto& x : solved.solutions) {
    const double e = protocol.error(solver::scheme_table_of(x, body));
    m.candidates.push_back({solver::scheme_table_name(x), x.analytic_remainder, e});
    if (point.best && solver::scheme_table_name(x) == solver::scheme_table_name(*point.best)) m.analytic_best_error = e;
  }
  std::stable_sort(m.candidates.begin(), m.candidates.end(), [](const auto& a, const auto& b) { return a.error < b.error; });
  return m;
}

double process_cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int run_best(const best_options& options) {
  if (options.inertia.empty()) throw usage_error("--inertia is required (I1,I2,I3, or water)");
  lie::moments_of_inertia body;
  try {
    body = lie::parse_moments(options.inertia);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what() + " (the body must lie in the set of rigid bodies, eq. 77)");
  }
  if (const auto symmetry = lie::symmetry_of(body); !symmetry.empty())
    throw usage_error("--inertia: a symmetric top (" + symmetry +
                      ") is outside the maps: its dedicated systems are singular; use `rotlie solve` for it");
  const auto [s, t] = solver::triangle_coordinates(body);

  const double start = process_cpu_seconds();
  std::vector<solver::map_point> points;
  std::vector<measured_family> measured;
  std::vector<runs::measured_reference> references;
  {
    progress_line progress;  // cleared before the answer is printed
    const runs::fixed_reduced_step_protocol protocol(body);
    for (const auto& f : bch::families()) {
      if (f.kind != bch::family_kind::one_free_parameter) continue;  // the maps' families: N, R, P
      const std::string family(f.name);
      progress.show("best: solving the " + family + " family at every permutation");
      const auto solved =
          solver::solve_dedicated(body, solver::family_schemes(family), bch::permutation_names(), 40);
      points.push_back(solver::summarize_family(body, family, solved));
      if (!options.analytic_only) {
        progress.show("best: measuring every " + family + " solution");
        measured.push_back(measure_family(protocol, body, solved, points.back()));
      }
    }
    if (!options.analytic_only) {
      progress.show("best: measuring every reference scheme at every permutation");
      references = runs::measure_references(protocol);
    }
  }
  const double cpu_seconds = process_cpu_seconds() - start;
  // The measured reference of the gains: RS4 S5 McLachlan at its best measured permutation.
  const runs::measured_reference* rs4 = nullptr;
  const runs::measured_reference* best_reference = nullptr;
  for (const auto& r : references) {
    if (r.name.rfind(std::string(solver::map_reference_scheme) + ":", 0) == 0) rs4 = &r;
    if (!best_reference || r.error < best_reference->error) best_reference = &r;
  }
  std::string recommended_measured;
  double smallest_error = std::numeric_limits<double>::infinity();
  for (const auto& m : measured)
    if (!m.candidates.empty() && m.candidates.front().error < smallest_error)
      smallest_error = m.candidates.front().error, recommended_measured = m.candidates.front().name;
  if (best_reference && best_reference->error < smallest_error) recommended_measured = best_reference->name;
  const auto& any = points.front();
  const std::string reference = std::string(solver::map_reference_scheme) + ":" + any.reference_permutation;
  // The recommendation: the largest predicted gain, or the reference when no family beats it.
  std::string recommended = reference;
  double best_gain = 1;
  for (const auto& p : points)
    if (p.ratio && *p.ratio > best_gain) best_gain = *p.ratio, recommended = solver::scheme_table_name(*p.best);

  if (options.json) {
    nlohmann::ordered_json j;
    j["inertia"] = {runs::fraction_text(body.I[0]), runs::fraction_text(body.I[1]), runs::fraction_text(body.I[2])};
    j["s"] = runs::fraction_text(s);
    j["t"] = runs::fraction_text(t);
    for (const auto& p : points) {
      nlohmann::ordered_json f;
      f["best"] = p.best ? nlohmann::ordered_json(solver::scheme_table_name(*p.best)) : nlohmann::ordered_json();
      f["remainder"] = p.best ? nlohmann::ordered_json(p.best->analytic_remainder) : nlohmann::ordered_json();
      f["cost"] = solver::family_cost(p.family);
      f["gain"] = p.ratio ? nlohmann::ordered_json(*p.ratio) : nlohmann::ordered_json();
      nlohmann::ordered_json singular = nlohmann::ordered_json::array();
      for (const auto& x : p.singular) singular.push_back(x.scheme + ":" + x.permutation);
      f["singular"] = singular;
      if (!measured.empty()) {
        const auto& m = measured[static_cast<std::size_t>(&p - points.data())];
        nlohmann::ordered_json mj;
        mj["best"] = m.candidates.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(m.candidates.front().name);
        mj["error"] = m.candidates.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(m.candidates.front().error);
        mj["gain"] = m.candidates.empty() || !rs4 ? nlohmann::ordered_json()
                                                   : nlohmann::ordered_json(rs4->error / m.candidates.front().error);
        mj["analytic_best_error"] = p.best ? nlohmann::ordered_json(m.analytic_best_error) : nlohmann::ordered_json();
        mj["analytic_best_gain"] =
            p.best && rs4 ? nlohmann::ordered_json(rs4->error / m.analytic_best_error) : nlohmann::ordered_json();
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        for (const auto& c : m.candidates) all.push_back({{"name", c.name}, {"remainder", c.remainder}, {"error", c.error}});
        mj["candidates"] = all;
        f["measured"] = mj;
      }
      j[p.family] = f;
    }
    j["reference"] = {{"best", reference},
                      {"remainder", any.reference_remainder},
                      {"cost", solver::reference_cost(solver::map_reference_scheme)}};
    j["recommended"] = recommended;
    j["measure"] = "analytic remainder ||H_R5|| (eq. 64), gain = R_M / R_family x (C_M / C_family)^4";
    if (!options.analytic_only) {
      nlohmann::ordered_json refs = nlohmann::ordered_json::array();
      for (const auto& r : references)
        refs.push_back({{"name", r.name}, {"cost", r.cost}, {"order", r.order}, {"error", r.error}});
      j["reference_measured"] = {{"best", rs4->name}, {"error", rs4->error}};
      j["best_reference_measured"] = {{"best", best_reference->name}, {"error", best_reference->error}};
      j["references_measured"] = refs;
      j["recommended_measured"] = recommended_measured;
      j["measured_protocol"] =
          "LV section 4.1 in double: G(0) = (1,1,1), identity attitude, T = 1, mean R^9 attitude error over every "
          "step at h/C = 1/1980 (C in rotations per step); gain = error of RS4-S5-McLachlan at its best measured "
          "permutation / error";
    }
    j["cpu_seconds"] = cpu_seconds;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "Body " << options.inertia << ": in the triangle of LV section 5 at s = " << runs::fraction_text(s)
            << ", t = " << runs::fraction_text(t) << "\n"
            << "Ranked by the analytic remainder ||H_R5|| (eq. 64); gain = R_M / R x (C_M / C)^4 at equal cost "
               "(> 1: better than the reference).\n\n";
  for (const auto& p : points) {
    std::cout << "  best " << p.family << " (cost " << solver::family_cost(p.family) << "): ";
    if (!p.best) {
      std::cout << "none (no real solution at this body)\n";
      continue;
    }
    std::cout << solver::scheme_table_name(*p.best) << "  ||H_R5|| = " << scientific(p.best->analytic_remainder)
              << "  gain " << scientific(*p.ratio, 3) << "\n";
  }
  std::cout << "  reference (cost " << solver::reference_cost(solver::map_reference_scheme) << "): " << reference
            << "  ||H_R5|| = " << scientific(any.reference_remainder) << "\n\n"
            << "Recommended: " << recommended << "   (rotlie integrate --scheme " << recommended << " --inertia "
            << options.inertia << " --h …)\n";
  if (!options.analytic_only) {
    std::cout << "\nMeasured (LV section 4.1 protocol in double, T = 1, at h/C = 1/1980; gain against " << rs4->name
              << ", its best measured permutation, error " << scientific(rs4->error) << "):\n";
    for (const auto& p : points) {
      const auto& m = measured[static_cast<std::size_t>(&p - points.data())];
      std::cout << "  best " << p.family << ": ";
      if (m.candidates.empty()) {
        std::cout << "none\n";
        continue;
      }
      std::cout << m.candidates.front().name << "  error " << scientific(m.candidates.front().error) << "  gain "
                << scientific(rs4->error / m.candidates.front().error) << "   (analytic best " << solver::scheme_table_name(*p.best)
                << ": measured gain " << scientific(rs4->error / m.analytic_best_error) << "; " << m.candidates.size()
                << " solutions measured)\n";
    }
    std::cout << "  best reference: " << best_reference->name << "  error " << scientific(best_reference->error) << "\n"
              << "Recommended by measurement: " << recommended_measured << "\n";
  }
  std::cout << "(" << scientific(cpu_seconds, 2) << " s CPU)\n";
  return 0;
}

}  // namespace rotlie::app
