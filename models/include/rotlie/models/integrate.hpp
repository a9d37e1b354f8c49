#pragma once
// The one integration loop: `steps` steps of size h of a composition from a state, every state
// handed to the observers (error against a reference, conserved quantities, CSV rows). Observers
// are called as obs(k, t, state) after step k (k = 1 … steps, t = k·h) and may return void, or
// bool (false stops the run early: a failure detected, a budget spent).
#include <type_traits>

#include "rotlie/models/scene_contracts.hpp"

namespace rotlie::models {

namespace detail {
template <class Observer, class State, class T>
bool notify(Observer& obs, long k, const T& t, const State& x) {
  if constexpr (std::is_same_v<decltype(obs(k, t, x)), bool>)
    return obs(k, t, x);
  else {
    obs(k, t, x);
    return true;
  }
}
}  // namespace detail

/// Runs the composition; returns the number of steps done (< steps when an observer stopped it).
template <class Composition, class... Observers>
  requires(run_observer<Observers, typename Composition::state, typename Composition::scalar> && ...)
long integrate(const Composition& method, typename Composition::state& x, const typename Composition::scalar& h,
               long steps, Observers&... observers) {
  using T = typename Composition::scalar;
  for (long k = 1; k <= steps; ++k) {
    method.step(x, h);
    if constexpr (sizeof...(Observers) > 0) {
      const T t = h * static_cast<T>(k);  // not accumulated: t_k is exact to one rounding
      if (!(detail::notify(observers, k, t, x) && ...)) return k;
    }
  }
  return steps;
}

}  // namespace rotlie::models
