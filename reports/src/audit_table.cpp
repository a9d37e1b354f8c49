// The audit's rows from the files of this report run (the claims of audit_file_claims.cpp, each
// evaluated once), and how rows are written (CSV, JSON).
#include "rotlie/reports/audit_table.hpp"

#include <algorithm>
#include <cmath>

#include "rotlie/reports/audit_files.hpp"

namespace rotlie::reports {
namespace {

std::string csv_field(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = (static_cast<double>(i + j) / 2) + 1;
    i = j + 1;
  }
  return r;
}

}  // namespace

double rank_correlation(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 3) return std::nan("");
  const auto rx = ranks(x), ry = ranks(y);
  const double n = static_cast<double>(x.size()), mean = (n + 1) / 2;
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < rx.size(); ++i) {
    sxy += (rx[i] - mean) * (ry[i] - mean);
    sxx += (rx[i] - mean) * (rx[i] - mean);
    syy += (ry[i] - mean) * (ry[i] - mean);
  }
  return sxx > 0 && syy > 0 ? sxy / std::sqrt(sxx * syy) : std::nan("");
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
