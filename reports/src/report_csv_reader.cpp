#include "rotlie/reports/report_csv_reader.hpp"

#include <sstream>
#include <stdexcept>

#include "rotlie/reports/output_file.hpp"
#include "rotlie/runs/text_file.hpp"

namespace rotlie::reports {
namespace {

// One record; a quoted field may hold commas and "" (never a line break in our files).
std::vector<std::string> split_record(const std::string& line, const std::filesystem::path& file) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') fields.back() += c;
      else if (i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
      else quoted = false;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  if (quoted) throw std::runtime_error(printable_path(file) + ": an unclosed quote");
  return fields;
}

double number(const std::string& text, const std::filesystem::path& file) {
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) throw std::runtime_error(printable_path(file) + ": '" + text + "' is not a number");
  return x;
}

}  // namespace

std::optional<std::size_t> csv_table::column(const std::string& name) const {
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k] == name) return k;
  return std::nullopt;
}

std::optional<csv_table> read_csv(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  std::istringstream in(runs::read_bounded_file(file, largest_csv_bytes));
  csv_table t;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(printable_path(file) + ": no header line");
  t.header = split_record(line, file);
  while (std::getline(in, line)) {
    if (line.empty() || line == "\r") continue;
    auto fields = split_record(line, file);
    if (fields.size() != t.header.size())
      throw std::runtime_error(printable_path(file) + ": a row of " + std::to_string(fields.size()) + " fields under a header of " +
                               std::to_string(t.header.size()));
    t.rows.push_back(std::move(fields));
  }
  return t;
}

std::optional<chart_data> read_chart_csv(const std::filesystem::path& file) {
  const auto t = read_csv(file);
  if (!t) return std::nullopt;
  const auto s = t->column("series"), x = t->column("x"), y = t->column("y");
  if (!s || !x || !y) throw std::runtime_error(printable_path(file) + " is not a chart CSV (series,x,y)");
  chart_data d;
  for (const auto& row : t->rows) {
    auto [it, fresh] = d.series.try_emplace(row[*s]);
    if (fresh) d.names.push_back(row[*s]);
    it->second.x.push_back(number(row[*x], file));
    it->second.y.push_back(number(row[*y], file));
  }
  return d;
}

}  // namespace rotlie::reports
