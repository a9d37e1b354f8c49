// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// A LAMMPS rigid body in rotlie's frame and back. LAMMPS numbers the principal axes by decreasing
// moment (ex_space has the largest); rotlie by increasing. rotlie's body axes are therefore
// (ez, ey, −ex): increasing moments, and a proper rotation (the sign keeps det Q = +1). Q's columns
// are those axes in the lab frame, G = Qᵀ L the body angular momentum.
#include <array>
#include <cmath>

#include "rotlie/models/rigid_body.hpp"

namespace rotlie::lammps {

/// The moments in rotlie's order; a flat body (water) whose rounded moments cross eq. (77) by an ulp
/// is put back on it (I3 = I1 + I2), as the body it is.
inline std::array<double, 3> rotlie_moments(const double* inertia) {
  std::array<double, 3> I{inertia[2], inertia[1], inertia[0]};
  if (I[2] > I[0] + I[1]) I[2] = I[0] + I[1];
  return I;
}

inline void to_rotlie(const double* ex, const double* ey, const double* ez, const double* angmom, models::body_state<double>& s) {
  for (int i = 0; i < 3; ++i) {
    s.Q(i, 0) = ez[i];
    s.Q(i, 1) = ey[i];
    s.Q(i, 2) = -ex[i];
  }
  for (int k = 0; k < 3; ++k)
    s.G[static_cast<std::size_t>(k)] = s.Q(0, k) * angmom[0] + s.Q(1, k) * angmom[1] + s.Q(2, k) * angmom[2];
}

inline void from_rotlie(const models::body_state<double>& s, double* ex, double* ey, double* ez, double* angmom) {
  for (int i = 0; i < 3; ++i) {
    ez[i] = s.Q(i, 0);
    ey[i] = s.Q(i, 1);
    ex[i] = -s.Q(i, 2);
    angmom[i] = s.Q(i, 0) * s.G[0] + s.Q(i, 1) * s.G[1] + s.Q(i, 2) * s.G[2];
  }
}

/// The free rotation of a linear body (a zero moment, the other two equal): a uniform rotation of the
/// axes about the constant angular velocity w (lab frame) by |w| t (Rodrigues' formula).
inline void rotate_about(const double* w, double t, double* ex, double* ey, double* ez) {
  const double norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (!(norm > 0)) return;
  const double k[3] = {w[0] / norm, w[1] / norm, w[2] / norm};
  const double c = std::cos(norm * t), s = std::sin(norm * t);
  for (double* v : {ex, ey, ez}) {
    const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    const double cross[3] = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]};
    for (int i = 0; i < 3; ++i) v[i] = v[i] * c + cross[i] * s + k[i] * kv * (1 - c);
  }
}

}  // namespace rotlie::lammps
