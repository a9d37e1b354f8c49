#pragma once
// `rotlie md --scene liquid-water`: vZS section V.C (Fig. 1) for one integrator and step.
// The option values stay text here (CLI11 lives in main.cpp); run_md_liquid_water checks them.
#include <string>

namespace rotlie::app {

struct md_liquid_water_options {
  std::string integrator = "SIER2";  ///< SIER2, SIER4, MRDL, SEJ4, SIER2/TABLE, SIER4/TABLE (a reference table)
  std::string h;                     ///< --h FS: the step itself (SIER4 at h/f = 1 fs is --h 4)
  std::string T = "1";               ///< --T PS: length of each run
  std::string runs = "9";            ///< --runs N
  std::string molecules = "512";     ///< --molecules N (at least 365: the box must exceed twice the 11 Å cutoff)
  std::string threads = "2";         ///< --threads N (results do not depend on it)
  std::string state;                 ///< --state FILE: read if it exists, else the equilibrated start is written there
  bool json = false;
};

/// Runs the scene; progress on stderr, the result on stdout (a table, or JSON with --json).
/// Throws usage_error (exit 2) for bad values, a state file of another system, a box smaller
/// than twice the cutoff or overlapping molecules; nothing is written then.
int run_md_liquid_water(const md_liquid_water_options& options);

}  // namespace rotlie::app
