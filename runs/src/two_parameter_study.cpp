// The measurements of the report's section "Beyond the paper: two free parameters at order 4" (see
// two_parameter_study.hpp).
#include "rotlie/runs/two_parameter_study.hpp"

#include <algorithm>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {

namespace {

std::optional<solver::two_parameter_entry> best_entry(const solver::two_parameter_result& r) {
  for (const auto& e : r.entries)
    if (e.polished) return e;
  return std::nullopt;
}

}  // namespace

two_parameter_listing two_parameter_coefficients(const solver::two_parameter_entry& e) {
  const auto layout = bch::layout_scheme(e.word, e.split, e.permutation);
  two_parameter_listing out{layout.permuted, {}};
  for (const auto& st : layout.stages) {
    if (std::any_of(out.coefficients.begin(), out.coefficients.end(), [&](const auto& c) { return c.name == st.coefficient; })) continue;
    out.coefficients.push_back({st.letter, st.coefficient, e.best.values.at(st.coefficient)});
  }
  return out;
}

two_parameter_study_result two_parameter_study(bool quick, const std::function<void(const std::string&)>& progress_to) {
  const auto progress = [&](const std::string& line) {
    if (progress_to) progress_to(line);
  };
  constexpr int digits = two_parameter_study_digits;
  two_parameter_study_result out;
  const auto body = lie::parse_moments("water");
  solver::minimum_search_options abc_search, rs_search;
  abc_search.starts = quick ? 8 : 40;
  rs_search.starts = quick ? 20 : 100;
  out.abc_starts = abc_search.starts, out.rs_starts = rs_search.starts;
  out.abc_words = solver::two_parameter_words(bch::splitting::abc).size();
  progress("searching the 13-stage ABC palindromes for water");
  out.q = solver::solve_two_parameter(body, bch::splitting::abc, solver::two_parameter_words(bch::splitting::abc),
                                      bch::permutation_names(), abc_search, digits, 10);
  progress("searching the 11-stage RS palindromes for water");
  out.qrs = solver::solve_two_parameter(body, bch::splitting::rs, solver::two_parameter_words(bch::splitting::rs),
                                        bch::permutation_names(), rs_search, digits);
  out.best_q = best_entry(out.q);
  out.best_rs = best_entry(out.qrs);
  if (!out.best_q || !out.best_rs) return out;

  // The comparison at equal cost, measured.
  progress("protocol runs against P1 BAC (5) and RS4 S5 McLachlan CBA");
  const auto p1_family = solver::solve_dedicated(body, {"P1"}, {"BAC"}, 40);
  const auto& p1 = find_solution(p1_family, "P1", "BAC", 5);
  const auto p1_table = solver::scheme_table_of(p1, body);
  out.p1_name = p1.name();
  out.p1_remainder = p1.analytic_remainder;
  out.max_level = quick ? 8 : 10;
  const protocol_runner runner(body, 1, out.max_level);
  const auto table_of = [&](const solver::two_parameter_entry& e) {
    const auto s = solver::two_parameter_conditions(bch::layout_scheme(e.word, e.split, e.permutation), body);
    return schemes::parse_scheme_table(solver::two_parameter_table_text(s, e.best, digits, body, two_parameter_name(e), "report"));
  };
  out.curves.push_back(runner.run(p1_table));
  out.curves.back().name = p1.name();
  out.curves.push_back(runner.run(*schemes::reference_scheme("RS4-S5-McLachlan:CBA")));
  out.curves.push_back(runner.run(table_of(*out.best_q)));
  out.curves.back().name = two_parameter_name(*out.best_q);
  out.curves.push_back(runner.run(table_of(*out.best_rs)));
  out.curves.back().name = two_parameter_name(*out.best_rs);
  out.remainders = {p1.analytic_remainder, 0, out.best_q->best.remainder, out.best_rs->best.remainder};

  // Every polished system measured, to see whether the norm's ranking is the error's.
  progress("protocol runs of every polished system");
  const protocol_runner screen(body, 1, 8, false);
  const auto p1_screen = screen.run(p1_table);
  for (const auto* family : {&out.q, &out.qrs})
    for (const auto& e : family->entries) {
      if (!e.polished) continue;
      const auto k = screen.run(table_of(e));
      out.screened.push_back({two_parameter_name(e), e.best.remainder, bch::family_cost(two_parameter_family(e.split)),
                              ratio_at_equal_reduced_step(p1_screen, k)});
    }
  return out;
}

}  // namespace rotlie::runs
