#pragma once
// The free rigid body as a system of the composition engine: ABC tables bind A, B, C to the
// rotations about the (permuted) body axes, RS tables bind R and S to the rotations of eqs. (8)–(9),
// with the G²/(2I_m) parts of S gathered into one rotation about G per step (section 3.1.2).
#include <optional>
#include <stdexcept>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/sub_flows.hpp"

namespace rotlie::models {

template <class T>
class free_rigid_body {
 public:
  using scalar = T;
  using state = body_state<T>;
  struct stage {
    int axis = -1;  ///< body axis 0, 1, 2; −1: the rotation about G
    T rate{};       ///< coefficient × (1/I_k or 1/I_k − 1/I_m), or 1/I_m for the rotation about G
  };

  explicit free_rigid_body(const vec3<T>& I) : I_(I) { validate_moments(I_); }

  const vec3<T>& moments() const { return I_; }

  /// The loader has checked the letters of the split; a TV table is for a body under torques.
  void check(const schemes::scheme_table& table) const {
    if (table.splitting == schemes::split::tv)
      throw std::invalid_argument("scheme table " + schemes::printable_text(table.name) +
                                  " splits free flight and kick (TV): the free rotation needs an ABC or RS table");
  }

  stage bind(const schemes::stage& s, const schemes::scheme_table& table) const {
    const T c = parse_scalar<T>(s.value);
    if (table.splitting == schemes::split::abc) {
      const int k = schemes::axis_of_letter(s.part);
      return {k, c / I_[static_cast<std::size_t>(k)]};
    }
    const auto axes = schemes::rs_axes(table);
    const int k = s.part == 'R' ? axes[0] : axes[2];
    return {k, c * (T(1) / I_[static_cast<std::size_t>(k)] - T(1) / I_[static_cast<std::size_t>(axes[1])])};
  }

  void apply(const stage& st, const T& h, state& x) const {
    if (st.axis >= 0)
      rotate_about_axis(x, st.axis, st.rate, h);
    else
      rotate_about_momentum(x, st.rate, h);
  }

  /// RS: Σ of the S coefficients is 1, so the gathered rotation about G runs for the whole step.
  std::optional<stage> step_end(const schemes::scheme_table& table) const {
    if (table.splitting != schemes::split::rs) return std::nullopt;
    return stage{-1, T(1) / I_[static_cast<std::size_t>(schemes::rs_axes(table)[1])]};
  }

  int cost(const schemes::scheme_table& table) const { return schemes::cost_in_rotations(table); }

 private:
  vec3<T> I_;
};

}  // namespace rotlie::models
