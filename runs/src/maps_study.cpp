// The computations behind the report's map sections (see maps_study.hpp).
#include "rotlie/runs/maps_study.hpp"

#include <cln/real.h>

#include <chrono>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/map_neighbour_check.hpp"
#include "rotlie/runs/map_run.hpp"
#include "rotlie/runs/maps_truth.hpp"
#include "rotlie/runs/maps_truth_csv.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::runs {

computed_map compute_family_map(const std::string& family, int K, const study_progress& progress) {
  computed_map m;
  const auto method = map_method_asked(family_to_map(family), K, false, false);
  m.method = map_method_name(method);
  single_process alone;
  map_run_output out;  // no file: the lines come back in the result
  out.progress = progress;
  auto r = run_map_rank0(plan_map(family, K, method), alone, out);  // with the neighbour check of a screened map
  auto header = map_header(family, K, r.lines.size(), m.method);
  if (r.neighbour_check) header["neighbour_check"] = neighbour_check_record(*r.neighbour_check);
  m.lines = std::move(r.lines);
  m.file_text = header.dump() + "\n";
  for (const auto& line : m.lines) m.file_text += line + "\n";
  m.seconds = r.seconds;
  return m;
}

std::pair<map_check_result, double> timed_map_check(const std::string& family, int K, std::vector<nlohmann::json> bodies,
                                                    std::size_t count, std::uint64_t seed,
                                                    const std::function<void(int done, int of)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  auto r = check_map_lines(family, K, std::move(bodies), count, seed, progress);
  return {std::move(r), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

truth_measurements measure_truth_grid(int K, const study_progress& progress) {
  truth_measurements out;
  const auto bodies = truth_bodies(K);
  out.bodies = bodies.size();
  out.csv = truth_csv_header();
  const double start = models::thread_cpu_seconds();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (progress) progress("body " + std::to_string(k + 1) + " of " + std::to_string(bodies.size()));
    out.csv += truth_csv_rows(measure_body_truth(bodies[k], {"N", "P"}));
  }
  out.cpu_seconds = models::thread_cpu_seconds() - start;
  return out;
}

int mapped_family_cost(const std::string& family) { return solver::family_cost(family); }

std::pair<double, double> grid_moments(int K, int i, int j) {
  const auto g = solver::grid_point(K, i, j);
  return {cln::double_approx(g.body.I[0]), cln::double_approx(g.body.I[1])};
}

}  // namespace rotlie::runs
