#pragma once
// The audit as data: each statement of the paper is one row of a claims table (its id, where the
// paper says it, what holds means, the report sections whose files it reads, and how it is
// measured), and one evaluator turns the table into audit rows. Adding a claim is adding a row.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rotlie/reports/audit_table.hpp"

namespace rotlie::reports {

/// What measuring a claim gives: a verdict with rotlie's numbers, or why there is none.
struct claim_outcome {
  audit_verdict verdict = audit_verdict::cannot_check;
  std::string value = "—";
  std::string why;

  static claim_outcome measured(bool holds, std::string value) {
    return {holds ? audit_verdict::holds : audit_verdict::does_not_hold, std::move(value), {}};
  }
  /// Not computed in this run: a section that did not run, a file or a curve it did not write.
  static claim_outcome missing(std::string why) { return {audit_verdict::not_computed, "—", std::move(why)}; }
  /// No number of rotlie's can decide it (a theorem the paper cites).
  static claim_outcome unverifiable(std::string why) { return {audit_verdict::cannot_check, "—", std::move(why)}; }
};

/// "not computed in this run (section KEY)": the reason of every claim whose section did not run.
inline std::string section_not_run(const std::string& key) { return "not computed in this run (section " + key + ")"; }

/// One row of a claims table. Evidence is what the measurements read (the files of this run, or
/// results the audit computes through the library); it says which report sections ran.
template <class Evidence>
struct audit_claim {
  std::string id;         ///< stable key of the claim (not printed)
  std::string statement;  ///< the paper's statement, paraphrased, with its number
  std::string where;      ///< section, figure, table or equation of LV (2018)
  std::string tolerance;  ///< what "holds" means for this row
  std::vector<std::string> sections;  ///< report sections it needs: the first that did not run is the reason
  std::function<claim_outcome(Evidence&)> measure;  ///< reads the evidence, compares with the paper
};

/// The audit rows of a claims table, in its order.
template <class Evidence>
std::vector<audit_row> evaluate_claims(const std::vector<audit_claim<Evidence>>& claims, Evidence& evidence) {
  std::vector<audit_row> rows;
  rows.reserve(claims.size());
  for (const auto& c : claims) {
    claim_outcome outcome;
    bool all_ran = true;
    for (const auto& key : c.sections)
      if (all_ran && !evidence.ran(key)) {
        outcome = claim_outcome::missing(section_not_run(key));
        all_ran = false;
      }
    if (all_ran) outcome = c.measure(evidence);
    rows.push_back({c.id, c.statement, c.where, std::move(outcome.value), c.tolerance, outcome.verdict, std::move(outcome.why)});
  }
  return rows;
}

}  // namespace rotlie::reports
