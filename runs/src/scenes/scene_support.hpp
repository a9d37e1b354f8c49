#pragma once
// What the scene entries share: reading an option of a request, the shortest decimal of a number,
// and models' refusals as bad input. The integrator is resolved by runs/methods.hpp.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "rotlie/models/md_trajectory.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/scenes.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs::scene_support {

/// The text of option `name` (run_scene has filled in every default).
inline const std::string& option(const scene_request& r, const std::string& name) { return r.options.at(name); }

/// The shortest decimal that reads back as x (so that long double and float128 read the same number).
inline std::string shortest(double x) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, ec == std::errc() ? end : buf);
}

/// --every K, the trajectory every K steps (every scene takes it).
inline scene_option every_option() {
  return {"--every", "0", "With --json: the trajectory every K steps from the start (its \"trajectory\": times, Q, the spin, energies); 0 for none"};
}

/// --every of a run of `steps` steps: 0 or a whole number of steps, at most max_trajectory_samples samples.
inline long trajectory_every(const scene_request& r, double steps) {
  const long every = integer_in_range(option(r, "--every"), "--every", 0, std::numeric_limits<long>::max());
  if (every > 0 && steps / static_cast<double>(every) + 1 > models::max_trajectory_samples)
    throw bad_input("--every " + std::to_string(every) + " keeps " + shortest(std::floor(steps / static_cast<double>(every)) + 1) +
                    " samples, over the limit of " + shortest(models::max_trajectory_samples) + ": take a larger --every");
  return every;
}

/// Runs f; a std::invalid_argument from the models (a value they refuse) becomes bad_input.
template <class F>
decltype(auto) as_bad_input(F&& f) {
  try {
    return f();
  } catch (const bad_input&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw bad_input(e.what());
  }
}

/// A thermostat's settings as typed (scenes whose integrator may carry -BAOAB, -OBABO or -NHC).
struct thermostat_request {
  double kelvin = 300, friction_per_ps = 1, tau_ps = 0.1;
  std::uint64_t seed = 1;
};

inline scene_option thermostat_option_temperature() {
  return {"--temperature", "", "At a temperature (an integrator with -BAOAB, -OBABO or -NHC): the target in K (default 300)"};
}
inline scene_option thermostat_option_friction() { return {"--friction", "", "Langevin friction per ps (-BAOAB, -OBABO; default 1)"}; }
inline scene_option thermostat_option_tau() { return {"--tau", "", "Nose-Hoover chains' period in ps (-NHC; default 0.1)"}; }

/// --temperature, --friction, --tau and --seed for an integrator with a thermostat; none without one.
/// Each is refused where it would go unused (without a thermostat, --friction with chains, --tau with
/// Langevin), so that a number typed is never silently ignored.
inline std::optional<thermostat_request> read_thermostat(const scene_request& r, const models::md_integrator& integrator) {
  const auto given = [&](const char* name) { return !option(r, name).empty(); };
  if (!integrator.thermostat) {
    for (const char* name : {"--temperature", "--friction", "--tau"})
      if (given(name))
        throw bad_input(std::string(name) + " needs an integrator at a temperature: " + integrator.name + "-BAOAB, -OBABO or -NHC");
    return std::nullopt;
  }
  thermostat_request t;
  const bool chain = *integrator.thermostat == schemes::thermostat_placement::chain;
  if (given("--temperature")) t.kelvin = positive_number(option(r, "--temperature"), "--temperature");
  if (given("--friction")) {
    if (chain) throw bad_input("--friction is the Langevin thermostat's (-BAOAB, -OBABO); " + integrator.name + " takes --tau");
    t.friction_per_ps = positive_number(option(r, "--friction"), "--friction");
  }
  if (given("--tau")) {
    if (!chain) throw bad_input("--tau is the Nose-Hoover chains' (-NHC); " + integrator.name + " takes --friction");
    t.tau_ps = positive_number(option(r, "--tau"), "--tau");
  }
  t.seed = static_cast<std::uint64_t>(integer_in_range(option(r, "--seed"), "--seed", 0, std::numeric_limits<long>::max()));
  if (t.kelvin > 1e5) throw bad_input("--temperature must be at most 1e5 K");
  if (t.friction_per_ps > 1e4) throw bad_input("--friction must be at most 1e4 per ps");
  if (t.tau_ps > 1e6) throw bad_input("--tau must be at most 1e6 ps");
  return t;
}

}  // namespace rotlie::runs::scene_support
