// rotlie best: the best integrator for one body (runs/best_for_body.hpp), printed as a table or as
// JSON (runs/best_io.hpp). Every name is one that `integrate` accepts with the same --inertia.
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/best_io.hpp"
#include "rotlie/runs/best_for_body.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::app {

int run_best(const best_options& options) {
  const auto body = runs::best_body(options.inertia);
  runs::best_result r;
  {
    progress_line progress;  // cleared before the answer is printed
    r = runs::best_for_body(body, options.analytic_only, [&](const std::string& line) { progress.show(line); });
  }
  if (options.json) {
    std::cout << runs::best_json(r).dump(2) << "\n";
    return 0;
  }
  const auto& points = r.points;
  const auto& measured = r.measured_families;
  const auto& any = points.front();
  const auto& s = r.s;
  const auto& t = r.t;
  const auto& reference = r.reference;
  const auto& recommended = r.recommended;
  const auto& rs4 = r.rs4;
  const auto& best_reference = r.best_reference;
  const auto& recommended_measured = r.recommended_measured;
  const double cpu_seconds = r.cpu_seconds;
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
    std::cout << solver::scheme_table_name(*p.best) << "  ||H_R5|| = " << runs::scientific_text(p.best->analytic_remainder, 3)
              << "  gain " << runs::scientific_text(*p.ratio, 3) << "\n";
  }
  std::cout << "  reference (cost " << solver::reference_cost(solver::map_reference_scheme) << "): " << reference
            << "  ||H_R5|| = " << runs::scientific_text(any.reference_remainder, 3) << "\n\n"
            << "Recommended: " << recommended << "   (rotlie integrate --scheme " << recommended << " --inertia "
            << options.inertia << " --h …)\n";
  if (!options.analytic_only) {
    std::cout << "\nMeasured (LV section 4.1 protocol in double, T = 1, at h/C = 1/1980; gain against " << rs4->name
              << ", its best measured permutation, error " << runs::scientific_text(rs4->error, 3) << "):\n";
    for (const auto& p : points) {
      const auto& m = measured[static_cast<std::size_t>(&p - points.data())];
      std::cout << "  best " << p.family << ": ";
      if (m.candidates.empty()) {
        std::cout << "none\n";
        continue;
      }
      std::cout << m.candidates.front().name << "  error " << runs::scientific_text(m.candidates.front().error, 3) << "  gain "
                << runs::scientific_text(rs4->error / m.candidates.front().error, 3) << "   (analytic best " << solver::scheme_table_name(*p.best)
                << ": measured gain " << runs::scientific_text(rs4->error / m.analytic_best_error, 3) << "; " << m.candidates.size()
                << " solutions measured)\n";
    }
    std::cout << "  best reference: " << best_reference->name << "  error " << runs::scientific_text(best_reference->error, 3) << "\n"
              << "Recommended by measurement: " << recommended_measured << "\n";
  }
  std::cout << "(" << runs::scientific_text(cpu_seconds, 2) << " s CPU)\n";
  return 0;
}

}  // namespace rotlie::app
