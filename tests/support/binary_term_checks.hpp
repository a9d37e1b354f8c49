#pragma once
// What the tests of the binary's added force terms share: a pair of comparable triaxial bodies, a turn
// about an axis, a term's potential alone, and its torques against the potential's derivative.
#include <algorithm>
#include <cmath>

#include "rotlie/runs/binary_run.hpp"
#include "rotlie/runs/binary_terms.hpp"

namespace rotlie::test {

/// The turn by `angle` about the unit axis u (Rodrigues).
inline models::mat3<double> rotation(const models::vec3<double>& u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  models::mat3<double> R;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) R(r, k) = (r == k ? c : 0) + (1 - c) * u[static_cast<std::size_t>(r)] * u[static_cast<std::size_t>(k)];
  R(0, 1) -= s * u[2], R(1, 0) += s * u[2];
  R(0, 2) += s * u[1], R(2, 0) -= s * u[1];
  R(1, 2) -= s * u[0], R(2, 1) += s * u[0];
  return R;
}

/// A triaxial pair of comparable bodies (the torques on both are of one size) on the circular start.
inline runs::binary_setup pair_setup() {
  runs::binary_request r;
  r.primary = "ellipsoid:0.45,0.3,0.2", r.secondary = "ellipsoid:0.35,0.25,0.15", r.density = "2000", r.separation = "1.5";
  r.integrator = "SIER4", r.T = "0";
  return runs::binary_setup_of(r);
}

/// The term's potential alone at (x, t).
inline double term_potential(const runs::registered_term& term, const models::binary_state<double>& x, double t) {
  models::mutual_gravity<double> f;
  term.add(x, t, f);
  return f.U;
}

/// The largest relative difference between each body's torque M (in `f`, the term's values at (x, t))
/// and −∂U/∂δ for a turn δ of that body about each inertial axis, Q → R(δ ê_j) Q (a fourth-order stencil
/// of step 1e-3 rad).
inline double torque_gradient_error(const runs::registered_term& term, const models::binary_state<double>& x, double t,
                                    const models::mutual_gravity<double>& f) {
  const double d = 1e-3;
  double worst = 0;
  for (int body = 0; body < 2; ++body) {
    const auto& M = body == 0 ? f.M1 : f.M2;
    for (std::size_t j = 0; j < 3; ++j) {
      models::vec3<double> axis{};
      axis[j] = 1;
      const auto U = [&](double delta) {
        auto y = x;
        y.body[body].Q = rotation(axis, delta) * x.body[body].Q;
        return term_potential(term, y, t);
      };
      const double slope = (8 * (U(d) - U(-d)) - (U(2 * d) - U(-2 * d))) / (12 * d);
      worst = std::max(worst, std::abs(-slope - M[j]) / models::norm(M));
    }
  }
  return worst;
}

}  // namespace rotlie::test
