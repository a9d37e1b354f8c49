// Report section "In LAMMPS": rotlie's fix styles inside LAMMPS (lammps/), measured by the benchmark
// lammps/bench/lammps_bench.py. The benchmark runs LAMMPS for minutes on up to 32,768 molecules, so
// the report does not run it: it renders the CSVs the benchmark wrote into <report>/lammps-bench/,
// and says how to produce them when they are absent.
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/section_writer.hpp"
#include "rotlie/runs/number_text.hpp"
#include "rotlie/reports/lammps_section.hpp"
#include "rotlie/reports/report_csv_reader.hpp"
#include "rotlie/runs/shipped_data.hpp"

namespace rotlie::reports {
namespace {

namespace fs = std::filesystem;

// A field of a CSV row by column name ("" when the column is absent).
struct row_view {
  const csv_table& table;
  const std::vector<std::string>& row;
  std::string operator[](const std::string& name) const {
    const auto c = table.column(name);
    return c && *c < row.size() ? row[*c] : std::string();
  }
  double number(const std::string& name) const {
    const auto text = (*this)[name];
    try {
      return text.empty() ? NAN : std::stod(text);
    } catch (const std::exception&) {
      return NAN;
    }
  }
};

std::string number(double x, int digits) { return std::isfinite(x) ? runs::significant_text(x, digits) : std::string("–"); }

std::string how_to_produce(const fs::path& out_dir) {
  return "Produce it with `lammps/bench/lammps_bench.py --out " + (out_dir / "lammps-bench").string() +
         "` (Debian's `/usr/bin/python3`, the build's `lmp_rotlie`; about 8 minutes on 2 idle cores, `--full` about 30, "
         "`--floor` adds the energy floor's diagnosis), "
         "then run `rotlie report --sections lammps` into the same folder.\n\n";
}

void benchmark_table(std::ostringstream& md, const csv_table& runs, double& load_min, double& load_max) {
  md << "| molecules | ranks | integrator | h (fs) | wall ms/step | ms per force evaluation | fix's own ms/step | CPU ms per ps | ΔE/ΔV (%) |\n"
        "|--:|--:|:--|--:|--:|--:|--:|--:|--:|\n";
  for (const auto& r : runs.rows) {
    const row_view v{runs, r};
    for (const char* load : {"load_before", "load_after"})
      if (std::isfinite(v.number(load))) load_min = std::min(load_min, v.number(load)), load_max = std::max(load_max, v.number(load));
    if (v["purpose"] != "table") continue;
    md << "| " << v["molecules"] << " | " << v["ranks"] << " | `" << v["integrator"] << "` | " << v["h_fs"] << " | ";
    if (v["status"] != "ok") {
      md << v["status"] << " | | | | |\n";
      continue;
    }
    md << number(v.number("wall_ms_per_step"), 3) << " | " << number(v.number("wall_ms_per_force"), 3) << " | "
       << number(v.number("modify_ms_per_step"), 3) << " | " << number(v.number("cpu_ms_per_ps"), 3) << " | "
       << number(v.number("dE_over_dV_percent"), 3) << " |\n";
  }
  md << "\n";
}

chart cost_chart(const csv_table& runs) {
  chart c;
  c.title = "512 rigid TIP3P in LAMMPS (pppm 1e-5, 1 rank): energy error against cost";
  c.x_label = "CPU time per simulated ps (ms)";
  c.y_label = "ΔE/ΔV (%)";
  for (const auto& r : runs.rows) {
    const row_view v{runs, r};
    if (v["purpose"] != "chart" || v["status"] != "ok") continue;
    auto it = std::find_if(c.series.begin(), c.series.end(), [&](const chart_series& s) { return s.name == v["integrator"]; });
    if (it == c.series.end()) it = c.series.insert(c.series.end(), chart_series{v["integrator"], {}, {}, false});
    it->x.push_back(v.number("cpu_ms_per_ps"));
    it->y.push_back(v.number("dE_over_dV_percent"));
  }
  for (auto& s : c.series) {  // each series as a line in order of cost
    std::vector<std::size_t> order(s.x.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
    chart_series sorted{s.name, {}, {}, false};
    for (auto k : order) sorted.x.push_back(s.x[k]), sorted.y.push_back(s.y[k]);
    s = std::move(sorted);
  }
  return c;
}

// The energy floor's diagnosis (lammps_bench.py --floor): the same runs with the LJ energy shifted to 0 at
// the cutoff and a tighter PPPM, beside the default runs at the same steps.
void floor_table(std::ostringstream& md, const csv_table& runs) {
  std::ostringstream rows;
  for (const auto& r : runs.rows) {
    const row_view v{runs, r};
    if (v["status"] != "ok" || v["molecules"] != "512" || v["ranks"] != "1") continue;
    if (v["purpose"] != "floor" && v["purpose"] != "chart") continue;
    rows << "| `" << v["integrator"] << "` | " << v["h_fs"] << " | " << (v["lj_shift"].empty() ? "no" : v["lj_shift"]) << " | "
         << (v["pppm_accuracy"].empty() ? "1.0e-5" : v["pppm_accuracy"]) << " | " << number(v.number("dE_over_dV_percent"), 3) << " |\n";
  }
  if (rows.str().empty() || std::none_of(runs.rows.begin(), runs.rows.end(), [&](const auto& r) { return row_view{runs, r}["purpose"] == "floor"; }))
    return;
  md << "Where the energy error stops falling with h (512 molecules, 1 rank; `lammps_bench.py --floor` runs the same inputs "
        "with `pair_modify shift yes` and with `pppm 1e-6` and `1e-7`):\n\n| integrator | h (fs) | LJ shifted | PPPM accuracy | ΔE/ΔV (%) |\n"
        "|:--|--:|:--|--:|--:|\n"
     << rows.str() << "\n";
}

void goals_table(std::ostringstream& md, const csv_table& goals) {
  md << "| goal | molecules | ranks | value | second figure | met | note |\n|:--|--:|--:|--:|--:|:--|:--|\n";
  for (const auto& r : goals.rows) {
    const row_view v{goals, r};
    md << "| " << v["goal"] << " | " << v["molecules"] << " | " << v["ranks"] << " | " << number(v.number("value"), 3) << " | "
       << number(v.number("alternative"), 3) << " | " << v["met"] << " | " << v["note"] << " |\n";
  }
  md << "\n";
}

// LAMMPS's own rigid examples (lammps/bench/rigid_examples.py): std of etotal per input, variant and fix,
// 1 and 2 ranks side by side.
void examples_table(std::ostringstream& md, const csv_table& runs) {
  md << "| input | variant | fix | std(etotal), 1 rank | 2 ranks |\n|:--|:--|:--|--:|--:|\n";
  auto shown = [](const row_view& v) { return v["status"] == "ran" ? number(v.number("std_etotal"), 3) : v["status"]; };
  for (const auto& r : runs.rows) {
    const row_view v{runs, r};
    if (v["ranks"] != "1") continue;
    std::string two;
    for (const auto& o : runs.rows) {
      const row_view w{runs, o};
      if (w["ranks"] == "2" && w["example"] == v["example"] && w["variant"] == v["variant"] && w["fix"] == v["fix"]) two = shown(w);
    }
    md << "| `" << v["example"] << "` | " << v["variant"] << " | `" << v["fix"] << "` | " << shown(v) << " | " << two << " |\n";
  }
  md << "\n";
}

// A CSV the benchmark scripts wrote into this report's folder (`local`), else the measurement shipped
// with rotlie (data/lammps/); `where` says which, as a markdown link or the shipped path.
std::optional<csv_table> measured_csv(const fs::path& out_dir, const std::string& local, std::string& where) {
  if (auto t = read_csv(out_dir / local)) {
    where = "[" + local + "](" + local + ")";
    return t;
  }
  const std::string name = fs::path(local).filename().string();
  if (const auto shipped = runs::shipped_file("lammps/" + name)) {
    where = "data/lammps/" + name + " (the measurement shipped with rotlie, on a 2-core machine other work shared)";
    return read_csv(*shipped);
  }
  return std::nullopt;
}

void examples_part(std::ostringstream& md, const fs::path& out_dir) {
  std::string where;
  if (const auto examples = measured_csv(out_dir, "lammps-examples/rigid_examples.csv", where)) {
    md << "LAMMPS's own example inputs with rigid bodies, the rigid fix of their constant-energy run swapped "
          "(" << where << ", `lammps/bench/rigid_examples.py`; what each input and variant is: lammps/README.md):\n\n";
    examples_table(md, *examples);
  } else {
    md << "LAMMPS's own example inputs with rigid bodies: `lammps/bench/rigid_examples.py --out "
       << (out_dir / "lammps-examples").string() << "` puts their table here.\n\n";
  }
}

}  // namespace

report_section lammps_section(const report_options& options) {
  section_writer w(options, "In LAMMPS", "LAMMPS");
  auto& md = w.md;
  md << "rotlie's SIER2 and SIER4 as LAMMPS fix styles `rigid/sier2/small` and `rigid/sier4/small` (folder `lammps/`, "
        "GPL-2.0-or-later, launcher `lmp_rotlie`), against LAMMPS's own `rigid/nve/small` (NO_SQUISH, i.e. MRDL), on "
        "rigid TIP3P with `lj/cut/coul/long` 9 Å and `pppm 1e-5`: 512, 4,096 and 32,768 molecules (a melted 512 replicated), "
        "1 and 2 MPI ranks. One SIER4 step is 4 force evaluations, so the table compares SIER4 at h = 8 fs with the "
        "others at 2 fs (the same force evaluations per simulated ps). ΔE/ΔV is the rms fluctuation of etotal over that "
        "of pe, sampled every step (as in the liquid-water section); the timed runs tally no energy in between. "
        "\"fix's own\" is LAMMPS's Modify time, the integrator's share of the step.\n\n";
  std::string where;
  const auto runs = measured_csv(options.out_dir, "lammps-bench/lammps_bench.csv", where);
  if (!runs) {
    md << "The benchmark's results (`lammps-bench/lammps_bench.csv` in this report's folder) are not there: the report "
          "does not run LAMMPS itself (the default sweep takes minutes). "
       << how_to_produce(options.out_dir);
    examples_part(md, options.out_dir);
    return w.finish();
  }
  double load_min = INFINITY, load_max = -INFINITY;
  std::ostringstream table;
  benchmark_table(table, *runs, load_min, load_max);
  md << "Read from " << where << " (written by `lammps/bench/lammps_bench.py`). The machine's one-minute load average during the runs was between "
     << number(load_min, 3) << " and " << number(load_max, 3)
     << " (it counts the benchmark's own 1 or 2 processes): wall times depend on it, above all on 2 ranks of a 2-core "
        "machine that other work shares; CPU time (wall time × LAMMPS's reported CPU use × ranks) depends on it less.\n\n"
     << table.str();
  const auto c = cost_chart(*runs);
  if (!c.series.empty()) {
    w.figure("lammps_cost", c, "ΔE/ΔV against CPU time per simulated ps, several h per integrator.");
    md << "\n";
  }
  floor_table(md, *runs);
  std::string goals_where;
  if (const auto goals = measured_csv(options.out_dir, "lammps-bench/lammps_goals.csv", goals_where)) {
    md << "The issue's goals on these runs (SIER4 against `rigid/nve/small` at equal CPU per ps: each `rigid/nve/small` "
          "point of the chart against SIER4's curve interpolated in log–log at the same cost):\n\n";
    goals_table(md, *goals);
  }
  examples_part(md, options.out_dir);
  md << "To measure again: " << how_to_produce(options.out_dir);
  return w.finish();
}

}  // namespace rotlie::reports
