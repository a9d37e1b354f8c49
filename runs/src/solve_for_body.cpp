#include "rotlie/runs/solve_for_body.hpp"

#include <algorithm>

#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

solved_body solve_for_body(const solve_request& q) {
  const auto& family = family_to_solve(q.family);
  if (family.kind == bch::family_kind::two_free_parameters)
    throw bad_input("--family " + q.family + " has two free parameters: it is searched (runs::solve_two_parameter), not solved");
  const auto members = members_asked(family, q.scheme);
  const auto perms = permutations_named(q.perm);
  solved_body out;
  out.body = required_body(q.body);
  integer_in_range(std::to_string(q.digits), "--digits", 10, max_solve_digits);
  out.result = solver::solve_dedicated(out.body, members, perms, q.digits);
  // A degenerate system has no isolated solutions at this body: an error when it is all that was
  // asked for, a warning next to the others.
  const auto& systems = out.result.systems;
  const auto degenerate = std::count_if(systems.begin(), systems.end(), [](const solver::system_report& r) { return r.degenerate; });
  if (degenerate == static_cast<long>(systems.size()) && !systems.empty()) {
    const auto& r = systems.front();
    throw bad_input(r.scheme + " " + r.permutation + (systems.size() > 1 ? " (and every other system asked for)" : "") +
                    " is undefined for this body: " + r.note);
  }
  for (const auto& r : systems)
    if (r.degenerate) out.warnings.push_back(r.scheme + " " + r.permutation + " is undefined for this body: " + r.note);
  for (const auto& r : systems)  // roots whose written coefficients would not be order 4
    if (r.uncertified > 0) out.warnings.push_back(r.scheme + " " + r.permutation + ": " + r.note);
  return out;
}

}  // namespace rotlie::runs
