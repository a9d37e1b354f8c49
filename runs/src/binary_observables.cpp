#include "rotlie/runs/binary_observables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

namespace {

using models::norm;
using models::vec3;

constexpr double seconds_per_hour = 3600;
constexpr double degrees_per_radian = 180 / std::numbers::pi;
constexpr double millimetre_per_second = 1e-6;  // in km/s

// The maximum-moment axis: its index, or, when two moments share the maximum, the index of the third
// (the angle is then to the plane normal to it); -1 for a sphere.
struct maximum_axis {
  int k = -1;
  bool plane = false;
};

maximum_axis maximum_axis_of(const vec3<double>& I) {
  const double tie = 1e-12 * (I[0] + I[1] + I[2]);
  const auto c = static_cast<int>(std::max_element(I.begin(), I.end()) - I.begin());
  std::vector<int> shared;  // the other axes whose moments equal the maximum
  for (int k = 0; k < 3; ++k)
    if (k != c && std::abs(I[static_cast<std::size_t>(k)] - I[static_cast<std::size_t>(c)]) <= tie) shared.push_back(k);
  if (shared.size() == 2) return {};
  if (shared.size() == 1) return {3 - c - shared[0], true};
  return {c, false};
}

// G's angles off body axis k and off the plane normal to it (they add to π/2).
double off_axis(const vec3<double>& G, std::size_t k) {
  return std::atan2(std::hypot(G[(k + 1) % 3], G[(k + 2) % 3]), std::abs(G[k]));
}
double off_plane(const vec3<double>& G, std::size_t k) {
  return std::atan2(std::abs(G[k]), std::hypot(G[(k + 1) % 3], G[(k + 2) % 3]));
}

// I sorted: A ≤ B ≤ C.
vec3<double> sorted_moments(vec3<double> I) {
  std::sort(I.begin(), I.end());
  return I;
}

}  // namespace

osculating_orbit osculating_elements(const models::binary_state<double>& x, double GM) {
  osculating_orbit o;
  const double r = norm(x.r), v2 = models::dot(x.v, x.v);
  const auto h = models::cross(x.r, x.v);
  o.a_km = 1 / (2 / r - v2 / GM);
  const auto vxh = models::cross(x.v, h);
  vec3<double> e;
  for (std::size_t k = 0; k < 3; ++k) e[k] = vxh[k] / GM - x.r[k] / r;
  o.e = norm(e);
  o.i_deg = std::acos(std::clamp(h[2] / norm(h), -1.0, 1.0)) * degrees_per_radian;
  o.period_h = o.a_km > 0 ? 2 * std::numbers::pi * std::sqrt(o.a_km * o.a_km * o.a_km / GM) / seconds_per_hour : 0;
  return o;
}

double libration_angle(const models::binary_state<double>& x) {
  const auto& Q = x.body[1].Q;
  double lib = std::atan2(Q(1, 0), Q(0, 0)) - std::atan2(x.r[1], x.r[0]);
  lib -= std::numbers::pi * std::round(lib / std::numbers::pi);
  return lib;
}

bool orbit_frame(const models::binary_state<double>& x, models::mat3<double>& frame) {
  const auto n = models::cross(x.r, x.v);
  const double r = norm(x.r), h = norm(n);
  if (!(r > 0) || !(h > 0) || !(h > 1e-14 * r * norm(x.v))) return false;
  vec3<double> ex, ez;
  for (std::size_t k = 0; k < 3; ++k) ex[k] = x.r[k] / r, ez[k] = n[k] / h;
  const auto ey = models::cross(ez, ex);
  for (int k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(k);
    frame(k, 0) = ex[i], frame(k, 1) = ey[i], frame(k, 2) = ez[i];
  }
  return true;
}

vec3<double> orbit_euler_angles(const models::binary_state<double>& x, int body) {
  models::mat3<double> F;
  if (!orbit_frame(x, F)) return {0, 0, 0};
  auto R = models::transpose(F) * x.body[body].Q;
  // the half turn about a body axis that brings R nearest the identity: R D with D = diag(s₀, s₁, s₂)
  const vec3<double> d{R(0, 0), R(1, 1), R(2, 2)};
  const vec3<double> signs[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::size_t best = 0;
  double most = -4;
  for (std::size_t m = 0; m < 4; ++m) {
    const double trace = signs[m][0] * d[0] + signs[m][1] * d[1] + signs[m][2] * d[2];
    if (trace > most) most = trace, best = m;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R(i, j) *= signs[best][static_cast<std::size_t>(j)];
  // R_x(φ) R_y(θ) R_z(ψ) = [[cθcψ, −cθsψ, sθ], [·, ·, −sφcθ], [·, ·, cφcθ]]
  const double pitch = std::asin(std::clamp(R(0, 2), -1.0, 1.0));
  const double roll = std::atan2(-R(1, 2), R(2, 2));
  const double yaw = std::atan2(-R(0, 1), R(0, 0));
  return {roll + 0.0, pitch + 0.0, yaw + 0.0};  // + 0.0: −0 reads 0
}

double max_moment_angle(const vec3<double>& I, const vec3<double>& G) {
  const auto c = maximum_axis_of(I);
  if (c.k < 0 || !(norm(G) > 0)) return 0;
  const auto k = static_cast<std::size_t>(c.k);
  return c.plane ? off_plane(G, k) : off_axis(G, k);
}

double dynamical_inertia(const vec3<double>& I, const vec3<double>& G) {
  const double G2 = models::dot(G, G);
  if (!(G2 > 0)) return *std::max_element(I.begin(), I.end());
  return G2 / (G[0] * G[0] / I[0] + G[1] * G[1] / I[1] + G[2] * G[2] / I[2]);
}

double spin_period_h(const models::binary_system<double>& sys, const models::binary_state<double>& x, int body) {
  const double w = norm(models::angular_velocity(sys.moments(body), x.body[body].G));
  return w > 0 ? 2 * std::numbers::pi / w / seconds_per_hour : 0;
}

void binary_observer::add(double t, const models::binary_state<double>& x) {
  const double angle = std::atan2(x.r[1], x.r[0]);
  if (!theta_.empty()) {
    double d = angle - last_;
    d -= 2 * std::numbers::pi * std::round(d / (2 * std::numbers::pi));
    unwrapped_ += d;
  } else {
    unwrapped_ = angle;
    d_min_ = std::numeric_limits<double>::infinity(), d_max_ = 0;
  }
  last_ = angle;
  t_.push_back(t), theta_.push_back(unwrapped_), phi_.push_back(libration_angle(x));
  const double d = norm(x.r);
  d_min_ = std::min(d_min_, d), d_max_ = std::max(d_max_, d);
  for (std::size_t b = 0; b < 2; ++b) {
    const auto& G = x.body[b].G;
    if (norm(G) > 0)
      for (std::size_t k = 0; k < 3; ++k)
        off_axis_max_[b][k] = std::max(off_axis_max_[b][k], off_axis(G, k)), off_plane_max_[b][k] = std::max(off_plane_max_[b][k], off_plane(G, k));
    const auto e = orbit_euler_angles(x, static_cast<int>(b));
    for (std::size_t k = 0; k < 3; ++k) euler_max_[b][k] = std::max(euler_max_[b][k], std::abs(e[k]));
  }
}

binary_observables binary_observer::result(const models::binary_system<double>& sys, const models::binary_state<double>& end) const {
  binary_observables o;
  o.separation_min_km = d_min_, o.separation_max_km = d_max_;
  const double n = static_cast<double>(t_.size());
  if (t_.size() >= 2) {  // the orbital angle's least-squares slope
    double st = 0, sa = 0, stt = 0, sta = 0;
    for (std::size_t k = 0; k < t_.size(); ++k) st += t_[k], sa += theta_[k], stt += t_[k] * t_[k], sta += t_[k] * theta_[k];
    const double slope = (n * sta - st * sa) / (n * stt - st * st);
    o.orbit_period_h = 2 * std::numbers::pi / slope / seconds_per_hour;
  }
  if (!phi_.empty()) {
    const auto [low, high] = std::minmax_element(phi_.begin(), phi_.end());
    o.libration_amplitude_deg = (*high - *low) / 2 * degrees_per_radian;
    double mean = 0;
    for (const double p : phi_) mean += p;
    mean /= n;
    o.libration_mean_deg = mean * degrees_per_radian;
    std::vector<double> ups;
    for (std::size_t k = 1; k < phi_.size(); ++k)
      if (phi_[k - 1] < mean && phi_[k] >= mean) ups.push_back(t_[k - 1] + (t_[k] - t_[k - 1]) * (mean - phi_[k - 1]) / (phi_[k] - phi_[k - 1]));
    if (ups.size() >= 2) o.libration_period_h = (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1) / seconds_per_hour;
  }
  o.primary_period_h = spin_period_h(sys, end, 0), o.secondary_period_h = spin_period_h(sys, end, 1);
  o.osculating = osculating_elements(end, sys.G() * sys.total_mass());
  o.tumbling_threshold_deg = threshold_deg_;
  for (std::size_t b = 0; b < 2; ++b) {
    const auto& I = sys.moments(static_cast<int>(b));
    const auto& G = end.body[b].G;
    auto& rot = o.rotation[b];
    const auto e = orbit_euler_angles(end, static_cast<int>(b));
    for (std::size_t k = 0; k < 3; ++k)
      rot.euler_end_deg[k] = e[k] * degrees_per_radian, rot.euler_max_deg[k] = std::max(euler_max_[b][k], std::abs(e[k])) * degrees_per_radian;
    const double end_angle = max_moment_angle(I, G);
    const auto c = maximum_axis_of(I);
    double most = end_angle;
    if (c.k >= 0) most = std::max(most, (c.plane ? off_plane_max_[b] : off_axis_max_[b])[static_cast<std::size_t>(c.k)]);
    rot.npa_angle_end_deg = end_angle * degrees_per_radian, rot.npa_angle_max_deg = most * degrees_per_radian;
    const auto ABC = sorted_moments(I);
    const double Id = dynamical_inertia(I, G);
    rot.id_over_c = Id / ABC[2];
    rot.short_axis_mode = Id >= ABC[1];
    rot.tumbling = rot.npa_angle_max_deg > threshold_deg_;
  }
  return o;
}

binary_impulse impulse_named(const std::string& text, const models::binary_system<double>& sys, const models::binary_state<double>& at) {
  const auto colon = text.find(':');
  const std::string body = colon == std::string::npos ? "" : text.substr(0, colon);
  if (body != "primary" && body != "secondary")
    throw bad_input("--impulse '" + one_line(text) + "': give BODY:dx,dy,dz (mm/s) or BODY:beta=B,m=KG,U=KM_S, BODY primary or secondary");
  binary_impulse out;
  out.body = body == "primary" ? 0 : 1;
  std::string rest = text.substr(colon + 1);
  const bool dart = rest.rfind("beta=", 0) == 0;
  if (dart) {  // beta=B,m=KG,U=KM_S: the names dropped, the order checked
    std::string numbers;
    std::size_t start = 0;
    for (const char* key : {"beta=", "m=", "U="}) {
      if (rest.compare(start, std::string(key).size(), key) != 0) throw bad_input("--impulse '" + one_line(text) + "': the DART form is BODY:beta=B,m=KG,U=KM_S");
      start += std::string(key).size();
      const auto comma = rest.find(',', start);
      numbers += (numbers.empty() ? "" : ",") + rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      start = comma == std::string::npos ? rest.size() : comma + 1;
    }
    rest = numbers;
  }
  const auto values = real_numbers(rest, "--impulse");
  if (values.size() != 3) throw bad_input("--impulse takes three numbers after '" + body + ":', got " + std::to_string(values.size()));
  if (!dart) {
    for (std::size_t k = 0; k < 3; ++k) out.dv[k] = values[k] * millimetre_per_second;
    return out;
  }
  if (!(values[0] > 0 && values[1] > 0 && values[2] > 0)) throw bad_input("--impulse: beta, m and U must be positive");
  const double speed = norm(at.v);
  if (!(speed > 0)) throw bad_input("--impulse: the pair is at rest, the orbital motion gives no direction");
  // the body's velocity about the barycentre is along +v (the secondary) or −v (the primary); the
  // impulse opposes it with |Δv| = β m U / M
  const double size = values[0] * values[1] * values[2] / sys.body(out.body).mass;
  const double along = out.body == 1 ? -1 : 1;
  for (std::size_t k = 0; k < 3; ++k) out.dv[k] = along * size * at.v[k] / speed;
  return out;
}

models::binary_state<double> with_impulse(models::binary_state<double> x, const binary_impulse& impulse) {
  const double sign = impulse.body == 1 ? 1 : -1;
  for (std::size_t k = 0; k < 3; ++k) x.v[k] += sign * impulse.dv[k];
  return x;
}

}  // namespace rotlie::runs
