// The solving behind the report's section "Dedicated N integrators" (see dedicated_study.hpp).
#include "rotlie/runs/dedicated_study.hpp"

#include <chrono>

#include "rotlie/bch/scheme_word.hpp"

namespace rotlie::runs {

dedicated_study_result dedicated_study(bool quick, const std::function<void(const std::string&)>& progress) {
  const std::vector<std::string> n = {"N1", "N2", "N3", "N4", "N5", "N6", "N7"};
  constexpr int digits = dedicated_study_digits;
  dedicated_study_result out;
  const auto start = std::chrono::steady_clock::now();
  out.sphere_body = lie::parse_moments("sphere"), out.water_body = lie::parse_moments("water");
  out.sphere = solver::solve_dedicated(out.sphere_body, n, {"ABC"}, digits);
  out.water = solver::solve_dedicated(out.water_body, n, bch::permutation_names(), digits);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (quick) return out;
  std::vector<std::string> p;
  for (int i = 1; i <= 15; ++i) p.push_back("P" + std::to_string(i));
  struct family {
    std::string name;
    std::vector<std::string> schemes;
    int paper;
  };
  for (const auto& f : {family{"R", {"R"}, 46}, family{"P", p, 724}}) {
    if (progress) progress("the " + f.name + " family for water (section 3.4)");
    const auto t0 = std::chrono::steady_clock::now();
    auto r = solver::solve_dedicated(out.water_body, f.schemes, bch::permutation_names(), digits);
    out.families.push_back({f.name, f.paper, std::move(r), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
  }
  return out;
}

}  // namespace rotlie::runs
