// The rotlie command-line interface. This is the only translation unit that includes CLI11.
//
// Exit statuses: 0 success; 1 the run failed (a write error such as a full disk, a numerical
// failure); 2 bad arguments (nothing computed); 3 a sweep completed with runs refused or failed. A closed output pipe (`rotlie … | head`) ends
// rotlie by SIGPIPE, as it does the standard filters: status 141 in the shell, no message.
#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <new>
#include <sstream>
#include <vector>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/runs/binary_fields.hpp"
#include "rotlie/runs/binary_terms.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/scenes.hpp"

namespace {

using namespace rotlie::app;

int fail(const std::string& message, int status) {
  std::cerr << "rotlie: error: " << rotlie::app::one_line(message) << "\n";
  return status;
}

const char* const exit_status_help =
    "Exit status: 0 success; 1 the run failed (a write error such as a full disk, an output folder in use by another run, a numerical failure); "
    "2 bad arguments; 3 a sweep completed with runs refused or failed. A closed output pipe ends rotlie by SIGPIPE (status 141), as it does the standard filters.";

// CLI11's wording, said in rotlie's: which option, and what was wrong with it.
std::string reworded(const CLI::ParseError& e, const CLI::App* sub) {
  const std::string what = e.what();
  const std::string where = sub ? " for " + sub->get_name() + " (see rotlie " + sub->get_name() + " --help)" : "";
  const auto colon = what.find(':');
  const std::string name = colon == std::string::npos ? "" : what.substr(0, colon);
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
    if (what.find("At Most") != std::string::npos) return name + " is given more than once";
    if (what.find("missing") != std::string::npos) return name + " needs a value";
    return name.empty() ? what : name + ": wrong number of values";
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    // "The following arguments were not expected: 1 --bogus": name an unknown option first.
    std::istringstream list(what.substr(colon == std::string::npos ? 0 : colon + 1));
    std::string word, first;
    while (list >> word) {
      if (word[0] == '-') return "unknown option " + word + where;
      if (first.empty()) first = word;
    }
    return "unexpected argument " + first + where;
  }
  if (dynamic_cast<const CLI::ConversionError*>(&e)) {
    // "Could not convert: --json = maybe": only a flag can fail to convert (every option is text)
    const auto equals = what.find(" = ");
    const auto flag = colon == std::string::npos || equals == std::string::npos ? std::string("a flag")
                                                                                : what.substr(colon + 2, equals - colon - 2);
    return flag + " takes no value" + (equals == std::string::npos ? "" : ", got '" + what.substr(equals + 3) + "'");
  }
  if (dynamic_cast<const CLI::RequiredError*>(&e) && what.find("subcommand") != std::string::npos)
    return "a subcommand is required (dims, stages, remainder, solve, integrate, order, exact, md, map, best, bch, sixth, spin, binary, sweep or report; see rotlie --help)";
  return what;
}

// What CLI11 lets through: an option or flag given twice, an empty value.
void check_given_options(const CLI::App& sub) {
  for (const CLI::Option* opt : sub.get_options()) {
    if (opt->get_name() == "--help" || opt->get_name() == "-h,--help") continue;
    if (opt->count() > 1) throw usage_error(opt->get_name() + " is given more than once");
    if (opt->count() == 1 && opt->get_expected_min() > 0)
      for (const auto& value : opt->results())
        if (value.empty()) throw usage_error(opt->get_name() + " must not be empty");
  }
}

// Standard output written in full, or a failure: a full disk must not end with status 0.
int finished(int status) {
  const auto why = rotlie::app::flush_standard_output();
  if (why.empty()) return status;
  return fail("cannot write to standard output: " + why, exit_failure);
}

// One subcommand: its node in CLI11's tree and what runs it once parsed (the checks CLI11 cannot
// make first, then the command), returning the exit status.
struct subcommand {
  CLI::App* node;
  std::function<int()> run;
};

// A command on one body: the scales of its inertia, G0 and T checked before it runs.
template <class Options>
std::function<int()> with_scales_checked(const Options& o, int (*run)(const Options&)) {
  return [&o, run] {
    rotlie::runs::check_numeric_scales(o.inertia, o.G0, o.T);
    return run(o);
  };
}

// A command that writes into --out: the folder checked before it runs (when given).
template <class Options>
std::function<int()> with_folder_checked(const Options& o, int (*run)(const Options&)) {
  return [&o, run] {
    if (!o.out.empty()) check_output_folder(o.out, "--out");
    return run(o);
  };
}

const char* const force_help = "Use a scheme-table file solved for another body (with a warning)";

// --help shows each option as `--name TYPE` and, where the option has a default, `TYPE=DEFAULT`
// (the option struct's initial value, shown as it is; an empty one shows nothing). Showing the default
// changes no parsing: an option not given keeps its initial value, and its count stays 0.
CLI::Option* typed(CLI::Option* option, const std::string& type) { return option->type_name(type); }
CLI::Option* with_default(CLI::Option* option, const std::string& type) { return option->type_name(type)->capture_default_str(); }

// A subcommand's footer (it replaces rotlie's): a command that runs as it stands (tests/apps/help_cli_test.cpp
// runs them), what more there is to say, then the exit statuses unless `more` says them.
std::string example(const std::string& command, const std::string& more = "", bool says_exit_status = false) {
  return "Example: rotlie " + command + (more.empty() ? "" : "\n" + more) + (says_exit_status ? "" : "\n" + std::string(exit_status_help));
}

const char* const inertia_type = "I1,I2,I3|NAME";
const char* const scheme_type = "NAME|FILE";

subcommand add_dims(CLI::App& app, dims_options& dims) {
  auto* dims_cmd = app.add_subcommand("dims", "Dimensions of L_k and the Theorem 1 and 2 verdicts per order");
  typed(dims_cmd->add_option("--max-order", dims.max_order, "Highest order k (1 to 200)"), "K")->required();
  dims_cmd->add_flag("--json", dims.json, "Machine-readable output on stdout");
  dims_cmd->add_flag("--exact", dims.exact, "Exact rational elimination at every order (no modular certificate)");
  dims_cmd->footer(example("dims --max-order 12"));
  return {dims_cmd, [&dims] { return run_dims(dims); }};
}

subcommand add_stages(CLI::App& app, stages_options& stages) {
  auto* stages_cmd = app.add_subcommand("stages", "Table 1: equation and stage counts, all four blocks");
  typed(stages_cmd->add_option("--max-order", stages.max_order, "Highest order (1 to 40)"), "K")->required();
  stages_cmd->add_flag("--json", stages.json, "Machine-readable output on stdout");
  stages_cmd->footer(example("stages --max-order 10"));
  return {stages_cmd, [&stages] { return run_stages(stages); }};
}

subcommand add_remainder(CLI::App& app, remainder_options& remainder) {
  auto* remainder_cmd = app.add_subcommand("remainder", "Modified Hamiltonian H_R2 … H_RK of a splitting scheme");
  typed(remainder_cmd->add_option("--scheme", remainder.scheme,
                                  "N1…N7, R, P1…P15, RSRSRSR, SRSRSRS, or a word such as ABCBA (at most 40 letters, and fewer free "
                                  "coefficients at high orders: the error says how many)"),
        "NAME|WORD")
      ->required();
  typed(remainder_cmd->add_option("--split", remainder.split, "ABC or RS (default: from the scheme)"), "ABC|RS");
  with_default(remainder_cmd->add_option("--perm", remainder.perm, "ABC, BCA, CAB, ACB, CBA or BAC"), "PERM");
  with_default(remainder_cmd->add_option("--order", remainder.order, "Highest order K (at most 9)"), "K");
  typed(remainder_cmd->add_option("--inertia", remainder.inertia, "I1,I2,I3 as exact numbers, or water, sphere (default: symbols)"), inertia_type);
  typed(remainder_cmd->add_option("--coeffs", remainder.coeffs, "Values of free coefficients, e.g. a1=1/6,b1=0.25"), "NAME=X,...");
  remainder_cmd->add_flag("--latex", remainder.latex, "LaTeX output");
  remainder_cmd->add_flag("--json", remainder.json, "Machine-readable output on stdout");
  remainder_cmd->footer(example("remainder --scheme N4 --order 5"));
  return {remainder_cmd, [&remainder] { return run_remainder(remainder); }};
}

subcommand add_solve(CLI::App& app, solve_options& solve) {
  auto* solve_cmd = app.add_subcommand("solve", "All real solutions of a dedicated family for one body, ranked");
  typed(solve_cmd->add_option("--family", solve.family, "N, R, P, or Q, QRS (two free parameters)"), "FAMILY")->required();
  typed(solve_cmd->add_option("--scheme", solve.scheme, "One scheme of the family, e.g. N2 (default: all)"), "NAME");
  with_default(solve_cmd->add_option("--perm", solve.perm, "ABC, BCA, CAB, ACB, CBA, BAC or all"), "PERM");
  typed(solve_cmd->add_option("--inertia", solve.inertia, "I1,I2,I3 as exact numbers, or water, sphere"), inertia_type);
  with_default(solve_cmd->add_option("--digits", solve.digits, "Significant digits of the coefficients"), "DIGITS");
  typed(solve_cmd->add_option("--out", solve.out, "Write one scheme table per solution into this folder"), "FOLDER");
  solve_cmd->add_flag("--json", solve.json, "Machine-readable output on stdout");
  with_default(solve_cmd->add_option("--starts", solve.starts, "Q, QRS: random starts per word and permutation"), "COUNT");
  with_default(solve_cmd->add_option("--seed", solve.seed, "Q, QRS: seed of the starts"), "SEED");
  solve_cmd->footer(example("solve --family N --scheme N2 --perm BAC --inertia water"));
  return {solve_cmd, with_folder_checked(solve, run_solve)};
}

// What the free-body commands share: the body (required), the initial angular momentum and --json.
template <class Options>
void add_free_body_options(CLI::App* cmd, Options& o) {
  typed(cmd->add_option("--inertia", o.inertia, "I1,I2,I3 as exact numbers, or water, sphere"), inertia_type)->required();
  with_default(cmd->add_option("--G0", o.G0, "Initial body angular momentum g1,g2,g3"), "g1,g2,g3");
  cmd->add_flag("--json", o.json, "Machine-readable output on stdout");
}

subcommand add_integrate(CLI::App& app, integrate_options& integrate) {
  auto* integrate_cmd = app.add_subcommand("integrate", "Mean attitude error and CPU time of one run against the exact solution");
  typed(integrate_cmd->add_option("--scheme", integrate.scheme, "Reference name (RS4-S5-McLachlan:CBA), SCHEME:PERM:LABEL (N2:BAC:2) or a scheme-table file"),
        scheme_type)
      ->required();
  add_free_body_options(integrate_cmd, integrate);
  typed(integrate_cmd->add_option("--h", integrate.h, "Step, e.g. 1/64 or 0.01"), "NUMBER")->required();
  with_default(integrate_cmd->add_option("--T", integrate.T, "Total time, a whole number of steps"), "NUMBER");
  integrate_cmd->add_flag("--force", integrate.force, force_help);
  integrate_cmd->footer(example("integrate --scheme N2:BAC:2 --inertia water --h 1/64"));
  return {integrate_cmd, with_scales_checked(integrate, run_integrate)};
}

subcommand add_order(CLI::App& app, order_options& order) {
  auto* order_cmd = app.add_subcommand("order", "Numeric order: errors at h = T/2^i and the fitted slope");
  typed(order_cmd->add_option("--scheme", order.scheme, "Reference name, SCHEME:PERM:LABEL or a scheme-table file"), scheme_type)->required();
  add_free_body_options(order_cmd, order);
  with_default(order_cmd->add_option("--scalar", order.scalar, "double, long-double or float128"), "SCALAR");
  with_default(order_cmd->add_option("--min-level", order.min_level, "Coarsest step T/2^i"), "I");
  with_default(order_cmd->add_option("--max-level", order.max_level, "Finest step T/2^i"), "I");
  with_default(order_cmd->add_option("--T", order.T, "Total time"), "NUMBER");
  order_cmd->add_flag("--force", order.force, force_help);
  order_cmd->footer(example("order --scheme N2:BAC:2 --inertia water"));
  return {order_cmd, with_scales_checked(order, run_order)};
}

subcommand add_exact(CLI::App& app, exact_options& exact) {
  auto* exact_cmd = app.add_subcommand("exact", "The exact free-body state (G, attitude Q) at time T");
  add_free_body_options(exact_cmd, exact);
  typed(exact_cmd->add_option("--T", exact.T, "Time"), "NUMBER")->required();
  exact_cmd->footer(example("exact --inertia 0.4,0.7,1 --T 100 --G0 0.1,1,0.2"));
  return {exact_cmd, with_scales_checked(exact, run_exact)};
}

// The type --help shows for a scene's option (each scene's help gives its unit and its default).
std::string scene_option_type(const std::string& name) {
  static const std::map<std::string, std::string> types = {
      {"--T", "PS|ORBITS"}, {"--runs", "COUNT"},   {"--seed", "SEED"},   {"--scalar", "SCALAR"},     {"--every", "K"},
      {"--dipole", "DEBYE"}, {"--field", "MV/M"},  {"--molecules", "COUNT"}, {"--threads", "COUNT"}, {"--state", "FILE"},
      {"--equilibrate", "PS"}, {"--body", "NAME|A,B,C"}, {"--e", "NUMBER"}, {"--theta0", "RAD"}, {"--omega0", "NUMBER"},
      {"--obliquity", "RAD"}};
  const auto found = types.find(name);
  return found == types.end() ? "VALUE" : found->second;
}

subcommand add_md(CLI::App& app, md_options& md) {
  auto* md_cmd = app.add_subcommand("md", "Rigid bodies under torques, any integrator: van Zon & Schofield's free water "
                                          "(orientation error time tau), dipole in a field (Table I) and liquid water (Fig. 1), "
                                          "and the spin-orbit scene of rotlie spin");
  std::string scenes;
  for (const auto& s : rotlie::runs::scenes()) scenes += (scenes.empty() ? "" : "; ") + s.name + ": " + s.summary;
  typed(md_cmd->add_option("--scene", md.scene, scenes), "NAME")->required();
  typed(md_cmd->add_option("--integrator", md.integrator, rotlie::runs::method_names_text(rotlie::runs::method_system::md) + " (spin-orbit: rotlie spin's)"),
        "NAME")
      ->required();
  typed(md_cmd->add_option("--h", md.h, "The step h in fs (the step itself: SIER4 at h/f = 4.2 fs is --h 16.8); spin-orbit: a fraction "
                                        "of the orbital period"),
        "FS|FRACTION")
      ->required();
  for (const auto& o : rotlie::runs::all_scene_options()) typed(md_cmd->add_option(o.name, md.values[o.name], o.help), scene_option_type(o.name));
  md_cmd->add_flag("--json", md.json, "Machine-readable output on stdout");
  md_cmd->footer(example("md --scene dipole-field --integrator SIER4 --h 16.8 --runs 10"));
  return {md_cmd, [md_cmd, &md] {
            for (const auto& [name, value] : md.values)
              if (md_cmd->count(name) > 0) md.given[name] = value;
            return run_md(md);
          }};
}

subcommand add_report(CLI::App& app, report_command_options& report) {
  auto* report_cmd = app.add_subcommand("report", "Regenerate every table and figure into one folder");
  with_default(report_cmd->add_option("--out", report.out, "Output folder"), "FOLDER");
  report_cmd->add_flag("--quick", report.quick, "Smaller sweeps, for a fast look");
  typed(report_cmd->add_option("--sections", report.sections, report_sections_help()), "SECTION,...");
  report_cmd->add_flag("--full", report.full,
                       "The papers' full statistics: liquid water's nine 1-ps runs per point (about 30 min), maps over all bodies at "
                       "the paper's grid (--grid 200; hours for the P family)");
  typed(report_cmd->add_option("--maps", report.maps, "Folder of map-N.jsonl / map-P.jsonl written by rotlie map, drawn instead of computed"), "FOLDER");
  report_cmd->footer(example("report --quick --sections lie-algebra --out my-report"));
  return {report_cmd, [&report] { return run_report_command(report); }};  // checks and locks its folder itself
}

// Body-set maps (LV section 5).
subcommand add_map(CLI::App& app, map_options& map) {
  auto* map_cmd = app.add_subcommand("map", "Best integrator of a family over the set of rigid bodies (LV Figs. 7-10), one JSON line per body");
  typed(map_cmd->add_option("--family", map.family, "N, R or P"), "FAMILY")->required();
  typed(map_cmd->add_option("--grid", map.grid, "Divisions K of the triangle: (K+1)^2 grid points, 200 for the paper's 40,401"), "K")->required();
  typed(map_cmd->add_option("--out", map.out, "Folder of the map file map-<family>.jsonl (default rotlie-map; none with --json alone)"), "FOLDER");
  map_cmd->add_flag("--resume", map.resume, "Continue the map file in --out where a killed run stopped");
  map_cmd->add_flag("--json", map.json, "The body lines on stdout");
  auto* map_exact = map_cmd->add_flag("--exact", map.exact, "Every body by the exact solver (the default for R; for N and P slower, the check of the default)");
  map_cmd->add_flag("--fast", map.fast, "N and P: continuation along each row (default). N: both ends and every doubtful chain by the exact solver; P: both ends and each body's best by the exact solver, then each body against its neighbours' bests (the neighbour check)")
      ->excludes(map_exact);
  map_cmd->footer(example("map --family N --grid 2 --out maps",
                          "Under mpirun (mpirun -n 4 rotlie map ...) the bodies are shared among the processes; the file is the same."));
  return {map_cmd, [&map] { return run_map(map); }};  // checks its folder itself (on rank 0 only under MPI)
}

// The best integrator for one body.
subcommand add_best(CLI::App& app, best_options& best) {
  auto* best_cmd = app.add_subcommand("best", "Best N, R and P integrators for one body, the best reference and the predicted gain");
  typed(best_cmd->add_option("--inertia", best.inertia, "I1,I2,I3 as exact numbers, or water"), inertia_type)->required();
  best_cmd->add_flag("--json", best.json, "Machine-readable output on stdout");
  best_cmd->add_flag("--analytic-only", best.analytic_only, "Only the analytic ranking (no measured column)");
  best_cmd->footer(example("best --inertia 0.2,0.8,1 --analytic-only"));
  return {best_cmd, [&best] { return run_best(best); }};
}

subcommand add_bch(CLI::App& app, bch_options& bch) {
  auto* bch_cmd = app.add_subcommand("bch", "A BCH-type series in the free Lie algebra, exact, in the Lyndon basis");
  typed(bch_cmd->add_option("--series", bch.series, "XY log(e^X e^Y), XYX log(e^X e^Y e^X), SYM log(e^{X/2} e^Y e^{X/2}), XYZ log(e^X e^Y e^Z)"), "NAME")
      ->required();
  typed(bch_cmd->add_option("--degree", bch.degree, "Highest degree (1 to 20; 1 to 14 for XYZ)"), "DEGREE")->required();
  with_default(bch_cmd->add_option("--threads", bch.threads, "Worker threads (1 to 64)"), "COUNT");
  bch_cmd->add_flag("--json", bch.json, "Machine-readable output on stdout");
  bch_cmd->footer(example("bch --series SYM --degree 9"));
  return {bch_cmd, [&bch] { return run_bch(bch); }};
}

subcommand add_sixth(CLI::App& app, sixth_options& sixth) {
  auto* sixth_cmd = app.add_subcommand("sixth", "Dedicated 6th-order schemes: scan 21-stage palindromes, rank by ||H_R7||, write tables");
  typed(sixth_cmd->add_option("--inertia", sixth.inertia, "I1,I2,I3 as exact numbers, or water, sphere"), inertia_type);
  with_default(sixth_cmd->add_option("--split", sixth.split, "ABC (21 stages) or RS (19 stages)"), "ABC|RS");
  typed(sixth_cmd->add_option("--words", sixth.words, "Comma-separated palindromes, WORD or WORD:PERM"), "WORD[:PERM],...");
  sixth_cmd->add_flag("--all", sixth.all, "Every palindrome in every permutation (ABC only for the spherical top)");
  with_default(sixth_cmd->add_option("--starts", sixth.starts, "Random starts per system (a resumed scan continues to it)"), "COUNT");
  with_default(sixth_cmd->add_option("--best", sixth.best, "Roots polished and written, best ||H_R7|| first"), "COUNT");
  with_default(sixth_cmd->add_option("--digits", sixth.digits, "Digits of the written tables (40 to 200)"), "DIGITS");
  typed(sixth_cmd->add_option("--out", sixth.out, "Folder for the resumable scan state and the scheme tables"), "FOLDER");
  sixth_cmd->add_flag("--references", sixth.references, "List the general 6th-order reference compositions");
  sixth_cmd->add_flag("--json", sixth.json, "Machine-readable output on stdout");
  sixth_cmd->footer(example("sixth --references"));
  return {sixth_cmd, with_folder_checked(sixth, run_sixth)};
}

// The spin-orbit scene (Touma & Wisdom): a triaxial body on a fixed Kepler orbit.
subcommand add_spin(CLI::App& app, spin_options& spin) {
  auto* spin_cmd = app.add_subcommand("spin", "A triaxial body on a fixed Kepler orbit under the quadrupole torque (G M = 1, a = 1, "
                                              "period 2 pi): its final attitude and spin");
  typed(spin_cmd->add_option("--body", spin.body, "Hyperion, Moon, Mercury (cited moments), or A,B,C with A <= B <= C"), "NAME|A,B,C")->required();
  typed(spin_cmd->add_option("--e", spin.e, "Orbital eccentricity in [0, 1)"), "NUMBER")->required();
  typed(spin_cmd->add_option("--integrator", spin.integrator, rotlie::runs::method_names_text(rotlie::runs::method_system::spin)), "NAME")->required();
  typed(spin_cmd->add_option("--h", spin.h, "The step as a fraction of the orbital period, e.g. 1/1000 (taken exactly; an adaptive "
                                            "method's first trial step and the spacing of its checks)"),
        "FRACTION")
      ->required();
  typed(spin_cmd->add_option("--T", spin.T, "Length of the run in orbits: a whole number of steps --h (else refused)"), "ORBITS")->required();
  with_default(spin_cmd->add_option("--theta0", spin.theta0, "Initial rotation of the axes A, B, C about z, radians"), "RAD");
  with_default(spin_cmd->add_option("--omega0", spin.omega0, "Initial spin about the C axis, units of the mean motion n"), "NUMBER");
  with_default(spin_cmd->add_option("--obliquity", spin.obliquity, "Initial tilt of the C axis about x, radians"), "RAD");
  with_default(spin_cmd->add_option("--scalar", spin.scalar, "double, long-double or float128"), "SCALAR");
  with_default(spin_cmd->add_option("--every", spin.every, "With --json: the trajectory every K steps from the start (time, Q, omega_body, energy); 0 for none"),
               "K");
  with_default(spin_cmd->add_option("--accuracy", spin.accuracy, "The error estimate's bounds: REL (the spin rate, relative) or REL,RAD (RAD the "
                                                                 "attitude's angle): beyond them the run is marked inaccurate"),
               "REL[,RAD]");
  spin_cmd->add_flag("--no-error-estimate", spin.no_error_estimate, "Skip the error estimate (a fixed-step run is otherwise repeated at twice "
                                                                    "the step alongside, about 50 % more CPU, to see phase errors the "
                                                                    "conserved quantity cannot)");
  spin_cmd->add_flag("--json", spin.json, "Machine-readable output on stdout");
  spin_cmd->footer(example("spin --body Hyperion --e 0.1 --integrator SIER4 --h 1/1000 --T 10"));
  return {spin_cmd, [&spin] { return run_spin(spin); }};
}

// The full two-body problem: two rigid bodies in mutual gravity (binary asteroids).
subcommand add_binary(CLI::App& app, binary_options& b) {
  auto* cmd = app.add_subcommand("binary", "Two rigid bodies in mutual gravity, rotation and orbit coupled both ways (the full two-body problem of "
                                           "binary asteroids); units km, kg, s");
  const rotlie::runs::binary_request defaults;
  for (const auto& f : rotlie::runs::binary_fields()) {
    if (f.type == rotlie::runs::binary_field::kind::flag) {
      cmd->add_flag(f.option, b.flags[f.name] = defaults.*f.flag, f.help);
      continue;
    }
    // a required field may come from --gubas-config instead: run_binary asks for it
    with_default(cmd->add_option(f.option, b.fields[f.name] = defaults.*f.text, f.help + (f.cli_required ? " (required unless --gubas-config gives it)" : "")),
                 f.cli_type);
  }
  for (const auto& term : rotlie::runs::binary_terms())
    typed(cmd->add_option("--" + term.name, b.terms[term.name], term.summary), rotlie::runs::term_syntax(term));
  typed(cmd->add_option("--out", b.out, "With --every: the trajectory into FILE, written whole at the end (CSV with a header line when FILE "
                                        "ends in .csv, NumPy's .npz of one array per CSV column when it ends in .npz, else JSON lines); "
                                        "the summary stays on stdout"),
        "FILE");
  cmd->add_flag("--json", b.json, "Machine-readable output on stdout (with --every and no --out: the trajectory's lines first, the run's JSON the last line)");
  typed(cmd->add_option("--gubas-config", b.gubas_config,
                        "GUBAS's configuration file (SI units): its bodies, densities, G, start, order, integrator, step and span, in rotlie's "
                        "units; the options it sets are not given beside it, the others (--every, --out, --json, --observe, ...) are"),
        "FILE");
  cmd->footer(example("binary --system didymos --integrator SIER4 --h 60 --T 86400",
                      "--every K needs --out FILE or --json: the trajectory never shares standard output with the text summary."));
  return {cmd, [&b, cmd] {
            for (const auto& f : rotlie::runs::binary_fields())
              if (cmd->count(f.option) > 0) b.given.insert(f.name);
            return run_binary(b);
          }};
}

// Many binary runs, one line each, over MPI ranks when started by mpirun.
subcommand add_sweep(CLI::App& app, sweep_options& s) {
  auto* cmd = app.add_subcommand("sweep", "Many binary runs from a JSON-lines file (one object of binary's options per line, "
                                          "\"state\" a file or the state itself), one result line each in the input's order; shared among "
                                          "MPI ranks under mpirun; resumable");
  typed(cmd->add_option("--in", s.in, "The runs: a JSON-lines file"), "FILE")->required();
  typed(cmd->add_option("--out", s.out, "The results: a JSON-lines file (a header naming the input, then one line per run)"), "FILE")->required();
  cmd->add_flag("--resume", s.resume, "Continue the results file of the same input after a kill");
  cmd->footer(example("sweep --in runs.jsonl --out results.jsonl",
                      "(runs.jsonl holding lines such as {\"system\": \"didymos\", \"integrator\": \"SIER4\", \"h\": 60, \"T\": 3600})\n"
                      "The last line counts the runs: computed, contact, refused, failed. Exit status: 0 the sweep is complete and every run "
                      "computed or ended in contact; 3 it is complete, but a run was refused or failed (its line says why); 1 the sweep failed "
                      "(a write error, the results file in use by another sweep); 2 bad arguments or input (nothing run).",
                      true));
  return {cmd, [&s] { return run_sweep(s); }};
}

// Every subcommand's options, filled by CLI11 while it parses: it keeps pointers to them, so they
// live as long as the parse and are never moved.
struct all_options {
  dims_options dims;
  stages_options stages;
  remainder_options remainder;
  solve_options solve;
  integrate_options integrate;
  order_options order;
  exact_options exact;
  md_options md;
  report_command_options report;
  map_options map;
  best_options best;
  bch_options bch;
  sixth_options sixth;
  spin_options spin;
  binary_options binary;
  sweep_options sweep;
};

// The command tree, in the order of rotlie --help.
std::vector<subcommand> add_subcommands(CLI::App& app, all_options& o) {
  return {add_dims(app, o.dims), add_stages(app, o.stages), add_remainder(app, o.remainder), add_solve(app, o.solve),
          add_integrate(app, o.integrate), add_order(app, o.order), add_exact(app, o.exact), add_md(app, o.md),
          add_report(app, o.report), add_map(app, o.map), add_best(app, o.best), add_bch(app, o.bch), add_sixth(app, o.sixth),
          add_spin(app, o.spin), add_binary(app, o.binary),
          add_sweep(app, o.sweep)};
}

// The subcommand argv[1] names, if any.
const CLI::App* named_subcommand(const CLI::App& app, int argc, char** argv) {
  for (const auto* sub : app.get_subcommands({}))
    if (argc > 1 && sub->get_name() == argv[1]) return sub;
  return nullptr;
}

// CLI11 would only say "a subcommand is required" for a mistyped one: name it instead. Empty when
// argv[1] is a subcommand, --help, --version or absent.
std::string first_argument_problem(const CLI::App& app, int argc, char** argv) {
  std::string names;
  for (const auto* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
  if (argc > 1 && argv[1][0] != '-' && !named_subcommand(app, argc, argv))
    return "unknown subcommand '" + std::string(argv[1]) + "' (expected one of: " + names + ")";
  if (argc > 1 && argv[1][0] == '-' && std::string(argv[1]) != "-h" && std::string(argv[1]) != "--help" && std::string(argv[1]) != "--version")
    return "unknown option " + std::string(argv[1]) + " before the subcommand (options follow it; see rotlie --help)";
  return "";
}

// The exception a command ended with, said in one line with its exit status.
int failure_status(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const usage_error& e) {
    return fail(e.what(), exit_usage);
  } catch (const rotlie::runs::bad_input& e) {  // a name or value the library refused
    return fail(e.what(), exit_usage);
  } catch (const std::filesystem::filesystem_error& e) {
    // "filesystem error: cannot …: Reason [path]" said without the library's prefix
    return fail("cannot use '" + e.path1().string() + "': " + e.code().message(), exit_failure);
  } catch (const std::bad_alloc&) {
    return fail("out of memory", exit_failure);
  } catch (const std::exception& e) {
    if (rotlie::app::is_library_message(e.what()))
      return fail("the computation failed inside a numerical library; the input is probably outside what the method "
                  "supports (please report this command line)",
                  exit_failure);
    return fail(e.what(), exit_failure);
  } catch (...) {
    return fail("unexpected internal failure (please report this command line)", exit_failure);
  }
}

// Runs the parsed subcommand after the option checks common to all.
int dispatch(const CLI::App& app, const std::vector<subcommand>& commands) {
  try {
    for (const auto* sub : app.get_subcommands()) check_given_options(*sub);
    for (const auto& command : commands)
      if (*command.node) return finished(command.run());
  } catch (...) {
    return failure_status(std::current_exception());
  }
  return fail("no subcommand", exit_usage);
}

}  // namespace

int main(int argc, char** argv) {
  // The same behaviour on a closed pipe whatever the parent left SIGPIPE as (see the top).
  std::signal(SIGPIPE, SIG_DFL);
  rotlie::app::route_standard_output();
  CLI::App app{"rotlie — dedicated symplectic integrators for rigid-body rotation (Laskar & Vaillant 2018)"};
  app.set_version_flag("--version", "rotlie " ROTLIE_VERSION_TEXT);
  app.require_subcommand(1);
  app.footer(exit_status_help);
  all_options options;
  const auto commands = add_subcommands(app, options);

  if (const auto problem = first_argument_problem(app, argc, argv); !problem.empty()) return fail(problem, exit_usage);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return finished(app.exit(e));  // --help
    return fail(reworded(e, named_subcommand(app, argc, argv)), exit_usage);
  }
  return dispatch(app, commands);
}
