#pragma once
// A fixed Keplerian orbit in closed form, the clock of the spin–orbit scene: units G M = 1 and
// semi-major axis a = 1, so that the mean motion n = 1 and the period is 2π. The orbit lies in the
// inertial xy plane, prograde, with the pericentre on +x at t = 0. Kepler's equation
// M = E − e sin E is solved by Newton's method from Danby's start E₀ = M + 0.85 e sgn(sin M) (which
// converges for every e < 1) to the round-off of the scalar, then
//   r = 1 − e cos E,   cos f = (cos E − e)/r,   sin f = √(1 − e²) sin E / r.
#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rotlie::models {

template <class T>
struct orbit_point {
  T r;            ///< distance to the point mass
  T cos_f, sin_f;  ///< true anomaly f
};

template <class T>
class kepler_orbit {
 public:
  explicit kepler_orbit(const T& e) : e_(e) {
    using std::isfinite;
    using std::sqrt;
    if (!(e >= 0) || !(e < 1) || !isfinite(static_cast<double>(e))) throw std::invalid_argument("the eccentricity must be in [0, 1)");
    root_ = sqrt((1 - e_) * (1 + e_));
  }

  const T& eccentricity() const { return e_; }
  const T& root() const { return root_; }  ///< √(1 − e²)

  /// The mean anomaly reduced to [−π, π].
  static T mean_anomaly(const T& t) {
    using std::round;
    const T two_pi = boost::math::constants::two_pi<T>();
    return t - two_pi * round(t / two_pi);
  }

  /// The eccentric anomaly E of mean anomaly M in [−π, π] (Newton to round-off).
  T eccentric_anomaly(const T& M) const {
    using std::abs;
    using std::cos;
    using std::sin;
    if (e_ == 0) return M;
    T E = M + T(0.85) * e_ * (sin(M) < 0 ? T(-1) : T(1));
    T last = std::numeric_limits<T>::max();
    for (int i = 0; i < 60; ++i) {
      const T dE = (E - e_ * sin(E) - M) / (1 - e_ * cos(E));
      E -= dE;
      // stop once the correction no longer shrinks or is at the round-off of E (|E| ≤ π + 1)
      if (abs(dE) <= 4 * std::numeric_limits<T>::epsilon() || !(abs(dE) < last)) break;
      last = abs(dE);
    }
    return E;
  }

  /// Distance and true anomaly at time t.
  orbit_point<T> at(const T& t) const {
    using std::cos;
    using std::sin;
    const T E = eccentric_anomaly(mean_anomaly(t));
    const T c = cos(E), s = sin(E), r = 1 - e_ * c;
    return {r, (c - e_) / r, root_ * s / r};
  }

 private:
  T e_;
  T root_;  ///< √(1 − e²)
};

}  // namespace rotlie::models
