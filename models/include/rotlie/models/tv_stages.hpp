#pragma once
// The stages of a TV table (free flight T, kick V) as the composition engine binds and applies them,
// shared by the systems under torques (torqued_rigid_bodies, the binary splittings). Derived provides
//   void free_flight(const T& t, state&) const   and   void kick(const T& t, state&) const
// and its own check() (what a table that does not fit is told).
#include <optional>

#include "rotlie/models/composition.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::models {

template <class Derived, class T>
class tv_stages {
 public:
  struct stage {
    bool kick = false;  ///< V (true) or T
    T c{};              ///< the stage's coefficient
  };

  stage bind(const schemes::stage& s, const schemes::scheme_table&) const { return {s.part == 'V', parse_scalar<T>(s.value)}; }
  std::optional<stage> step_end(const schemes::scheme_table&) const { return std::nullopt; }

  /// Force evaluations per step (first-same-as-last), the unit of h/f in vZS section V.
  int cost(const schemes::scheme_table& table) const { return schemes::force_evaluations(table); }

  /// The clock's advance of a stage in units of h: a free flight's coefficient, 0 for a kick.
  T time_coefficient(const stage& st) const { return st.kick ? T(0) : st.c; }

  template <class State>
  void apply(const stage& st, const T& h, State& s) const {
    const T t = st.c * h;
    const auto& self = static_cast<const Derived&>(*this);
    if (st.kick)
      self.kick(t, s);
    else
      self.free_flight(t, s);
  }
};

}  // namespace rotlie::models
