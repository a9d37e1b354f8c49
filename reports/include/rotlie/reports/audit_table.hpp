#pragma once
// The audit of LV sections 4 and 5: every statement of the paper next to rotlie's number for it
// and a verdict. This part gives the rows that come from files an earlier section of the same
// report run wrote (accuracy curves, solver solutions, maps, measured map ratios: the claims of
// audit_file_claims.cpp); rows the audit computes itself through the library are added by
// audit_section.cpp. A row whose section did not run in this run says so instead of reading a
// file left by an earlier run.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rotlie::reports {

enum class audit_verdict { holds, does_not_hold, cannot_check, not_computed };

struct audit_row {
  std::string id;          ///< the claim's stable key (audit_claim.hpp); not written out
  std::string statement;   ///< the paper's statement, paraphrased, with its number
  std::string where;       ///< section, figure or table of LV (2018)
  std::string value;       ///< rotlie's numbers, from this run
  std::string tolerance;   ///< what "holds" means for this row
  audit_verdict verdict = audit_verdict::cannot_check;
  std::string why;         ///< for cannot_check / not_computed: the reason
};

/// What the builder may read: the report folder of this run, the folder of map files given to
/// the maps section (empty: the maps are in `folder`), the sections this run executed, --quick.
struct audit_inputs {
  std::filesystem::path folder;
  std::filesystem::path maps_folder;
  std::set<std::string> sections_run;
  bool quick = false;
};

/// The rows read from the files of the accuracy, dedicated, maps and maps-truth sections.
/// Throws std::runtime_error when a file of this run is malformed.
std::vector<audit_row> audit_rows_from_reports(const audit_inputs& in);

/// "holds", "does not hold", "cannot be checked: …", "not computed in this run (…)".
std::string verdict_text(const audit_row& row);

/// audit.csv: statement, section, rotlie value, tolerance, verdict.
std::string audit_csv(const std::vector<audit_row>& rows);
nlohmann::json audit_json(const std::vector<audit_row>& rows);

/// Spearman's rank correlation (average ranks for ties); NaN for fewer than 3 pairs or a constant side.
double rank_correlation(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace rotlie::reports
