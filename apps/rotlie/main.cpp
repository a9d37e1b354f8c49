// The rotlie command-line interface. This is the only translation unit that includes CLI11.
#include <CLI/CLI.hpp>

#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"

namespace {

int fail(const std::string& message, int status) {
  std::cerr << "rotlie: error: " << message << "\n";
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rotlie::app;
  CLI::App app{"rotlie — dedicated symplectic integrators for rigid-body rotation (Laskar & Vaillant 2018)"};
  app.require_subcommand(1);

  dims_options dims;
  auto* dims_cmd = app.add_subcommand("dims", "Dimensions of L_k and the Theorem 1 and 2 verdicts per order");
  dims_cmd->add_option("--max-order", dims.max_order, "Highest order k (1 to 200)")->required();
  dims_cmd->add_flag("--json", dims.json, "Machine-readable output on stdout");
  dims_cmd->add_flag("--exact", dims.exact, "Exact rational elimination at every order (no modular certificate)");

  stages_options stages;
  auto* stages_cmd = app.add_subcommand("stages", "Table 1: equation and stage counts, all four blocks");
  stages_cmd->add_option("--max-order", stages.max_order, "Highest order (1 to 40)")->required();
  stages_cmd->add_flag("--json", stages.json, "Machine-readable output on stdout");

  remainder_options remainder;
  auto* remainder_cmd = app.add_subcommand("remainder", "Modified Hamiltonian H_R2 … H_RK of a splitting scheme");
  remainder_cmd->add_option("--scheme", remainder.scheme, "N1…N7, R, P1…P15, RSRSRSR, SRSRSRS, or a word such as ABCBA")
      ->required();
  remainder_cmd->add_option("--split", remainder.split, "ABC or RS (default: from the scheme)");
  remainder_cmd->add_option("--perm", remainder.perm, "ABC, BCA, CAB, ACB, CBA or BAC (default ABC)");
  remainder_cmd->add_option("--order", remainder.order, "Highest order K (default 5, at most 9)");
  remainder_cmd->add_option("--inertia", remainder.inertia, "I1,I2,I3 as exact numbers, or water, sphere (default: symbols)");
  remainder_cmd->add_option("--coeffs", remainder.coeffs, "Values of free coefficients, e.g. a1=1/6,b1=0.25");
  remainder_cmd->add_flag("--latex", remainder.latex, "LaTeX output");
  remainder_cmd->add_flag("--json", remainder.json, "Machine-readable output on stdout");

  solve_options solve;
  auto* solve_cmd = app.add_subcommand("solve", "All real solutions of a dedicated family for one body, ranked");
  solve_cmd->add_option("--family", solve.family, "N, R or P")->required();
  solve_cmd->add_option("--scheme", solve.scheme, "One scheme of the family, e.g. N2 (default: all)");
  solve_cmd->add_option("--perm", solve.perm, "ABC, BCA, CAB, ACB, CBA, BAC or all (default all)");
  solve_cmd->add_option("--inertia", solve.inertia, "I1,I2,I3 as exact numbers, or water, sphere");
  solve_cmd->add_option("--digits", solve.digits, "Significant digits of the coefficients (default 40)");
  solve_cmd->add_option("--out", solve.out, "Write one scheme table per solution into this folder");
  solve_cmd->add_flag("--json", solve.json, "Machine-readable output on stdout");

  integrate_options integrate;
  auto* integrate_cmd = app.add_subcommand("integrate", "Mean attitude error and CPU time of one run against the exact solution");
  integrate_cmd->add_option("--scheme", integrate.scheme, "Reference name (RS4-S5-McLachlan:CBA), SCHEME:PERM:LABEL (N2:BAC:2) or a scheme-table file")->required();
  integrate_cmd->add_option("--inertia", integrate.inertia, "I1,I2,I3 as exact numbers, or water, sphere")->required();
  integrate_cmd->add_option("--h", integrate.h, "Step, e.g. 1/64 or 0.01")->required();
  integrate_cmd->add_option("--T", integrate.T, "Total time (default 1), a whole number of steps");
  integrate_cmd->add_option("--G0", integrate.G0, "Initial body angular momentum g1,g2,g3 (default 1,1,1)");
  integrate_cmd->add_flag("--json", integrate.json, "Machine-readable output on stdout");

  order_options order;
  auto* order_cmd = app.add_subcommand("order", "Numeric order: errors at h = T/2^i and the fitted slope");
  order_cmd->add_option("--scheme", order.scheme, "Reference name, SCHEME:PERM:LABEL or a scheme-table file")->required();
  order_cmd->add_option("--inertia", order.inertia, "I1,I2,I3 as exact numbers, or water, sphere")->required();
  order_cmd->add_option("--scalar", order.scalar, "double, long-double or float128 (default double)");
  order_cmd->add_option("--min-level", order.min_level, "Coarsest step T/2^i (default i = 1)");
  order_cmd->add_option("--max-level", order.max_level, "Finest step T/2^i (default i = 10)");
  order_cmd->add_option("--T", order.T, "Total time (default 1)");
  order_cmd->add_option("--G0", order.G0, "Initial body angular momentum (default 1,1,1)");
  order_cmd->add_flag("--json", order.json, "Machine-readable output on stdout");

  exact_options exact;
  auto* exact_cmd = app.add_subcommand("exact", "The exact free-body state (G, attitude Q) at time T");
  exact_cmd->add_option("--inertia", exact.inertia, "I1,I2,I3 as exact numbers, or water, sphere")->required();
  exact_cmd->add_option("--T", exact.T, "Time")->required();
  exact_cmd->add_option("--G0", exact.G0, "Initial body angular momentum (default 1,1,1)");
  exact_cmd->add_flag("--json", exact.json, "Machine-readable output on stdout");

  report_command_options report;
  auto* report_cmd = app.add_subcommand("report", "Regenerate every table and figure into one folder");
  report_cmd->add_option("--out", report.out, "Output folder (default: rotlie-report)");
  report_cmd->add_flag("--quick", report.quick, "Smaller sweeps, for a fast look");
  report_cmd->add_option("--sections", report.sections,
                         "Only these sections, comma-separated: lie-algebra, remainders, dedicated, accuracy, stability, exact-flow");

  // CLI11 would only say "a subcommand is required" for a mistyped one: name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string word = argv[1];
    bool known = false;
    std::string names;
    for (const auto* sub : app.get_subcommands({})) {
      known = known || sub->get_name() == word;
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) return fail("unknown subcommand '" + word + "' (expected one of: " + names + ")", 2);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return fail(e.what(), 2);
  }

  try {
    if (*dims_cmd) return run_dims(dims);
    if (*stages_cmd) return run_stages(stages);
    if (*remainder_cmd) return run_remainder(remainder);
    if (*solve_cmd) return run_solve(solve);
    if (*integrate_cmd) return run_integrate(integrate);
    if (*order_cmd) return run_order(order);
    if (*exact_cmd) return run_exact(exact);
    if (*report_cmd) return run_report_command(report);
  } catch (const usage_error& e) {
    return fail(e.what(), 2);
  } catch (const std::exception& e) {
    return fail(e.what(), 1);
  }
  return fail("no subcommand", 2);
}
