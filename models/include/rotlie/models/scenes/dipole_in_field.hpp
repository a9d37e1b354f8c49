#pragma once
// A point dipole fixed in each body, in a uniform field (vZS section V.B): V = −μ·E, no force,
// lab torque τ = μ × E, with μ = Q μ_body. The field's direction keeps L along it: τ ⟂ E.
// Units: μ in e·Å, E in V/Å; e·Å·V/Å = e·V, converted to kcal/mol by qe2f.
#include <cmath>
#include <stdexcept>
#include <vector>

#include "rotlie/models/real_units.hpp"
#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

template <class T>
class dipole_in_field {
 public:
  /// A dipole of size `dipole` (e·Å) along body axis `axis` (0, 1, 2) and the lab field (V/Å).
  /// Throws std::invalid_argument for a non-finite dipole or field or an axis outside 0…2.
  dipole_in_field(const T& dipole, int axis, const vec3<T>& field) : E_(field) {
    using std::isfinite;
    if (!isfinite(static_cast<double>(dipole))) throw std::invalid_argument("the dipole must be a finite number");
    for (const auto& e : field)
      if (!isfinite(static_cast<double>(e))) throw std::invalid_argument("the field must be finite");
    if (axis < 0 || axis > 2) throw std::invalid_argument("the dipole's body axis must be 0, 1 or 2");
    axis_ = axis;
    const T k = real_units::qe2f<T>();
    mu_ = dipole * k;  // μ in kcal/mol per V/Å
  }

  bool acts() const { return true; }

  T evaluate(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque) const {
    T V = 0;
    for (std::size_t n = 0; n < bodies.size(); ++n) {
      const mat3<T>& Q = bodies[n].rot.Q;
      const vec3<T> mu{mu_ * Q(0, axis_), mu_ * Q(1, axis_), mu_ * Q(2, axis_)};  // Q μ_body: column `axis`
      V -= dot(mu, E_);
      force[n] = vec3<T>{};
      torque[n] = cross(mu, E_);
    }
    return V;
  }

  const vec3<T>& field() const { return E_; }
  int axis() const { return axis_; }

 private:
  vec3<T> E_;
  int axis_ = 1;
  T mu_{};  ///< qe2f · dipole
};

}  // namespace rotlie::models
