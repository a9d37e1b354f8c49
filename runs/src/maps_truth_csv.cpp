#include "rotlie/runs/maps_truth_csv.hpp"

#include <cln/real.h>

#include <sstream>
#include "rotlie/runs/number_text.hpp"

namespace rotlie::runs {
namespace {

std::string decimal(const cln::cl_RA& x) {
  std::ostringstream s;
  s.precision(17);
  s << cln::double_approx(x);
  return s.str();
}


}  // namespace

std::string truth_csv_header() {
  return "I1,I2,I3,family,best,analytic_ratio,measured_ratio_h,measured_ratio_cpu,predicted_ratio,gradient_ratio,"
         "slope,predicted_constant,measured_constant,reference\n";
}

std::string truth_csv_rows(const body_truth& b) {
  std::string out;
  for (const auto& f : b.families) {
    if (!f.best) continue;  // no solution: nothing measured
    out += decimal(b.body.I[0]) + "," + decimal(b.body.I[1]) + "," + decimal(b.body.I[2]) + "," + f.family + "," +
           *f.best + "," + significant_text(f.analytic_ratio) + "," + significant_text(f.measured_ratio_h) + "," +
           significant_text(f.measured_ratio_cpu) + "," + significant_text(f.predicted_ratio) + "," + significant_text(f.gradient_ratio) + "," +
           significant_text(f.slope) + "," + significant_text(f.predicted_constant) + "," + significant_text(f.measured_constant) + "," +
           b.reference + "\n";
  }
  return out;
}

}  // namespace rotlie::runs
