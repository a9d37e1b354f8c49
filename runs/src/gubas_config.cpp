#include "rotlie/runs/gubas_config.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/runs/binary_bodies.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/rotation_check.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

namespace {

using models::mat3;
using models::vec3;

constexpr std::size_t config_file_limit = std::size_t(1) << 20;

// Every option GUBAS's driver reads (hou_config_funcs.py), by section, lower case as configparser keeps them.
const std::map<std::string, std::set<std::string>>& known_options() {
  static const auto known = [] {
    std::map<std::string, std::set<std::string>> k;
    k["Gravity Parameter"] = {"g"};
    auto& ic = k["Initial Conditions"];
    ic.insert("fahnestock input file flag");
    for (const char* axis : {"x", "y", "z"}) {
      for (const char* what : {"relative position ", "relative velocity ", "primary angular velocity ", "secondary angular velocity "}) ic.insert(what + std::string(axis));
    }
    for (const char* frames : {"b into a", "a into n"}) {
      for (int i = 1; i <= 3; ++i)
        for (int j = 1; j <= 3; ++j) ic.insert(std::string(frames) + " (" + std::to_string(i) + "," + std::to_string(j) + ")");
      ic.insert(std::string(frames) + " euler flag");
      ic.insert(std::string(frames) + " euler 1 x"), ic.insert(std::string(frames) + " euler 2 y"), ic.insert(std::string(frames) + " euler 3 z");
    }
    k["Integration Settings"] = {"start time", "final time", "integrator flag", "fixed time step", "absolute tolerance"};
    k["Output Settings"] = {"post processing", "fixed output frequency", "specified time list filename", "case name"};
    auto& body = k["Body Model Definitions"];
    body.insert("inertia integral generation flag");
    for (const std::string b : {"primary ", "secondary "})
      for (const char* what : {"shape flag", "semi-major axis", "semi-intermediate axis", "semi-minor axis", "vertex file", "tetrahedron file", "density"})
        body.insert(b + what);
    k["Mutual Gravity Expansion Parameters"] = {"gravity expansion truncation order", "primary inertia integral truncation order",
                                                "secondary inertia integral truncation order"};
    k["Additional Forces and Perturbations"] = {
        "flyby", "planetary mass", "semimajor axis", "eccentricity", "inclination", "raan", "argument of periapsis", "flyby time",
        "heliocentric orbit", "sun mass", "heliocentric semimajor axis", "heliocentric eccentricity", "heliocentric inclination", "heliocentric raan",
        "heliocentric argument of periapsis", "time of periapsis passage", "solar gravity", "solar orbit radius", "au definition", "solar mass",
        "tidal torque", "primary love number", "secondary love number", "primary reference radius", "secondary reference radius",
        "primary tidal lag angle", "secondary tidal lag angle"};
    return k;
  }();
  return known;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A number as rotlie's options take it: the shortest text that reads back as the same double.
std::string text_of(double x) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, end);
}

// The file's options, checked against what GUBAS reads, and typed access to them.
class config {
 public:
  config(const std::string& text, std::string where) : where_(std::move(where)) {
    std::istringstream in(text);
    std::string line, section;
    long n = 0;
    while (std::getline(in, line)) {
      ++n;
      const auto t = trimmed(line);
      if (t.empty() || t[0] == '#' || t[0] == ';') continue;
      const auto refuse = [&](const std::string& why) { throw bad_input(where_ + ", line " + std::to_string(n) + ": " + why); };
      if (t.front() == '[') {
        if (t.back() != ']') refuse("a section line is [NAME]");
        section = t.substr(1, t.size() - 2);
        if (!known_options().count(section)) refuse("[" + one_line(section) + "] is not a section of GUBAS's configuration");
        if (!sections_.insert(section).second) refuse("the section [" + one_line(section) + "] is given twice");
        continue;
      }
      const auto colon = t.find_first_of(":=");
      if (colon == std::string::npos) refuse("'" + one_line(t) + "' is neither a [section] nor an 'option: value' line");
      if (section.empty()) refuse("an option before the first [section]");
      const auto key = lower(trimmed(t.substr(0, colon)));
      if (!known_options().at(section).count(key))
        refuse("GUBAS option '" + one_line(trimmed(t.substr(0, colon))) + "' is not one GUBAS reads in [" + section + "]");
      if (!values_.emplace(key, entry{trimmed(t.substr(colon + 1)), n, trimmed(t.substr(0, colon))}).second)
        refuse("GUBAS option '" + one_line(trimmed(t.substr(0, colon))) + "' is given twice");
    }
  }

  bool has(const std::string& key) const { return values_.count(lower(key)) > 0; }

  const std::string& text(const std::string& key) const {
    const auto found = values_.find(lower(key));
    if (found == values_.end()) throw bad_input(where_ + ": GUBAS option '" + key + "' is missing");
    return found->second.value;
  }

  // The value times 10^shift, rounded once from the decimal (391.30 m is 0.3913 km, not 391.3/1000).
  double number(const std::string& key, int shift = 0) const {
    const auto& t = text(key);
    double x = 0;
    const std::size_t sign = !t.empty() && t[0] == '+' ? 1 : 0;
    const auto [end, error] = std::from_chars(t.data() + sign, t.data() + t.size(), x);
    if (error != std::errc() || end != t.data() + t.size() || t.empty() || !std::isfinite(x))
      refuse(key, "'" + one_line(t) + "' is not a finite number");
    if (shift == 0 || x == 0) return x;
    const auto e = t.find_first_of("eE");
    long exponent = 0;
    if (e != std::string::npos) std::from_chars(t.data() + e + 1 + (t[e + 1] == '+' ? 1 : 0), t.data() + t.size(), exponent);
    const std::string shifted = t.substr(sign, e == std::string::npos ? std::string::npos : e - sign) + "e" + std::to_string(exponent + shift);
    double y = 0;
    std::from_chars(shifted.data(), shifted.data() + shifted.size(), y);
    if (!std::isfinite(y) || y == 0) refuse(key, "'" + one_line(t) + "' is out of range in rotlie's units");
    return y;
  }

  long integer(const std::string& key) const {
    const auto& t = text(key);
    long x = 0;
    const std::size_t sign = !t.empty() && t[0] == '+' ? 1 : 0;
    const auto [end, error] = std::from_chars(t.data() + sign, t.data() + t.size(), x);
    if (error != std::errc() || end != t.data() + t.size() || t.empty()) refuse(key, "'" + one_line(t) + "' is not a whole number");
    return x;
  }

  // configparser's booleans: 1, yes, true, on and 0, no, false, off
  bool flag(const std::string& key) const {
    const auto t = lower(text(key));
    if (t == "1" || t == "yes" || t == "true" || t == "on") return true;
    if (t == "0" || t == "no" || t == "false" || t == "off") return false;
    refuse(key, "'" + one_line(text(key)) + "' is not a flag (1 or 0)");
    return false;
  }

  [[noreturn]] void refuse(const std::string& key, const std::string& why) const {
    const auto found = values_.find(lower(key));
    const std::string line = found == values_.end() ? "" : ", line " + std::to_string(found->second.line);
    throw bad_input(where_ + line + ": GUBAS option '" + key + "' " + why);
  }

  const std::string& where() const { return where_; }

 private:
  struct entry {
    std::string value;
    long line;
    std::string written;
  };
  std::string where_;
  std::set<std::string> sections_;
  std::map<std::string, entry> values_;
};

vec3<double> vector_of(const config& c, const std::string& stem, int shift) {
  return {c.number(stem + " X", shift), c.number(stem + " Y", shift), c.number(stem + " Z", shift)};
}

// GUBAS's attitude from `frames` ("B into A"): the matrix by its entries, or with the Euler flag the
// 1-2-3 angles (rad) as its driver turns them into a matrix.
mat3<double> attitude_of(const config& c, const std::string& frames) {
  mat3<double> C;
  if (c.flag(frames + " Euler Flag")) {
    const double t1 = c.number(frames + " Euler 1 X"), t2 = c.number(frames + " Euler 2 Y"), t3 = c.number(frames + " Euler 3 Z");
    const double c1 = std::cos(t1), s1 = std::sin(t1), c2 = std::cos(t2), s2 = std::sin(t2), c3 = std::cos(t3), s3 = std::sin(t3);
    const double M[3][3] = {{c2 * c3, s1 * s2 * c3 + c1 * s3, -c1 * s2 * c3 + s1 * s3},
                            {-c2 * s3, -s1 * s2 * s3 + c1 * c3, c1 * s2 * s3 + s1 * c3},
                            {s2, -s1 * c2, c1 * c2}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) C(i, j) = M[j][i];  // the driver's matrix is the transpose of M
    return C;
  }
  double entries[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      entries[3 * i + j] = C(i, j) = c.number(frames + " (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ")");
  if (const auto why = rotation_problem(entries, 1e-9); !why.empty())
    throw bad_input(c.where() + ": GUBAS options '" + frames + " (i,j)' do not form a rotation (" + why + ")");
  return C;
}

// One body's shape as a rotlie spec: a sphere or an ellipsoid (semi-axes in m), or GUBAS's files.
std::string shape_of(const config& c, const std::string& body, const std::filesystem::path& folder) {
  const long kind = c.integer(body + " Shape Flag");
  if (kind == 0 || kind == 1) {
    const double a = c.number(body + " Semi-Major Axis", -3);  // m to km
    const double b = kind == 0 ? a : c.number(body + " Semi-Intermediate Axis", -3), d = kind == 0 ? a : c.number(body + " Semi-Minor Axis", -3);
    if (!(a > 0 && b > 0 && d > 0)) c.refuse(body + " Semi-Major Axis", "and its semi-axes must be positive");
    if (!(a >= b && b >= d))
      c.refuse(body + " Semi-Major Axis", "and its semi-intermediate and semi-minor axes must not grow (rotlie's ellipsoid has a >= b >= c along x, y, z)");
    return "ellipsoid:" + text_of(a) + "," + text_of(b) + "," + text_of(d);
  }
  if (kind == 2) {
    const auto file = [&](const std::string& key) {
      const std::filesystem::path p = c.text(key);
      return (p.is_absolute() ? p : folder / p).string();
    };
    const auto vertices = file(body + " Vertex File"), facets = file(body + " Tetrahedron File");
    if (vertices.find(',') != std::string::npos) c.refuse(body + " Vertex File", "names a path with a comma, which rotlie's gubas:VERTICES,FACETS cannot hold");
    return "gubas:" + vertices + "," + facets;
  }
  c.refuse(body + " Shape Flag", "= " + std::to_string(kind) + " is none of GUBAS's shapes (0 sphere, 1 ellipsoid, 2 polyhedron)");
}

// The one order both bodies are truncated at: GUBAS's driver runs max(primary's, secondary's) and raises
// a polyhedron's to it; a sphere's or an ellipsoid's own lower order (its higher integrals set to zero)
// has no rotlie counterpart, and an expansion order that the driver would replace is refused as unclear.
long order_of(const config& c, bool primary_polyhedron, bool secondary_polyhedron) {
  const long n = c.integer("Gravity Expansion Truncation Order"), nA = c.integer("Primary Inertia Integral Truncation Order"),
             nB = c.integer("Secondary Inertia Integral Truncation Order");
  const long order = std::max(nA, nB);
  if (n != order)
    c.refuse("Gravity Expansion Truncation Order", "(" + std::to_string(n) + ") differs from the larger of the bodies' truncation orders (" + std::to_string(order) +
                                                       "), which GUBAS's driver runs instead: make them agree");
  if (!primary_polyhedron && nA != order)
    c.refuse("Primary Inertia Integral Truncation Order", "(" + std::to_string(nA) + ") below the expansion's " + std::to_string(order) +
                                                              " (a body truncated at an order of its own) has no rotlie counterpart: rotlie truncates both bodies at one order");
  if (!secondary_polyhedron && nB != order)
    c.refuse("Secondary Inertia Integral Truncation Order", "(" + std::to_string(nB) + ") below the expansion's " + std::to_string(order) +
                                                                " (a body truncated at an order of its own) has no rotlie counterpart: rotlie truncates both bodies at one order");
  return order;
}

// The forces GUBAS adds on request, each refused when switched on (absent: off, as in its older files).
void refuse_perturbations(const config& c) {
  const std::pair<const char*, const char*> terms[] = {
      {"Flyby", "a planet's flyby on a Kepler orbit; rotlie's --flyby takes q, v_inf and the angles in degrees: give it by hand"},
      {"Heliocentric Orbit", "the Sun on the binary's heliocentric Kepler orbit; rotlie's --sun takes the elements in AU and degrees: give it by hand"},
      {"Solar Gravity", "Hill's solar tide on a circular orbit"},
      {"Tidal Torque", "tides of a constant lag angle; rotlie's --tides has a constant time lag"}};
  for (const auto& [key, meaning] : terms)
    if (c.has(key) && c.flag(key)) c.refuse(key, "(" + std::string(meaning) + ") has no rotlie counterpart");
}

nlohmann::json rows(const mat3<double>& Q) { return {{Q(0, 0), Q(0, 1), Q(0, 2)}, {Q(1, 0), Q(1, 1), Q(1, 2)}, {Q(2, 0), Q(2, 1), Q(2, 2)}}; }

}  // namespace

gubas_mapping read_gubas_config(const std::filesystem::path& path) {
  const std::string where = "--gubas-config " + printable_path(path);
  std::string text;
  try {
    text = read_bounded_file(path.string(), config_file_limit);
  } catch (const std::runtime_error& e) {
    throw bad_input("--gubas-config: " + one_line(e.what()));
  }
  return parse_gubas_config(text, path.parent_path(), where);
}

gubas_mapping parse_gubas_config(const std::string& text, const std::filesystem::path& folder, const std::string& where) {
  const config c(text, where);
  if (c.flag("Fahnestock Input File Flag"))
    c.refuse("Fahnestock Input File Flag", "(the start, G and densities from Fahnestock's files) has no rotlie counterpart");
  refuse_perturbations(c);
  gubas_mapping m;
  auto& r = m.request;
  const auto set = [&](std::string binary_request::*field, const std::string& name, const std::string& value, const std::string& from) {
    r.*field = value;
    m.source[name] = from;
  };

  set(&binary_request::G, "G", text_of(c.number("G", -9)), "G");  // m³ kg⁻¹ s⁻² to km³ kg⁻¹ s⁻²
  const auto primary = shape_of(c, "Primary", folder), secondary = shape_of(c, "Secondary", folder);
  set(&binary_request::primary, "primary", primary, "Primary Shape Flag");
  set(&binary_request::secondary, "secondary", secondary, "Secondary Shape Flag");
  // g/cm³ to kg/m³
  set(&binary_request::density, "density", text_of(c.number("Primary Density", 3)) + "," + text_of(c.number("Secondary Density", 3)),
      "Primary Density");
  const long order = order_of(c, primary.rfind("gubas:", 0) == 0, secondary.rfind("gubas:", 0) == 0);
  set(&binary_request::order, "order", std::to_string(order), "Gravity Expansion Truncation Order");

  if (c.number("Start Time") != 0)
    c.refuse("Start Time", "(the clock at the start, " + text_of(c.number("Start Time")) +
                               " s) has no rotlie counterpart: rotlie's runs start at t = 0 (set it to 0 and 'Final Time' to the run's length)");
  set(&binary_request::T, "T", text_of(c.number("Final Time")), "Final Time");
  set(&binary_request::h, "h", text_of(c.number("Fixed Time Step")), "Fixed Time Step");
  const long integrator = c.integer("Integrator Flag");
  if (integrator == 1) {
    set(&binary_request::integrator, "integrator", "RK4", "Integrator Flag");
  } else if (integrator == 2) {
    set(&binary_request::integrator, "integrator", "LGVI", "Integrator Flag");
  } else if (integrator == 3) {
    const double tolerance = c.number("Absolute Tolerance");
    if (!(tolerance > 0)) c.refuse("Absolute Tolerance", "must be positive");
    set(&binary_request::integrator, "integrator", "odeint-rkf78:" + text_of(tolerance), "Integrator Flag");
  } else if (integrator == 4) {
    c.refuse("Integrator Flag", "= 4 (the Adams-Bashforth-Moulton predictor-corrector) has no rotlie counterpart");
  } else {
    c.refuse("Integrator Flag", "= " + std::to_string(integrator) + " is none of GUBAS's integrators (1 RK4, 2 LGVI, 3 RK 7(8), 4 ABM)");
  }

  // The start: GUBAS's frame A is the primary's shape frame; rotlie's body frames are principal.
  const auto principal_axes = [&](const std::string& spec, const std::string& body) {
    if (spec.rfind("gubas:", 0) != 0) return mat3<double>::identity();
    return binary_shape_named(spec, where + " (" + body + " Vertex File)").axes;
  };
  const auto A1 = principal_axes(primary, "Primary"), A2 = principal_axes(secondary, "Secondary");
  const auto C_AN = attitude_of(c, "A into N"), C_BA = attitude_of(c, "B into A");
  const auto r_A = vector_of(c, "Relative Position", -3), v_A = vector_of(c, "Relative Velocity", -3);  // m, m/s to km, km/s
  const auto w_A = vector_of(c, "Primary Angular Velocity", 0), w_B = vector_of(c, "Secondary Angular Velocity", 0);
  nlohmann::json state = {{"r", C_AN * r_A},
                          {"v", C_AN * v_A},
                          {"Q1", rows(C_AN * A1)},
                          {"Q2", rows(C_AN * C_BA * A2)},
                          {"omega1", transpose(A1) * w_A},
                          {"omega2", transpose(A2) * w_B}};
  r.state_text = state.dump();
  m.source["state"] = "Initial Conditions";
  return m;
}

}  // namespace rotlie::runs
