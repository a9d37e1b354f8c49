#pragma once
// How the report and the CLI print a double: one function per format, so that a table keeps its
// exact bytes when its code moves. Each is an std::ostream with the named flags, nothing more.
#include <cln/rational.h>

#include <string>

namespace rotlie::runs {

/// `decimals` digits after the point (std::fixed): fixed_text(3.14159, 2) is "3.14".
std::string fixed_text(double x, int decimals);

/// Scientific notation with `decimals` digits after the point (std::scientific): "1.23e-04".
std::string scientific_text(double x, int decimals);

/// As scientific_text, but "—" for NaN and infinities (a table cell with nothing to show).
std::string scientific_or_dash(double x, int decimals);

/// `digits` significant digits in the stream's general format (as %g: "0.00123", "1.2e+03",
/// trailing zeros dropped). digits = 6 is what `std::cout << x` prints.
std::string significant_text(double x, int digits = 6);

/// A duration for progress and summaries: "4.2 s", "12.5 min", "3.1 h" (2 significant digits below
/// 10 s, else 3).
std::string duration_text(double seconds);

/// An exact number as `digits` decimals (lie::to_decimal): the coefficients of tables and solutions.
std::string decimal_text(const cln::cl_RA& x, int digits);

}  // namespace rotlie::runs
