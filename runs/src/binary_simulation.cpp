#include "rotlie/runs/binary_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "rotlie/models/closed_form_rotors.hpp"
#include "rotlie/models/composition.hpp"
#include "rotlie/models/cpu_time.hpp"
#include "rotlie/models/scenes/binary_anchors.hpp"
#include "rotlie/models/scenes/binary_odeint.hpp"
#include "rotlie/models/scenes/binary_splitting.hpp"
#include "rotlie/models/table_rotor.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {

namespace {

using models::norm;
using models::vec3;
using schemes::message_number;

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double round_off_turn_eps = 1000;       // a step that moves the pair by less is lost in round-off
constexpr double round_off_per_step = 10;         // what a step's roundings can add to a sum, in ε
constexpr double max_checks = 1e4;               // the conserved quantities' samples per run
constexpr long open_check_every = 100;           // the same when the run's length is not known
constexpr double adaptive_steps_per_orbit = 1e6;  // an adaptive run's budget (tried steps per mutual orbit)
constexpr double step_grid_slack = 1e-9;          // a target time this close to a step's end reaches it
constexpr long stop_poll_steps = 64;               // how often a run asks whether to stop

}  // namespace

/// One integrator with what it carries between steps; cloned when the simulation is copied.
class binary_stepper {
 public:
  virtual ~binary_stepper() = default;
  virtual std::unique_ptr<binary_stepper> clone() const = 0;
  /// Step number k (from 0) of length h: from time k·h.
  virtual void step(models::binary_state<double>& x, long k, double h) = 0;
  /// Mutual-gravity evaluations over the first `steps` steps.
  virtual long evaluations(long steps) const = 0;
  /// An adaptive method's step budget, from the time it is asked to reach.
  virtual void plan(double) {}
};

namespace {

template <class Derived>
class cloneable_stepper : public binary_stepper {
 public:
  std::unique_ptr<binary_stepper> clone() const override { return std::make_unique<Derived>(static_cast<const Derived&>(*this)); }
};

class rk4_stepper final : public cloneable_stepper<rk4_stepper> {
 public:
  explicit rk4_stepper(const models::binary_system<double>& sys) : rk4_(sys) {}
  void step(models::binary_state<double>& x, long k, double h) override { rk4_.step(x, h, static_cast<double>(k) * h); }
  long evaluations(long steps) const override { return 4 * steps; }

 private:
  models::binary_rk4<double> rk4_;
};

class lgvi_stepper final : public cloneable_stepper<lgvi_stepper> {
 public:
  explicit lgvi_stepper(const models::binary_system<double>& sys) : lgvi_(sys) {}
  void step(models::binary_state<double>& x, long k, double h) override { lgvi_.step(x, h, forces_, valid_, static_cast<double>(k) * h); }
  long evaluations(long steps) const override { return steps + (steps > 0 ? 1 : 0); }

 private:
  models::binary_lgvi<double> lgvi_;
  models::mutual_gravity<double> forces_;  // at the state the next step starts from
  bool valid_ = false;
};

// Odeint's own clock is carried (t + h per step), as it always was.
class odeint_stepper final : public cloneable_stepper<odeint_stepper> {
 public:
  odeint_stepper(const models::binary_system<double>& sys, const binary_setup& s)
      : ode_(sys, s.method.ode, s.method.tolerance, s.h > 0 ? s.h : 1.0),
        period_(2 * std::acos(-1.0) * norm(s.start.r) / std::max(norm(s.start.v), std::numeric_limits<double>::min())) {}
  void plan(double until) override { budget_ = adaptive_steps_per_orbit * (until / period_ + 1); }
  void step(models::binary_state<double>& x, long, double h) override {
    ode_.advance(x, t_, t_ + h);
    if (static_cast<double>(ode_.steps_tried()) > budget_)
      throw std::runtime_error("the adaptive run used its budget of " + message_number(budget_) + " steps by t = " + message_number(t_) +
                               " s: the tolerance asks for more steps than the run can afford (raise it)");
  }
  long evaluations(long) const override { return ode_.evaluations(); }

 private:
  models::binary_odeint<double> ode_;
  double period_, budget_ = 0, t_ = 0;
};

template <class Rotor>
class splitting_stepper final : public cloneable_stepper<splitting_stepper<Rotor>> {
  using splitting = models::binary_splitting<double, Rotor>;

 public:
  splitting_stepper(const schemes::scheme_table& tv, splitting split, const models::binary_state<double>& start)
      : method_(tv, std::move(split)), state_{start} {}
  void step(models::binary_state<double>& x, long k, double h) override {
    state_.x = x;
    state_.t = static_cast<double>(k) * h;
    method_.step(state_, h);
    x = state_.x;
  }
  long evaluations(long steps) const override { return static_cast<long>(method_.cost()) * steps + (steps > 0 ? 1 : 0); }

 private:
  models::composition<splitting> method_;
  models::binary_split_state<double> state_;  // its forces serve the next step's first kick
};

std::unique_ptr<binary_stepper> stepper_for(const binary_setup& s, const models::binary_system<double>& sys) {
  const auto& m = s.method;
  switch (m.family) {
    case binary_method::kind::rk4:
      return std::make_unique<rk4_stepper>(sys);
    case binary_method::kind::lgvi:
      return std::make_unique<lgvi_stepper>(sys);
    case binary_method::kind::odeint:
      return std::make_unique<odeint_stepper>(sys, s);
    case binary_method::kind::splitting:
      break;
  }
  const auto tv = *schemes::reference_scheme(m.splitting.tv_table);
  const auto drift = m.kepler ? models::binary_drift::kepler : models::binary_drift::straight;
  const auto with_rotors = [&](auto rotor_of) -> std::unique_ptr<binary_stepper> {
    using rotor = decltype(rotor_of(0));
    return std::make_unique<splitting_stepper<rotor>>(tv, models::binary_splitting<double, rotor>(sys, rotor_of(0), rotor_of(1), drift), s.start);
  };
  if (!m.splitting.table_rotor())
    return models::with_closed_form_rotor<double>(m.splitting.rotor, [&](auto type) {
      using R = typename decltype(type)::type;
      return with_rotors([&](int b) { return R(sys.moments(b)); });
    });
  return with_rotors([&](int b) {
    if (!m.rotor[b]) throw std::logic_error("binary_simulation: the rotor table was not resolved");
    return models::table_rotor<double>(*m.rotor[b], sys.moments(b));
  });
}

}  // namespace

// The conserved quantities, sampled; CPU spent here is not the method's. With a time-dependent or a
// dissipative term the energy is not conserved: its change alone does not mark the run unstable.
class binary_watch {
 public:
  binary_watch(const models::binary_system<double>& sys, const models::binary_state<double>& start) {
    E0_ = sys.energy(start);
    L0_ = sys.angular_momentum(start);
    U_low_ = U_high_ = sys.forces(start, 0.0).U;
    scale_ = std::abs(sys.kinetic_energy(start)) + std::abs(U_low_);
  }

  void sample(const models::binary_system<double>& sys, const models::binary_state<double>& x, double t) {
    const double before = models::thread_cpu_seconds();
    const double U = sys.forces(x, t).U, E = sys.kinetic_energy(x) + U;
    const auto L = sys.angular_momentum(x);
    const double dL = models::norm(vec3<double>{L[0] - L0_[0], L[1] - L0_[1], L[2] - L0_[2]}) / norm(L0_);
    max_dE_ = std::max(max_dE_, std::isfinite(E) ? std::abs(E - E0_) : std::numeric_limits<double>::infinity());
    max_dL_ = std::max(max_dL_, std::isfinite(dL) ? dL : std::numeric_limits<double>::infinity());
    U_low_ = std::min(U_low_, U), U_high_ = std::max(U_high_, U);
    spent_ += models::thread_cpu_seconds() - before;
  }

  double spent() const { return spent_; }

  binary_check judged(const binary_setup& s, const models::binary_system<double>& sys) const {
    binary_check c;
    c.max_rel_energy_error = max_dE_ / std::abs(E0_);
    c.max_rel_angular_momentum_error = max_dL_;
    c.potential_fluctuation = U_high_ - U_low_;
    double fastest = norm(s.start.v) / norm(s.start.r);
    for (int b = 0; b < 2; ++b) fastest = std::max(fastest, norm(models::angular_velocity(sys.moments(b), s.start.body[b].G)));
    c.round_off_floor = s.steps > 0 && fastest * s.h < round_off_turn_eps * eps;
    if (c.round_off_floor)
      c.warnings.push_back("one step moves the pair by " + message_number(fastest * s.h / eps) + " ε only: the step's change is lost in round-off (take a larger step)");
    const double reach = std::max(1000.0, round_off_per_step * static_cast<double>(s.steps)) * eps * scale_;
    const bool finite = std::isfinite(max_dE_) && std::isfinite(max_dL_);
    const bool conserved = sys.conserves_energy();
    c.unstable = !finite || (conserved && !c.round_off_floor && max_dE_ > reach && max_dE_ >= c.potential_fluctuation && s.steps > 0);
    if (c.unstable)
      c.warnings.push_back(finite ? "the energy changed by " + message_number(max_dE_) + " kg km2 s-2, as much as the mutual potential's own fluctuation (" +
                                        message_number(c.potential_fluctuation) + " kg km2 s-2): the step is beyond the integrator's stable or accurate range; the result cannot be trusted"
                                  : std::string("the energy or the angular momentum is no longer finite: the run diverged; the result cannot be trusted"));
    return c;
  }

 private:
  double E0_, U_low_, U_high_, scale_;
  vec3<double> L0_;
  double max_dE_ = 0, max_dL_ = 0, spent_ = 0;
};

binary_simulation::binary_simulation(const binary_setup& setup, long check_every)
    : setup_(setup), system_(setup.system_model()), x_(setup.start) {
  if (!(setup_.h > 0) || !std::isfinite(setup_.h)) throw std::invalid_argument("the step h must be positive (seconds)");
  check_every_ = check_every > 0 ? check_every
                 : setup_.steps > 0 ? std::max(1L, static_cast<long>(std::ceil(static_cast<double>(setup_.steps) / max_checks)))
                                    : open_check_every;
  stepper_ = stepper_for(setup_, system_);
  watch_ = std::make_unique<binary_watch>(system_, setup_.start);
}

binary_simulation::binary_simulation(const binary_simulation& o)
    : setup_(o.setup_),
      system_(o.system_),
      x_(o.x_),
      steps_(o.steps_),
      check_every_(o.check_every_),
      cpu_s_(o.cpu_s_),
      stepper_(o.stepper_->clone()),
      watch_(std::make_unique<binary_watch>(*o.watch_)) {}

binary_simulation& binary_simulation::operator=(const binary_simulation& o) {
  if (this != &o) {
    binary_simulation copy(o);
    *this = std::move(copy);
  }
  return *this;
}

binary_simulation::binary_simulation(binary_simulation&&) noexcept = default;
binary_simulation& binary_simulation::operator=(binary_simulation&&) noexcept = default;
binary_simulation::~binary_simulation() = default;

double binary_simulation::energy() const { return system_.energy(x_, t()); }

void binary_simulation::step() { advance(1); }

void binary_simulation::integrate(double t, const std::function<void(const binary_sample&)>& sample, const std::function<void(double)>& progress) {
  if (!std::isfinite(t)) throw std::invalid_argument("the time to integrate to must be finite");
  const double now = this->t();
  if (t < now) throw std::invalid_argument("the time " + message_number(t) + " s lies before the simulation's time " + message_number(now) + " s");
  const double target = std::floor(t / setup_.h + step_grid_slack);
  if (target > 9e18) throw std::invalid_argument("the time " + message_number(t) + " s is more steps than a run can count");
  advance(static_cast<long>(target) - steps_, sample, progress);
}

void binary_simulation::advance(long count, const std::function<void(const binary_sample&)>& sample, const std::function<void(double)>& progress,
                                const std::function<bool()>& stop) {
  if (count < 0) throw std::invalid_argument("a simulation does not step backwards");
  const auto& s = setup_;
  const long end = steps_ + count;
  stepper_->plan(static_cast<double>(end) * s.h);
  if (sample && s.every > 0 && steps_ == 0) sample({0.0, x_, system_.energy(x_, 0.0)});
  const long progress_every = std::max(1L, count / 100);
  double sampling = 0;
  const double begin = models::thread_cpu_seconds(), checks_before = watch_->spent();
  for (long k = steps_ + 1; k <= end; ++k) {
    if (stop && k % stop_poll_steps == 0 && stop()) break;
    stepper_->step(x_, k - 1, s.h);
    steps_ = k;
    if (s.stops_at_contact && bodies_touch(s.primary, x_.body[0].Q, s.secondary, x_.body[1].Q, x_.r)) throw binary_contact(static_cast<double>(k) * s.h, k);
    if (k % check_every_ == 0 || k == end) watch_->sample(system_, x_, static_cast<double>(k) * s.h);
    if (progress && (k - (end - count)) % progress_every == 0) progress(static_cast<double>(k - (end - count)) / static_cast<double>(count));
    if (sample && s.every > 0 && k % s.every == 0) {
      const double before = models::thread_cpu_seconds();
      sample({static_cast<double>(k) * s.h, x_, system_.energy(x_, static_cast<double>(k) * s.h)});
      sampling += models::thread_cpu_seconds() - before;
    }
  }
  cpu_s_ += std::max(0.0, models::thread_cpu_seconds() - begin - (watch_->spent() - checks_before) - sampling);
}

binary_result binary_simulation::result() const {
  binary_result out;
  out.setup = setup_;
  out.setup.T = t(), out.setup.steps = steps_;
  out.end = {t(), x_, energy()};
  out.angular_momentum = system_.angular_momentum(x_);
  out.mutual = system_.gravity(x_);
  out.check = watch_->judged(out.setup, system_);
  out.cpu_s = cpu_s_;
  out.evaluations = stepper_->evaluations(steps_);
  return out;
}

}  // namespace rotlie::runs
