#include "rotlie/runs/number_text.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "rotlie/lie/exact_number.hpp"

namespace rotlie::runs {

std::string fixed_text(double x, int decimals) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(decimals) << x;
  return o.str();
}

std::string scientific_text(double x, int decimals) {
  std::ostringstream o;
  o << std::scientific << std::setprecision(decimals) << x;
  return o.str();
}

std::string scientific_or_dash(double x, int decimals) { return std::isfinite(x) ? scientific_text(x, decimals) : "—"; }

std::string significant_text(double x, int digits) {
  std::ostringstream o;
  o << std::setprecision(digits) << x;
  return o.str();
}

std::string decimal_text(const cln::cl_RA& x, int digits) { return lie::to_decimal(x, digits); }

std::string duration_text(double seconds) {
  std::ostringstream s;
  s.precision(seconds < 10 ? 2 : 3);
  if (seconds < 120) s << seconds << " s";
  else if (seconds < 7200) s << seconds / 60 << " min";
  else s << seconds / 3600 << " h";
  return s.str();
}

}  // namespace rotlie::runs
