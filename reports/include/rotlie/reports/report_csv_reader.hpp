#pragma once
// Reading back what earlier sections of the same report run wrote: CSV tables (RFC 4180, a
// header line) and the chart CSVs (series,x,y[,z]) that write_chart puts beside every PNG.
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rotlie::reports {

/// A CSV file: its header and rows of fields (quotes removed, "" read as ").
struct csv_table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// The column called `name`, or nullopt.
  std::optional<std::size_t> column(const std::string& name) const;
};

/// nullopt when the file does not exist or cannot be read; throws std::runtime_error on a
/// malformed line (an unclosed quote, a row with another number of fields than the header).
/// The largest CSV file the report reads back (its CSVs, the maps-truth study's, are at most a few MB).
inline constexpr std::size_t largest_csv_bytes = std::size_t(1) << 28;

std::optional<csv_table> read_csv(const std::filesystem::path& file);

/// One curve of a chart CSV: its points in file order.
struct chart_curve {
  std::vector<double> x, y;
};

/// The series of a chart CSV by name (in file order of first appearance in `names`).
struct chart_data {
  std::vector<std::string> names;
  std::map<std::string, chart_curve> series;
};

/// nullopt when the file does not exist; throws std::runtime_error when it is not a chart CSV.
std::optional<chart_data> read_chart_csv(const std::filesystem::path& file);

}  // namespace rotlie::reports
