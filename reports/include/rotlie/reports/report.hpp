#pragma once
// `rotlie report`: runs every experiment and writes its tables, data and figures into one
// output folder, with an index.md that links them.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rotlie::reports {

struct report_options {
  std::filesystem::path out_dir = "rotlie-report";
  bool quick = false;                                   ///< smaller sweeps, for a fast look
  std::function<void(std::string_view)> progress;      ///< one line per step, may be empty
};

/// What one section of the report produced: its markdown for index.md and the files it wrote.
struct report_section {
  std::string title;
  std::string markdown;
  std::vector<std::filesystem::path> files;
};

/// Writes every section and index.md; returns the paths written. Throws std::runtime_error on I/O failure.
std::vector<std::filesystem::path> run_report(const report_options& options);

/// Section "Lie algebra of the free rigid body": dimensions, Theorems 1–2 verdicts, Table 1.
report_section lie_algebra_section(const report_options& options);

/// Section "Remainder formulas": the paper's remainders regenerated in LaTeX, H_R5 structure.
report_section remainder_section(const report_options& options);

}  // namespace rotlie::reports
