#include <algorithm>
#include <filesystem>
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/solve_for_body.hpp"
#include "rotlie/runs/solve_io.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::app {

int run_solve(const solve_options& options) {
  if (runs::family_to_solve(options.family).kind == bch::family_kind::two_free_parameters) return run_solve_two_parameter(options);
  const int digits = static_cast<int>(parse_integer_in_range(options.digits, "--digits", 10, runs::max_solve_digits));
  const auto solved = runs::solve_for_body({options.family, options.scheme, options.perm, options.inertia, digits});
  const auto& result = solved.result;
  const auto& body = solved.body;
  for (const auto& w : solved.warnings) std::cerr << "rotlie: warning: " << w << "\n";

  if (!options.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.out, ec);
    if (ec) throw std::runtime_error("cannot create the output folder " + options.out + ": " + ec.message());
    for (const auto& s : result.solutions) {
      std::string file = solver::scheme_table_name(s);
      std::replace(file.begin(), file.end(), ':', '_');
      runs::write_file_atomically(std::filesystem::path(options.out) / (file + ".scheme"),
                                     solver::scheme_table_text(s, body, digits));
    }
  }
  print_answer(options.json, [&] { return runs::solve_json(result, body, options.family, digits); },
               [&] { return runs::solve_text(result, body, digits, 20); });
  return 0;
}

}  // namespace rotlie::app
