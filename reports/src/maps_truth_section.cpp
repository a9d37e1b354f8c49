// Section "maps-truth": do the maps tell the truth? (issue 14, item 6.) The maps' analytic ratio,
// the measured ratio and two cheap predictors, over a fixed set of bodies (runs/maps_truth.hpp).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "rotlie/runs/number_text.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "rotlie/reports/report_csv_reader.hpp"
#include "sections.hpp"
#include "rotlie/reports/triangle_contour.hpp"
#include "rotlie/runs/maps_truth.hpp"
#include "rotlie/runs/maps_truth_csv.hpp"
#include "rotlie/runs/maps_study.hpp"
#include "rotlie/runs/text_file.hpp"

namespace rotlie::reports {

// From the runs library (rotlie::runs):
using runs::spearman;
using runs::truth_csv_header;
using runs::truth_max_level;
using runs::truth_min_level;

namespace {

constexpr int truth_default_grid = 5;  // 20 asymmetric grid bodies and water: about 2 CPU minutes
constexpr int truth_full_grid = 11;    // 110 and water: about 12 CPU minutes
constexpr int truth_quick_grid = 2;    // --quick: a look at the method, not a verdict

struct truth_row {
  double I1 = 0, I2 = 0;
  std::string family, best;
  double analytic = 0, measured_h = 0, measured_cpu = 0, predicted = 0, gradient = 0, slope = 0;
  double predicted_constant = 0, measured_constant = 0;
};

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) out.push_back(cell);
  return out;
}

std::vector<truth_row> parse_rows(const std::string& csv) {
  std::vector<truth_row> rows;
  std::stringstream in(csv);
  std::string line;
  std::getline(in, line);
  if (line + "\n" != truth_csv_header()) throw std::runtime_error("measured-ratios.csv: unexpected header");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto c = split_commas(line);
    if (c.size() != 14) throw std::runtime_error("measured-ratios.csv: a row without 14 columns");
    truth_row r;
    r.I1 = std::stod(c[0]) / std::stod(c[2]);
    r.I2 = std::stod(c[1]) / std::stod(c[2]);
    r.family = c[3];
    r.best = c[4];
    r.analytic = std::stod(c[5]);
    r.measured_h = std::stod(c[6]);
    r.measured_cpu = std::stod(c[7]);
    r.predicted = std::stod(c[8]);
    r.gradient = std::stod(c[9]);
    r.slope = std::stod(c[10]);
    r.predicted_constant = std::stod(c[11]);
    r.measured_constant = std::stod(c[12]);
    rows.push_back(r);
  }
  return rows;
}

// (i, j) of a body on the grid of K, when it is a grid body (issue 14's grid: I2 = 1/2 + s/2,
// I1 = (1 − I2) + t (2 I2 − 1)).
bool grid_indices(const truth_row& r, int K, int& i, int& j) {
  const double s = 2 * r.I2 - 1, t = (r.I1 - (1 - r.I2)) / (2 * r.I2 - 1);
  i = static_cast<int>(std::lround(s * K));
  j = static_cast<int>(std::lround(t * K));
  return std::abs(s * K - i) < 1e-9 && std::abs(t * K - j) < 1e-9;
}

// The level log10(measured ratio) = 0 over the grid, drawn in (I1, I2).
chart_series ratio_one_contour(const std::vector<truth_row>& rows, int K) {
  std::map<std::pair<int, int>, double> level;
  for (const auto& r : rows) {
    int i = 0, j = 0;
    if (r.measured_h > 0 && grid_indices(r, K, i, j)) level[{i, j}] = std::log10(r.measured_h);
  }
  return zero_contour(level, K, "measured ratio = 1");
}

std::string measured_map_chart(const report_options& options, const std::vector<truth_row>& rows,
                               const std::string& family, int K, std::vector<std::filesystem::path>& files) {
  chart c = triangle_chart("log10 measured ratio R_RS4S5 / R_" + family + " at equal h/C (best analytic " + family + ")");
  c.colour_label = "log10 measured ratio";
  chart_series s;
  s.name = "log10 measured ratio";
  s.point_size = std::clamp(30.0 / K, 0.8, 3.0);
  for (const auto& r : rows)
    if (r.family == family && r.measured_h > 0) {
      s.x.push_back(r.I1);
      s.y.push_back(r.I2);
      s.z.push_back(std::log10(r.measured_h));
    }
  if (!s.z.empty()) {
    const auto [lo, hi] = std::minmax_element(s.z.begin(), s.z.end());
    c.colour_range = std::pair(std::min(*lo, -0.1), std::max(*hi, 0.1));
  }
  c.series.push_back(std::move(s));
  std::vector<truth_row> of_family;
  for (const auto& r : rows)
    if (r.family == family) of_family.push_back(r);
  auto contour = ratio_one_contour(of_family, K);
  if (!contour.x.empty()) c.series.push_back(std::move(contour));
  const std::string name = "maps_truth_measured_" + family;
  const auto f = write_chart(options.out_dir, name, c);
  files.insert(files.end(), f.written.begin(), f.written.end());
  return chart_markdown(f, name,
                        "Measured ratio of the best analytic " + family +
                            " against RS4 S5 McLachlan at its best measured permutation (> 0: " + family +
                            " wins); black: the measured contour ratio = 1 on the grid cells.");
}

std::string scatter_chart(const report_options& options, const std::vector<truth_row>& rows,
                          std::vector<std::filesystem::path>& files) {
  chart c;
  c.title = "Analytic map ratio and transported-remainder prediction against the measured ratio";
  c.x_label = "measured ratio (equal h/C)";
  c.y_label = "predicted ratio";
  c.diagonal = true;
  for (const std::string family : {"N", "P"})
    for (const bool analytic : {true, false}) {
      chart_series s;
      s.name = family + (analytic ? ": analytic ||H_R5|| ratio" : ": transported remainder");
      s.points_only = true;
      for (const auto& r : rows)
        if (r.family == family && r.measured_h > 0) {
          s.x.push_back(r.measured_h);
          s.y.push_back(analytic ? r.analytic : r.predicted);
        }
      c.series.push_back(std::move(s));
    }
  const std::string name = "maps_truth_scatter";
  const auto f = write_chart(options.out_dir, name, c);
  files.insert(files.end(), f.written.begin(), f.written.end());
  return chart_markdown(f, name, "Each body twice per family: the maps' analytic ratio and the transported prediction, "
                                 "against the measured ratio; the diagonal is a perfect predictor.");
}

std::string summary_table(const std::vector<truth_row>& rows) {
  std::ostringstream md;
  md << "| family | bodies | Spearman: analytic ‖H_R5‖ ratio | Spearman: transported remainder | Spearman: mean "
        "\\|∇H_R5\\| | median \\|log10(predicted / measured)\\| (transported; analytic) | measured > 1 (equal h/C; equal "
        "CPU) | analytic > 1 | verdict flips (analytic; transported) | fitted order (min–max) |\n"
        "|--|--|--|--|--|--|--|--|--|--|\n";
  for (const std::string family : {"N", "P"}) {
    std::vector<double> analytic, predicted, gradient, measured, measured_cpu, off_pred, off_an;
    int flips_an = 0, flips_pred = 0, wins_h = 0, wins_cpu = 0, wins_an = 0;
    double slope_lo = 1e9, slope_hi = -1e9;
    for (const auto& r : rows) {
      if (r.family != family || !(r.measured_h > 0)) continue;
      analytic.push_back(r.analytic);
      predicted.push_back(r.predicted);
      gradient.push_back(r.gradient);
      measured.push_back(r.measured_h);
      measured_cpu.push_back(r.measured_cpu);
      off_pred.push_back(std::abs(std::log10(r.predicted / r.measured_h)));
      off_an.push_back(std::abs(std::log10(r.analytic / r.measured_h)));
      flips_an += (r.analytic > 1) != (r.measured_h > 1);
      flips_pred += (r.predicted > 1) != (r.measured_h > 1);
      wins_h += r.measured_h > 1;
      wins_cpu += r.measured_cpu > 1;
      wins_an += r.analytic > 1;
      slope_lo = std::min(slope_lo, r.slope);
      slope_hi = std::max(slope_hi, r.slope);
    }
    if (measured.empty()) continue;
    const auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    md << "| " << family << " | " << measured.size() << " | " << runs::fixed_text(spearman(analytic, measured), 3) << " (CPU: "
       << runs::fixed_text(spearman(analytic, measured_cpu), 3) << ") | " << runs::fixed_text(spearman(predicted, measured), 3) << " (CPU: "
       << runs::fixed_text(spearman(predicted, measured_cpu), 3) << ") | " << runs::fixed_text(spearman(gradient, measured), 3) << " | "
       << runs::significant_text(median(off_pred), 3) << "; " << runs::significant_text(median(off_an), 3) << " | " << wins_h << "; " << wins_cpu << " | "
       << wins_an << " | " << flips_an << "; " << flips_pred << " | " << runs::fixed_text(slope_lo, 2) << "–" << runs::fixed_text(slope_hi, 2)
       << " |\n";
  }
  return md.str();
}

std::string flips_table(const std::vector<truth_row>& rows) {
  std::ostringstream md;
  md << "| family | I1 | I2 | best (analytic) | analytic ratio | measured ratio, equal h/C | equal CPU | transported "
        "prediction |\n|--|--|--|--|--|--|--|--|\n";
  int n = 0;
  for (const auto& r : rows)
    if ((r.analytic > 1) != (r.measured_h > 1)) {
      ++n;
      md << "| " << r.family << " | " << runs::fixed_text(r.I1, 4) << " | " << runs::fixed_text(r.I2, 4) << " | " << r.best << " | "
         << runs::significant_text(r.analytic, 3) << " | " << runs::significant_text(r.measured_h, 3) << " | " << runs::significant_text(r.measured_cpu, 3) << " | "
         << runs::significant_text(r.predicted, 3) << " |\n";
    }
  if (n == 0) return "No body's verdict flips.\n";
  return md.str();
}

}  // namespace

report_section maps_truth_section(const report_options& options) {
  report_section sec;
  sec.title = "Do the maps tell the truth?";
  const std::filesystem::path given = options.maps_dir.empty() ? std::filesystem::path()
                                                                : options.maps_dir / "measured-ratios.csv";
  const int K = options.full ? truth_full_grid : options.quick ? truth_quick_grid : truth_default_grid;
  std::string csv;
  double cpu_seconds = 0;
  std::string provenance;
  if (!given.empty() && std::filesystem::exists(given)) {
    csv = runs::read_bounded_file(given, largest_csv_bytes);  // the one bounded reader: no FIFO waited on
    provenance = "read from the given measured-ratios.csv (`bench/maps_truth_study`)";
  } else {
    const auto measured = runs::measure_truth_grid(K, [&](const std::string& line) {
      if (options.progress) options.progress("Maps truth: " + line);
    });
    csv = measured.csv;
    cpu_seconds = measured.cpu_seconds;
    provenance = "computed in this run: the " + std::to_string(measured.bodies - 1) + " asymmetric bodies of the grid K = " +
                 std::to_string(K) + " (issue 14's grid) and water, " + runs::fixed_text(cpu_seconds, 0) + " s CPU" +
                 (options.full ? "" : " (`--full`: K = 11, 111 bodies)");
  }
  const auto rows = parse_rows(csv);
  const auto dir = options.out_dir / "maps-truth";
  std::filesystem::create_directories(dir);
  write_file_atomically(dir / "measured-ratios.csv", csv);
  sec.files.push_back(dir / "measured-ratios.csv");
  // the grid of the rows (for the contour): the K whose grid holds most of them
  int grid_K = K;
  for (const int k : {truth_full_grid, truth_default_grid, truth_quick_grid}) {
    int on = 0, i = 0, j = 0;
    for (const auto& r : rows) on += grid_indices(r, k, i, j);
    if (on > static_cast<int>(rows.size()) / 2) {
      grid_K = k;
      break;
    }
  }

  std::ostringstream md;
  md << "## Do the maps tell the truth? (issue 14, item 6)\n\n"
     << "Bodies: " << provenance << ". For each body, the best N and the best P integrator by the analytic remainder "
        "‖H_R5‖ (the maps' choice, exact solver) are run with the numeric protocol of LV section 4.1 (G(0) = (1, 1, 1), "
        "identity attitude, T = 1, h = 2^-" << truth_min_level << " … 2^-" << truth_max_level
     << ", long double, error constants error / (h/C)^4 from the three finest steps) against RS4 S5 McLachlan at its "
        "best MEASURED permutation among the six. Ratios > 1: the family's integrator is more accurate. Equal CPU: "
        "the error constants scaled by the measured CPU seconds per step (this thread) of the double stepper "
        "(fastest of 5 runs of ≥ 10 ms).\n\n"
     << "Predictors, computed from H_R5 alone, without running any scheme: (a) the maps' ratio R_M / R_best · "
        "(12/C)^4; (b) the **transported remainder**: a 4th-order symmetric composition is the exact flow of "
        "H + h^4 H_R5 up to O(h^6), so its attitude error is h^4 times the first-order response to H_R5 carried along "
        "the exact motion by the variational equations (models/remainder_predictor.hpp); its mean over [0, T] "
        "predicts the error constant itself; (c) the mean of |∇H_R5| along the unperturbed motion. (b) and (c) "
        "compare with the reference at its best predicted permutation.\n\n"
     << summary_table(rows) << "\n"
     << "Bodies where the verdict \"better than RS4 S5 McLachlan\" (ratio > 1 at equal h/C) flips between the "
        "analytic map and the measurement:\n\n"
     << flips_table(rows) << "\n";
  for (const auto& r : rows)
    if (std::abs(r.I1 - 10220.0 / 29376) < 1e-12 && std::abs(r.I2 - 19187.0 / 29376) < 1e-12)
      md << "Water, " << r.family << ": the analytic best " << r.best << " has analytic ratio " << runs::significant_text(r.analytic, 3)
         << ", measured " << runs::significant_text(r.measured_h, 3) << " (equal CPU " << runs::significant_text(r.measured_cpu, 3)
         << "), transported prediction " << runs::significant_text(r.predicted, 3) << "; error constant measured "
         << runs::significant_text(r.measured_constant, 3) << ", predicted " << runs::significant_text(r.predicted_constant, 3) << ".\n\n";
  md << measured_map_chart(options, rows, "N", grid_K, sec.files) << "\n"
     << measured_map_chart(options, rows, "P", grid_K, sec.files) << "\n"
     << scatter_chart(options, rows, sec.files) << "\n"
     << "Per-body rows: [maps-truth/measured-ratios.csv](maps-truth/measured-ratios.csv).\n";
  sec.markdown = md.str();
  return sec;
}

}  // namespace rotlie::reports
