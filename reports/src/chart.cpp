#include "rotlie/reports/chart.hpp"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "rotlie/reports/output_file.hpp"

namespace rotlie::reports {
namespace {

std::string quoted(std::string s) {
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\\\"") : std::string(1, c);
  return out + "\"";
}

// A point is drawable when it is finite and, on a log axis, positive.
bool drawable(const chart& c, double x, double y) {
  return std::isfinite(x) && std::isfinite(y) && (!c.log_x || x > 0) && (!c.log_y || y > 0);
}

std::string gnuplot_script(const chart& c, const std::filesystem::path& png) {
  std::ostringstream g;
  g << std::setprecision(17);
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    g << "$s" << k << " << EOD\n";
    const auto& s = c.series[k];
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (drawable(c, s.x[i], s.y[i])) g << s.x[i] << " " << s.y[i] << "\n";
    g << "EOD\n";
  }
  g << "set terminal pngcairo size 1000,700 enhanced font 'Sans,10'\n"
    << "set output " << quoted(png.string()) << "\n"
    << "set title " << quoted(c.title) << " noenhanced\n"
    << "set xlabel " << quoted(c.x_label) << " noenhanced\n"
    << "set ylabel " << quoted(c.y_label) << " noenhanced\n"
    << (c.log_x ? "set logscale x\nset format x '10^{%L}'\n" : "")
    << (c.log_y ? "set logscale y\nset format y '10^{%L}'\n" : "")
    << "set grid\nset key outside right top noenhanced\n";
  g << "plot ";
  bool first = true;
  for (std::size_t k = 0; k < c.series.size(); ++k) {
    g << (first ? "" : ", \\\n     ") << "$s" << k << " using 1:2 with "
      << (c.series[k].points_only ? "points pt " + std::to_string(7 + 2 * k) : "linespoints pt 7 ps 0.6")
      // gnuplot's palette has 8 colours: the next eight series are dashed, then dotted
      << " dt " << 1 + k / 8 << " lw " << (k >= 8 ? 1.5 : 1.0) << " title " << quoted(c.series[k].name);
    first = false;
  }
  if (c.horizontal_line)
    g << (first ? "" : ", \\\n     ") << *c.horizontal_line << " with lines dt 2 lc rgb 'black' title "
      << quoted(c.horizontal_label), first = false;
  if (c.diagonal) g << (first ? "" : ", \\\n     ") << "x with lines dt 3 lc rgb 'gray' title 'y = x'";
  g << "\n";
  return g.str();
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

bool gnuplot_available() {
  static const bool available = std::system("gnuplot --version > /dev/null 2>&1") == 0;
  return available;
}

}  // namespace

chart_files write_chart(const std::filesystem::path& dir, const std::string& name, const chart& c) {
  chart_files out;
  std::ostringstream csv;
  csv << std::setprecision(17) << "series,x,y\n";
  for (const auto& s : c.series)
    for (std::size_t i = 0; i < s.x.size(); ++i) csv << quoted(s.name) << "," << s.x[i] << "," << s.y[i] << "\n";
  write_file_atomically(dir / (name + ".csv"), csv.str());
  out.written.push_back(dir / (name + ".csv"));

  // The script draws into a temporary name, renamed when gnuplot succeeded: never a half PNG.
  const auto png = dir / (name + ".png"), partial = dir / (name + ".png.partial");
  write_file_atomically(dir / (name + ".gp"), gnuplot_script(c, name + ".png"));
  out.written.push_back(dir / (name + ".gp"));
  if (!gnuplot_available()) {
    out.note = "gnuplot is not installed: " + name + ".csv and " + name + ".gp written, no PNG";
    return out;
  }
  const auto run = dir / (name + ".run.gp");
  write_file_atomically(run, gnuplot_script(c, partial));
  const std::string command = "gnuplot " + shell_quoted(run.string()) + " > /dev/null 2>&1";
  const int status = std::system(command.c_str());
  std::error_code ec;
  std::filesystem::remove(run, ec);
  if (status != 0 || !std::filesystem::exists(partial)) {
    std::filesystem::remove(partial, ec);
    out.note = "gnuplot failed on " + name + ".gp: no PNG";
    return out;
  }
  std::filesystem::rename(partial, png, ec);
  if (ec) throw std::runtime_error("cannot write " + png.string() + ": " + ec.message());
  out.written.push_back(png);
  out.png = true;
  return out;
}

std::string chart_markdown(const chart_files& files, const std::string& name, const std::string& caption) {
  const std::string image = files.png ? "![" + caption + "](" + name + ".png)" : "*" + files.note + "*";
  return image + "\n\n" + caption + " Data: [" + name + ".csv](" + name + ".csv).\n\n";
}

}  // namespace rotlie::reports
