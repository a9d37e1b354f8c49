#pragma once
// What a section writer does besides its own content: its heading, progress lines prefixed with the
// section's name, and charts written into the report folder, listed among its files and linked in its markdown.
#include <sstream>
#include <string>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

/// A section being written: the section (its title and files) and its markdown, which starts with the
/// "## title" heading.
struct section_text {
  report_section section;
  std::ostringstream md;
  explicit section_text(const std::string& title) {
    section.title = title;
    md << "## " << title << "\n\n";
  }
};

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
