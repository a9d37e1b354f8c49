#pragma once
// One function per subcommand. They take plain option structs, so that CLI11 stays in main.cpp
// (the slowest header to compile). Each returns the process exit status.
#include <map>
#include <set>
#include <string>

namespace rotlie::app {

struct dims_options {
  std::string max_order;
  bool json = false;
  bool exact = false;
};
int run_dims(const dims_options& options);

struct stages_options {
  std::string max_order;
  bool json = false;
};
int run_stages(const stages_options& options);

struct report_command_options {
  std::string out = "rotlie-report";
  bool quick = false;
  bool full = false;  ///< the papers' full statistics: nine 1-ps liquid-water runs per point, maps at the paper's grid
  std::string sections;  ///< comma-separated section keys; empty: all
  std::string maps;      ///< folder of map-N.jsonl / map-P.jsonl to draw
};
int run_report_command(const report_command_options& options);
/// --sections' help: every section's key, from the report's one list of sections.
std::string report_sections_help();

}  // namespace rotlie::app

namespace rotlie::app {

struct remainder_options {
  std::string scheme, split, perm = "ABC", order = "5", inertia, coeffs;
  bool latex = false, json = false;
};
int run_remainder(const remainder_options& options);

}  // namespace rotlie::app

namespace rotlie::app {

struct solve_options {
  std::string family, scheme, perm = "all", inertia, digits = "40", out;
  bool json = false;
  std::string starts = "40", seed = "1";  ///< Q, QRS: random starts per (word, permutation)
};
int run_solve(const solve_options& options);
int run_solve_two_parameter(const solve_options& options);

}  // namespace rotlie::app

namespace rotlie::app {

struct integrate_options {
  std::string scheme, inertia, h, T = "1", G0 = "1,1,1";
  bool json = false;
  bool force = false;  ///< use a scheme-table file solved for another body (with a warning)
};
int run_integrate(const integrate_options& options);

struct order_options {
  std::string scheme, inertia, T = "1", G0 = "1,1,1", scalar = "double", min_level = "1", max_level = "10";
  bool json = false;
  bool force = false;  ///< use a scheme-table file solved for another body (with a warning)
};
int run_order(const order_options& options);

struct exact_options {
  std::string inertia, T, G0 = "1,1,1";
  bool json = false;
};
int run_exact(const exact_options& options);

}  // namespace rotlie::app

namespace rotlie::app {

// Body-set maps (LV section 5) and the best integrator for one body.
struct map_options {
  std::string family, grid, out;
  bool resume = false, json = false;
  bool exact = false;  ///< every body by the exact solver (default for R)
  bool fast = false;   ///< continuation along rows (default for N and P, the families checked against the exact solver)
};
int run_map(const map_options& options);

struct best_options {
  std::string inertia;
  bool json = false;
  bool analytic_only = false;  ///< skip the measured column
};
int run_best(const best_options& options);
/// `rotlie md`: empty T and runs take the scene's defaults.
struct md_options {
  std::string scene, integrator, h;
  std::map<std::string, std::string> values;  ///< every scene option's storage, by name ("--T")
  std::map<std::string, std::string> given;   ///< the options given on the command line
  bool json = false;
};
int run_md(const md_options& options);
struct bch_options {
  std::string series, degree, threads = "1";
  bool json = false;
};
int run_bch(const bch_options& options);

}  // namespace rotlie::app

namespace rotlie::app {

struct sixth_options {
  std::string inertia, split = "ABC", words, starts = "40", best = "5", digits = "45", out;
  bool all = false, json = false, references = false;
};
int run_sixth(const sixth_options& options);

}  // namespace rotlie::app

namespace rotlie::app {

/// `rotlie spin`: a body on a fixed Kepler orbit under the quadrupole torque (the option strings as typed).
struct spin_options {
  std::string body, e, integrator, h, T, theta0 = "0", omega0 = "1", obliquity = "0", scalar = "double", every = "0";
  std::string accuracy = "1e-3,1e-2";
  bool no_error_estimate = false;
  bool json = false;
};
int run_spin(const spin_options& options);

/// The full two-body problem (binary asteroids): each field of runs/binary_fields.hpp as typed (flags as
/// booleans), and each registered force term's values (runs/binary_terms.hpp), checked by runs::binary_setup_of.
struct binary_options {
  std::map<std::string, std::string> fields, terms;
  std::map<std::string, bool> flags;
  std::string out;  ///< --every's trajectory file (JSON lines, CSV for a .csv name, NumPy for a .npz name); empty: none
  std::string gubas_config;  ///< GUBAS's configuration file (runs/gubas_config.hpp); empty: none
  std::set<std::string> given;  ///< the fields given on the command line (by name), not left at their defaults
  bool json = false;
};
int run_binary(const binary_options& options);

struct sweep_options {
  std::string in, out;
  bool resume = false;
};
int run_sweep(const sweep_options& options);

}  // namespace rotlie::app
