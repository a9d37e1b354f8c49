#pragma once
// What the scene entries share: reading an option of a request, the shortest decimal of a number,
// and models' refusals as bad input. The integrator is resolved by runs/methods.hpp.
#include <charconv>
#include <cmath>
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

}  // namespace rotlie::runs::scene_support
