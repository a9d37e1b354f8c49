// The audit's evidence from the files of this run, and the measurements its claims share.
#include "rotlie/reports/audit_files.hpp"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <stdexcept>

#include "rotlie/runs/number_text.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/protocol_curves.hpp"
#include "rotlie/runs/shipped_data.hpp"

namespace rotlie::reports {
namespace {

namespace fs = std::filesystem;


double fraction_value(const std::string& f) {
  const auto slash = f.find('/');
  return slash == std::string::npos ? std::stod(f) : std::stod(f.substr(0, slash)) / std::stod(f.substr(slash + 1));
}

// A map file (runs/map_file.hpp's reader) as the audit measures it: place, ratio, best, singular.
std::optional<audit_map> read_map_file(const fs::path& file) {
  const auto contents = runs::read_map_contents(file);
  if (!contents) return std::nullopt;
  audit_map m;
  m.K = contents->K;
  for (const auto& j : contents->bodies) {
    if (!j.contains("I")) continue;
    audit_map_body b;
    b.I1 = fraction_value(j["I"][0].get<std::string>());
    b.I2 = fraction_value(j["I"][1].get<std::string>());
    b.i = static_cast<int>(std::lround(fraction_value(j.value("s", "0")) * m.K));
    b.j = static_cast<int>(std::lround(fraction_value(j.value("t", "0")) * m.K));
    if (j.contains("ratio") && j["ratio"].is_number()) b.ratio = j["ratio"].get<double>();
    b.singular = j.contains("singular") && !j["singular"].empty();
    if (j.contains("best") && j["best"].is_string()) b.best = j["best"].get<std::string>();
    m.bodies.push_back(b);
  }
  return m;
}

// The shipped maps (data/maps-K200) do not change while rotlie runs: each is read and parsed once per
// process (about a second for its 39,800 lines), however many audits read it.
std::optional<audit_map> read_shipped_map_once(const fs::path& file) {
  static std::mutex guard;
  static std::map<fs::path, std::optional<audit_map>> read;
  const std::lock_guard<std::mutex> lock(guard);
  auto it = read.find(file);
  if (it == read.end()) it = read.emplace(file, read_map_file(file)).first;
  return it->second;
}

// "d.ddd…e-2" as an exact rational.
cln::cl_RA decimal(const std::string& text) {
  std::string digits;
  long exponent = 0, point = -1;
  bool negative = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '-' && i == 0) negative = true;
    else if (c == '.') point = static_cast<long>(digits.size());
    else if (c == 'e' || c == 'E') {
      exponent = std::stol(text.substr(i + 1));
      break;
    } else if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
    else if (c != '+') throw std::runtime_error("'" + text + "' is not a decimal number");
  }
  if (digits.empty()) throw std::runtime_error("'" + text + "' is not a decimal number");
  const long fraction = point < 0 ? 0 : static_cast<long>(digits.size()) - point;
  const long shift = exponent - fraction;
  cln::cl_RA x = cln::cl_I(digits.c_str());
  x = shift >= 0 ? x * cln::expt_pos(cln::cl_I(10), cln::cl_I(shift)) : x / cln::expt_pos(cln::cl_I(10), cln::cl_I(-shift));
  return negative ? -x : x;
}

}  // namespace

const chart_data* report_files::chart(const std::string& file) {
  auto it = charts_.find(file);
  if (it == charts_.end()) it = charts_.emplace(file, read_chart_csv(in_.folder / (file + ".csv"))).first;
  return it->second ? &*it->second : nullptr;
}

const nlohmann::json* report_files::json(const std::string& file) {
  auto it = jsons_.find(file);
  if (it == jsons_.end()) {
    std::optional<nlohmann::json> j;
    std::ifstream f(in_.folder / file);
    if (f) {
      j = nlohmann::json::parse(f, nullptr, false);
      if (j->is_discarded()) throw std::runtime_error(printable_path(in_.folder / file) + " is not JSON");
    }
    it = jsons_.emplace(file, std::move(j)).first;
  }
  return it->second ? &*it->second : nullptr;
}

const csv_table* report_files::csv(const std::string& file) {
  auto it = csvs_.find(file);
  if (it == csvs_.end()) it = csvs_.emplace(file, read_csv(in_.folder / file)).first;
  return it->second ? &*it->second : nullptr;
}

const audit_map* report_files::map(const std::string& family) {
  auto it = maps_.find(family);
  if (it == maps_.end()) {
    // the map the maps section drew: --maps DIR, else the one it computed into the folder, else the shipped
    // one (data/maps-K200; drawing it removes an older computed map from the folder)
    const fs::path given = in_.maps_folder.empty() ? fs::path() : runs::map_file_path(in_.maps_folder, family);
    fs::path file = !given.empty() && fs::exists(given) ? given : runs::map_file_path(in_.folder, family);
    const auto shipped = fs::exists(file) ? std::nullopt : runs::shipped_map(family);
    it = maps_.emplace(family, shipped ? read_shipped_map_once(*shipped) : read_map_file(file)).first;
  }
  return it->second ? &*it->second : nullptr;
}

curve_fit fit(const chart_curve& c, int order) {
  std::vector<std::pair<double, double>> p;
  for (std::size_t i = 0; i < c.x.size(); ++i) p.emplace_back(c.x[i], c.y[i]);
  const auto f = runs::fit_finest(std::move(p), order);
  return {f.constant, f.slope};
}

const chart_curve* series(const chart_data& d, const std::string& name) {
  for (const auto& n : d.names)
    if (n == name || n.rfind(name + ":", 0) == 0) return &d.series.at(n);
  return nullptr;
}

std::string series_name(const chart_data& d, const std::string& name) {
  for (const auto& n : d.names)
    if (n == name || n.rfind(name + ":", 0) == 0) return n;
  return name;
}

std::vector<std::pair<std::string, curve_fit>> n_fits(const chart_data& d) {
  std::vector<std::pair<std::string, curve_fit>> out;
  for (const auto& n : d.names)
    if (n.size() > 1 && n[0] == 'N' && std::isdigit(static_cast<unsigned char>(n[1]))) out.emplace_back(n, fit(d.series.at(n), 4));
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second.constant < b.second.constant; });
  return out;
}

std::string solution_name(const nlohmann::json& s) {
  return s.at("scheme").get<std::string>() + " " + s.at("perm").get<std::string>() + " (" + std::to_string(s.at("label").get<int>()) + ")";
}

const nlohmann::json* find_solution_named(const nlohmann::json& file, const std::string& name) {
  for (const auto& s : file.at("solutions"))
    if (solution_name(s) == name) return &s;
  return nullptr;
}

double agreeing_digits(const std::string& ours, const std::string& paper) {
  const cln::cl_RA x = decimal(ours), y = decimal(paper);
  if (x == y) return 45;
  const double rel = cln::double_approx(cln::abs((x - y) / y));
  return std::min(45.0, -std::log10(rel));
}

bool positive_decimal(const std::string& text) { return cln::plusp(decimal(text)); }

std::string percent(double x) { return runs::fixed_text(100 * x, 1) + " %"; }

}  // namespace rotlie::reports
