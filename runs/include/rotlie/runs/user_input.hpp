#pragma once
// What a user types is checked here, once, for every front end (the CLI, the Python module, the
// LAMMPS fix): a name that names nothing, or a value out of range, throws bad_input with one line
// that names the option, as the command line prints it.
#include <stdexcept>
#include <string>
#include <string_view>

namespace rotlie::runs {

/// Bad user input: nothing was computed. The CLI prints what() and exits with status 2.
struct bad_input : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// A decimal integer in [lo, hi]; throws bad_input naming `option` otherwise.
long integer_in_range(std::string_view text, std::string_view option, long lo, long hi);

/// Why `text` is not a usable number, for a message: "is out of range" when it is written like a
/// number whose exponent or digit count is too large, "is not a finite number" for nan/inf, and
/// "is not a number" otherwise.
std::string why_not_a_number(std::string_view text);

/// `message` on one line: control characters (a newline in a value, an escape sequence) are
/// shown as \n, \r, \t or \xHH so that no value can add lines or drive the terminal.
std::string one_line(std::string_view message);

}  // namespace rotlie::runs
