#include "rotlie/runs/binary_fields.hpp"

#include "rotlie/runs/methods.hpp"

namespace rotlie::runs {

namespace {

using field_kind = binary_field::kind;

binary_field text(std::string name, std::string cli_type, std::string type, std::string python_default, std::string help, std::string binary_request::*member,
                  field_kind kind = field_kind::text) {
  binary_field f;
  f.cli_type = std::move(cli_type);
  f.name = name;
  f.option = "--" + name;
  for (auto& c : f.option)
    if (c == '_') c = '-';
  f.type = kind, f.python_type = std::move(type), f.python_default = std::move(python_default), f.help = std::move(help), f.text = member;
  return f;
}

binary_field flag(std::string name, std::string help, bool binary_request::*member) {
  binary_field f;
  f.name = name, f.option = "--" + name, f.type = field_kind::flag;
  for (auto& c : f.option)
    if (c == '_') c = '-';
  f.python_type = "bool", f.python_default = "False", f.help = std::move(help), f.flag = member;
  return f;
}

std::vector<binary_field> all_fields() {
  std::vector<binary_field> f;
  f.push_back(text("system", "NAME", "str | None", "None", "A named system (didymos): its bodies, densities and start; the options below override it", &binary_request::system));
  f.push_back(text("primary", "SHAPE", "str | None", "None",
                   "ellipsoid:a,b,c (semi-axes in km, a >= b >= c along x, y, z) or polyhedron:FILE (a shape model in km: Wavefront OBJ, or "
                   "'N_vertices N_facets' then vertices and 1-based facets, or ICQ: Q then 6(Q+1)^2 vertices), or gubas:VERTICES,FACETS (GUBAS's CSV pair, in metres)",
                   &binary_request::primary));
  f.push_back(text("secondary", "SHAPE", "str | None", "None", "As primary", &binary_request::secondary));
  f.push_back(text("density", "RHO|RHO1,RHO2", "float | tuple[float, float] | None", "None", "kg/m3: one value for both bodies, or RHO1,RHO2", &binary_request::density, field_kind::numbers));
  f.push_back(text("mass", "M1,M2", "tuple[float, float] | None", "None", "M1,M2 in kg (instead of the density)", &binary_request::mass, field_kind::numbers));
  f.push_back(text("order", "ORDER", "int", "2", "Truncation of the mutual potential by the inertia integrals' total degree: 0 to 16 (0 point masses, 2 MacCullagh)", &binary_request::order, field_kind::integer));
  f.push_back(text("G", "NUMBER", "float | str", "'6.67430e-20'", "Gravitational constant in km3 kg-1 s-2", &binary_request::G, field_kind::number));
  f.push_back(text("separation", "KM", "float | None", "None",
                   "km: a circular mutual orbit in the primary's equatorial plane, frames aligned, the secondary synchronous (its long axis at the "
                   "primary), the rate balancing the mutual pull",
                   &binary_request::separation, field_kind::number));
  f.push_back(text("primary_period", "HOURS", "float | None", "None", "Hours: the primary's spin with the separation (default: synchronous)", &binary_request::primary_period,
                   field_kind::number));
  f.push_back(text("state", "FILE", "str | os.PathLike | dict | BinaryResult | BinarySimulation | None", "None",
                   "A start from a JSON file (or, in Python and a sweep, the object; in Python also a result or simulation whose end it is) with r, v "
                   "(km, km/s), Q1, Q2 (rows), omega1, omega2 (rad/s, body frames): a run's JSON output starts the next",
                   &binary_request::state_file, field_kind::state));
  f.push_back(text("integrator", "NAME", "str", "'SIER4'", method_names_text(method_system::binary) + " (X for both bodies)", &binary_request::integrator));
  f.back().cli_required = true;
  f.push_back(text("h", "SECONDS", "float | None", "None", "The step in seconds (an adaptive method's first trial step and the spacing of its checks)", &binary_request::h,
                   field_kind::number));
  f.push_back(text("T", "SECONDS", "float", "", "Length of the run in seconds, a whole number of steps h; 0 gives the start's values", &binary_request::T, field_kind::number));
  f.back().cli_required = true, f.back().run_only = true;
  f.push_back(text("every", "K", "int | None", "None", "The trajectory every K steps from the start, one sample each (t, r, v, Q1, Q2, omega1, omega2, energy); 0 for none",
                   &binary_request::every, field_kind::integer));
  f.back().run_only = true, f.back().sweep = false;
  f.push_back(text("impulse", "BODY:VALUES", "str | None", "None",
                   "An impulse on one body at the start: BODY:dx,dy,dz (mm/s, inertial) or BODY:beta=B,m=KG,U=KM_S (DART's form: beta m U / M "
                   "against the body's orbital motion); BODY primary or secondary",
                   &binary_request::impulse));
  f.push_back(flag("observe",
                   "Read off every step: the mean orbit period, the secondary's libration (amplitude, mean, period), both spin periods, the "
                   "osculating elements at the end, each body's roll, pitch and yaw in the orbit frame and its spin state (the angle of G off "
                   "the maximum-moment axis, I_d/C, SAM or LAM, tumbling beyond 1 deg) (the JSON's observables)",
                   &binary_request::observe));
  f.back().run_only = true;
  f.push_back(text("accuracy", "REL[,RAD]", "float | tuple[float, float]", "'1e-3,1e-2'",
                   "The error estimate's bounds: REL (position and velocity, relative) or REL,RAD (RAD the attitudes' angle): "
                   "beyond them the run is marked inaccurate",
                   &binary_request::accuracy, field_kind::numbers));
  f.back().run_only = true;
  f.push_back(flag("no_error_estimate",
                   "Skip the error estimate (a fixed-step run is otherwise repeated at twice and four times the step alongside, about 75 % more "
                   "CPU, to see phase errors the energy cannot)",
                   &binary_request::no_error_estimate));
  f.back().run_only = true;
  f.push_back(flag("force", "Run values that look like unit mistakes (G in SI, a density in g/cm3, sizes in metres, a period in seconds)", &binary_request::force));
  return f;
}

}  // namespace

const std::vector<binary_field>& binary_fields() {
  static const std::vector<binary_field> all = all_fields();
  return all;
}

const binary_field* binary_field_named(std::string_view name) {
  for (const auto& f : binary_fields())
    if (f.name == name || std::string_view(f.option).substr(2) == name) return &f;
  return nullptr;
}

}  // namespace rotlie::runs
