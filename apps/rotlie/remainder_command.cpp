// `rotlie remainder`: the modified Hamiltonian of a scheme (runs/remainder_run) as text, JSON or LaTeX.
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/runs/remainder_io.hpp"
#include "rotlie/runs/remainder_run.hpp"

namespace rotlie::app {

int run_remainder(const remainder_options& options) {
  if (options.latex && options.json) throw usage_error("--latex and --json exclude each other");
  const auto result = runs::remainder_run(
      {options.scheme, options.split, options.perm, options.order, options.inertia, runs::coefficient_list(options.coeffs)});
  if (options.json)
    std::cout << runs::remainder_json(result).dump(2) << "\n";
  else if (options.latex)
    std::cout << runs::remainder_latex(result);
  else
    std::cout << runs::remainder_text(result);
  return 0;
}

}  // namespace rotlie::app
