// Report section "Stability: where methods fail": for water, a near-symmetric and a near-flat
// body, the step beyond which each scheme stops working (models/stability_scan.hpp).
#include <iomanip>
#include <sstream>

#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/models/stability_scan.hpp"
#include "rotlie/reports/chart.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::reports {

// From the runs library (rotlie::runs):
using runs::find_solution;
using runs::protocol_runner;

namespace {

constexpr double threshold = 0.1;  // mean attitude error (or relative energy error) that counts as failure

struct body_case {
  std::string key, title, inertia;
};

}  // namespace

report_section stability_section(const report_options& options) {
  report_section s;
  s.title = "Stability: where methods fail";
  const double total_time = options.quick ? 4 : 10;
  const std::vector<body_case> bodies = {{"water", "water molecule", "10220/29376,19187/29376,1"},
                                         {"near_symmetric", "near-symmetric body (I1 ≈ I2)", "1/2,501/1000,1"},
                                         {"near_flat", "near-flat body (I1 + I2 ≈ I3)", "1/5,8001/10000,1"}};
  const std::vector<std::string> reference_bases = {"ABCBA2",           "RSR2",           "ABCBA4-SS3-Yoshida",
                                                    "RSR4-SS3-Yoshida", "ABC4-S5-McLachlan", "RS4-S5-McLachlan"};
  std::ostringstream md;
  md << "## " << s.title << "\n\n"
     << "From G(0) = (1, 1, 1) and the identity attitude, each scheme runs to T = " << total_time
     << " with steps h = T/n growing from 1/32 (four per factor 2) and is compared with the exact flow at every step. "
        "A run fails when its mean attitude error exceeds "
     << threshold << ", its relative energy error exceeds " << threshold
     << ", |G| drifts beyond round-off, or a value is not finite. h* is the largest working step below the first "
        "failure. Every stage of these schemes is an exact rotation: |G| is conserved to round-off and the energy "
        "stays between |G|²/(2 I_max) and |G|²/(2 I_min), so no scheme here can diverge; failure is the loss of "
        "accuracy, which the attitude error measures. Reference schemes run at the permutation most accurate for the "
        "body at small steps; \"best N\" is the N solution with the smallest analytic remainder for that body.\n\n";
  for (const auto& b : bodies) {
    if (options.progress) options.progress("Stability: " + b.title);
    const auto body = lie::parse_moments(b.inertia);
    const auto I = models::moments_from_text<double>(lie::inertia_text(body));
    std::vector<schemes::scheme_table> tables;
    const protocol_runner chooser(body, 3, 7, false);
    for (const auto& base : reference_bases) {
      const auto best = chooser.best_permutation(base);
      tables.push_back(*schemes::reference_scheme(best.name));
    }
    const auto n = solver::solve_dedicated(body, {"N1", "N2", "N3", "N4", "N5", "N6", "N7"}, bch::permutation_names(), 40);
    if (n.solutions.empty()) throw std::runtime_error("no N solution for the " + b.title);
    auto best_n = solver::scheme_table_of(n.solutions.front(), body);
    best_n.name = "best N: " + n.solutions.front().name();
    tables.push_back(best_n);
    if (b.key == "water") {
      const auto p = solver::solve_dedicated(body, {"P1"}, {"BAC"}, 40), r = solver::solve_dedicated(body, {"R"}, {"ABC"}, 40);
      auto p1 = solver::scheme_table_of(find_solution(p, "P1", "BAC", 5), body);
      p1.name = "P1 BAC (5)";
      auto r4 = solver::scheme_table_of(find_solution(r, "R", "ABC", 4), body);
      r4.name = "R ABC (4)";
      tables.push_back(p1), tables.push_back(r4);
    }
    chart c;
    c.title = "Stability, " + b.title + " (I = " + b.inertia + "), T = " + runs::significant_text(total_time, 3);
    c.x_label = "reduced step h/C";
    c.y_label = "mean attitude error";
    c.horizontal_line = threshold;
    c.horizontal_label = "failure threshold";
    md << "### " << b.title << ", I = (" << b.inertia << ")\n\n"
       << "| scheme | C/C0 | h* | h*/C | first failing h | why it fails |\n|:--|--:|--:|--:|--:|:--|\n";
    models::body_state<double> initial;
    initial.G = {1, 1, 1};
    for (const auto& t : tables) {
      const auto scan = models::stability_scan<double>(t, I, initial, total_time, 1.0 / 32, 4, threshold);
      const int cost = schemes::cost_in_rotations(t);
      chart_series series{t.name, {}, {}, false};
      for (const auto& p : scan.points)
        if (p.finite) series.x.push_back(p.h / cost), series.y.push_back(p.mean_error);
      c.series.push_back(std::move(series));
      md << "| " << t.name << " | " << cost << " | " << runs::significant_text(scan.last_working_h, 3) << " | "
         << runs::significant_text(scan.last_working_h / cost, 3) << " | "
         << (scan.failure.empty() ? std::string("none up to T") : runs::significant_text(scan.first_failing_h, 3)) << " | "
         << (scan.failure.empty() ? "" : scan.failure) << " |\n";
    }
    md << "\n";
    const auto f = write_chart(options.out_dir, "stability_" + b.key, c);
    s.files.insert(s.files.end(), f.written.begin(), f.written.end());
    md << chart_markdown(f, "stability_" + b.key, "Stability, " + b.title + ".");
  }
  s.markdown = md.str();
  return s;
}

}  // namespace rotlie::reports
