#pragma once
// A free rotor that runs any ABC or RS scheme table: one step of size t of
// composition<free_rigid_body<T>> (the free rotation inside SIER2/X, SIER4/X and MRDL).
#include "rotlie/models/free_rigid_body.hpp"

namespace rotlie::models {

template <class T>
class table_rotor {
 public:
  /// Throws std::invalid_argument for a table that is not ABC or RS or does not load.
  table_rotor(const schemes::scheme_table& table, const vec3<T>& I) : method_(table, free_rigid_body<T>(I)) {}

  void advance(body_state<T>& s, const T& t) const { method_.step(s, t); }

  const schemes::scheme_table& table() const { return method_.table(); }
  const vec3<T>& moments() const { return method_.system().moments(); }
  /// Rotations about principal axes per free flight (LV section 4.1).
  int rotations() const { return method_.cost(); }

 private:
  composition<free_rigid_body<T>> method_;
};

}  // namespace rotlie::models
