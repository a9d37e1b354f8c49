#include "rotlie/runs/spin_simulation.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>

#include "rotlie/runs/held_steps.hpp"
#include "rotlie/runs/spin_orbit_stepper.hpp"
#include "rotlie/runs/spin_orbit_stepping.hpp"

namespace rotlie::runs {

// The run in its scalar, behind a scalar-free interface.
class spin_simulation::held {
 public:
  virtual ~held() = default;
  virtual void step() = 0;
  virtual void set_step_budget(double steps) = 0;
  virtual long steps() const = 0;
  virtual models::mat3<double> Q() const = 0;
  virtual models::vec3<double> G() const = 0;
  virtual models::vec3<double> omega_body() const = 0;
  virtual double theta() const = 0;
  virtual double energy() const = 0;
  virtual long evaluations() const = 0;
};

namespace {

template <class T>
models::vec3<double> spin_double(const models::vec3<T>& v) {
  return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
}

template <class T>
class spin_held_in final : public spin_simulation::held {
 public:
  explicit spin_held_in(spin_orbit_stepper<T> run) : run_(std::move(run)) {}
  void step() override { run_.step(); }
  void set_step_budget(double steps) override { run_.set_step_budget(steps); }
  long steps() const override { return run_.steps(); }
  models::mat3<double> Q() const override {
    models::mat3<double> q;
    for (std::size_t i = 0; i < 9; ++i) q.a[i] = static_cast<double>(run_.state().Q.a[i]);
    return q;
  }
  models::vec3<double> G() const override { return spin_double(run_.state().G); }
  models::vec3<double> omega_body() const override { return spin_double(models::angular_velocity(run_.tide().moments(), run_.state().G)); }
  double theta() const override { return static_cast<double>(models::spin_angle(run_.state())); }
  double energy() const override { return static_cast<double>(models::spin_orbit_energy(run_.tide(), run_.state(), run_.t())); }
  long evaluations() const override { return run_.evaluations(); }

 private:
  spin_orbit_stepper<T> run_;
};

// The start and step exactly as spin_run's (spin_orbit_run.cpp): the same bits from the same setup.
template <class T>
std::unique_ptr<spin_simulation::held> spin_held_of(const spin_setup& s) {
  const auto I = spin_moments_in<T>(s.body);
  const auto start = models::spin_orbit_start<T>(I, T(s.theta0), T(s.omega0), T(s.obliquity));
  const T h = boost::math::constants::two_pi<T>() * T(s.T) / T(s.steps);
  return std::make_unique<spin_held_in<T>>(spin_orbit_stepper<T>(s.method, I, T(s.e), start, h));
}

}  // namespace

spin_simulation::spin_simulation(const spin_setup& setup) : setup_(setup) {
  if (setup_.scalar == "long-double")
    held_ = spin_held_of<long double>(setup_);
  else if (setup_.scalar == "float128")
    held_ = spin_held_of<quad>(setup_);
  else
    held_ = spin_held_of<double>(setup_);
}

spin_simulation::~spin_simulation() = default;
spin_simulation::spin_simulation(spin_simulation&&) noexcept = default;
spin_simulation& spin_simulation::operator=(spin_simulation&&) noexcept = default;

void spin_simulation::step() {
  if (setup_.method.adaptive) held_->set_step_budget(adaptive_steps_per_orbit * std::max(1.0, static_cast<double>(steps() + 1) * setup_.h));
  held_->step();
}

void spin_simulation::integrate(double t, const std::function<bool()>& stop) {
  const long target = held_steps_until(t, setup_.h, steps(), "spin_simulation.integrate");
  // the budget spin_run gives a run of this length
  if (setup_.method.adaptive) held_->set_step_budget(adaptive_steps_per_orbit * std::max(1.0, static_cast<double>(target) * setup_.h));
  while (steps() < target) {
    if (stop && stop()) return;
    held_->step();
  }
}

double spin_simulation::t() const { return static_cast<double>(steps()) * setup_.h; }
long spin_simulation::steps() const { return held_->steps(); }
models::mat3<double> spin_simulation::Q() const { return held_->Q(); }
models::vec3<double> spin_simulation::G() const { return held_->G(); }
models::vec3<double> spin_simulation::omega_body() const { return held_->omega_body(); }
double spin_simulation::theta() const { return held_->theta(); }
double spin_simulation::energy() const { return held_->energy(); }
long spin_simulation::evaluations() const { return held_->evaluations(); }

}  // namespace rotlie::runs
