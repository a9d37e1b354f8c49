// The audit's rows from the files of this report run (the claims of audit_file_claims.cpp, each
// evaluated once), and how rows are written (CSV, JSON).
#include "rotlie/reports/audit_table.hpp"

#include <algorithm>
#include <cmath>

#include "rotlie/reports/audit_files.hpp"
#include "rotlie/runs/maps_truth.hpp"

namespace rotlie::reports {
namespace {

std::string csv_field(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

double rank_correlation(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) return std::nan("");
  return runs::spearman(x, y);  // NaN below three points and where a side has no spread
}

std::vector<audit_row> audit_rows_from_reports(const audit_inputs& in) {
  report_files files(in);
  return evaluate_claims(file_claims(), files);
}

std::string verdict_text(const audit_row& row) {
  switch (row.verdict) {
    case audit_verdict::holds: return "holds";
    case audit_verdict::does_not_hold: return "does not hold";
    case audit_verdict::cannot_check: return "cannot be checked: " + row.why;
    case audit_verdict::not_computed: return row.why.rfind("not computed", 0) == 0 ? row.why : "not computed in this run: " + row.why;
  }
  return "";
}

std::string audit_csv(const std::vector<audit_row>& rows) {
  std::string out = "statement,section,rotlie_value,tolerance,verdict\n";
  for (const auto& r : rows)
    out += csv_field(r.statement) + "," + csv_field(r.where) + "," + csv_field(r.value) + "," + csv_field(r.tolerance) + "," +
           csv_field(verdict_text(r)) + "\n";
  return out;
}

nlohmann::json audit_json(const std::vector<audit_row>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& r : rows) {
    const char* key = r.verdict == audit_verdict::holds           ? "holds"
                      : r.verdict == audit_verdict::does_not_hold ? "does_not_hold"
                      : r.verdict == audit_verdict::cannot_check  ? "cannot_check"
                                                                  : "not_computed";
    a.push_back({{"statement", r.statement}, {"section", r.where}, {"rotlie_value", r.value}, {"tolerance", r.tolerance},
                 {"verdict", key}, {"verdict_text", verdict_text(r)}});
  }
  return {{"source", "Laskar & Vaillant (2018), sections 4 and 5"}, {"rows", a}};
}

}  // namespace rotlie::reports
