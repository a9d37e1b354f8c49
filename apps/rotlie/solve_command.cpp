#include <algorithm>
#include <filesystem>
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/solve_io.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/scheme_names.hpp"

namespace rotlie::app {
namespace {

constexpr int max_digits = 300;  // beyond this the exact bisection dominates for no use

}  // namespace

int run_solve(const solve_options& options) {
  const auto& family = runs::family_to_solve(options.family);
  if (family.kind == bch::family_kind::two_free_parameters) return run_solve_two_parameter(options);
  const auto schemes = runs::members_asked(family, options.scheme);
  const std::vector<std::string> perms = runs::permutations_named(options.perm);
  const lie::moments_of_inertia body = runs::required_body(options.inertia);
  const int digits = static_cast<int>(parse_integer_in_range(options.digits, "--digits", 10, max_digits));

  const auto result = solver::solve_dedicated(body, schemes, perms, digits);
  // A degenerate system has no isolated solutions at this body: an error when it is all that was
  // asked for, a warning next to the others.
  const auto degenerate = std::count_if(result.systems.begin(), result.systems.end(),
                                        [](const solver::system_report& r) { return r.degenerate; });
  for (const auto& r : result.systems)
    if (r.degenerate && degenerate < static_cast<long>(result.systems.size()))
      std::cerr << "rotlie: warning: " << r.scheme << " " << r.permutation << " is undefined for this body: " << r.note
                << "\n";
  for (const auto& r : result.systems)  // roots whose written coefficients would not be order 4
    if (r.uncertified > 0) std::cerr << "rotlie: warning: " << r.scheme << " " << r.permutation << ": " << r.note << "\n";
  if (degenerate == static_cast<long>(result.systems.size()) && !result.systems.empty()) {
    const auto& r = result.systems.front();
    throw usage_error(r.scheme + " " + r.permutation + (result.systems.size() > 1 ? " (and every other system asked for)" : "") +
                      " is undefined for this body: " + r.note);
  }

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
  if (options.json)
    std::cout << runs::solve_json(result, body, options.family, digits).dump(2) << "\n";
  else
    std::cout << runs::solve_text(result, body, digits, 20);
  return 0;
}

}  // namespace rotlie::app
