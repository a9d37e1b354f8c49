#pragma once
// The range 1e-150 … 1e150 of the numeric runs, checked exactly before any conversion to double
// can overflow, and numbers shown in messages (internal to runs/).
#include <cln/rational.h>

#include <string>

namespace rotlie::runs {

/// "1e-150 … 1e150"
std::string range_text();

/// |x| within the range, compared exactly with 10^±150.
bool magnitude_in_range(const cln::cl_RA& x);

/// A number as a message shows it: 6 significant digits (exact), 3 (double).
std::string shown(const cln::cl_RA& x);
std::string shown(double x);

}  // namespace rotlie::runs
