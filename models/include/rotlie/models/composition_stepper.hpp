#pragma once
// Runs any scheme table on a rigid body: one rotation per stage, each with its precomputed rate,
// and for the RS splitting one rotation about the angular momentum per step (cost (N+1)·C0).
// The table is checked when the stepper is built; the step itself never allocates.
#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

#include "rotlie/models/sub_flows.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::models {

/// A decimal string at the full precision of T.
template <class T>
T parse_scalar(const std::string& text) {
  if constexpr (std::is_same_v<T, double>)
    return std::strtod(text.c_str(), nullptr);
  else if constexpr (std::is_same_v<T, long double>)
    return std::strtold(text.c_str(), nullptr);
  else
    return T(text);
}

template <class T>
class composition_stepper {
 public:
  composition_stepper(const schemes::scheme_table& table, const vec3<T>& I) : table_(table) {
    schemes::check_scheme_table(table);
    validate_moments(I);
    if (table.splitting == schemes::split::abc) {
      for (const auto& s : table.stages) {
        const int k = schemes::axis_of_letter(s.part);
        stages_.push_back({k, parse_scalar<T>(s.value) / I[static_cast<std::size_t>(k)]});
      }
    } else {
      const auto axes = schemes::rs_axes(table);
      const T inverse_middle = T(1) / I[static_cast<std::size_t>(axes[1])];
      for (const auto& s : table.stages) {
        const int k = s.part == 'R' ? axes[0] : axes[2];
        stages_.push_back({k, parse_scalar<T>(s.value) * (T(1) / I[static_cast<std::size_t>(k)] - inverse_middle)});
      }
      momentum_rate_ = inverse_middle;  // Σ of the S coefficients is 1
    }
  }

  void step(body_state<T>& s, const T& h) const {
    for (const auto& st : stages_) rotate_about_axis(s, st.axis, st.rate, h);
    if (momentum_rate_ != 0) rotate_about_momentum(s, momentum_rate_, h);
  }

  const schemes::scheme_table& table() const { return table_; }
  int cost() const { return schemes::cost_in_rotations(table_); }

 private:
  struct compiled_stage {
    int axis;
    T rate;  // coefficient × (1/I_k or 1/I_k − 1/I_m)
  };
  schemes::scheme_table table_;
  std::vector<compiled_stage> stages_;
  T momentum_rate_ = 0;
};

}  // namespace rotlie::models
