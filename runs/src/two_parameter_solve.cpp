#include "rotlie/runs/two_parameter_solve.hpp"

#include <algorithm>

#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {
namespace {

constexpr long max_digits = 300;
constexpr long max_starts = 100000;

}  // namespace

std::string two_parameter_solution::table_text(const solver::two_parameter_entry& e, const std::string& source) const {
  const auto s = solver::two_parameter_conditions(bch::layout_scheme(e.word, split, e.permutation), body);
  return solver::two_parameter_table_text(s, e.best, digits, body, two_parameter_name(e), source);
}

two_parameter_solution solve_two_parameter(const two_parameter_inputs& in) {
  two_parameter_solution out;
  const auto& f = family_to_solve(in.family);
  if (f.kind != bch::family_kind::two_free_parameters)
    throw bad_input("--family " + in.family + " is not a family of two free parameters (Q, QRS)");
  out.family = in.family;
  out.split = f.split;
  auto words = solver::two_parameter_words(out.split);
  if (!in.scheme.empty()) {
    if (std::find(words.begin(), words.end(), in.scheme) == words.end())
      throw bad_input("--scheme '" + in.scheme + "' is not a word of the " + in.family + " family (" + words.front() + " … " +
                      words.back() + ")");
    words = {in.scheme};
  }
  const std::vector<std::string> perms = permutations_named(in.perm);
  out.body = required_body(in.inertia);
  out.digits = static_cast<int>(integer_in_range(in.digits, "--digits", 10, max_digits));
  out.search.starts = static_cast<int>(integer_in_range(in.starts, "--starts", 1, max_starts));
  out.search.seed = static_cast<std::uint64_t>(integer_in_range(in.seed, "--seed", 0, 1L << 62));
  out.result = solver::solve_two_parameter(out.body, out.split, words, perms, out.search, out.digits);
  return out;
}

}  // namespace rotlie::runs
