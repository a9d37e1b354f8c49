#pragma once
// Log-log line charts for the report: a CSV beside every PNG (the numbers, for any other tool),
// the gnuplot script that drew it (to restyle), and the PNG drawn by gnuplot's pngcairo terminal.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rotlie::reports {

struct chart_series {
  std::string name;
  std::vector<double> x, y;
  bool points_only = false;  ///< scatter instead of lines with points
};

struct chart {
  std::string title, x_label, y_label;
  bool log_x = true, log_y = true;
  std::vector<chart_series> series;
  std::optional<double> horizontal_line;  ///< e.g. a failure threshold
  std::string horizontal_label;
  bool diagonal = false;                   ///< draw y = x (analytic vs numeric comparisons)
};

struct chart_files {
  std::vector<std::filesystem::path> written;  ///< CSV, script and, when gnuplot ran, PNG
  bool png = false;
  std::string note;                             ///< why there is no PNG, when there is none
};

/// Writes <name>.csv (series,x,y), <name>.gp and <name>.png into dir. The PNG is drawn with
/// gnuplot; without gnuplot the CSV and the script are still written and `note` says why.
/// Throws std::runtime_error when a file cannot be written.
chart_files write_chart(const std::filesystem::path& dir, const std::string& name, const chart& c);

/// The report's markdown for a chart written as `name`: the image (or why there is none), the
/// caption and a link to the CSV.
std::string chart_markdown(const chart_files& files, const std::string& name, const std::string& caption);

}  // namespace rotlie::reports
