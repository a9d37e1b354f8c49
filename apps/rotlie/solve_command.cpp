#include <algorithm>
#include <filesystem>
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "scheme_lookup.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/solve_io.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::app {
namespace {

constexpr int max_digits = 300;  // beyond this the exact bisection dominates for no use

std::vector<std::string> schemes_of(const solve_options& o) {
  if (o.family != "N" && o.family != "R" && o.family != "P")
    throw usage_error("--family must be N, R, P, Q or QRS, got '" + o.family + "'");
  std::vector<std::string> all;
  if (o.family == "R") all.push_back("R");
  const int members = o.family == "N" ? 7 : o.family == "P" ? 15 : 0;
  for (int i = 1; i <= members; ++i) all.push_back(o.family + std::to_string(i));
  if (o.scheme.empty()) return all;
  if (std::find(all.begin(), all.end(), o.scheme) == all.end())
    throw usage_error("--scheme '" + o.scheme + "' is not in the " + o.family + " family (" + all.front() +
                      (all.size() > 1 ? " … " + all.back() : std::string()) + ")");
  return {o.scheme};
}

}  // namespace

int run_solve(const solve_options& options) {
  if (is_two_parameter_family(options.family)) return run_solve_two_parameter(options);
  const auto schemes = schemes_of(options);
  const std::vector<std::string> perms = permutations_option(options.perm);
  const lie::moments_of_inertia body = required_moments_option(options.inertia);
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
      reports::write_file_atomically(std::filesystem::path(options.out) / (file + ".scheme"),
                                     solver::scheme_table_text(s, body, digits));
    }
  }
  if (options.json)
    std::cout << reports::solve_json(result, body, options.family, digits).dump(2) << "\n";
  else
    std::cout << reports::solve_text(result, body, digits, 20);
  return 0;
}

}  // namespace rotlie::app
