// Report section "Comparison over all rigid bodies" (LV section 5, Figs. 6–10): the best N and P
// integrators and their gain over RS4 S5 McLachlan at every body of a grid over the triangle of
// bodies, at a resolution the default report affords, or from map files of `rotlie map`.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "rotlie/reports/body_cells.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/reports/report.hpp"
#include "sections.hpp"
#include "rotlie/reports/triangle_contour.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/map_check.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/maps_study.hpp"
#include "rotlie/runs/shipped_data.hpp"

namespace rotlie::reports {
namespace {

// Grids of the default report: N by the fast path (two exact solves per row and per system stop), P
// by the exact solver (the screened path is checked at K = 200 only: at K = 8 it named a wrong best
// at 2 of 56 bodies); --full and map files give the paper's K = 200, P there by the screened path.
constexpr int default_grid_N = 40, default_grid_P = 8, quick_grid_N = 10, quick_grid_P = 2, full_grid = 200;
// Bodies of each fast map checked against the exact solver (P: about 4 s each): a handful by
// default, 200 at the paper's grid or for a map file.
constexpr std::size_t default_checks_N = 10, default_checks_P = 4, full_checks = 200;

struct body_result {
  int i = 0, j = 0;
  double I1 = 0, I2 = 0, s = 0, t = 0;
  std::string best, permutation;  // best: "N2:BAC:2", permutation: "BAC"
  std::optional<double> ratio;
  std::vector<std::string> singular;
};

struct family_map {
  std::string family, source, method;
  int K = 0;
  double seconds = 0;
  std::vector<body_result> bodies;
  std::vector<nlohmann::json> lines;  ///< the body lines, for the check against the exact solver
  bool from_file = false;
  bool shipped = false;  ///< the full-resolution map shipped with rotlie (data/maps-K200)
};

body_result from_line(const nlohmann::json& j, int K) {
  body_result b;
  const auto ij = runs::map_line_indices(j, K);
  if (!ij) throw std::runtime_error("a map line is not a body of its grid");
  b.i = ij->first;
  b.j = ij->second;
  std::tie(b.I1, b.I2) = runs::grid_moments(K, b.i, b.j);
  b.s = static_cast<double>(b.i) / K;
  b.t = static_cast<double>(b.j) / K;
  if (j.contains("best") && j["best"].is_string()) {
    b.best = j["best"].get<std::string>();
    const auto first = b.best.find(':');
    b.permutation = b.best.substr(first + 1, b.best.find(':', first + 1) - first - 1);
  }
  if (j.contains("ratio") && j["ratio"].is_number()) b.ratio = j["ratio"].get<double>();
  if (j.contains("singular"))
    for (const auto& s : j["singular"]) b.singular.push_back(s.get<std::string>());
  return b;
}

family_map compute_map(const report_options& options, const std::string& family, int K) {
  family_map m;
  m.family = family;
  m.K = K;
  // The path rotlie map takes by default for the family at this grid (N continued, P screened at
  // K ≥ 200 and exact below, R exact).
  const auto computed = runs::compute_family_map(family, K, [&](const std::string& line) {
    if (options.progress) options.progress("Maps: " + line);
  });
  m.method = computed.method;
  m.source = std::string("computed here (") +
             (m.method == "exact" ? "exact solver" : m.method == "screened" ? "screened fast path" : "fast path") +
             ", --grid " + std::to_string(K) + ")";
  for (const auto& line : computed.lines) {
    auto j = nlohmann::json::parse(line);
    if (j.contains("failed")) continue;  // drawn as a map file is: without the bodies whose solve failed
    m.lines.push_back(std::move(j));
    m.bodies.push_back(from_line(m.lines.back(), K));
  }
  m.seconds = computed.seconds;
  write_file_atomically(runs::map_file_path(options.out_dir, family), computed.file_text);
  return m;
}

family_map read_map(const std::filesystem::path& file, const std::string& family) {
  const auto contents = runs::read_map_contents(file);
  if (!contents || contents->family != family) throw std::runtime_error(printable_path(file) + " is not a map of family " + family);
  family_map m;
  m.family = family;
  m.K = contents->K;
  m.method = contents->method;
  m.source = "read from " + file.filename().string() + " (--grid " + std::to_string(m.K) + ", " + m.method + ")";
  if (m.method == "screened" && !runs::recorded_neighbour_check(contents->header))
    m.source += "; its rows were not neighbour-checked (a file of an earlier rotlie: `rotlie map --resume` on it runs the check)";
  m.from_file = true;
  for (const auto& j : contents->bodies) {
    m.bodies.push_back(from_line(j, m.K));
    m.lines.push_back(j);
  }
  return m;
}

// 15 colours that stay apart (categorical maps; one per integrator or permutation).
const std::array<const char*, 15> palette = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                              "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
                                              "#393b79", "#e7ba52", "#637939", "#ad494a", "#000000"};

std::string categories_chart(const report_options& options, const family_map& m, bool by_permutation,
                             const std::string& name, const std::string& caption, std::vector<std::filesystem::path>& files) {
  std::map<std::string, chart_series> by;
  std::map<std::string, int> bodies_of;
  body_cells cells(m.K);
  for (const auto& b : m.bodies) {
    if (b.best.empty()) continue;
    const std::string key = by_permutation ? b.permutation : b.best.substr(0, b.best.find(':'));
    cells.add(b.i, b.j, by[key].x, by[key].y);
    ++bodies_of[key];
  }
  auto c = triangle_chart("Best " + m.family + std::string(by_permutation ? " permutation" : " integrator") +
                          " by ‖H_R5‖, --grid " + std::to_string(m.K));
  std::vector<std::string> keys;
  for (const auto& [k, s] : by) keys.push_back(k);
  if (!by_permutation)  // N1 … N15 in numeric order
    std::sort(keys.begin(), keys.end(), [](const std::string& a, const std::string& b) {
      return a.size() != b.size() ? a.size() < b.size() : a < b;
    });
  for (std::size_t k = 0; k < keys.size(); ++k) {
    auto s = by[keys[k]];
    s.name = keys[k] + " (" + std::to_string(bodies_of[keys[k]]) + ")";
    s.cells = true;
    s.colour = palette[k % palette.size()];
    c.series.push_back(std::move(s));
  }
  const auto f = write_chart(options.out_dir, name, c);
  files.insert(files.end(), f.written.begin(), f.written.end());
  return chart_markdown(f, name, caption);
}

// The level log10(ratio) = 0 over the grid, drawn in (I1, I2).
chart_series ratio_one_contour(const family_map& m) {
  std::map<std::pair<int, int>, double> level;
  for (const auto& b : m.bodies)
    if (b.ratio && *b.ratio > 0) level[{b.i, b.j}] = std::log10(*b.ratio);
  return zero_contour(level, m.K, "ratio = 1");
}

std::string ratio_chart(const report_options& options, const family_map& m, const std::string& name,
                        const std::string& caption, std::vector<std::filesystem::path>& files) {
  auto c = triangle_chart("log10(R_M / R_" + m.family + ") at equal cost, --grid " + std::to_string(m.K));
  c.colour_label = "log10 ratio";
  chart_series s;
  s.name = "log10 ratio";
  s.cells = true;
  body_cells cells(m.K);
  for (const auto& b : m.bodies)
    if (b.ratio && *b.ratio > 0) {
      cells.add(b.i, b.j, s.x, s.y);
      s.z.insert(s.z.end(), 5, std::log10(*b.ratio));
    }
  if (!s.z.empty()) {
    const auto [lo, hi] = std::minmax_element(s.z.begin(), s.z.end());
    c.colour_range = std::pair(std::min(*lo, -0.1), std::max(*hi, 0.1));  // ratio = 1 is white
  }
  c.series.push_back(std::move(s));
  auto contour = ratio_one_contour(m);
  if (!contour.x.empty()) c.series.push_back(std::move(contour));
  const auto f = write_chart(options.out_dir, name, c);
  files.insert(files.end(), f.written.begin(), f.written.end());
  return chart_markdown(f, name, caption);
}

// Fig. 6: the set E of eq. (77) in the (I1, I2) plane, its symmetric tops and flat bodies, the
// triangle ESA, and the six images of water (one per permutation).
std::string bodies_chart(const report_options& options, std::vector<std::filesystem::path>& files) {
  chart c = moments_plane_chart("The set of rigid bodies (I1, I2, 1), eq. (77), and the six images of water", "I1", "I2", {0.0, 3.0},
                                {0.0, 3.0});
  const auto line = [](const std::string& name, const std::string& colour, std::vector<double> x, std::vector<double> y) {
    chart_series s;
    s.name = name;
    s.colour = colour;
    s.x = std::move(x);
    s.y = std::move(y);
    return s;
  };
  // symmetric tops: I1 = I2, I2 = 1, I1 = 1 (red); flat bodies: I1 + I2 = 1, I2 = 1 + I1, I1 = 1 + I2 (blue)
  c.series.push_back(line("symmetric tops I1 = I2", "#d62728", {0.5, 3}, {0.5, 3}));
  c.series.push_back(line("symmetric tops I2 = 1", "#ff9896", {0, 3}, {1, 1}));
  c.series.push_back(line("symmetric tops I1 = 1", "#e377c2", {1, 1}, {0, 3}));
  c.series.push_back(line("flat I1 + I2 = 1", "#1f77b4", {0, 1}, {1, 0}));
  c.series.push_back(line("flat I2 = 1 + I1", "#aec7e8", {0, 2}, {1, 3}));
  c.series.push_back(line("flat I1 = 1 + I2", "#17becf", {1, 3}, {0, 2}));
  c.series.push_back(line("triangle ESA (the maps)", "#000000", {0, 0.5, 1, 0}, {1, 0.5, 1, 1}));
  const double I1 = 10220.0 / 29376, I2 = 19187.0 / 29376;  // water (section 4.3)
  const std::array<std::pair<std::string, std::pair<double, double>>, 6> images = {
      std::pair("ABC", std::pair(I1, I2)),          std::pair("BCA", std::pair(I2 / I1, 1 / I1)),
      std::pair("CAB", std::pair(1 / I2, I1 / I2)), std::pair("ACB", std::pair(I1 / I2, 1 / I2)),
      std::pair("CBA", std::pair(1 / I1, I2 / I1)), std::pair("BAC", std::pair(I2, I1))};
  for (std::size_t k = 0; k < images.size(); ++k) {
    chart_series s;
    s.name = "water " + images[k].first;
    s.points_only = true;
    s.colour = palette[k];
    s.point_size = 1.5;
    s.x = {images[k].second.first};
    s.y = {images[k].second.second};
    c.series.push_back(std::move(s));
  }
  const auto f = write_chart(options.out_dir, "maps_fig6_bodies", c);
  files.insert(files.end(), f.written.begin(), f.written.end());
  return chart_markdown(f, "maps_fig6_bodies",
                        "Fig. 6: the set of bodies (I1, I2, 1) of eq. (77): symmetric tops in red, flat bodies in blue; the "
                        "triangle ESA (I1 ≤ I2 ≤ 1) holds one image of every body, and the six points are water under the six "
                        "permutations (section 5.1).");
}

// Distance of a body (I1, I2, 1) to the symmetric tops: min(I2 − I1, 1 − I2), at most 1/3 (at (1/3, 2/3)).
double asymmetry(const body_result& b) { return std::min(b.I2 - b.I1, 1 - b.I2); }

std::string fractions_table(const std::vector<family_map>& maps) {
  std::ostringstream md;
  md << "| family | grid | bodies | better than RS4 S5 McLachlan (ratio > 1) | near symmetric tops (δ < 1/9) | "
        "middle (1/9 ≤ δ < 2/9) | very asymmetric (δ ≥ 2/9) | largest ratio, at (I1, I2) |\n"
        "|:--|--:|--:|--:|--:|--:|--:|:--|\n";
  for (const auto& m : maps) {
    std::array<int, 3> all{}, better{};
    int n = 0, wins = 0;
    double best = 0;
    std::pair<double, double> where{};
    for (const auto& b : m.bodies) {
      if (!b.ratio) continue;
      const double d = asymmetry(b);
      const std::size_t band = d < 1.0 / 9 ? 0 : d < 2.0 / 9 ? 1 : 2;
      ++n;
      ++all[band];
      if (*b.ratio > 1) ++wins, ++better[band];
      if (*b.ratio > best) best = *b.ratio, where = {b.I1, b.I2};
    }
    const auto percent = [](int a, int b) {
      std::ostringstream s;
      s << std::fixed << std::setprecision(1) << (b > 0 ? 100.0 * a / b : 0.0) << " % (" << a << "/" << b << ")";
      return s.str();
    };
    md << "| " << m.family << " | " << m.K << " | " << n << " | " << percent(wins, n) << " | " << percent(better[0], all[0])
       << " | " << percent(better[1], all[1]) << " | " << percent(better[2], all[2]) << " | " << std::setprecision(3)
       << best << " at (" << where.first << ", " << where.second << ") |\n";
  }
  return md.str();
}

// The fast maps against the exact solver at random bodies of each (map_check.hpp).
std::string fast_path_check(const report_options& options, const std::vector<family_map>& maps) {
  std::ostringstream md;
  md << "| family | grid | method | bodies checked | disagreements (best, label, reference, confirmed per-permutation bests, "
        "count) | unconfirmed per-permutation bests: other scheme or permutation | seconds |\n|---|---|---|---|---|---|---|\n";
  std::vector<std::string> differences;
  for (const auto& m : maps) {
    if (m.method == "exact") continue;
    const bool many = options.full || (m.from_file && !m.shipped);  // the shipped maps' own check is a slow test
    const std::size_t count = many ? full_checks : m.family == "P" ? default_checks_P : default_checks_N;
    const auto [r, seconds] = runs::timed_map_check(m.family, m.K, m.lines, count, 14, [&](int done, int of) {
      if (options.progress)
        options.progress("Maps: the " + m.family + " map against the exact solver, body " + std::to_string(done + 1) + " of " +
                         std::to_string(of));
    });
    md << "| " << m.family << " | " << m.K << " | " << m.method << " | " << r.checked << " | " << r.disagreements << " | ";
    if (r.unconfirmed > 0) md << r.unconfirmed_differ << " of " << r.unconfirmed;
    else md << "none unconfirmed";
    md << " | " << std::fixed << std::setprecision(0) << seconds << std::defaultfloat << " |\n";
    for (const auto& d : r.differences) differences.push_back(m.family + ": " + d);
  }
  md << "\nBodies drawn at random (seed 14) from each fast map; " << full_checks
     << " per map with --full or a map file. The screened path (P) makes each body's best complete (the exact solver, or a "
        "complete state carried over with an unchanged count of real eliminant roots), so its best, label and remainder "
        "are exact wherever the screening found the right system; the neighbour check then holds each body against its "
        "neighbours' best systems, solved exactly there, and the check here tests the result. Its per-permutation bests other than the best are labelled only where their system "
        "was confirmed too, and the count of real solutions is left out.\n\n";
  for (const auto& d : differences) md << "- " << d << "\n";
  if (!differences.empty()) md << "\n";
  return md.str();
}

std::string singular_bodies(const family_map& m) {
  std::ostringstream md;
  std::vector<const body_result*> found;
  for (const auto& b : m.bodies)
    if (!b.singular.empty()) found.push_back(&b);
  md << "- " << m.family << ": ";
  if (found.empty()) return md.str() + "no body of the grid has a singular system.\n";
  md << found.size() << " bod" << (found.size() == 1 ? "y" : "ies") << " with singular systems:";
  for (const auto* b : found) {
    md << " (I1, I2) = (" << b->I1 << ", " << b->I2 << "): " << b->singular.size() << " systems (";
    for (std::size_t k = 0; k < std::min<std::size_t>(b->singular.size(), 6); ++k) md << (k ? ", " : "") << b->singular[k];
    md << (b->singular.size() > 6 ? ", …" : "") << ");";
  }
  return md.str() + "\n";
}

}  // namespace

report_section maps_section(const report_options& options) {
  report_section sec;
  sec.title = "Comparison over all rigid bodies";
  std::ostringstream md;
  md << "## Comparison over all rigid bodies (LV section 5, Figs. 6–10)\n\n";
  md << bodies_chart(options, sec.files);
  std::vector<family_map> maps;
  for (const std::string family : {"N", "P", "R"}) {
    const auto file = options.maps_dir.empty() ? std::filesystem::path() : runs::map_file_path(options.maps_dir, family);
    if (!file.empty() && std::filesystem::exists(file)) {
      maps.push_back(read_map(file, family));
      continue;
    }
    if (const auto shipped = runs::shipped_map(family)) {  // the paper's grid, computed once (data/README.md)
      // a map an earlier run computed into this folder is not what is drawn now: the audit must not read it
      std::error_code ec;
      std::filesystem::remove(runs::map_file_path(options.out_dir, family), ec);
      maps.push_back(read_map(*shipped, family));
      maps.back().shipped = true;
      maps.back().source = "the shipped map data/maps-K200/" + shipped->filename().string() + " (--grid " +
                           std::to_string(maps.back().K) + ", " + maps.back().method + ")";
      continue;
    }
    if (family == "R") continue;  // no figure in the paper: drawn when its map is given or shipped, never computed here
    const int K = options.full ? full_grid
                  : options.quick ? (family == "N" ? quick_grid_N : quick_grid_P)
                                  : (family == "N" ? default_grid_N : default_grid_P);
    maps.push_back(compute_map(options, family, K));
  }
  md << "The maps: ";
  for (const auto& m : maps) {
    md << m.family << " " << m.source << " (" << m.bodies.size() << " bodies";
    if (m.seconds > 0) md << ", " << std::fixed << std::setprecision(0) << m.seconds << " s";
    md << std::defaultfloat << "); ";
  }
  md << "the paper's grid is --grid 200 (40,401 points). A family whose full-resolution map is shipped with rotlie "
        "(data/maps-K200, made by scripts/make-full-data.sh; data/README.md says how) is drawn from it; for the others "
        "the default report computes coarse grids (N by continuation "
        "confirmed by the exact solver; P by the exact solver at every body, since the screened path, checked at --grid 200, "
        "can miss the best between the far-apart bodies of a coarse grid); `rotlie report --full` computes --grid 200 here "
        "(P by the screened path: every system solved exactly at both ends of each row, the best of each body made complete, "
        "then the neighbour check; about 4.5 CPU hours for P, 10 minutes for N), and "
        "`--maps DIR` draws the files `map-N.jsonl`, `map-P.jsonl` of `rotlie map --out DIR` instead. The family R, "
        "which has no figure in the paper, is drawn in the same way when its map is shipped or in `--maps DIR` "
        "(`map-R.jsonl`). Each body is placed at (I1, I2) of its image in the triangle; the map files are in this "
        "folder.\n\n";
  // the paper's figure numbers (N: Figs. 7-8, P: Figs. 9-10); R's charts are named by the family alone
  const std::map<std::string, std::array<std::string, 2>> figures = {{"N", {"7", "8"}}, {"P", {"9", "10"}}};
  for (const auto& m : maps) {
    const std::string f = m.family;
    const auto numbered = figures.find(f);
    // chart file name and caption head of the best (0) and ratio (1) figures, a/b for best and permutation
    const auto name = [&](int which, const std::string& part, const std::string& kind) {
      return numbered == figures.end() ? "maps_" + f + "_" + kind : "maps_fig" + numbered->second[which] + part + "_" + kind + "_" + f;
    };
    const auto caption = [&](int which, const std::string& part) {
      return numbered == figures.end() ? "Family " + f + " (no figure in the paper)" + (part.empty() ? "" : ", " + part)
                                       : "Fig. " + numbered->second[which] + part;
    };
    md << "### Family " << f << "\n\n";
    md << categories_chart(options, m, false, name(0, "a", "best"),
                           caption(0, "a") + ": the best " + f + " integrator by analytic remainder ‖H_R5‖.", sec.files);
    md << categories_chart(options, m, true, name(0, "b", "permutation"),
                           caption(0, "b") + ": the permutation of that best integrator.", sec.files);
    md << ratio_chart(options, m, name(1, "", "ratio"),
                      caption(1, "") + ": log10 of R_M / R_" + f + " × (12/" + std::to_string(runs::mapped_family_cost(f)) +
                          ")^4, RS4 S5 McLachlan at its best permutation against the best " + f +
                          "; above 0 (right of the black contour ratio = 1) " + f + " wins at equal cost.",
                      sec.files);
  }
  md << "### Where the dedicated integrators beat RS4 S5 McLachlan\n\n" << fractions_table(maps) << "\n";
  md << "δ = min(I2 − I1, I3 − I2) / I3 measures the distance to the symmetric tops (δ = 0 on them, at most 1/3, at "
        "(1/3, 2/3, 1)). The paper (section 5.2): the integrators N are better than RS4 S5 McLachlan \"only for some "
        "bodies\", RS4 S5 McLachlan being \"especially more accurate for the ones close to the symmetric tops\"; (section "
        "5.3) the integrators P are better \"only for very asymmetric bodies\".\n\n";
  md << "### The fast paths against the exact solver\n\n" << fast_path_check(options, maps);
  md << "### Isolated singular points (Fig. 9)\n\n";
  for (const auto& m : maps) md << singular_bodies(m);
  md << "\nSingular systems occur only on flat bodies (t = 0, I1 + I2 = I3) in every map computed so far. The one with "
        "most is (1/4, 3/4, 1) (s = 1/2, on any grid with K even), where also I2 − I1 = I3/2: 38 of the 90 P systems. "
        "Fassò (2003) observed (the paper recalls "
        "it in section 3.2) that a leapfrog is of order 4 there, and rotlie confirms it: `rotlie remainder --scheme ABCBA "
        "--inertia 1/4,3/4,1 --order 3` prints H_R3 = 0 (permutation ABC; the other five permutations do not vanish). At "
        "this body the two conditions P1, P2 of the singular systems share a factor, so their solutions form a curve "
        "instead of isolated points and the automatic resolution stops (the eliminant vanishes identically). The likely "
        "reason, not checked system by system: those words reduce to that leapfrog when some of their stages are zero, "
        "so H_R3 = 0 along a whole curve of their coefficients. These are the paper's isolated points \"where a "
        "singularity occurs during the automatic resolution\" (Fig. 9). A second flat body, (3/10, 7/10, 1) (s = 2/5, "
        "on grids with K a multiple of 5), has five singular P systems (P1, P5, P7, P13 in CAB, P4 in CBA): there too "
        "their two conditions share a factor, but no leapfrog is of order 4 there (`rotlie remainder --scheme ABCBA "
        "--inertia 3/10,7/10,1 --order 3` is nonzero at all six permutations); the reason was not found.\n\n";
  sec.markdown = md.str();
  return sec;
}

}  // namespace rotlie::reports
