// Issue 24's long runs: the attitude error (rotation angle of Q_refᵀ Q) after 10², 10³, … orbits of
// the exact rotor (SIER4), the best dedicated rotor, the best general composition (RS4-S5) and
// Boost.Odeint's RKF78 at equal CPU, in double, for the regular states of runs::spin_drift_cases().
// The reference is RKF78 in long double at tolerance 1e-18; SIER4 in long double at a step four
// times finer is a second one, and their distance is printed as the floor the errors are read to.
//   spin_drift_bench           10⁴ orbits for the Moon and Mercury, 10³ for Hyperion (about 5 CPU minutes)
//   spin_drift_bench --full    10⁶ orbits for the Moon and Mercury, 10⁵ for Hyperion, the reference at 1e-16
//                              and the second one to 10⁵ orbits (about 3 CPU hours; with both references
//                              of the default run to the end, about 8)
//   --body NAME                one body's case only;  --orbits N  the last checkpoint instead (10², 10³, … up to N)
//   --reference-tolerance T    RKF78's tolerance for the reference (default 1e-18; at 1e-16 it costs half, and
//                              the second reference's distance to it over 10³ Moon orbits is that to 1e-18's within 1 %)
//   --second-until N           the second reference to N orbits only (its cost is the exact rotor in long double)
// CSV rows on stdout (case, method, orbits, angle, cpu_s), then one table per case.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/runs/spin_orbit_drift.hpp"

namespace runs = rotlie::runs;

namespace {

std::vector<long> checkpoints_to(long last) {
  std::vector<long> out;
  for (long n = 100; n <= last; n *= 10) out.push_back(n);
  return out;
}

std::string best_dedicated(const std::string& body) {
  // the best of the cheapest family for Hyperion, R by ||H_R5|| for the near-symmetric bodies (spin_bench)
  return body == "Hyperion" ? "SIER4/N4:ABC:3" : "SIER4/R:CBA:4";
}

}  // namespace

int main(int argc, char** argv) {
  bool full = false;
  std::string only;  // --body NAME: that body's case alone
  long orbits = 0;   // --orbits N: the last checkpoint (a power of ten from 100), instead of the defaults
  std::string tolerance;  // --reference-tolerance T: the long double RKF78's (1e-18; 1e-16 with --full)
  long second_until = -1;  // --second-until N: the second reference's last checkpoint (0: all; 10⁵ with --full)
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--full")
      full = true;
    else if (a == "--body" && i + 1 < argc)
      only = argv[++i];
    else if (a == "--orbits" && i + 1 < argc)
      orbits = std::atol(argv[++i]);
    else if (a == "--reference-tolerance" && i + 1 < argc)
      tolerance = argv[++i];
    else if (a == "--second-until" && i + 1 < argc)
      second_until = std::atol(argv[++i]);
    else {
      std::fprintf(stderr, "usage: spin_drift_bench [--full] [--body Moon|Mercury|Hyperion] [--orbits N] [--reference-tolerance T] [--second-until N]\n");
      return 2;
    }
  }
  if (tolerance.empty()) tolerance = full ? "1e-16" : "1e-18";
  if (second_until < 0) second_until = full ? 100000 : 0;
  const double cpu_start = rotlie::models::thread_cpu_seconds();
  std::printf("case,method,scalar,steps_per_orbit,orbits,angle,cpu_s\n");
  for (const auto& c : runs::spin_drift_cases()) {
    if (!only.empty() && c.body != only) continue;
    const bool hyperion = c.body == "Hyperion";
    const auto checkpoints = checkpoints_to(orbits > 0 ? orbits : hyperion ? (full ? 100000 : 1000) : (full ? 1000000 : 10000));
    if (checkpoints.empty()) {
      std::fprintf(stderr, "spin_drift_bench: --orbits must be at least 100\n");
      return 2;
    }
    const std::string tol = runs::rkf78_tolerance_at_equal_cpu(c, 100);
    const auto ref = runs::spin_track_of(c, "odeint-rkf78:" + tolerance, true, 1, checkpoints);
    std::vector<long> second_checkpoints;
    for (long n : checkpoints)
      if (second_until == 0 || n <= second_until) second_checkpoints.push_back(n);
    const auto second = runs::spin_track_of(c, "SIER4", true, 4 * c.steps_per_orbit, second_checkpoints);
    std::vector<runs::spin_track> tracks;
    for (const std::string& m : std::vector<std::string>{"SIER4", best_dedicated(c.body), "SIER4/RS4-S5-McLachlan:ABC", "odeint-rkf78:" + tol})
      tracks.push_back(runs::spin_track_of(c, m, false, c.steps_per_orbit, checkpoints));
    auto row = [&](const runs::spin_track& t, long spo) {
      for (std::size_t i = 0; i < t.orbits.size(); ++i)
        std::printf("\"%s\",%s,%s,%ld,%ld,%.4Le,%.4e\n", c.label.c_str(), t.method.c_str(), t.long_double ? "long double" : "double", spo,
                    t.orbits[i], runs::attitude_angle(ref.Q[i], t.Q[i]), t.cpu_s[i]);
    };
    row(second, 4 * c.steps_per_orbit);
    for (const auto& t : tracks) row(t, t.method.rfind("odeint", 0) == 0 ? 0 : c.steps_per_orbit);
    std::printf("\n# %s (e = %g): attitude error (rad) against RKF78 in long double at %s; h = 1/%ld orbit; CPU s at the last column\n",
                c.label.c_str(), c.e, tolerance.c_str(), c.steps_per_orbit);
    std::printf("# %-34s", "method");
    for (long n : checkpoints) std::printf(" %10ld", n);
    std::printf(" %9s\n", "cpu_s");
    auto line = [&](const runs::spin_track& t, const std::string& what) {
      std::printf("# %-34s", what.c_str());
      for (std::size_t i = 0; i < ref.orbits.size(); ++i)
        if (i < t.orbits.size())
          std::printf(" %10.2Le", runs::attitude_angle(ref.Q[i], t.Q[i]));
        else
          std::printf(" %10s", "-");
      std::printf(" %9.3g\n", t.cpu_s.back());
    };
    line(second, "(second reference) SIER4 long double h/4");
    for (const auto& t : tracks) line(t, t.method);
    std::printf("# reference cost: RKF78 long double %.3g s, SIER4 long double %.3g s\n\n", ref.cpu_s.back(), second.cpu_s.back());
    std::fflush(stdout);
  }
  std::printf("# total CPU %.1f s\n", rotlie::models::thread_cpu_seconds() - cpu_start);
  return 0;
}
