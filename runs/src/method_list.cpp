#include <cln/dfloat.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <algorithm>
#include <cctype>
#include <limits>

#include "rotlie/models/closed_form_rotors.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace rotlie::runs {

namespace {

using enum method_system;

// An embedded pair cannot meet less than a few ε of the scalar it runs in.
constexpr double tolerance_floor_eps = 5;

// What each system asks of an adaptive method: its tolerance when none is typed and the widest scalar
// it runs in (spin runs Odeint in long double too; binary in double only).
struct adaptive_rule {
  double default_tolerance;
  double widest_epsilon;
  const char* widest;
};

adaptive_rule adaptive_rule_of(method_system s) {
  if (s == binary) return {1e-12, std::numeric_limits<double>::epsilon(), "double"};
  return {1e-10, std::numeric_limits<long double>::epsilon(), "long double"};
}

}  // namespace

const std::vector<method_family>& method_families() {
  using k = method_kind;
  const std::vector<method_system> all = {md, spin, binary};
  // clang-format off
  static const std::vector<method_family> families = {
      {"SIER2", k::tv_splitting, 2, "Strang-TV", "exact", true, {}, all,
       "van Zon & Schofield's Strang-TV splitting with the exact free rotation (their eq. 7)", true},
      {"SIER4", k::tv_splitting, 4, "PEFRL-TV", "exact", true, {}, all,
       "van Zon & Schofield's PEFRL-TV splitting (eq. 8, corrected h5) with the exact free rotation", true},
      {"SIER6", k::tv_splitting, 6, "KahanLi6-TV", "exact", true, {}, all,
       "Kahan & Li's s9odr6a composition of Strang-TV with the exact free rotation", true},
      {"MRDL", k::tv_splitting, 2, "Strang-TV", models::mrdl_rotor_table, false, {}, all,
       "Strang-TV with the planar rotations of Dullweber, Leimkuhler & McLachlan, axes 1-2-3-2-1 (LAMMPS's NO_SQUISH map)"},
      {"MRDL-reversed", k::tv_splitting, 2, "Strang-TV", models::mrdl_reversed_rotor_table, false, {}, all,
       "MRDL with the axes reversed, 3-2-1-2-3 (the full step on the smallest moment)"},
      {"SEJ4", k::tv_splitting, 2, "Strang-TV", "sej4", false, {}, all,
       "Strang-TV with the sej4 rotor (a reconstruction)"},
      {"KEPLER2", k::kepler_splitting, 2, "Strang-TV", "exact", true, {}, {binary},
       "SIER2's composition of H_Kepler + T_rot and U - U0: the point masses' Kepler orbit drifts exactly"},
      {"KEPLER4", k::kepler_splitting, 4, "PEFRL-TV", "exact", true, {}, {binary},
       "SIER4's composition with the Kepler split"},
      {"KEPLER6", k::kepler_splitting, 6, "KahanLi6-TV", "exact", true, {}, {binary},
       "SIER6's composition with the Kepler split"},
      {"RK4", k::rk4, 4, "", "", false, {}, {binary},
       "the classical Runge-Kutta step of the equations of motion (GUBAS's fixed-step anchor)"},
      {"LGVI", k::lgvi, 2, "", "", false, {}, {binary},
       "the Lie-group variational integrator (GUBAS's fixed-step anchor)"},
      {"odeint-rkf78", k::adaptive, 7, "", "", false, models::odeint_method::rkf78, {spin, binary},
       "Boost.Odeint's controlled Runge-Kutta-Fehlberg 7(8), TOL absolute and relative"},
      {"odeint-dopri5", k::adaptive, 5, "", "", false, models::odeint_method::dopri5, {spin, binary},
       "Boost.Odeint's controlled Dormand-Prince 5(4), TOL absolute and relative"},
  };
  // clang-format on
  return families;
}

bool method_family::steps(method_system s) const { return std::find(systems.begin(), systems.end(), s) != systems.end(); }

int method_family::force_evaluations() const {
  switch (kind) {
    case method_kind::tv_splitting:
    case method_kind::kepler_splitting:
      return schemes::force_evaluations(*schemes::reference_scheme(tv_table));
    case method_kind::rk4:
      return 4;
    case method_kind::lgvi:
      return 1;
    case method_kind::adaptive:
      break;
  }
  return 0;
}

std::vector<std::string> method_family::forms() const {
  if (kind == method_kind::adaptive) return {name + "[:TOL]"};
  if (takes_rotor) return {name, name + "/X"};
  return {name};
}

const std::vector<method_system>& method_systems() {
  static const std::vector<method_system> systems = {md, spin, binary};
  return systems;
}

std::string system_name(method_system s) {
  switch (s) {
    case md:
      return "md";
    case spin:
      return "spin";
    case binary:
      return "binary";
  }
  return "";
}

std::optional<method_system> system_named(const std::string& name) {
  for (auto s : method_systems())
    if (system_name(s) == name) return s;
  return std::nullopt;
}

double default_tolerance(method_system s) { return adaptive_rule_of(s).default_tolerance; }

std::string rotor_values_text() {
  std::string text;
  for (const auto& r : models::closed_form_rotor_names()) text += r + ", ";
  return text + "a reference scheme (RS4-S5-McLachlan:CBA), SCHEME:PERM:LABEL solved for the body, or a scheme-table file";
}

std::string method_names_text(method_system s) {
  // the plain names, then FAMILY/X, then the adaptive ones: the order a reader looks them up in
  std::vector<std::string> plain, with_rotor, adaptive;
  for (const auto& f : method_families()) {
    if (!f.steps(s)) continue;
    const auto forms = f.forms();
    (f.kind == method_kind::adaptive ? adaptive : plain).push_back(forms.front());
    if (forms.size() > 1) with_rotor.push_back(forms.back());
  }
  std::string text;
  for (const auto* list : {&plain, &with_rotor, &adaptive})
    for (const auto& n : *list) text += (text.empty() ? "" : ", ") + n;
  if (!with_rotor.empty()) text += "; X a rotor: " + rotor_values_text();
  if (s == method_system::md) text += "; at a temperature: any splitting with -BAOAB, -OBABO (Langevin) or -NHC (Nose-Hoover chains), e.g. SIER2-BAOAB";
  if (!adaptive.empty()) text += "; default TOL " + schemes::message_number(default_tolerance(s));
  return text;
}

lie::moments_of_inertia exact_moments(const models::vec3<double>& I) {
  lie::moments_of_inertia m;
  for (std::size_t i = 0; i < 3; ++i) m.I[i] = cln::rational(cln::cl_R(cln::cl_DF(I[i])));
  return m;
}

free_rotor free_rotor_named(const std::string& text, const lie::moments_of_inertia& body, const std::string& what, foreign_table policy,
                            const warning_sink& warn) {
  if (models::is_closed_form_rotor(text)) return {text, std::nullopt};
  free_rotor r;
  try {
    r.table = scheme_named(text, body, policy, warn);
  } catch (const bad_input& e) {
    std::string why = e.what();
    if (why.rfind("--scheme: ", 0) == 0) why = why.substr(10);
    throw bad_input(what + ": " + why);
  }
  if (r.table->splitting == schemes::split::tv)  // the free rotation needs ABC or RS (free_rigid_body::check)
    throw bad_input(what + ": " + one_line(text) + " is a TV table (it splits free flight and kick, an integrator): the free rotation needs an ABC or RS table");
  return r;
}

resolved_method method_named(const std::string& text, method_system system, const std::vector<lie::moments_of_inertia>& bodies) {
  const auto unknown = [&](const std::string& why) {
    return bad_input("--integrator: " + why + " (" + system_name(system) + ": " + method_names_text(system) + ")");
  };
  resolved_method m;
  m.name = text;
  // odeint-METHOD[:TOL]
  for (const auto& f : method_families()) {
    if (f.kind != method_kind::adaptive || (text != f.name && text.rfind(f.name + ":", 0) != 0)) continue;
    if (!f.steps(system)) throw unknown(f.name + " does not step " + system_name(system));
    const auto rule = adaptive_rule_of(system);
    m.family = &f;
    m.tolerance = rule.default_tolerance;
    if (text.size() > f.name.size())
      m.tolerance = positive_number(text.substr(f.name.size() + 1), "--integrator " + one_line(text) + ": the tolerance");
    const double floor = tolerance_floor_eps * rule.widest_epsilon;
    if (m.tolerance > 1e-2 || m.tolerance < floor) {
      std::string note = std::string("5 ε of ") + rule.widest;
      if (rule.widest_epsilon != std::numeric_limits<double>::epsilon())
        note += "; in double the floor is " + schemes::message_number(tolerance_floor_eps * std::numeric_limits<double>::epsilon());
      throw bad_input("--integrator " + one_line(text) + ": the tolerance must be within " + schemes::message_number(floor) + " … 1e-2 (" + note + ")");
    }
    return m;
  }
  // FAMILY[/ROTOR][-THERMOSTAT]; a table file's path may hold further '/'
  std::optional<schemes::thermostat_placement> thermostat;
  std::string plain = text;
  for (const auto& [suffix, placement] : {std::pair{"-BAOAB", schemes::thermostat_placement::middle},
                                          std::pair{"-OBABO", schemes::thermostat_placement::ends},
                                          std::pair{"-NHC", schemes::thermostat_placement::chain}}) {
    const std::string tail = suffix;
    if (plain.size() > tail.size() && plain.compare(plain.size() - tail.size(), tail.size(), tail) == 0) {
      thermostat = placement;
      plain.resize(plain.size() - tail.size());
      break;
    }
  }
  const auto slash = plain.find('/');
  const std::string head = plain.substr(0, slash);
  const auto& all = method_families();
  const auto f = std::find_if(all.begin(), all.end(), [&](const method_family& x) { return x.kind != method_kind::adaptive && x.name == head; });
  if (f == all.end() || !f->steps(system)) throw unknown("unknown integrator '" + one_line(text) + "'");
  if (slash != std::string::npos && !f->takes_rotor) throw unknown(f->name + " takes no rotor, got '" + one_line(text) + "'");
  if (thermostat && (system != method_system::md || f->kind != method_kind::tv_splitting))
    throw unknown("a thermostat (-BAOAB, -OBABO, -NHC) goes on a splitting of md's bodies, got '" + one_line(text) + "'");
  m.family = &*f;
  if (f->kind != method_kind::tv_splitting && f->kind != method_kind::kepler_splitting) return m;
  const std::string rotor = slash == std::string::npos ? f->rotor : plain.substr(slash + 1);
  if (rotor.empty() || rotor.find_first_of(" \t\r\n") != std::string::npos)
    throw bad_input("--integrator '" + one_line(text) + "': " + head + "/ needs a scheme table name or file, e.g. " + head + "/RS4-S5-McLachlan:CBA");
  m.splitting = models::md_integrator_of(text, f->tv_table, rotor, f->force_evaluations());
  m.splitting.thermostat = thermostat;
  if (!m.splitting.table_rotor()) return m;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    try {
      m.rotors.push_back(free_rotor_named(rotor, bodies[b], "--integrator " + one_line(text)).table);
    } catch (const bad_input& e) {
      if (b == 0) throw;
      throw bad_input(std::string("the secondary: ") + e.what());  // the binary's second body
    }
  }
  return m;
}

resolved_method method_named(const std::string& text, method_system system, const std::vector<models::vec3<double>>& bodies) {
  std::vector<lie::moments_of_inertia> exact;
  for (const auto& I : bodies) exact.push_back(exact_moments(I));
  return method_named(text, system, exact);
}

std::string lammps_style_of(const method_family& f) {
  std::string lower = f.name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return "rigid/" + lower + "/small";
}

const method_family* lammps_style_family(const std::string& style) {
  for (const auto& f : method_families())
    if (f.lammps_style && lammps_style_of(f) == style) return &f;
  return nullptr;
}

}  // namespace rotlie::runs
