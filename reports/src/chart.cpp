#include "rotlie/reports/chart.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "rotlie/reports/child_process.hpp"
#include "rotlie/reports/output_file.hpp"

namespace rotlie::reports {
namespace {

thread_local chart_log* current_log = nullptr;

// A gnuplot single-quoted string: no backquote substitution, no macros, no escapes but ''.
// A line break would end the command, so control characters become spaces.
std::string gnuplot_text(const std::string& s) {
  std::string out = "'";
  for (const char c : s) {
    if (c == '\'') out += "''";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) out += ' ';
    else out += c;
  }
  return out + "'";
}

// A CSV field (RFC 4180): quoted, with "" for a quote.
std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

bool plain_file_name(const std::string& name) {
  if (name.empty() || name[0] == '-' || name[0] == '.') return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

// A point is drawable when it is finite and, on a log axis, positive.
bool drawable(const chart& c, double x, double y) {
  return std::isfinite(x) && std::isfinite(y) && (!c.log_x || x > 0) && (!c.log_y || y > 0);
}

// Everything but `set output`: run as it is, gnuplot writes the PNG to stdout.
std::string gnuplot_script(const chart& c) {
  std::ostringstream g;
  g << std::setprecision(17);
  bool coloured = false;
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    g << "$s" << k << " << EOD\n";
    const auto& s = c.series[k];
    const bool with_z = s.z.size() == s.x.size() && !s.z.empty();
    coloured = coloured || with_z;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!drawable(c, s.x[i], s.y[i]) || (with_z && !std::isfinite(s.z[i]))) continue;
      g << s.x[i] << " " << s.y[i];
      if (with_z) g << " " << s.z[i];
      g << "\n";
      if (s.segments && i % 2 == 1) g << "\n";  // a blank line ends a segment
      if (s.cells && i % 5 == 4) g << "\n";     // and a cell
    }
    g << "EOD\n";
  }
  g << "set terminal pngcairo size 1000,700 enhanced font 'Sans,10'\n"
    << "set title " << gnuplot_text(c.title) << " noenhanced\n"
    << "set xlabel " << gnuplot_text(c.x_label) << " noenhanced\n"
    << "set ylabel " << gnuplot_text(c.y_label) << " noenhanced\n"
    << (c.log_x ? "set logscale x\nset format x '10^{%L}'\n" : "")
    << (c.log_y ? "set logscale y\nset format y '10^{%L}'\n" : "")
    << "set grid\nset key outside right top noenhanced\n";
  if (c.equal_axes) g << "set size ratio -1\n";
  if (c.x_range) g << "set xrange [" << c.x_range->first << ":" << c.x_range->second << "]\n";
  if (c.y_range) g << "set yrange [" << c.y_range->first << ":" << c.y_range->second << "]\n";
  if (coloured && c.colour_range && c.colour_range->first < 0 && c.colour_range->second > 0) {
    const auto [lo, hi] = *c.colour_range;  // palette positions in data units: 0 is white
    g << "set cbrange [" << lo << ":" << hi << "]\nset palette defined (" << lo << " '#313695', " << lo / 2 << " '#74add1', 0 "
      << "'#f7f7f7', " << hi / 2 << " '#f46d43', " << hi << " '#a50026')\n";
  } else if (coloured) {
    if (c.colour_range) g << "set cbrange [" << c.colour_range->first << ":" << c.colour_range->second << "]\n";
    g << "set palette defined (0 '#313695', 1 '#74add1', 2 '#e0f3f8', 3 '#fee090', 4 '#f46d43', 5 '#a50026')\n";
  }
  if (coloured) g << "set cblabel " << gnuplot_text(c.colour_label) << " noenhanced\nset colorbox\n";
  g << "plot ";
  bool first = true;
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    const auto& s = c.series[k];
    g << (first ? "" : ", \\\n     ") << "$s" << k;
    if (s.cells && !s.z.empty()) {
      g << " using 1:2:3 with filledcurves closed fc palette fs solid 1.0 noborder notitle";
    } else if (s.cells) {
      const std::string colour = s.colour.empty() ? std::string("'#7f7f7f'") : gnuplot_text(s.colour);
      g << " using 1:2 with filledcurves closed fc rgb " << colour << " fs solid 1.0 border lc rgb " << colour
        << " lw 0.5 title " << gnuplot_text(s.name);
    } else if (!s.z.empty()) {
      g << " using 1:2:3 with points pt 5 ps " << (s.point_size > 0 ? s.point_size : 0.5) << " lc palette notitle";
    } else if (s.segments) {
      g << " using 1:2 with lines lw 2 lc rgb 'black' title " << gnuplot_text(s.name);
    } else {
      // point types that stay apart when curves coincide: filled and open circles, squares, triangles, diamonds
      constexpr int kinds[] = {7, 4, 5, 8, 9, 6, 11, 12, 13, 10};
      const int pt = s.point_type > 0 ? s.point_type : kinds[k % std::size(kinds)];
      g << " using 1:2 with "
        << (s.points_only ? "points pt " + (s.point_type > 0 ? std::to_string(pt)
                                             : s.colour.empty() ? std::to_string(7 + 2 * k) : std::string("5"))
                          : "linespoints pt " + std::to_string(pt) + " ps 0.8");
      if (s.point_size > 0) g << " ps " << s.point_size;
      if (!s.colour.empty()) g << " lc rgb " << gnuplot_text(s.colour);
      // gnuplot's palette has 8 colours: the next eight series are dashed, then dotted
      g << " dt " << 1 + k / 8 << " lw " << (k >= 8 ? 1.5 : 1.0) << " title " << gnuplot_text(s.name);
    }
    first = false;
  }
  if (c.horizontal_line)
    g << (first ? "" : ", \\\n     ") << *c.horizontal_line << " with lines dt 2 lc rgb 'black' title "
      << gnuplot_text(c.horizontal_label), first = false;
  if (c.diagonal) g << (first ? "" : ", \\\n     ") << "x with lines dt 3 lc rgb 'gray' title 'y = x'";
  g << "\n";
  return g.str();
}

// The first line of gnuplot's complaint, printable and short, for the failure message.
std::string first_line(const std::string& text) {
  std::string line;
  for (const char c : text) {
    if (c == '\n' && !line.empty()) break;
    if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7f && !(c == ' ' && line.empty())) line += c;
    if (line.size() >= 160) break;
  }
  return line;
}

// Runs gnuplot on the script; returns the PNG, or an empty string and the reason.
std::string draw_png(const std::string& script, std::string& reason) {
  child_result r;
  try {
    r = run_child({"gnuplot"}, script, std::chrono::seconds(gnuplot_seconds));
  } catch (const child_start_error& e) {
    reason = e.error == ENOENT ? "gnuplot is not installed (not found on PATH)" : e.what();
    return {};
  }
  const std::string said = first_line(r.err);
  if (r.timed_out) reason = "gnuplot did not finish within " + std::to_string(gnuplot_seconds) + " s";
  else if (r.signal != 0) reason = "gnuplot was ended by signal " + std::to_string(r.signal);
  else if (r.exit_status != 0)
    reason = "gnuplot failed with status " + std::to_string(r.exit_status) + (said.empty() ? "" : ": " + said);
  else if (r.out.empty()) reason = "gnuplot drew an empty PNG";
  else if (!is_complete_png(r.out)) reason = "gnuplot's output is not a complete PNG";
  else return std::move(r.out);
  return {};
}

std::uint32_t big_endian(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(b[at + i]);
  return v;
}

}  // namespace

chart_log::chart_log() : previous_(current_log) { current_log = this; }
chart_log::~chart_log() { current_log = previous_; }

bool is_complete_png(const std::string& bytes) {
  static const std::string signature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.compare(0, signature.size(), signature) != 0) return false;
  std::size_t at = signature.size();
  bool first = true;
  while (at + 12 <= bytes.size()) {
    const std::size_t length = big_endian(bytes, at);
    const std::string type = bytes.substr(at + 4, 4);
    if (first && type != "IHDR") return false;
    first = false;
    if (length > bytes.size() - at - 12) return false;
    at += 12 + length;
    if (type == "IEND") return at == bytes.size();
  }
  return false;
}

chart_files write_chart(const std::filesystem::path& dir, const std::string& name, const chart& c) {
  if (!plain_file_name(name)) throw std::invalid_argument("chart name '" + name + "' is not a plain file name");
  chart_files out;
  std::ostringstream csv;
  bool with_z = false;
  for (const auto& s : c.series) with_z = with_z || !s.z.empty();
  csv << std::setprecision(17) << (with_z ? "series,x,y,z\n" : "series,x,y\n");
  for (const auto& s : c.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      csv << csv_text(s.name) << "," << s.x[i] << "," << s.y[i];
      if (with_z) csv << "," << (i < s.z.size() ? std::to_string(s.z[i]) : std::string());
      csv << "\n";
    }
  write_file_atomically(dir / (name + ".csv"), csv.str());
  out.written.push_back(dir / (name + ".csv"));

  const std::string script = gnuplot_script(c);
  // The saved copy draws into <name>.png when run as `gnuplot <name>.gp` inside the folder.
  write_file_atomically(dir / (name + ".gp"), "set output " + gnuplot_text(name + ".png") + "\n" + script);
  out.written.push_back(dir / (name + ".gp"));

  if (current_log) ++current_log->charts_;
  std::string reason;
  const std::string png = draw_png(script, reason);
  if (png.empty()) {
    std::error_code ignored;
    std::filesystem::remove(dir / (name + ".png"), ignored);  // an earlier run's picture of other data
    out.note = "no PNG for " + name + ": " + reason;
    if (current_log) current_log->failures_.push_back({name, reason});
    return out;
  }
  write_file_atomically(dir / (name + ".png"), png);
  out.written.push_back(dir / (name + ".png"));
  out.png = true;
  return out;
}

std::string chart_markdown(const chart_files& files, const std::string& name, const std::string& caption) {
  const std::string image = files.png ? "![" + caption + "](" + name + ".png)" : "*" + files.note + "*";
  return image + "\n\n" + caption + " Data: [" + name + ".csv](" + name + ".csv).\n\n";
}

}  // namespace rotlie::reports
