#pragma once
// What a section writer does besides its own content: progress lines prefixed with the section's name,
// and charts written into the report folder, listed among the section's files and linked in its markdown.
#include <sstream>
#include <string>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

struct section_writer {
  const report_options& options;
  report_section& section;
  std::ostringstream& md;
  std::string name;  ///< progress lines read "name: line"

  void progress(const std::string& line) const {
    if (options.progress) options.progress(name + ": " + line);
  }
  void figure(const std::string& file, const chart& c, const std::string& caption) {
    const auto f = write_chart(options.out_dir, file, c);
    section.files.insert(section.files.end(), f.written.begin(), f.written.end());
    md << chart_markdown(f, file, caption);
  }
};

}  // namespace rotlie::reports
