#pragma once
// `solve --family Q|QRS` for every front end: the options as typed, checked once, the search of
// solver/two_parameter.hpp run, and the scheme table of each polished system.
#include <string>
#include <vector>

#include "rotlie/solver/two_parameter.hpp"

namespace rotlie::runs {

/// The inputs of a two-parameter search as a user types them (the CLI's option texts).
struct two_parameter_inputs {
  std::string family;         ///< Q or QRS
  std::string scheme;         ///< one word of the family, or empty for all
  std::string perm = "all";   ///< one permutation or all
  std::string inertia;        ///< a body name or I1,I2,I3
  std::string digits = "40";  ///< 10 … 300
  std::string starts = "40";  ///< random starts per (word, permutation), 1 … 100000
  std::string seed = "1";     ///< 0 … 2^62
};

struct two_parameter_solution {
  std::string family;
  bch::splitting split = bch::splitting::abc;
  lie::moments_of_inertia body;
  int digits = 40;
  solver::minimum_search_options search;
  solver::two_parameter_result result;  ///< ranked as the CLI ranks it

  /// The scheme table text (docs/scheme_table_format.md) of a polished entry; `source` is the
  /// command line recorded in it.
  std::string table_text(const solver::two_parameter_entry& e, const std::string& source) const;
};

/// Checks every input (throws bad_input naming the option) and runs the search.
two_parameter_solution solve_two_parameter(const two_parameter_inputs& in);

}  // namespace rotlie::runs
