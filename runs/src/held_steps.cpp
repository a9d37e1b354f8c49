#include "rotlie/runs/held_steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

long held_steps_until(double t, double h, long now, const char* what) {
  if (!std::isfinite(t)) throw std::invalid_argument(std::string(what) + ": the time must be finite");
  const double steps = t / h;
  // t/h is rounded, and so is a t the caller computed as k·h: both within a few ulps of k
  const double slack = std::max(1e-9, 8 * std::numeric_limits<double>::epsilon() * std::abs(steps));
  const double k = std::floor(steps + slack);
  if (!(k <= 1e15)) throw std::invalid_argument(std::string(what) + ": t = " + schemes::message_number(t) + " is beyond 1e15 steps");
  if (k < static_cast<double>(now))
    throw std::invalid_argument(std::string(what) + ": t = " + schemes::message_number(t) + " is before the simulation's time " +
                                schemes::message_number(static_cast<double>(now) * h) + " (step " + std::to_string(now) +
                                "); a held simulation only goes forward");
  return static_cast<long>(k);
}

}  // namespace rotlie::runs
