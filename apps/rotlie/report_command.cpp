#include <iostream>

#include "commands.hpp"
#include "rotlie/reports/report.hpp"

namespace rotlie::app {

int run_report_command(const report_command_options& options) {
  reports::report_options report;
  report.out_dir = options.out;
  report.quick = options.quick;
  report.progress = [](std::string_view line) { std::cerr << "rotlie report: " << line << std::endl; };
  const auto files = reports::run_report(report);
  std::cerr << "rotlie report: wrote " << files.size() << " files; open " << (report.out_dir / "index.md").string()
            << std::endl;
  return 0;
}

}  // namespace rotlie::app
