// The held spin–orbit run, compiled once per scalar: the integrators are instantiated here only
// (each scalar costs about 10 s of compile time).
#include "rotlie/runs/spin_orbit_stepper.hpp"

#include <type_traits>
#include <utility>
#include <vector>

#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/scenes/spin_orbit_odeint.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

template <class T>
struct spin_orbit_stepper<T>::engine {
  virtual ~engine() = default;
  virtual void advance(const T& h, const T& t_next) = 0;  // a splitting's step of h, Odeint to t_next
  virtual bool adaptive() const { return false; }
  virtual void set_step_budget(double) {}
  virtual const T& t() const = 0;
  virtual const models::body_state<T>& state() const = 0;
  virtual long evaluations() const = 0;
  virtual const models::spin_orbit_tide<T>& tide() const = 0;
};

namespace {

// A splitting: its composition and the state it steps (the clock and the cached torques included).
template <class T, class Composition>
struct splitting_engine final : spin_orbit_stepper<T>::engine {
  splitting_engine(const Composition& c, const models::body_state<T>& start) : method(c), x(models::spin_orbit_state(start)) {}
  void advance(const T& h, const T&) override { method.step(x, h); }  // the engine writes the clock (step_clock.hpp)
  const T& t() const override { return x.t; }
  const models::body_state<T>& state() const override { return x.bodies[0].rot; }
  long evaluations() const override { return x.force_evaluations; }
  const models::spin_orbit_tide<T>& tide() const override { return method.system().potential(); }

  Composition method;
  typename Composition::state x;
};

// Boost.Odeint's adaptive stepper, which keeps its step size from one call to the next.
template <class T>
struct odeint_engine final : spin_orbit_stepper<T>::engine {
  odeint_engine(const spin_method& m, const models::spin_orbit_tide<T>& t, const models::body_state<T>& start, const T& h)
      : tide_(t), stepper(tide_, m.ode, T(m.tolerance), m.first_step > 0 ? T(m.first_step) : h), s(start) {}
  void advance(const T&, const T& t_next) override { stepper.advance(s, clock, t_next); }
  bool adaptive() const override { return true; }
  void set_step_budget(double steps) override { stepper.set_step_budget(steps); }
  const T& t() const override { return clock; }
  const models::body_state<T>& state() const override { return s; }
  long evaluations() const override { return stepper.evaluations(); }
  const models::spin_orbit_tide<T>& tide() const override { return tide_; }

  models::spin_orbit_tide<T> tide_;  // the stepper refers to it: declared first
  models::spin_odeint_stepper<T> stepper;
  models::body_state<T> s;
  T clock{};
};

}  // namespace

template <class T>
spin_orbit_stepper<T>::spin_orbit_stepper(const spin_method& m, const models::vec3<T>& I, const T& e, const models::body_state<T>& start,
                                          const T& h)
    : h_(h) {
  const models::spin_orbit_tide<T> tide(I, e);
  if (m.adaptive) {
    // Odeint's norms do not take Boost.Multiprecision's float128 (its value_type recursion): the peer
    // runs in double and long double
    if constexpr (!std::is_floating_point_v<T>) {
      throw bad_input("--integrator " + m.name + " runs in double or long double, not in float128");
    } else {
      engine_ = std::make_unique<odeint_engine<T>>(m, tide, start, h);
    }
    return;
  }
  const std::vector<models::body_kind<T>> kinds{{T(1), I, m.rotor ? &*m.rotor : nullptr}};
  engine_ = models::with_md_integrator<T>(m.splitting, kinds, tide, models::unit_system<T>::natural(),
                                          [&](const auto& method) -> std::unique_ptr<engine> {
                                            using C = std::decay_t<decltype(method)>;
                                            return std::make_unique<splitting_engine<T, C>>(method, start);
                                          });
}

template <class T>
spin_orbit_stepper<T>::~spin_orbit_stepper() = default;
template <class T>
spin_orbit_stepper<T>::spin_orbit_stepper(spin_orbit_stepper&&) noexcept = default;
template <class T>
spin_orbit_stepper<T>& spin_orbit_stepper<T>::operator=(spin_orbit_stepper&&) noexcept = default;

template <class T>
void spin_orbit_stepper<T>::step() {
  engine_->advance(h_, T(k_ + 1) * h_);
  ++k_;
}

template <class T>
void spin_orbit_stepper<T>::jump_to(long k) {
  if (engine_->adaptive()) {
    if (k > k_) engine_->advance(h_, T(k) * h_), k_ = k;
    return;
  }
  while (k_ < k) step();
}

template <class T>
void spin_orbit_stepper<T>::set_step_budget(double steps) {
  engine_->set_step_budget(steps);
}

template <class T>
const T& spin_orbit_stepper<T>::t() const {
  return engine_->t();
}
template <class T>
const models::body_state<T>& spin_orbit_stepper<T>::state() const {
  return engine_->state();
}
template <class T>
long spin_orbit_stepper<T>::evaluations() const {
  return engine_->evaluations();
}
template <class T>
const models::spin_orbit_tide<T>& spin_orbit_stepper<T>::tide() const {
  return engine_->tide();
}

template class spin_orbit_stepper<double>;
template class spin_orbit_stepper<long double>;
template class spin_orbit_stepper<quad>;

}  // namespace rotlie::runs
