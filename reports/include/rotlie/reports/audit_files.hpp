#pragma once
// The evidence of the audit's claims that read the files of this report run (accuracy curves,
// solver solutions, maps, measured map ratios), and the measurements shared by those claims.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "rotlie/reports/audit_claim.hpp"
#include "rotlie/reports/audit_table.hpp"
#include "rotlie/reports/report_csv_reader.hpp"

namespace rotlie::reports {

/// One body of a map file (rotlie map): its moments, ratio, best scheme and grid position.
struct audit_map_body {
  double I1 = 0, I2 = 0;
  std::optional<double> ratio;
  bool singular = false;
  std::string best;
  int i = 0, j = 0;
};

struct audit_map {
  int K = 0;
  std::vector<audit_map_body> bodies;
};

/// The files of this run, each read once, and only when the section that writes it ran.
class report_files {
 public:
  explicit report_files(const audit_inputs& in) : in_(in) {}

  bool ran(const std::string& section) const { return in_.sections_run.count(section) > 0; }
  bool quick() const { return in_.quick; }
  /// " (--quick: h down to 2^-8)" with --quick, else empty: said after values from shorter curves.
  std::string quick_note() const { return in_.quick ? " (--quick: h down to 2^-8)" : ""; }

  /// FILE.csv of a chart; null when it does not exist. Throws when it is no chart CSV.
  const chart_data* chart(const std::string& file);
  /// A JSON file; null when it does not exist. Throws when it is not JSON.
  const nlohmann::json* json(const std::string& file);
  /// A CSV table; null when it does not exist.
  const csv_table* csv(const std::string& file);
  /// map-FAMILY.jsonl, from the folder given with --maps when it is there, else from this run's
  /// folder; null when absent. Throws when the file has no map header.
  const audit_map* map(const std::string& family);

 private:
  const audit_inputs& in_;
  std::map<std::string, std::optional<chart_data>> charts_;
  std::map<std::string, std::optional<nlohmann::json>> jsons_;
  std::map<std::string, std::optional<csv_table>> csvs_;
  std::map<std::string, std::optional<audit_map>> maps_;
};

/// The claims read from the report's files (dedicated, accuracy, maps, maps-truth), in the
/// audit's order.
std::vector<audit_claim<report_files>> file_claims();

// ---- measurements shared by the claims

/// error = constant (h/C)^order over the three finest points, as the accuracy section fits it.
struct curve_fit {
  double constant = 0, slope = 0;
};
curve_fit fit(const chart_curve& c, int order);

/// The series called `name` or `name:PERM` (a reference scheme at its best permutation); null if none.
const chart_curve* series(const chart_data& d, const std::string& name);
/// Its full name (`name` when there is none).
std::string series_name(const chart_data& d, const std::string& name);
/// The N series of a chart (names "N<k> PERM (label)") with their fits, smallest constant first.
std::vector<std::pair<std::string, curve_fit>> n_fits(const chart_data& d);

/// "N2 BAC (2)" of a solution of solutions_*.json; the solution of that name, or null.
std::string solution_name(const nlohmann::json& s);
const nlohmann::json* find_solution_named(const nlohmann::json& file, const std::string& name);

/// How many significant digits two decimal texts share: −log10 |x − y| / |y|, at most 45.
double agreeing_digits(const std::string& ours, const std::string& paper);
/// A decimal text ("d.ddd…e-2") is > 0, read exactly.
bool positive_decimal(const std::string& text);

/// "12.5 %".
std::string percent(double x);

}  // namespace rotlie::reports
