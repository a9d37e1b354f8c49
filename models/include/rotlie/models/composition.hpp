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
// A system whose state carries a time t (a time-dependent potential) is a clocked_system when it also says
//   S::scalar time_coefficient(const S::stage&) const   how far the stage advances t, in units of h (0: not)
// and its state holds a step_clock `clock`: the engine then writes t after every stage that advances it from
// the step count and the stage's cumulative coefficient (step_clock.hpp), so that t never drifts.
// The step itself never allocates.
#include <cstdlib>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "rotlie/models/step_clock.hpp"
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

/// A system whose state has a time that its stages advance (see the header comment).
template <class S>
concept clocked_system = requires(const S& sys, const typename S::stage& st, typename S::state& x) {
  { sys.time_coefficient(st) } -> std::convertible_to<typename S::scalar>;
  { x.t } -> std::convertible_to<typename S::scalar>;
  { x.clock } -> std::convertible_to<step_clock<typename S::scalar>>;
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
    if constexpr (clocked_system<System>) bind_clock();
  }

  /// One step of size h (h may be negative: the adjoint of a symmetric scheme is the scheme itself).
  void step(state& x, const scalar& h) const {
    if constexpr (clocked_system<System>) {
      x.clock.begin(x.t, h);
      for (std::size_t j = 0; j < stages_.size(); ++j) {
        system_.apply(stages_[j], h, x);
        set_time(times_[j], x);
      }
      if (end_) {
        system_.apply(*end_, h, x);
        set_time(times_.back(), x);
      }
      if (advances_) x.t = x.clock.close();
    } else {
      for (const auto& st : stages_) system_.apply(st, h, x);
      if (end_) system_.apply(*end_, h, x);
    }
  }

  const schemes::scheme_table& table() const { return table_; }
  const System& system() const { return system_; }
  int cost() const { return system_.cost(table_); }

 private:
  // Where a stage leaves the clock: unchanged, within the step (at its cumulative coefficient), or at the
  // step's end (the last stage that advances it: the coefficients sum to 1, check_scheme_table).
  enum class clock_mark { none, within, end };
  struct stage_time {
    clock_mark mark = clock_mark::none;
    scalar cumulative{};
  };

  void bind_clock() {
    std::vector<typename System::stage> all = stages_;
    if (end_) all.push_back(*end_);
    scalar sum{};
    std::size_t last = all.size();
    for (std::size_t j = 0; j < all.size(); ++j) {
      const scalar c = system_.time_coefficient(all[j]);
      sum += c;
      times_.push_back({c != scalar(0) ? clock_mark::within : clock_mark::none, sum});
      if (c != scalar(0)) last = j;
    }
    if (last < all.size()) times_[last].mark = clock_mark::end, advances_ = true;
  }

  static void set_time(const stage_time& st, state& x) {
    if (st.mark == clock_mark::within) x.t = x.clock.within(st.cumulative);
    else if (st.mark == clock_mark::end) x.t = x.clock.end();
  }

  schemes::scheme_table table_;
  System system_;
  std::vector<typename System::stage> stages_;
  std::optional<typename System::stage> end_;
  std::vector<stage_time> times_;  ///< per stage, then the step end's (clocked systems)
  bool advances_ = false;
};

}  // namespace rotlie::models
