// Report section "Stability: where methods fail": for water, a near-symmetric and a near-flat
// body, the step beyond which each scheme stops working (models/stability_scan.hpp).
#include <sstream>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/report.hpp"
#include "sections.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/runs/stability_study.hpp"

namespace rotlie::reports {

report_section stability_section(const report_options& options) {
  report_section s;
  s.title = "Stability: where methods fail";
  const auto study = runs::stability_study(options.quick, [&](const std::string& title) {
    if (options.progress) options.progress("Stability: " + title);
  });
  const double total_time = study.total_time, threshold = study.threshold;
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
  for (const auto& b : study.bodies) {
    chart c;
    c.title = "Stability, " + b.title + " (I = " + b.inertia + "), T = " + runs::significant_text(total_time, 3);
    c.x_label = "reduced step h/C";
    c.y_label = "mean attitude error";
    c.horizontal_line = threshold;
    c.horizontal_label = "failure threshold";
    md << "### " << b.title << ", I = (" << b.inertia << ")\n\n"
       << "| scheme | C/C0 | h* | h*/C | first failing h | why it fails |\n|:--|--:|--:|--:|--:|:--|\n";
    for (const auto& row : b.rows) {
      const auto& scan = row.scan;
      const int cost = row.cost;
      chart_series series{row.name, {}, {}, false};
      for (const auto& p : scan.points)
        if (p.finite) series.x.push_back(p.h / cost), series.y.push_back(p.mean_error);
      c.series.push_back(std::move(series));
      md << "| " << row.name << " | " << cost << " | " << runs::significant_text(scan.last_working_h, 3) << " | "
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
