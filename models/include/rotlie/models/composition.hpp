#pragma once
// The one composition engine: a scheme table's letters bind to the sub-flows of a *system*, and a
// step runs the stages in time order. The engine knows nothing of rigid bodies; a system says which
// letters it has and what each one does (DESIGN.md, "models/").
//
// A system S provides
//   S::scalar, S::state, S::stage                      the scalar, the state, a part bound to its coefficient
//   void check(const schemes::scheme_table&) const     throws std::invalid_argument if the table does not fit
//   S::stage bind(const schemes::stage&, const schemes::scheme_table&) const
//                                                       a letter and its coefficient (read from the table's
//                                                       decimal text in S::scalar), precomputed once
//   void apply(const S::stage&, const S::scalar& h, S::state&) const
//                                                       the flow of the bound part for the step h
//   std::optional<S::stage> step_end(const schemes::scheme_table&) const
//                                                       a flow applied once after every step (the gathered
//                                                       rotations about G of an RS step), or none
//   int cost(const schemes::scheme_table&) const        cost of one step in the system's unit (C0 for a free
//                                                       rotor, force evaluations f for a body under torques)
// The step itself never allocates.
#include <cstdlib>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::models {

/// A decimal string at the full precision of T (a table's coefficients, a body's moments).
template <class T>
T parse_scalar(const std::string& text) {
  if constexpr (std::is_same_v<T, double>)
    return std::strtod(text.c_str(), nullptr);
  else if constexpr (std::is_same_v<T, long double>)
    return std::strtold(text.c_str(), nullptr);
  else
    return T(text);
}

template <class S>
concept splitting_system = requires(const S& sys, typename S::state& x, const typename S::scalar& h,
                                    const schemes::scheme_table& table, const typename S::stage& st) {
  sys.check(table);
  { sys.bind(table.stages.front(), table) } -> std::same_as<typename S::stage>;
  sys.apply(st, h, x);
  { sys.step_end(table) } -> std::same_as<std::optional<typename S::stage>>;
  { sys.cost(table) } -> std::convertible_to<int>;
};

template <splitting_system System>
class composition {
 public:
  using system_type = System;
  using scalar = typename System::scalar;
  using state = typename System::state;

  composition(const schemes::scheme_table& table, System system) : table_(table), system_(std::move(system)) {
    schemes::check_scheme_table(table_);
    system_.check(table_);
    stages_.reserve(table_.stages.size());
    for (const auto& s : table_.stages) stages_.push_back(system_.bind(s, table_));
    end_ = system_.step_end(table_);
  }

  /// One step of size h (h may be negative: the adjoint of a symmetric scheme is the scheme itself).
  void step(state& x, const scalar& h) const {
    for (const auto& st : stages_) system_.apply(st, h, x);
    if (end_) system_.apply(*end_, h, x);
  }

  const schemes::scheme_table& table() const { return table_; }
  const System& system() const { return system_; }
  int cost() const { return system_.cost(table_); }

 private:
  schemes::scheme_table table_;
  System system_;
  std::vector<typename System::stage> stages_;
  std::optional<typename System::stage> end_;
};

}  // namespace rotlie::models
