#pragma once
// The audit as data: each statement of the paper is one row of a claims table: its id, where the
// paper says it, the paper's value and what "holds" means (an expectation of one of a handful of
// kinds), the report sections it needs, and which measurement gives rotlie's value (a measurement
// function shared by many rows, with the row's arguments: a file, two curves, a family). One
// evaluator turns the table into audit rows: the measurement gives rotlie's numbers and their text,
// the expectation alone decides the verdict. Adding a claim is adding a row.
#include <string>
#include <utility>
#include <vector>

#include "rotlie/reports/audit_table.hpp"

namespace rotlie::reports {

/// How rotlie's measured value is compared with the paper's.
enum class expect_kind {
  equal_to,          ///< number == paper
  relative_within,   ///< |number / paper − 1| ≤ tolerance
  absolute_within,   ///< |number − paper| ≤ tolerance
  at_most,           ///< number ≤ paper
  at_least,          ///< number ≥ paper
  below,             ///< number < paper
  between_0_and,     ///< 0 < number < paper
  each_within,       ///< deviations not empty, every |deviation| ≤ tolerance (a missing row is NaN)
  same_names,        ///< names == the paper's names, in order
  same_name_set,     ///< names == the paper's names, in any order
  names_differ,      ///< two names, not the same
  holds,             ///< the measurement's flag (a property with no number: isolated, all positive, …)
  cannot_check,      ///< no number of rotlie's can decide it; the row's first argument says why
};

/// The paper's value and what "holds" means.
struct expectation {
  expect_kind kind = expect_kind::holds;
  double paper = 0;                ///< the paper's number or the bound
  double tolerance = 0;            ///< absolute or relative, by kind
  std::vector<std::string> names;  ///< the paper's names, for the kinds on names
};

inline expectation equal_to(double paper) { return {expect_kind::equal_to, paper, 0, {}}; }
inline expectation relative_within(double paper, double tolerance) { return {expect_kind::relative_within, paper, tolerance, {}}; }
inline expectation absolute_within(double paper, double tolerance) { return {expect_kind::absolute_within, paper, tolerance, {}}; }
inline expectation at_most(double bound) { return {expect_kind::at_most, bound, 0, {}}; }
inline expectation at_least(double bound) { return {expect_kind::at_least, bound, 0, {}}; }
inline expectation below(double bound) { return {expect_kind::below, bound, 0, {}}; }
inline expectation between_0_and(double bound) { return {expect_kind::between_0_and, bound, 0, {}}; }
inline expectation each_within(double tolerance) { return {expect_kind::each_within, 0, tolerance, {}}; }
inline expectation same_names(std::vector<std::string> names) { return {expect_kind::same_names, 0, 0, std::move(names)}; }
inline expectation same_name_set(std::vector<std::string> names) { return {expect_kind::same_name_set, 0, 0, std::move(names)}; }
inline expectation names_differ() { return {expect_kind::names_differ, 0, 0, {}}; }
inline expectation property_holds() { return {expect_kind::holds, 0, 0, {}}; }
inline expectation cannot_be_checked() { return {expect_kind::cannot_check, 0, 0, {}}; }

/// What a measurement gives: rotlie's value as text and what the expectation compares (a number,
/// deviations, names or a flag), or why there is none in this run.
struct measurement {
  std::string text;
  double number = 0;
  std::vector<double> deviations;
  std::vector<std::string> names;
  bool flag = false;
  std::string missing;  ///< not empty: not computed in this run (a section, a file, a curve), and why

  static measurement of(double number, std::string text) {
    measurement m;
    m.number = number, m.text = std::move(text);
    return m;
  }
  static measurement of_deviations(std::vector<double> deviations, std::string text) {
    measurement m;
    m.deviations = std::move(deviations), m.text = std::move(text);
    return m;
  }
  static measurement of_names(std::vector<std::string> names, std::string text) {
    measurement m;
    m.names = std::move(names), m.text = std::move(text);
    return m;
  }
  static measurement of_flag(bool flag, std::string text) {
    measurement m;
    m.flag = flag, m.text = std::move(text);
    return m;
  }
  static measurement absent(std::string why) {
    measurement m;
    m.missing = std::move(why);
    return m;
  }
};

/// Whether a measurement meets the expectation (never called for cannot_check).
bool meets(const expectation& e, const measurement& m);

/// "not computed in this run (section KEY)": the reason of every claim whose section did not run.
inline std::string section_not_run(const std::string& key) { return "not computed in this run (section " + key + ")"; }

/// One row of a claims table. Evidence is what the measurements read (the files of this run, or
/// results the audit computes through the library); it says which report sections ran.
template <class Evidence>
struct audit_claim {
  std::string id;         ///< stable key of the claim (not printed)
  std::string statement;  ///< the paper's statement, paraphrased, with its number
  std::string where;      ///< section, figure, table or equation of LV (2018)
  std::string tolerance;  ///< what "holds" means for this row, in words
  std::vector<std::string> sections;  ///< report sections it needs: the first that did not run is the reason
  expectation expected;               ///< the paper's value and the comparison
  /// rotlie's measurement: a function many rows share, reading the row's arguments
  measurement (*measure)(Evidence&, const audit_claim&) = nullptr;
  std::vector<std::string> args;  ///< the measurement's arguments (files, curves, schemes, a family)
};

/// The audit rows of a claims table, in its order.
template <class Evidence>
std::vector<audit_row> evaluate_claims(const std::vector<audit_claim<Evidence>>& claims, Evidence& evidence) {
  std::vector<audit_row> rows;
  rows.reserve(claims.size());
  for (const auto& c : claims) {
    audit_row row{c.id, c.statement, c.where, "—", c.tolerance, audit_verdict::not_computed, {}};
    for (const auto& key : c.sections)
      if (row.why.empty() && !evidence.ran(key)) row.why = section_not_run(key);
    if (row.why.empty()) {
      if (c.expected.kind == expect_kind::cannot_check) {
        row.verdict = audit_verdict::cannot_check;
        row.why = c.args.empty() ? std::string() : c.args.front();
      } else {
        auto m = c.measure(evidence, c);
        if (!m.missing.empty()) {
          row.why = std::move(m.missing);
        } else {
          row.verdict = meets(c.expected, m) ? audit_verdict::holds : audit_verdict::does_not_hold;
          row.value = std::move(m.text);
        }
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace rotlie::reports
