#include "rotlie/runs/binary_io.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/rotation_check.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "stepping_fields.hpp"

namespace rotlie::runs {

namespace {

using models::mat3;
using models::vec3;
using nlohmann::json;

constexpr std::size_t state_file_limit = std::size_t(1) << 20;

json rows(const mat3<double>& Q) {
  return json::array({{Q(0, 0), Q(0, 1), Q(0, 2)}, {Q(1, 0), Q(1, 1), Q(1, 2)}, {Q(2, 0), Q(2, 1), Q(2, 2)}});
}

json state_fields(const models::binary_state<double>& x, const models::binary_system<double>& sys) {
  return {{"r", x.r},
          {"v", x.v},
          {"Q1", rows(x.body[0].Q)},
          {"Q2", rows(x.body[1].Q)},
          {"omega1", models::angular_velocity(sys.moments(0), x.body[0].G)},
          {"omega2", models::angular_velocity(sys.moments(1), x.body[1].G)}};
}

// The largest size a component of r (km), v (km/s) or omega (rad/s) may have: far beyond any binary,
// and small enough that the run's energies, momenta and their squares stay within double's range.
constexpr double largest_component = 1e30;
// The shortest separation (km) told apart from zero (|r|² and |r|³ stay normal numbers).
constexpr double shortest_separation = 1e-30;

// Where the parser met a number it cannot hold (1e999): the keys and indices down to it, and its text.
class number_locator : public nlohmann::json_sax<json> {
 public:
  std::string where, token;

  bool null() override { return next(); }
  bool boolean(bool) override { return next(); }
  bool number_integer(number_integer_t) override { return next(); }
  bool number_unsigned(number_unsigned_t) override { return next(); }
  bool number_float(number_float_t, const string_t&) override { return next(); }
  bool string(string_t&) override { return next(); }
  bool binary(binary_t&) override { return next(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& k) override {
    path.back().key = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string& last_token, const nlohmann::detail::exception&) override {
    for (const auto& f : path) where += f.array ? "[" + std::to_string(f.index) + "]" : "\"" + one_line(f.key) + "\"";
    token = one_line(last_token);
    return false;
  }

 private:
  struct level {
    bool array = false;
    std::size_t index = 0;
    std::string key;
  };
  std::vector<level> path;

  bool next() {
    if (!path.empty() && path.back().array) ++path.back().index;
    return true;
  }
  bool open(bool array) {
    path.push_back({array, 0, ""});
    return true;
  }
  bool close() {
    path.pop_back();
    return next();
  }
};

json parsed(const std::string& text, const std::string& where) {
  try {
    return json::parse(text);
  } catch (const json::out_of_range&) {  // a number beyond double's range
    number_locator locator;
    json::sax_parse(text, &locator);
    throw bad_input(where + ": " + (locator.where.empty() ? "a number" : locator.where) + " = " + locator.token +
                    " is out of range (beyond double's 1.8e308)");
  } catch (const json::exception& e) {
    throw bad_input(where + ": not JSON (" + one_line(e.what()) + ")");
  }
}

vec3<double> vector_field(const json& j, const std::string& key, const std::string& where) {
  if (!j.contains(key)) throw bad_input(where + ": the field \"" + key + "\" is missing");
  const auto& v = j[key];
  if (!v.is_array() || v.size() != 3) throw bad_input(where + ": \"" + key + "\" must be three numbers");
  vec3<double> out;
  for (std::size_t k = 0; k < 3; ++k) {
    if (!v[k].is_number()) throw bad_input(where + ": \"" + key + "\" must be three numbers");
    out[k] = v[k].get<double>();
    if (!(std::abs(out[k]) <= largest_component))
      throw bad_input(where + ": \"" + key + "\"[" + std::to_string(k) + "] = " + schemes::message_number(out[k]) + " is out of range (at most " +
                      schemes::message_number(largest_component) + " in size)");
  }
  return out;
}

mat3<double> rotation_field(const json& j, const std::string& key, const std::string& where) {
  if (!j.contains(key)) throw bad_input(where + ": the field \"" + key + "\" is missing");
  const auto& m = j[key];
  if (!m.is_array() || m.size() != 3) throw bad_input(where + ": \"" + key + "\" must be a 3x3 matrix, row by row");
  mat3<double> Q;
  for (int i = 0; i < 3; ++i) {
    const auto& row = m[static_cast<std::size_t>(i)];
    if (!row.is_array() || row.size() != 3) throw bad_input(where + ": \"" + key + "\" must be a 3x3 matrix, row by row");
    for (int k = 0; k < 3; ++k) {
      if (!row[static_cast<std::size_t>(k)].is_number()) throw bad_input(where + ": \"" + key + "\" must hold numbers");
      Q(i, k) = row[static_cast<std::size_t>(k)].get<double>();
    }
  }
  const double entries[9] = {Q(0, 0), Q(0, 1), Q(0, 2), Q(1, 0), Q(1, 1), Q(1, 2), Q(2, 0), Q(2, 1), Q(2, 2)};
  if (const auto why = rotation_problem(entries, 1e-9); !why.empty()) throw bad_input(where + ": \"" + key + "\" is not a rotation (" + why + ")");
  for (int pass = 0; pass < 2; ++pass) {  // Newton steps toward the nearest rotation: Q (3 − QᵀQ)/2
    auto half = transpose(Q) * Q;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) half(i, k) = ((i == k ? 3.0 : 0.0) - half(i, k)) / 2;
    Q = Q * half;
  }
  return Q;
}

// The start in the units a user checks by eye: km, m/s, hours, kg/m³.
std::string start_text(const binary_setup& s, const models::binary_system<double>& sys) {
  using schemes::message_number;
  const double full_turn = 2 * std::acos(-1.0);
  std::ostringstream out;
  out << "start: |r| = " << message_number(std::sqrt(models::dot(s.start.r, s.start.r))) << " km, |v| = "
      << message_number(1000 * std::sqrt(models::dot(s.start.v, s.start.v))) << " m/s, spin periods";
  for (int b = 0; b < 2; ++b) {
    const auto w = models::angular_velocity(sys.moments(b), s.start.body[b].G);
    const double rate = std::sqrt(models::dot(w, w));
    out << (b ? " and " : " ") << (rate > 0 ? message_number(full_turn / rate / 3600) + " h" : std::string("none"));
  }
  out << ", densities " << message_number(s.primary.density) << " and " << message_number(s.secondary.density) << " kg/m3\n";
  return out.str();
}

}  // namespace

json binary_json(const binary_result& r) {
  const auto& s = r.setup;
  const auto sys = s.system_model();
  json j = {{"system", s.system.empty() ? json(nullptr) : json(s.system)},
            {"primary", s.primary.spec},
            {"secondary", s.secondary.spec},
            {"order", s.order},
            {"G", s.G},
            {"masses", {sys.body(0).mass, sys.body(1).mass}},
            {"moments", {sys.moments(0), sys.moments(1)}},
            {"densities", {s.primary.density, s.secondary.density}},
            {"t", r.end.t}};
  j.update(stepping_fields(s, r.evaluations));
  j.update(state_fields(r.end.x, sys));
  j["energy"] = r.end.energy;
  j["energy_start"] = sys.energy(s.start);
  j["angular_momentum"] = r.angular_momentum;
  j["max_rel_energy_error"] = r.check.max_rel_energy_error;
  j["max_rel_angular_momentum_error"] = r.check.max_rel_angular_momentum_error;
  j["cpu_s"] = r.cpu_s;
  j["mutual"] = {{"U", r.mutual.U}, {"F", r.mutual.F}, {"M1", r.mutual.M1}, {"M2", r.mutual.M2}};
  for (const auto& [name, term] : s.terms) j[name] = term->values(r.end.x, r.end.t);
  if (s.impulse) j["impulse"] = {{"body", s.impulse->body == 0 ? "primary" : "secondary"}, {"dv", s.impulse->dv}};
  if (r.observables) {
    const auto& o = *r.observables;
    j["observables"] = {{"orbit_period_h", o.orbit_period_h},
                        {"libration_amplitude_deg", o.libration_amplitude_deg},
                        {"libration_mean_deg", o.libration_mean_deg},
                        {"libration_period_h", o.libration_period_h},
                        {"spin_periods_h", {o.primary_period_h, o.secondary_period_h}},
                        {"separation_km", {o.separation_min_km, o.separation_max_km}},
                        {"osculating", {{"a_km", o.osculating.a_km}, {"e", o.osculating.e}, {"i_deg", o.osculating.i_deg}, {"period_h", o.osculating.period_h}}}};
    // roll, pitch, yaw: 1-2-3 Euler angles of the principal axes in the orbit frame (x̂ = r̂, ẑ = r × v)
    const auto euler = [](const body_rotation& b) {
      return json{{"roll_max", b.euler_max_deg[0]}, {"pitch_max", b.euler_max_deg[1]}, {"yaw_max", b.euler_max_deg[2]},
                  {"roll_end", b.euler_end_deg[0]}, {"pitch_end", b.euler_end_deg[1]}, {"yaw_end", b.euler_end_deg[2]}};
    };
    const auto spin = [](const body_rotation& b) {
      return json{{"npa_angle_max_deg", b.npa_angle_max_deg}, {"npa_angle_end_deg", b.npa_angle_end_deg}, {"id_over_c", b.id_over_c},
                  {"mode", b.short_axis_mode ? "SAM" : "LAM"}, {"tumbling", b.tumbling}};
    };
    j["observables"]["euler_deg"] = {{"primary", euler(o.rotation[0])}, {"secondary", euler(o.rotation[1])}};
    j["observables"]["spin_state"] = {
        {"tumbling_threshold_deg", o.tumbling_threshold_deg},
        {"tumbling_definition", "the angle between G and the maximum-moment axis exceeds tumbling_threshold_deg at a sample"},
        {"primary", spin(o.rotation[0])},
        {"secondary", spin(o.rotation[1])}};
  }
  j["unstable"] = r.check.unstable;
  j["round_off_floor"] = r.check.round_off_floor;
  j["inaccurate"] = r.check.inaccurate;
  j["accuracy"] = {{"relative", s.accuracy_rel}, {"angle_rad", s.accuracy_rad}};
  if (r.error_estimate) {
    const auto& e = *r.error_estimate;
    j["error_estimate"] = {{"position_rel", e.position_rel}, {"velocity_rel", e.velocity_rel}, {"attitude1_rad", e.attitude1_rad},
                           {"attitude2_rad", e.attitude2_rad}, {"order", e.order}, {"observed_order", e.observed_order}, {"step_ratio", e.step_ratio}, {"cpu_s", e.cpu_s}};
  } else {
    j["error_estimate"] = nullptr;
  }
  j["warnings"] = r.check.warnings;
  return j;
}

json binary_sample_json(const binary_sample& s, const models::binary_system<double>& sys) {
  json j = {{"t", s.t}};
  j.update(state_fields(s.x, sys));
  j["energy"] = s.energy;
  return j;
}

std::string binary_text(const binary_result& r) {
  using schemes::message_number;
  const auto& s = r.setup;
  const auto sys = s.system_model();
  const double d = std::sqrt(models::dot(r.end.x.r, r.end.x.r));
  std::ostringstream out;
  out << "binary" << (s.system.empty() ? "" : " " + s.system) << ": " << s.primary.spec << " (" << message_number(sys.body(0).mass) << " kg) and "
      << s.secondary.spec << " (" << message_number(sys.body(1).mass) << " kg), order " << s.order << "\n"
      << start_text(s, sys) << s.method.name << ", h = " << message_number(s.h) << " s, T = " << message_number(s.T) << " s (" << s.steps << " steps, " << r.evaluations
      << " gravity evaluations)\n"
      << "final separation " << message_number(d) << " km; relative errors: energy " << message_number(r.check.max_rel_energy_error)
      << ", angular momentum " << message_number(r.check.max_rel_angular_momentum_error) << (r.check.unstable ? ": UNSTABLE" : "") << "\n"
      << "CPU " << message_number(r.cpu_s) << " s\n";
  if (r.error_estimate)
    out << "estimated error at the end: position " << message_number(r.error_estimate->position_rel) << ", velocity "
        << message_number(r.error_estimate->velocity_rel) << " relative; attitudes " << message_number(r.error_estimate->attitude1_rad) << " and "
        << message_number(r.error_estimate->attitude2_rad) << " rad" << (r.check.inaccurate ? ": INACCURATE" : "") << "\n";
  if (r.observables) {
    const auto& o = *r.observables;
    out << "observed: mean orbit period " << message_number(o.orbit_period_h) << " h (osculating at the end " << message_number(o.osculating.period_h)
        << " h, e = " << message_number(o.osculating.e) << "), libration " << message_number(o.libration_amplitude_deg) << " deg about "
        << message_number(o.libration_mean_deg) << " deg, period " << message_number(o.libration_period_h) << " h; spin periods "
        << message_number(o.primary_period_h) << " and " << message_number(o.secondary_period_h) << " h\n";
    for (int b = 0; b < 2; ++b) {
      const auto& rot = o.rotation[b];
      out << (b == 0 ? "primary" : "secondary") << ": G up to " << message_number(rot.npa_angle_max_deg) << " deg off its maximum-moment axis, I_d/C "
          << message_number(rot.id_over_c) << " (" << (rot.short_axis_mode ? "SAM" : "LAM") << ")" << (rot.tumbling ? ": TUMBLING" : "")
          << "; roll, pitch, yaw up to " << message_number(rot.euler_max_deg[0]) << ", " << message_number(rot.euler_max_deg[1]) << ", "
          << message_number(rot.euler_max_deg[2]) << " deg\n";
    }
  }
  for (const auto& [name, term] : s.terms) out << name << " at the end: " << term->values(r.end.x, r.end.t).dump() << "\n";
  return out.str();
}

models::binary_state<double> read_binary_state(const std::string& path, const models::binary_system<double>& sys) {
  const std::string where = "--state " + printable_path(path);
  std::string text;
  try {
    text = read_bounded_file(path, state_file_limit);
  } catch (const std::runtime_error& e) {
    throw bad_input("--state: " + one_line(e.what()));
  }
  return parse_binary_state(text, where, sys);
}

models::binary_state<double> parse_binary_state(const std::string& text, const std::string& where, const models::binary_system<double>& sys) {
  const json j = parsed(text, where);
  if (!j.is_object()) throw bad_input(where + ": a JSON object with r, v, Q1, Q2, omega1, omega2 is expected");
  models::binary_state<double> x;
  x.r = vector_field(j, "r", where);
  x.v = vector_field(j, "v", where);
  x.body[0].Q = rotation_field(j, "Q1", where);
  x.body[1].Q = rotation_field(j, "Q2", where);
  const auto w1 = vector_field(j, "omega1", where), w2 = vector_field(j, "omega2", where);
  for (std::size_t k = 0; k < 3; ++k) x.body[0].G[k] = sys.moments(0)[k] * w1[k], x.body[1].G[k] = sys.moments(1)[k] * w2[k];
  const double separation = std::hypot(x.r[0], x.r[1], x.r[2]);
  if (!(separation > 0)) throw bad_input(where + ": r must not be zero");
  if (separation < shortest_separation)
    throw bad_input(where + ": \"r\" is out of range (|r| = " + schemes::message_number(separation) + " km, below " + schemes::message_number(shortest_separation) +
                    ")");
  return x;
}

}  // namespace rotlie::runs
