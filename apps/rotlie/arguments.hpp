#pragma once
// Validation of command-line values, with one-line messages that name the option, and the checks
// every subcommand shares at the boundary (output folders, the state of standard output).
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "rotlie/runs/user_input.hpp"

namespace rotlie::app {

/// A bad command-line value: reported as one line on stderr, exit status 2.
struct usage_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Exit statuses (also listed in `rotlie --help`).
inline constexpr int exit_failure = 1;  ///< the run failed: a write error, a numerical failure
inline constexpr int exit_usage = 2;    ///< bad arguments: nothing was computed
inline constexpr int exit_runs_not_made = 3;  ///< rotlie sweep: complete, but some of its runs were refused or failed

/// Parses a decimal integer in [lo, hi]; throws runs::bad_input naming `option` otherwise.
inline long parse_integer_in_range(std::string_view text, std::string_view option, long lo, long hi) {
  return runs::integer_in_range(text, option, lo, hi);
}
using runs::why_not_a_number;

/// A command's answer on standard output: its JSON (two-space indent) with --json, else its text.
template <class Json, class Text>
void print_answer(bool json, const Json& json_of, const Text& text_of) {
  if (json)
    std::cout << json_of().dump(2) << "\n";
  else
    std::cout << text_of();
}

/// Throws usage_error naming `option` and the path unless `folder` is, or can be created as, a
/// folder that accepts new files. Leaves the file system as it found it (a probe file and any
/// folders made to test creation are removed again).
void check_output_folder(const std::string& folder, std::string_view option);

/// The one writer's rule for a results file appended during a run (a map, a sweep), before any work: a
/// symbolic link at `path` must lead to a regular file (runs::writable_target), else it is refused as a
/// usage_error naming `option` and left as it is (opening it to append would create a link's missing
/// target). Anything else at `path` is the resume reader's and the writer's to refuse.
void check_output_file(const std::string& path, std::string_view option);

/// Sends std::cout through a buffer that remembers the first failed write, after putting a
/// placeholder on any closed standard descriptor; call once, first.
void route_standard_output();
/// Flushes standard output; on failure returns the reason of the first failed write ("No space
/// left on device"), else "".
std::string flush_standard_output();

using runs::one_line;

/// True for a message worded by a library rather than by rotlie (Boost, CLN, GiNaC, the C++
/// standard library): such text is never shown to the user.
bool is_library_message(std::string_view message);

}  // namespace rotlie::app
