#pragma once
// What the external-body terms share: an orbit's orientation from its angles (degrees), and a body's
// inertia tensor in the inertial frame (the MacCullagh torque's J).
#include <cmath>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs::term_geometry {

inline constexpr double degree = 0.017453292519943295;  // π/180

/// The perifocal axes in the inertial frame of r, R₃(Ω) R₁(i) R₃(ω) applied to x̂ and ŷ: P toward the
/// periapsis, Q along the motion there (angles in degrees).
struct perifocal_axes {
  models::vec3<double> P, Q;
};

inline perifocal_axes perifocal_axes_of(double i_deg, double node_deg, double peri_deg) {
  const double i = i_deg * degree, node = node_deg * degree, peri = peri_deg * degree;
  const double cO = std::cos(node), sO = std::sin(node), ci = std::cos(i), si = std::sin(i), cw = std::cos(peri), sw = std::sin(peri);
  return {{cO * cw - sO * sw * ci, sO * cw + cO * sw * ci, sw * si}, {-cO * sw - sO * cw * ci, -sO * sw + cO * cw * ci, cw * si}};
}

/// J = Q diag(I) Qᵀ: the principal moments I of a body at attitude Q, in the inertial frame.
inline models::mat3<double> inertial_inertia(const models::mat3<double>& Q, const models::vec3<double>& I) {
  models::mat3<double> QI = Q;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) QI(r, c) *= I[static_cast<std::size_t>(c)];
  return QI * transpose(Q);
}

}  // namespace rotlie::runs::term_geometry
