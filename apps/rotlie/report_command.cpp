#include <algorithm>
#include <filesystem>
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "rotlie/reports/interruption.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/report_folder.hpp"

namespace rotlie::app {
namespace {

// "a, b, c": every section's key in report order
std::string known_sections() {
  std::string keys;
  for (const auto& k : reports::report_section_keys()) keys += (keys.empty() ? "" : ", ") + k;
  return keys;
}

}  // namespace

std::string report_sections_help() { return "Only these sections, comma-separated: " + known_sections(); }

namespace {

// "a,b" → {"a", "b"}, each a known section key.
std::vector<std::string> section_list(const std::string& text) {
  std::vector<std::string> keys;
  const std::string known = known_sections();
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string key = text.substr(start, comma - start);
    const auto& all = reports::report_section_keys();
    if (std::find(all.begin(), all.end(), key) == all.end())
      throw usage_error("--sections: unknown section '" + key + "' (expected a comma-separated list of: " + known + ")");
    keys.push_back(key);
    start = comma + 1;
  }
  return keys;
}

}  // namespace

int run_report_command(const report_command_options& options) {
  if (options.quick && options.full) throw usage_error("--quick and --full contradict each other: give one");
  reports::report_options report;
  report.out_dir = options.out;
  report.quick = options.quick;
  report.full = options.full;
  if (!options.maps.empty()) {
    if (!std::filesystem::is_directory(options.maps))
      throw usage_error("--maps: '" + options.maps + "' is not a folder (expected the --out folder of rotlie map)");
    report.maps_dir = options.maps;
  }
  if (!options.sections.empty()) report.sections = section_list(options.sections);
  report.progress = [](std::string_view line) { std::cerr << "rotlie report: " << line << std::endl; };

  const reports::interruption_guard stop_cleanly;  // Ctrl-C: kill gnuplot, remove the temporary, exit 130
  reports::report_result result;
  try {
    result = reports::run_report(report);
  } catch (const reports::unusable_output_folder& e) {
    throw usage_error(e.what());
  }
  const std::string index = reports::printable_path(report.out_dir / "index.md");
  if (!result.failed_charts.empty()) {
    std::string list;
    for (const auto& f : result.failed_charts) list += (list.empty() ? "" : "; ") + f.chart + " (" + f.reason + ")";
    std::cerr << "rotlie: error: " << result.failed_charts.size() << " of " << result.charts
              << " charts have no PNG: " << list << "; the rest of the report is in " << index << std::endl;
    return 1;
  }
  std::cerr << "rotlie report: wrote " << result.files.size() << " files; open " << index << std::endl;
  return std::cerr ? 0 : 1;
}

}  // namespace rotlie::app
