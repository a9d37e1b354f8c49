#include "rotlie/runs/binary_run.hpp"

#include <cln/rational.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/models/md_trajectory.hpp"
#include "rotlie/runs/binary_estimate.hpp"
#include "rotlie/runs/binary_simulation.hpp"
#include "rotlie/runs/binary_state_file.hpp"
#include "rotlie/runs/binary_units.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {

namespace {

using models::norm;
using models::vec3;
using schemes::message_number;


// The registry's method for the pair, in the form binary_simulation steps it.
binary_method method_named(const std::string& name, const vec3<double>& I1, const vec3<double>& I2) {
  auto r = runs::method_named(name, method_system::binary, std::vector<vec3<double>>{I1, I2});
  binary_method m;
  m.name = name;
  switch (r.kind()) {
    case method_kind::rk4:
      return m.family = binary_method::kind::rk4, m;
    case method_kind::lgvi:
      return m.family = binary_method::kind::lgvi, m;
    case method_kind::adaptive:
      m.family = binary_method::kind::odeint;
      m.ode = r.family->ode;
      m.tolerance = r.tolerance;
      return m;
    case method_kind::tv_splitting:
    case method_kind::kepler_splitting:
      break;
  }
  m.kepler = r.kind() == method_kind::kepler_splitting;
  m.splitting = std::move(r.splitting);
  for (std::size_t b = 0; b < 2 && b < r.rotors.size(); ++b) m.rotor[b] = std::move(r.rotors[b]);
  return m;
}

// The circular start: r along x, the frames aligned (the secondary's long axis at the primary), the
// orbit's rate balancing the mutual pull at that configuration, the secondary synchronous.
models::binary_state<double> circular_start(const models::binary_system<double>& sys, double separation, double primary_spin) {
  models::binary_state<double> x;
  x.r = {separation, 0, 0};
  const double pull = -sys.gravity(x).F[0];
  if (!(pull > 0)) throw bad_input("--separation: the bodies do not attract each other at this separation");
  const double n = std::sqrt(pull / (sys.reduced_mass() * separation));
  x.v = {0, n * separation, 0};
  x.body[0].G = {0, 0, (primary_spin > 0 ? primary_spin : n) * sys.moments(0)[2]};
  x.body[1].G = {0, 0, n * sys.moments(1)[2]};
  return x;
}

}  // namespace

binary_contact::binary_contact(double time, long at_step)
    : std::runtime_error("the bodies touch at t = " + message_number(time) + " s (step " + std::to_string(at_step) + "): the run stops there"),
      t(time),
      step(at_step) {}

binary_unconfirmed_contact::binary_unconfirmed_contact(const binary_contact& seen, const std::string& at_half_step)
    : std::runtime_error("the bodies touch at t = " + message_number(seen.t) + " s (step " + std::to_string(seen.step) + "), but the same run at half the step " +
                         at_half_step + ": the contact may be the step's error; take a smaller step"),
      t(seen.t) {}

models::binary_system<double> binary_setup::system_model() const {
  models::binary_system<double> sys{primary.body, secondary.body, G, order};
  for (const auto& term : terms) sys.add_term(term.second);
  return sys;
}

binary_setup binary_setup_of(const binary_request& given) {
  binary_request r = given;
  binary_setup s;
  // A preset's numbers stay the doubles they are (never through text): each is taken where the
  // request leaves its option empty.
  const binary_system_preset* preset = nullptr;
  if (!r.system.empty()) {
    preset = &binary_system_named(r.system);
    s.system = preset->name;
    if (r.primary.empty()) r.primary = preset->primary;
    if (r.secondary.empty()) r.secondary = preset->secondary;
  }
  const bool own_start = !r.state_file.empty() || !r.state_text.empty();
  const bool preset_density = preset && r.density.empty() && r.mass.empty();
  const bool preset_separation = preset && r.separation.empty() && !own_start;
  const bool preset_period = preset_separation && r.primary_period.empty();
  if (r.primary.empty() || r.secondary.empty()) throw bad_input("--primary and --secondary are required (or --system NAME)");
  s.primary = binary_shape_named(r.primary, "--primary");
  s.secondary = binary_shape_named(r.secondary, "--secondary");
  if (!r.density.empty() && !r.mass.empty()) throw bad_input("--density and --mass exclude each other: give one");
  if (preset_density) {
    s.primary = with_density(s.primary, preset->density1);
    s.secondary = with_density(s.secondary, preset->density2);
  } else if (r.density.empty() && r.mass.empty()) {
    throw bad_input("--density RHO (kg/m3, one or two values) or --mass M1,M2 (kg) is required");
  } else if (!r.density.empty()) {
    const auto rho = positive_numbers(r.density, "--density");
    if (rho.size() > 2) throw bad_input("--density takes one value (both bodies) or two, got '" + one_line(r.density) + "'");
    if (!r.force)
      for (const double x : rho) check_density_units(x, "--density");
    s.primary = with_density(s.primary, rho[0]);
    s.secondary = with_density(s.secondary, rho.back());
  } else {
    const auto m = positive_numbers(r.mass, "--mass");
    if (m.size() != 2) throw bad_input("--mass takes two values M1,M2 in kg, got '" + one_line(r.mass) + "'");
    s.primary = with_mass(s.primary, m[0]);
    s.secondary = with_mass(s.secondary, m[1]);
  }
  s.order = static_cast<int>(integer_in_range(r.order, "--order", 0, models::max_gravity_order));
  s.primary = with_degree(std::move(s.primary), s.order);
  s.secondary = with_degree(std::move(s.secondary), s.order);
  s.G = positive_number(r.G, "--G");
  if (!r.force) check_G_units(s.G, r.G);
  const auto sys = s.system_model();
  if (!r.state_file.empty() && !r.state_text.empty()) throw bad_input("the state is given twice (a file and inline)");
  if (own_start && !r.separation.empty()) throw bad_input("--state and --separation exclude each other: give one");
  if (!r.state_text.empty()) {
    s.start = parse_binary_state(r.state_text, "state", sys);
  } else if (!r.state_file.empty()) {
    s.start = read_binary_state(r.state_file, sys);
  } else if (!r.separation.empty() || preset_separation) {
    const double R = preset_separation ? preset->separation : positive_number(r.separation, "--separation");
    const std::string separation_text = "--separation " + (preset_separation ? message_number(R) : one_line(r.separation)) + " km";
    const double period = preset_period ? preset->primary_period : r.primary_period.empty() ? 0 : positive_number(r.primary_period, "--primary-period");
    if (!r.force && period > 0) check_period_units(period, "--primary-period");
    const double spin = period > 0 ? 2 * std::acos(-1.0) / (3600 * period) : 0;
    if (!r.force) check_size_units(s.primary, s.secondary, R, separation_text);
    if (R <= s.primary.inner_radius + s.secondary.inner_radius || bodies_touch(s.primary, models::mat3<double>::identity(), s.secondary, models::mat3<double>::identity(), {R, 0, 0}))
      throw bad_input(separation_text + ": the bodies overlap (their bounding radii are " + message_number(s.primary.bounding_radius) +
                      " and " + message_number(s.secondary.bounding_radius) + " km)");
    s.start = circular_start(sys, R, spin);
  } else {
    throw bad_input("the start is required: --separation R (km) or --state FILE");
  }
  const bool circular = !r.separation.empty() || preset_separation;
  if (!r.primary_period.empty() && !circular) throw bad_input("--primary-period goes with --separation (a --state file gives omega1)");
  if (!r.force && !circular) check_size_units(s.primary, s.secondary, norm(s.start.r), "--state (|r| = " + message_number(norm(s.start.r)) + " km)");
  if (!r.impulse.empty()) {
    s.impulse = impulse_named(r.impulse, sys, s.start);
    s.start = with_impulse(s.start, *s.impulse);
  }
  s.observe = r.observe;
  s.error_estimate = !r.no_error_estimate;
  {
    const auto bounds = positive_numbers(r.accuracy, "--accuracy");
    if (bounds.size() > 2) throw bad_input("--accuracy takes REL or REL,RAD, got '" + one_line(r.accuracy) + "'");
    s.accuracy_rel = bounds[0], s.accuracy_rad = bounds.size() == 2 ? bounds[1] : 10 * bounds[0];
  }
  // the start: apart, and on an orbit that does not surely collide
  if (bodies_touch(s.primary, s.start.body[0].Q, s.secondary, s.start.body[1].Q, s.start.r))
    throw bad_input("--state: the bodies overlap at the start (|r| = " + message_number(norm(s.start.r)) + " km)");
  {
    const double GM = s.G * sys.total_mass(), d = norm(s.start.r), v2 = models::dot(s.start.v, s.start.v);
    const auto L = models::cross(s.start.r, s.start.v);
    const double energy = v2 / 2 - GM / d, p = models::dot(L, L) / GM;
    const double e = std::sqrt(std::max(0.0, 1 + 2 * energy * p / GM));
    const double pericentre = p / (1 + e);
    const bool reaches = energy < 0 || models::dot(s.start.r, s.start.v) < 0;
    const auto T_given = lie::parse_exact_number(r.T);
    const bool pose_only = T_given && cln::zerop(*T_given);  // --T 0 asks for this pose's values, not its future
    if (reaches && !pose_only && pericentre < s.primary.inner_radius + s.secondary.inner_radius)
      throw bad_input("the orbit's pericentre (" + message_number(pericentre) + " km, e = " + message_number(e) + ") lies within the bodies' inner radii (" +
                      message_number(s.primary.inner_radius + s.secondary.inner_radius) + " km): they collide");
  }
  for (const auto& [name, text] : r.terms) {
    const auto* term = binary_term_named(name);
    if (!term) throw bad_input("'" + one_line(name) + "' is not a force term of binary");
    s.terms.emplace_back(term->name, term->make(real_numbers(with_named_values(*term, text), "--" + term->name), sys));
  }
  if (r.integrator.empty()) throw bad_input("--integrator is required");
  s.method = method_named(r.integrator, sys.moments(0), sys.moments(1));
  if (r.T.empty()) throw bad_input("--T is required (seconds; 0 for the start's values)");
  const auto T_exact = lie::parse_exact_number(r.T);
  if (T_exact && cln::zerop(*T_exact)) {
    s.T = 0, s.steps = 0;
    if (!r.h.empty()) s.h = positive_number(r.h, "--h");
  } else {
    s.T = positive_number(r.T, "--T");
    if (r.h.empty()) throw bad_input("--h is required (seconds) when --T is not 0");
    s.h = positive_number(r.h, "--h");
    s.steps = whole_steps(r.h, r.T, s.h, s.T);
    s.h = s.T / static_cast<double>(s.steps);
  }
  s.every = integer_in_range(r.every, "--every", 0, std::numeric_limits<long>::max());
  if (s.every > 0 && static_cast<double>(s.steps / s.every) > models::max_trajectory_samples)
    throw bad_input("--every " + one_line(r.every) + " keeps " + message_number(static_cast<double>(s.steps / s.every)) +
                    " samples of the trajectory, over the limit of 1e7: take a larger --every");
  return s;
}

namespace {

constexpr double rotation_gap_unstable = 1e-3;       // |QᵀQ − 1| beyond which an attitude is no longer a rotation (RK4 leaves it at its truncation error)
constexpr double angular_momentum_unstable = 1e-3;  // a relative change of L no method that converges makes

// What the energy criterion cannot see: an attitude off the rotations, a conserved angular momentum
// lost (the non-symplectic methods drift in it; a blow-up loses it whole).
void judge_beyond_energy(binary_result& r, const models::binary_system<double>& sys) {
  if (r.check.unstable) return;
  double gap = 0;
  for (int b = 0; b < 2; ++b) {
    const auto P = transpose(r.end.x.body[b].Q) * r.end.x.body[b].Q;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) gap = std::max(gap, std::abs(P(i, k) - (i == k ? 1.0 : 0.0)));
  }
  std::string why;
  if (!(gap <= rotation_gap_unstable)) why = "an attitude is no longer a rotation (|QᵀQ − 1| = " + message_number(gap) + ")";
  else if (!sys.time_dependent() && r.check.max_rel_angular_momentum_error > angular_momentum_unstable)
    why = "the total angular momentum changed by " + message_number(r.check.max_rel_angular_momentum_error) + " of itself";
  if (why.empty()) return;
  r.check.unstable = true;
  r.check.warnings.push_back(why + ": the step is beyond the integrator's stable or accurate range; the result cannot be trusted");
}

// A fixed-step run's contact stands when the state that touched is known to the accuracy asked for:
// the same run at half the step, stepping through, estimates its error at the contact's time.
void confirm_contact(const binary_setup& s, const binary_contact& seen, const models::binary_state<double>& touching, const std::function<bool()>& stop) {
  if (s.method.family == binary_method::kind::odeint) throw seen;  // an adaptive run's error is its tolerance's
  std::string why;
  const auto e = estimate_contact_error(s, seen.step, touching, why, stop);
  if (!e) throw binary_unconfirmed_contact(seen, why);
  if (e->position_rel <= s.accuracy_rel && e->attitude1_rad <= s.accuracy_rad && e->attitude2_rad <= s.accuracy_rad) throw seen;
  throw binary_unconfirmed_contact(seen, "puts the pair elsewhere then (estimated error: position " + message_number(e->position_rel) + " relative, attitudes " +
                                             message_number(e->attitude1_rad) + " and " + message_number(e->attitude2_rad) + " rad)");
}

}  // namespace

binary_result binary_run(const binary_setup& s, const std::function<void(const binary_sample&)>& sample, const std::function<void(double)>& progress,
                         const std::function<bool()>& stop) {
  binary_setup stepped = s;
  if (!(stepped.h > 0)) stepped.h = 1;  // T = 0 without a step: nothing is stepped
  binary_observer observer;
  if (s.observe) stepped.every = 1;  // the observer sees every step; the caller's samples stay every K
  binary_simulation simulation(stepped);
  const auto observed = [&](const binary_sample& x) {
    observer.add(x.t, x.x);
    if (sample && s.every > 0 && std::llround(x.t / stepped.h) % s.every == 0) sample(x);
  };
  try {
    if (s.observe)
      simulation.advance(s.steps, observed, progress, stop);
    else
      simulation.advance(s.steps, sample, progress, stop);
  } catch (const binary_contact& seen) {
    confirm_contact(stepped, seen, simulation.state(), stop);
  }
  if (simulation.steps() < s.steps) throw binary_stopped();
  auto r = simulation.result();
  if (s.observe) r.observables = observer.result(simulation.system(), r.end.x);
  judge_beyond_energy(r, simulation.system());
  if (s.error_estimate && !r.check.unstable) {
    std::string why;
    r.error_estimate = estimate_binary_error(s, r.end.x, why, stop);
    const auto& e = r.error_estimate;
    if (!e && s.steps > 0 && s.method.family != binary_method::kind::odeint) {  // the companions failed: the step is near the method's limit
      r.check.inaccurate = true;
      r.check.warnings.push_back("the error of the final state could not be estimated: " + why + "; take a smaller step");
    }
    if (e && (e->position_rel > s.accuracy_rel || e->velocity_rel > s.accuracy_rel || e->attitude1_rad > s.accuracy_rad || e->attitude2_rad > s.accuracy_rad)) {
      r.check.inaccurate = true;
      r.check.warnings.push_back("the estimated error of the final state (position " + message_number(e->position_rel) + ", velocity " +
                                 message_number(e->velocity_rel) + " relative; attitudes " + message_number(e->attitude1_rad) + " and " +
                                 message_number(e->attitude2_rad) + " rad, from the same method at " + message_number(e->step_ratio) +
                                 "x the step) is beyond the accuracy asked for (" + message_number(s.accuracy_rel) + ", " + message_number(s.accuracy_rad) +
                                 " rad): take a smaller step");
    }
  }
  r.setup = s;
  r.end.t = s.T;
  return r;
}

}  // namespace rotlie::runs
