#include "rotlie/runs/spin_orbit_run.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/float128.hpp>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/models/md_trajectory.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/spin_orbit_stepping.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {
namespace {

using quad = boost::multiprecision::float128;

// An embedded pair's error estimate is a difference of two results, each rounded to a few ε of the
// state (of size 1 here): a tolerance below 5 ε cannot be met; 1e-18 in long double (9 ε) serves the
// references of the report and the benches.
constexpr double tolerance_floor_eps = 5;
constexpr double unstable_percent = 100;    // the conserved quantity moves as much as the potential does
constexpr double round_off_turn_eps = 1000;  // a step that turns the body by less is lost in round-off
constexpr double round_off_per_step = 10;    // what a step's roundings can add to a sum, in ε
constexpr double rotation_gap_unstable = 1e-3;  // |QᵀQ − 1| beyond which the attitude is no longer a rotation
constexpr long stop_poll_steps = 64;            // how often a fixed-step run asks whether to stop (an Odeint run: every h)

template <class T>
double epsilon_of() {
  return static_cast<double>(std::numeric_limits<T>::epsilon());
}

double epsilon_of_scalar(const std::string& scalar) {
  if (scalar == "long-double") return epsilon_of<long double>();
  if (scalar == "float128") return epsilon_of<boost::multiprecision::float128>();
  return epsilon_of<double>();
}

// The conserved quantity of spin_check, sampled after each step (see spin_orbit_run.hpp).
template <class T>
class conservation_watch {
 public:
  conservation_watch(const models::spin_orbit_tide<T>& tide, const models::body_state<T>& start, const T& h)
      : tide_(tide), jacobi_(tide.orbit().eccentricity() == 0), h_(h) {
    rate_ = jacobi_ ? T(0) : tide_.anisotropic_potential_rate(start.Q, T(0));
    start_ = value(start, T(0));
    low_ = high_ = static_cast<double>(tide_.anisotropic_potential(start.Q, T(0)));
    size_ = magnitude(start, T(0));
  }

  void operator()(long, const T& t, const models::body_state<T>& s) {
    if (!jacobi_) {  // p_t by the trapezoidal rule over the step
      const T rate = tide_.anisotropic_potential_rate(s.Q, t);
      p_t_ -= h_ / 2 * (rate_ + rate);
      rate_ = rate;
    }
    const double change = static_cast<double>(abs_of(value(s, t) - start_));
    if (!(change <= max_change_)) max_change_ = change;  // a NaN stays
    const double v = static_cast<double>(tide_.anisotropic_potential(s.Q, t));
    low_ = std::min(low_, v), high_ = std::max(high_, v);
    size_ = std::max(size_, magnitude(s, t));
  }

  const char* quantity() const { return jacobi_ ? "jacobi" : "extended_hamiltonian"; }
  double start() const { return static_cast<double>(start_); }
  double max_change() const { return max_change_; }
  double fluctuation() const { return high_ - low_; }
  double size() const { return size_; }

 private:
  static T abs_of(const T& x) { return x < 0 ? T(-x) : x; }

  T value(const models::body_state<T>& s, const T& t) const {
    const T kinetic = models::kinetic_energy(tide_.moments(), s.G);
    const T V = tide_.anisotropic_potential(s.Q, t);
    if (jacobi_) return kinetic + V - (s.Q * s.G)[2];
    return kinetic + V + p_t_;
  }

  // the terms' sizes: what round-off acts on
  double magnitude(const models::body_state<T>& s, const T& t) const {
    const T kinetic = models::kinetic_energy(tide_.moments(), s.G);
    const T V = tide_.anisotropic_potential(s.Q, t);
    T m = abs_of(kinetic) + abs_of(V) + (jacobi_ ? abs_of((s.Q * s.G)[2]) : abs_of(p_t_));
    return static_cast<double>(m);
  }

  const models::spin_orbit_tide<T>& tide_;
  bool jacobi_;
  T h_, rate_{}, p_t_{}, start_{};
  double max_change_ = 0, low_ = 0, high_ = 0, size_ = 0;
};

template <class T>
spin_check judged(const conservation_watch<T>& w, const spin_setup& s, const models::vec3<T>& I, const models::body_state<T>& start) {
  spin_check c;
  c.quantity = w.quantity();
  c.start = w.start();
  c.max_change = w.max_change();
  c.potential_fluctuation = w.fluctuation();
  c.change_percent = c.potential_fluctuation > 0 ? 100 * c.max_change / c.potential_fluctuation : std::numeric_limits<double>::infinity();
  const double eps = epsilon_of<T>();
  const auto omega = models::angular_velocity(I, start.G);
  const double turn = std::sqrt(static_cast<double>(omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2])) *
                      2 * boost::math::constants::pi<double>() * s.h;
  c.round_off_floor = turn < round_off_turn_eps * eps && turn > 0;
  if (c.round_off_floor)
    c.warnings.push_back("one step turns the body by " + schemes::message_number(turn / eps) +
                         " ε only: the step's change is lost in round-off (take a larger step or a wider --scalar)");
  const double reach = std::max(1000.0, round_off_per_step * static_cast<double>(s.steps)) * eps * w.size();
  c.unstable = !c.round_off_floor && !(c.max_change <= reach) && !(c.change_percent < unstable_percent);
  if (c.unstable)
    c.warnings.push_back(std::string("the ") + (c.quantity == "jacobi" ? "Jacobi integral" : "extended-phase-space Hamiltonian") +
                         " changed by " + schemes::message_number(c.max_change) + ", " + schemes::message_number(c.change_percent) +
                         " % of the potential's own fluctuation (" + schemes::message_number(c.potential_fluctuation) +
                         "): the step is beyond the integrator's stable or accurate range; the result cannot be trusted");
  return c;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A finite number as typed (decimal or rational, any sign); `what` names the option.
double finite_number(const std::string& text, const std::string& what) {
  const auto x = lie::parse_exact_number(text);
  if (!x) {
    const auto why = why_not_a_number(text);
    if (why == "is not a number") throw bad_input(what + " must be a number such as 0.1 or 1/10, got '" + one_line(text) + "'");
    throw bad_input(what + " '" + one_line(text) + "' " + why);
  }
  const double v = cln::double_approx(*x);
  if (!std::isfinite(v) || std::abs(v) > 1e6) throw bad_input(what + " '" + one_line(text) + "' is outside the range -1e6 … 1e6");
  return v;
}

// What the conserved quantity cannot see: a spin or an energy no longer finite (a NaN in the sum is
// missed when the step is lost in round-off), an attitude off the rotations.
void judge_beyond_conservation(spin_result& r) {
  if (r.check.unstable) return;
  double gap = 0;
  const auto P = transpose(r.Q) * r.Q;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) gap = std::max(gap, std::abs(P(i, k) - (i == k ? 1.0 : 0.0)));
  std::string why;
  if (!std::isfinite(r.omega_body[0] + r.omega_body[1] + r.omega_body[2]) || !std::isfinite(r.energy_end))
    why = "the final spin or energy is no longer finite: the run diverged";
  else if (!(gap <= rotation_gap_unstable))
    why = "the attitude is no longer a rotation (|QᵀQ − 1| = " + schemes::message_number(gap) + ")";
  if (why.empty()) return;
  r.check.unstable = true;
  r.check.warnings.push_back(why + ": the step is beyond the integrator's stable or accurate range; the result cannot be trusted");
}

// The error estimate at twice the step (spin_estimate.hpp) and its verdict.
void judge_accuracy(spin_result& r, const std::function<bool()>& stop) {
  const auto& s = r.setup;
  if (!s.error_estimate || r.check.unstable) return;
  std::string why;
  r.error_estimate = estimate_spin_error(s, r.Q, r.omega_body, why, stop);
  const auto& e = r.error_estimate;
  if (!e && !s.method.adaptive && s.steps > 0) {  // the companions failed: the step is near the method's limit
    r.check.inaccurate = true;
    r.check.warnings.push_back("the error of the final state could not be estimated: " + why + "; take a smaller step");
    return;
  }
  if (!e || (e->attitude_rad <= s.accuracy_rad && e->spin_rate_rel <= s.accuracy_rel)) return;
  r.check.inaccurate = true;
  r.check.warnings.push_back("the estimated error of the final state (attitude " + schemes::message_number(e->attitude_rad) + " rad, spin rate " +
                             schemes::message_number(e->spin_rate_rel) + " relative, from the same method at " +
                             schemes::message_number(e->step_ratio) + "x the step) is beyond the accuracy asked for (" +
                             schemes::message_number(s.accuracy_rel) + ", " + schemes::message_number(s.accuracy_rad) + " rad): take a smaller step");
}

template <class T>
spin_result run_in(const spin_setup& s, const std::function<bool()>& stop) {
  const auto I = spin_moments_in<T>(s.body);
  const T e = T(s.e);
  const auto start = models::spin_orbit_start<T>(I, T(s.theta0), T(s.omega0), T(s.obliquity));
  const T h = boost::math::constants::two_pi<T>() * T(s.T) / T(s.steps);
  const models::spin_orbit_tide<T> tide(I, e);
  conservation_watch<T> watch(tide, start, h);
  spin_result r;
  r.setup = s;
  const auto sample = [&](long k, const T& t, const models::body_state<T>& x) {
    auto& tr = r.trajectory;
    tr.t.push_back(static_cast<double>(k) * s.T / static_cast<double>(s.steps));  // orbits: k steps of T/steps, the last exactly T
    std::array<double, 9> Q{};
    for (std::size_t i = 0; i < 9; ++i) Q[i] = static_cast<double>(x.Q.a[i]);
    tr.Q.push_back(Q);
    const auto w = models::angular_velocity(I, x.G);
    tr.omega_body.push_back({static_cast<double>(w[0]), static_cast<double>(w[1]), static_cast<double>(w[2])});
    tr.energy.push_back(static_cast<double>(models::spin_orbit_energy(tide, x, t)));
  };
  if (s.every > 0) sample(0, T(0), start);
  const long poll = s.method.adaptive ? 1 : stop_poll_steps;
  const auto out = step_spin_orbit<T>(s.method, I, e, start, h, s.steps, [&](long k, const T& t, const models::body_state<T>& x) {
    if (stop && k % poll == 0 && stop()) throw spin_stopped();
    watch(k, t, x);
    if (s.every > 0 && k % s.every == 0) sample(k, t, x);
  });
  const auto omega = models::angular_velocity(I, out.state.G);
  for (std::size_t i = 0; i < 9; ++i) r.Q.a[i] = static_cast<double>(out.state.Q.a[i]);
  for (std::size_t i = 0; i < 3; ++i) r.omega_body[i] = static_cast<double>(omega[i]);
  for (double x : r.Q.a)
    if (!std::isfinite(x)) throw std::runtime_error("the integration diverged (non-finite attitude): the step is beyond the integrator's stability limit");
  r.check = judged(watch, s, I, start);
  r.theta = static_cast<double>(models::spin_angle(out.state));
  r.energy_start = static_cast<double>(models::spin_orbit_energy(tide, start, T(0)));
  r.energy_end = static_cast<double>(models::spin_orbit_energy(tide, out.state, out.t));
  r.cpu_s = out.cpu_s;
  r.evaluations = out.evaluations;
  return r;
}

}  // namespace

const std::vector<spin_body>& spin_bodies() {
  static const std::vector<spin_body> bodies = {
      {"Hyperion", "34021/57125,49096/57125,1", 0.1,
       "uniform ellipsoid 190 x 145 x 114 km: (B-A)/C = 0.264, omega0 = sqrt(3(B-A)/C) = 0.89 (Wisdom, Peale & Mignard 1984)"},
      {"Moon", "9999998563213/10006310000000,10002277/10006310,1", 0.0549,
       "beta = (C-A)/B = 631.0e-6, gamma = (B-A)/C = 227.7e-6 (lunar laser ranging and GRAIL, Williams et al. 2014)"},
      {"Mercury", "34593351/34600000,34596587/34600000,1", 0.2056,
       "C/MR^2 = 0.346 (Margot et al. 2012), J2 = 5.031e-5, C22 = 0.809e-5 (MESSENGER, Smith et al. 2012)"},
  };
  return bodies;
}

spin_body spin_body_named(const std::string& text) {
  for (const auto& b : spin_bodies())
    if (lower(text) == lower(b.name)) return b;
  if (text.find(',') == std::string::npos)
    throw bad_input("--body: unknown body '" + one_line(text) + "' (Hyperion, Moon, Mercury, or moments A,B,C)");
  lie::moments_of_inertia exact;
  try {
    exact = numeric_body(text);
  } catch (const bad_input& e) {
    std::string why = e.what();
    if (why.rfind("--inertia", 0) == 0) why = why.substr(9);
    throw bad_input("--body" + why);
  }
  if (exact.I[0] > exact.I[1] || exact.I[1] > exact.I[2])
    throw bad_input("--body: the moments must be ordered A <= B <= C, got '" + one_line(text) + "'");
  return {text, text, 0, "given"};
}

models::vec3<double> spin_moments(const spin_body& body) { return to_double(numeric_body(body.moments)); }

spin_method spin_method_named(const std::string& name, const spin_body& body) {
  auto r = method_named(name, method_system::spin, {numeric_body(body.moments)});
  spin_method m;
  m.name = name;
  m.adaptive = r.adaptive();
  m.order = r.family->order;
  if (m.adaptive) {
    m.ode = r.family->ode;
    m.tolerance = r.tolerance;
    return m;
  }
  m.splitting = std::move(r.splitting);
  if (!r.rotors.empty()) m.rotor = std::move(r.rotors.front());
  if (m.rotor) m.order = std::min(m.order, m.rotor->order);
  return m;
}

spin_setup spin_setup_of(const spin_request& r) {
  spin_setup s;
  s.body = spin_body_named(r.body);
  s.e = finite_number(r.e, "--e");
  if (!(s.e >= 0 && s.e < 1)) throw bad_input("--e must be in [0, 1) (a closed orbit), got '" + one_line(r.e) + "'");
  if (r.scalar != "double" && r.scalar != "long-double" && r.scalar != "float128")
    throw bad_input("--scalar must be double, long-double or float128, got '" + one_line(r.scalar) + "'");
  s.scalar = r.scalar;
  s.h = positive_number(r.h, "--h");
  s.T = positive_number(r.T, "--T");
  s.steps = whole_steps(r.h, r.T, s.h, s.T);
  s.h = s.T / static_cast<double>(s.steps);  // the step used: h itself, or h to within 1e-9
  s.theta0 = finite_number(r.theta0, "--theta0");
  s.omega0 = finite_number(r.omega0, "--omega0");
  s.obliquity = finite_number(r.obliquity, "--obliquity");
  s.every = integer_in_range(r.every, "--every", 0, std::numeric_limits<long>::max());
  if (s.every > 0 && static_cast<double>(s.steps / s.every) > models::max_trajectory_samples)
    throw bad_input("--every " + one_line(r.every) + " keeps " + schemes::message_number(static_cast<double>(s.steps / s.every)) +
                    " samples of the trajectory, over the limit of 1e7: take a larger --every");
  s.error_estimate = !r.no_error_estimate;
  {
    const auto bounds = positive_numbers(r.accuracy, "--accuracy");
    if (bounds.size() > 2) throw bad_input("--accuracy takes REL or REL,RAD, got '" + one_line(r.accuracy) + "'");
    s.accuracy_rel = bounds[0], s.accuracy_rad = bounds.size() == 2 ? bounds[1] : 10 * bounds[0];
  }
  s.method = spin_method_named(r.integrator, s.body);
  if (s.method.adaptive && s.scalar == "float128")
    throw bad_input("--integrator " + one_line(r.integrator) + " runs in double or long double, not in float128");
  const double floor = tolerance_floor_eps * epsilon_of_scalar(s.scalar);
  if (s.method.adaptive && s.method.tolerance < floor)
    throw bad_input("--integrator " + one_line(r.integrator) + ": the tolerance is below what " + s.scalar + " can reach (5 ε = " +
                    schemes::message_number(floor) + "); take a larger one" + (s.scalar == "double" ? " or --scalar long-double" : ""));
  return s;
}

spin_result spin_run(const spin_setup& s, const std::function<bool()>& stop) {
  spin_result r = s.scalar == "long-double" ? run_in<long double>(s, stop) : s.scalar == "float128" ? run_in<quad>(s, stop) : run_in<double>(s, stop);
  judge_beyond_conservation(r);
  judge_accuracy(r, stop);
  return r;
}

}  // namespace rotlie::runs
