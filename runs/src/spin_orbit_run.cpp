#include "rotlie/runs/spin_orbit_run.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/float128.hpp>
#include <cln/real.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/spin_orbit_stepping.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {
namespace {

using quad = boost::multiprecision::float128;

constexpr double max_steps = 2e9;  // T/h: about an hour of SIER2 in double

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

spin_method splitting_named(const std::string& name, const spin_body& body) {
  spin_method m;
  m.name = name;
  try {
    m.splitting = models::md_integrator_named(name);
  } catch (const std::invalid_argument& e) {
    std::string why = e.what();
    const auto odeint = " or odeint-dopri5[:TOL], odeint-rkf78[:TOL])";
    if (why.rfind("unknown integrator", 0) == 0 && why.back() == ')') why = why.substr(0, why.size() - 1) + odeint;
    throw bad_input("--integrator: " + why);
  }
  if (m.splitting.rotor == models::rotor_kind::table) {
    // a reference name, SCHEME:PERM:LABEL solved for this body, or a table file solved for it
    try {
      m.rotor = scheme_named(m.splitting.rotor_table, numeric_body(body.moments), foreign_table::refuse);
    } catch (const bad_input& e) {
      std::string why = e.what();
      if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
      throw bad_input("--integrator " + one_line(name) + ": " + why);
    }
  }
  return m;
}

template <class T>
spin_result run_in(const spin_setup& s) {
  const auto I = spin_moments_in<T>(s.body);
  const T e = T(s.e);
  const auto start = models::spin_orbit_start<T>(I, T(s.theta0), T(s.omega0), T(s.obliquity));
  const T h = boost::math::constants::two_pi<T>() * T(s.T) / T(s.steps);
  const auto out = step_spin_orbit<T>(s.method, I, e, start, h, s.steps);
  spin_result r;
  r.setup = s;
  const models::spin_orbit_tide<T> tide(I, e);
  const auto omega = models::angular_velocity(I, out.state.G);
  for (std::size_t i = 0; i < 9; ++i) r.Q.a[i] = static_cast<double>(out.state.Q.a[i]);
  for (std::size_t i = 0; i < 3; ++i) r.omega_body[i] = static_cast<double>(omega[i]);
  for (double x : r.Q.a)
    if (!std::isfinite(x)) throw std::runtime_error("the integration diverged (non-finite attitude): the step is beyond the integrator's stability limit");
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
  for (const auto& [prefix, kind] : {std::pair<std::string, models::odeint_method>{"odeint-dopri5", models::odeint_method::dopri5},
                                     {"odeint-rkf78", models::odeint_method::rkf78}}) {
    if (name.rfind(prefix, 0) != 0) continue;
    spin_method m;
    m.name = name;
    m.adaptive = true;
    m.ode = kind;
    const std::string rest = name.substr(prefix.size());
    if (rest.empty()) return m;
    if (rest[0] != ':') break;
    m.tolerance = positive_number(rest.substr(1), "--integrator " + one_line(name) + ": the tolerance");
    if (m.tolerance > 1e-2 || m.tolerance < 1e-30)
      throw bad_input("--integrator " + one_line(name) + ": the tolerance must be within 1e-30 … 1e-2");
    return m;
  }
  return splitting_named(name, body);
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
  const double steps = std::round(s.T / s.h);
  if (steps < 1) throw bad_input("--T must be at least one step --h (T = " + one_line(r.T) + " orbits, h = " + one_line(r.h) + ")");
  if (steps > max_steps) throw bad_input("--T/--h is over the limit of 2e9 steps");
  s.steps = static_cast<long>(steps);
  s.theta0 = finite_number(r.theta0, "--theta0");
  s.omega0 = finite_number(r.omega0, "--omega0");
  s.obliquity = finite_number(r.obliquity, "--obliquity");
  s.method = spin_method_named(r.integrator, s.body);
  if (s.method.adaptive && s.scalar == "float128")
    throw bad_input("--integrator " + one_line(r.integrator) + " runs in double or long double, not in float128");
  return s;
}

spin_result spin_run(const spin_setup& s) {
  if (s.scalar == "long-double") return run_in<long double>(s);
  if (s.scalar == "float128") return run_in<quad>(s);
  return run_in<double>(s);
}

}  // namespace rotlie::runs
