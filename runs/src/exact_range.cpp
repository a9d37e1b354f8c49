#include "exact_range.hpp"

#include <cln/integer.h>
#include <cln/rational_io.h>
#include <cln/real.h>

#include <sstream>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/body_names.hpp"

namespace rotlie::runs {

std::string range_text() {
  return "1e-" + std::to_string(max_decimal_exponent) + " … 1e" + std::to_string(max_decimal_exponent);
}

bool magnitude_in_range(const cln::cl_RA& x) {
  static const cln::cl_RA big = cln::expt_pos(cln::cl_I(10), static_cast<unsigned>(max_decimal_exponent));
  const cln::cl_RA a = cln::abs(x);
  return a <= big && a * big >= 1;
}

std::string shown(const cln::cl_RA& x) { return lie::to_decimal(x, 6); }

std::string shown(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

}  // namespace rotlie::runs
