#pragma once
// Log-log line charts for the report: a CSV beside every PNG (the numbers, for any other tool),
// the gnuplot script that drew it (to restyle), and the PNG drawn by gnuplot's pngcairo terminal.
//
// gnuplot runs without a shell and never sees a path: the script goes to its stdin, the PNG
// comes back on its stdout and is written by write_file_atomically. Text inside the script
// (titles, series names) is in single-quoted gnuplot strings, where neither backquote command
// substitution nor macros apply, with '' for a quote and line breaks replaced by spaces.
#include <boost/core/noncopyable.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rotlie::reports {

struct chart_series {
  std::string name;
  std::vector<double> x, y;
  bool points_only = false;  ///< scatter instead of lines with points
  /// Maps: a value per point, drawn as the point's colour on the chart's colour scale (and a
  /// fourth CSV column); the series then needs no legend entry.
  std::vector<double> z{};
  bool segments = false;     ///< points 2k, 2k + 1 are one line segment (a contour), black
  /// Maps drawn continuously: points 5k … 5k + 4 are one closed quadrilateral (a body's cell, its
  /// first corner repeated), filled with `colour`, or by z (one value per corner, all equal).
  bool cells = false;
  std::string colour{};      ///< "#rrggbb" for this series, else gnuplot's own
  double point_size = 0;     ///< 0: gnuplot's default
  int point_type = 0;        ///< gnuplot's point type; 0: one per series, so that curves that coincide stay apart
};

struct chart {
  std::string title, x_label, y_label;
  bool log_x = true, log_y = true;
  std::vector<chart_series> series;
  std::optional<double> horizontal_line;  ///< e.g. a failure threshold
  std::string horizontal_label;
  bool diagonal = false;                   ///< draw y = x (analytic vs numeric comparisons)
  std::string colour_label;                ///< the colour scale's title (series with z)
  /// The colour scale's range; when it holds 0 inside, 0 is white, below blue, above red.
  std::optional<std::pair<double, double>> colour_range;
  bool equal_axes = false;                 ///< one unit is as long on both axes (maps of bodies)
  std::optional<std::pair<double, double>> x_range, y_range;
};

struct chart_files {
  std::vector<std::filesystem::path> written;  ///< CSV, script and, when gnuplot ran, PNG
  bool png = false;
  std::string note;                             ///< why there is no PNG, when there is none
};

/// A chart whose PNG could not be drawn, and why.
struct chart_failure {
  std::string chart, reason;
};

/// While one exists, every chart drawn on this thread is counted and each failure recorded in
/// it, so that the report's exit status can say that a chart is missing.
class chart_log : boost::noncopyable {
 public:
  chart_log();
  ~chart_log();
  const std::vector<chart_failure>& failures() const { return failures_; }
  std::size_t charts() const { return charts_; }

 private:
  friend chart_files write_chart(const std::filesystem::path&, const std::string&, const chart&);
  chart_log* previous_;
  std::vector<chart_failure> failures_;
  std::size_t charts_ = 0;
};

/// gnuplot's time limit for one chart.
inline constexpr int gnuplot_seconds = 120;

/// Writes <name>.csv (series,x,y), <name>.gp and <name>.png into dir. `name` is a plain file name
/// chosen by the program (letters, digits, '_', '-'). When gnuplot is missing, fails, or returns
/// no complete PNG, the CSV and the script are still written, a PNG of an earlier run is removed,
/// `note` says why and the failure goes to the current chart_log.
/// Throws std::runtime_error when a file cannot be written.
chart_files write_chart(const std::filesystem::path& dir, const std::string& name, const chart& c);

/// The report's markdown for a chart written as `name`: the image (or why there is none), the
/// caption and a link to the CSV.
std::string chart_markdown(const chart_files& files, const std::string& name, const std::string& caption);

/// True when `bytes` is a whole PNG: the signature, then chunks up to IEND at the very end.
bool is_complete_png(const std::string& bytes);

}  // namespace rotlie::reports
