#pragma once
// `rotlie report`: runs every experiment and writes its tables, data and figures into one
// output folder, with an index.md that links them. The folder is locked for the run (see
// report_folder.hpp); a chart gnuplot could not draw is listed in the result, the rest of the
// report is still written.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/reports/chart.hpp"

namespace rotlie::reports {

struct report_options {
  std::filesystem::path out_dir = "rotlie-report";
  bool quick = false;                                   ///< smaller sweeps, for a fast look
  bool full = false;                                    ///< the papers' full statistics: liquid water's nine 1-ps runs, maps at the paper's grid (long)
  std::vector<std::string> sections;                    ///< keys of report_section_keys(); empty: all
  std::function<void(std::string_view)> progress;      ///< one line per step, may be empty
  std::filesystem::path maps_dir;                       ///< map-N.jsonl, map-P.jsonl of `rotlie map` to draw
};

/// What one section of the report produced: its markdown for index.md and the files it wrote.
struct report_section {
  std::string title;
  std::string markdown;
  std::vector<std::filesystem::path> files;
};

/// What a run wrote, and the charts that have no PNG.
struct report_result {
  std::vector<std::filesystem::path> files;
  std::size_t charts = 0;
  std::vector<chart_failure> failed_charts;
};

/// A section of the report as data: its key (`--sections`), what it draws, and its writer. The list in
/// report order is report_sections() (reports/src/report.cpp); a new section is one file and one entry.
struct report_section_entry {
  std::string key, summary;
  report_section (*write)(const report_options&) = nullptr;
};
const std::vector<report_section_entry>& report_sections();

/// The keys of report_sections(), in report order.
const std::vector<std::string>& report_section_keys();

/// The section `key` alone, written into options.out_dir (which the caller has made); throws
/// std::invalid_argument for an unknown key.
report_section write_section(const std::string& key, const report_options& options);

/// Writes the chosen sections and index.md. Throws unusable_output_folder (a bad --out),
/// output_folder_busy (another report runs there), std::invalid_argument (an unknown section)
/// and std::runtime_error on I/O failure.
report_result run_report(const report_options& options);

}  // namespace rotlie::reports
