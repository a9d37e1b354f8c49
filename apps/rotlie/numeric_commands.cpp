// integrate, order and exact: the free-body runs of the library floor (runs/free_body_runs.hpp)
// on the command line, printed as a table or as JSON (runs/free_body_io.hpp).
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/runs/free_body_io.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/free_body_runs.hpp"
#include "rotlie/runs/numeric_inputs.hpp"

namespace rotlie::app {
namespace {

std::string number(double x) { return runs::significant_text(x, 6); }

void warn_reference(double error, double reference_error, const std::string& where) {
  std::cerr << "rotlie: warning: " << where << ": the exact reference's estimated error " << reference_error
            << " is not well below the measured error " << error
            << " (within a factor " << models::reference_margin << "): the figure may measure the reference rather than the scheme\n";
}

// A table solved for another body is refused unless --force.
runs::free_body_input free_body_of(const std::string& scheme, const std::string& inertia, bool force) {
  return runs::free_body_of(scheme, inertia, force ? runs::foreign_table::use_with_warning : runs::foreign_table::refuse_unless_forced);
}

}  // namespace

int run_integrate(const integrate_options& o) {
  const auto in = free_body_of(o.scheme, o.inertia, o.force);
  const double h = runs::positive_number(o.h, "--h"), total = runs::positive_number(o.T, "--T");
  runs::step_count(total, h);  // checked before the momentum, as the options are listed
  const auto G0 = runs::initial_momentum(o.G0);
  progress_line progress;
  const auto r = runs::integrate_run(in, G0, h, total, [&](long k, long steps) {
    progress.show("step " + std::to_string(k) + " of " + std::to_string(steps));
  });
  if (!r.point.attributable()) warn_reference(r.point.error, r.point.reference_error, "h = " + number(h));
  if (o.json) {
    std::cout << runs::integrate_json(r).dump(2) << "\n";
  } else {
    std::cout << r.scheme << " (" << r.cost << " C0 per step), h = " << h << ", T = " << total << ", " << r.steps
              << " steps\nmean attitude error " << r.point.error << " (exact reference: estimated error "
              << r.point.reference_error << ")\nCPU " << r.cpu_s << " s (stepping only)\n";
  }
  return 0;
}

int run_order(const order_options& o) {
  const auto in = free_body_of(o.scheme, o.inertia, o.force);
  const double total = runs::positive_number(o.T, "--T");
  const auto g0 = runs::initial_momentum(o.G0);
  const int first = static_cast<int>(parse_integer_in_range(o.min_level, "--min-level", 0, 20));
  const int last = static_cast<int>(parse_integer_in_range(o.max_level, "--max-level", first, 20));
  const auto r = runs::order_run(in, g0, total, first, last, o.scalar);
  const auto& m = r.measurement;
  for (const auto& p : m.points)
    if (!p.attributable()) warn_reference(p.error, p.reference_error, "h = " + number(p.h) + " (left out of the fit)");
  if (o.json) {
    std::cout << runs::order_json(r).dump(2) << "\n";
  } else {
    std::cout << r.scheme << " in " << o.scalar << ": declared order " << r.declared_order << ", fitted slope " << m.slope << "\n";
    for (std::size_t i = 0; i < m.points.size(); ++i)
      std::cout << "  h = " << m.points[i].h << "  h/C = " << m.points[i].h_over_cost << "  error = " << m.points[i].error
                << "  reference error = " << m.points[i].reference_error << "  cpu = " << r.cpu_s[i] << " s\n";
  }
  return 0;
}

int run_exact(const exact_options& o) {
  const auto body = runs::numeric_body(o.inertia);
  const double total = runs::positive_number(o.T, "--T");
  const auto r = runs::exact_run(body, runs::initial_momentum(o.G0), total);
  const auto& s = r.state;
  if (o.json) {
    std::cout << runs::exact_json(r).dump(2) << "\n";
  } else {
    std::ostringstream out;
    out.precision(17);
    out << "T = " << total << "\nG = (" << s.G[0] << ", " << s.G[1] << ", " << s.G[2] << ")\nQ =\n";
    for (int i = 0; i < 3; ++i) out << "  " << s.Q(i, 0) << "  " << s.Q(i, 1) << "  " << s.Q(i, 2) << "\n";
    out.precision(2);
    out << "estimated error (max abs entry of Q and of G/|G|) " << r.error_estimate << "\n";
    std::cout << out.str();
  }
  return 0;
}

}  // namespace rotlie::app
