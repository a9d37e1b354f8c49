#pragma once
// What a section writer does besides its own content: its heading, progress lines prefixed with the
// section's name, and charts written into the report folder, listed among its files and linked in its markdown.
#include <sstream>
#include <string>
#include <utility>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/report.hpp"

namespace rotlie::reports {

/// A chart written into the report folder, listed among the section's files and linked in its markdown.
inline void add_chart(report_section& s, std::ostringstream& md, const report_options& o, const std::string& name, const chart& c,
                      const std::string& caption) {
  const auto f = write_chart(o.out_dir, name, c);
  s.files.insert(s.files.end(), f.written.begin(), f.written.end());
  md << chart_markdown(f, name, caption);
}

/// A section being written: its title and files, its markdown (which starts with the "## title" heading),
/// and progress lines that read "name: line".
struct section_writer {
  const report_options& options;
  std::string name;
  report_section section;
  std::ostringstream md;

  section_writer(const report_options& o, const std::string& title, std::string progress_name) : options(o), name(std::move(progress_name)) {
    section.title = title;
    md << "## " << title << "\n\n";
  }
  void progress(const std::string& line) const {
    if (options.progress) options.progress(name + ": " + line);
  }
  void figure(const std::string& file, const chart& c, const std::string& caption) { add_chart(section, md, options, file, c, caption); }
  /// The section with its markdown, once everything is written.
  report_section finish() {
    section.markdown = md.str();
    return std::move(section);
  }
};

}  // namespace rotlie::reports
