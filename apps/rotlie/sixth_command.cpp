// rotlie sixth: dedicated 6th-order schemes for one body (runs/sixth_search.hpp): the options
// checked, the search run, its best tables printed as a table or JSON (runs/sixth_io.hpp).
// --references lists the general 6th-order compositions instead.
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/sixth_io.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/sixth_search.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::app {
namespace {

int list_references(bool json) {
  if (json) {
    std::cout << runs::sixth_references_json().dump(2) << "\n";
    return 0;
  }
  for (const auto& name : schemes::reference_sixth_order_scheme_names()) {
    const auto t = *schemes::reference_scheme(name);
    std::cout << name << "  order " << t.order << ", " << t.stages.size() << " stages, cost " << schemes::cost_in_rotations(t)
              << " rotations  (" << t.source << ")\n";
  }
  return 0;
}

std::string table_line(const runs::sixth_order_table& t) {
  std::ostringstream s;
  if (!t.polished) {
    s << "  " << t.word << ":" << t.permutation << "  ‖H_R7‖ = " << runs::scientific_text(t.remainder7, 3) << "  not polished: " << t.why
      << "; Jacobian σmin/σmax = " << runs::scientific_text(t.jacobian_ratio, 2)
      << ", smallest |free coefficient| = " << runs::scientific_text(t.smallest_free_coefficient, 2) << "\n";
    return s.str();
  }
  s << "  " << t.name << "  ‖H_R7‖ = " << runs::scientific_text(t.remainder7, 3) << "  ‖H_R7‖·C^6 = " << runs::scientific_text(t.remainder7_at_equal_cost, 3)
    << "  C = " << t.cost << "  max|c| = " << runs::scientific_text(t.max_coefficient, 2) << "  hits " << t.hits << "  residual "
    << runs::scientific_text(t.residual, 2) << "  σmin/σmax " << runs::scientific_text(t.jacobian_ratio, 2) << (t.file.empty() ? "" : "  " + t.file)
    << "\n";
  return s.str();
}

}  // namespace

int run_sixth(const sixth_options& o) {
  if (o.references) return list_references(o.json);
  if (o.inertia.empty()) throw usage_error("--inertia is required (I1,I2,I3, water or sphere), or --references");
  runs::sixth_search_request q;
  q.body = runs::required_body(o.inertia);
  if (o.all == !o.words.empty()) throw usage_error("give exactly one of --words LIST and --all");
  if (o.split == "ABC") q.split = bch::splitting::abc;
  else if (o.split == "RS") q.split = bch::splitting::rs;
  else throw usage_error("--split must be ABC or RS, got '" + one_line(o.split) + "'");
  q.starts = static_cast<int>(parse_integer_in_range(o.starts, "--starts", 1, 1000000));
  q.best = static_cast<int>(parse_integer_in_range(o.best, "--best", 0, 1000));
  q.digits = static_cast<int>(parse_integer_in_range(o.digits, "--digits", 40, 200));
  const bool sphere = lie::symmetry_of(q.body) == "I1 = I2 = I3";
  q.systems = runs::sixth_order_systems(o.words, o.all, q.split, sphere);
  q.out = o.out;
  runs::sixth_search_result r;
  {
    progress_line progress;  // cleared before the answer is printed
    r = runs::sixth_search(q, [&](const std::string& line) { progress.show(line); });
  }
  if (o.json) {
    std::cout << runs::sixth_json(r, q.body, o.split).dump(2) << "\n";
    return 0;
  }
  const auto& stats = r.stats;
  std::cout << "systems " << stats.systems << " (" << stats.with_roots << " with real roots), starts " << stats.starts
            << ", converged " << stats.converged << ", distinct roots " << stats.roots << "\n"
            << "hits: " << stats.hit_once << " roots once, " << stats.hit_twice << " twice, " << stats.hit_more
            << " more; Good-Turing unseen mass f1/N = " << runs::scientific_text(stats.unseen, 2)
            << "; Chao1 estimate of the roots reachable = " << runs::scientific_text(stats.chao1, 2) << "\n"
            << "best by ‖H_R7‖ (body scaled to I3 = 1):\n";
  for (const auto& t : r.best) std::cout << table_line(t);
  std::cout << "CPU " << runs::scientific_text(r.cpu_seconds, 3) << " s\n";
  return 0;
}

}  // namespace rotlie::app
