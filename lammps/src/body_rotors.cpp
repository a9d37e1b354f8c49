// SPDX-License-Identifier: GPL-2.0-or-later
#include "body_rotors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <type_traits>

#include "map_choice.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/closed_form_rotors.hpp"
#include "rotlie/models/exact_free_rotation.hpp"
#include "rotlie/models/table_rotor.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/schemes/same_body.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::lammps {
namespace {

template <class Rotor>
class rotor_of final : public body_rotor {
 public:
  explicit rotor_of(Rotor r) : r_(std::move(r)) {}
  void advance(models::body_state<double>& s, double t) const override { r_.advance(s, t); }
  const models::exact_free_rotation<double>* exact() const override {
    if constexpr (std::is_same_v<Rotor, models::exact_free_rotation<double>>) return &r_;
    else return nullptr;
  }

 private:
  Rotor r_;
};

std::string moments_text(const std::array<double, 3>& I) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.10g, %.10g, %.10g)", I[0], I[1], I[2]);
  return text;
}

// The shape as exact moments for the solver: 12 significant digits each, and a flat body (water:
// I3 = I1 + I2 up to the rounding of the coordinates) kept flat rather than pushed across eq. (77).
lie::moments_of_inertia exact_shape(const std::array<double, 3>& I) {
  lie::moments_of_inertia m;
  for (std::size_t k = 0; k < 3; ++k) {
    char text[40];
    std::snprintf(text, sizeof text, "%.12g", I[k]);
    m.I[k] = *lie::parse_exact_number(text);
  }
  if (m.I[2] > m.I[0] + m.I[1]) m.I[2] = m.I[0] + m.I[1];
  lie::validate_moments(m);
  return m;
}

// The exact rotor for a symmetric top (the reason, shared by the shapes that fall back for it).
const std::string symmetric_reason = "a symmetric top (two moments equal to 1e-6 relative), which the maps and their dedicated schemes leave out";

// `rotor TABLE` for one shape: the named table, checked to be a free rotation solved for the shape.
schemes::scheme_table checked_table(const std::string& name, const std::array<double, 3>& I, long id) {
  auto t = *runs::free_rotor_named(name, exact_shape(I), "rotor " + name, runs::foreign_table::use_with_warning,
                                   [](const std::string&) {}).table;  // the body checked below, with LAMMPS's tolerance
  if (schemes::same_body(t, I, shape_tolerance) == schemes::body_match::different)
    throw runs::bad_input("rotor " + name + ": the table was solved for moments (" + t.inertia + "), not for body " +
                          std::to_string(id) + " with moments " + moments_text(I));
  return t;
}

// In a 2-d system (the reason, shared by every shape).
const std::string planar_reason = "a 2-d system, where every body turns about the plane's normal by its closed form (no table needed)";

}  // namespace

// Whether `rotor auto` looks a shape up in the maps (the others run the exact rotor without them).
bool body_rotors::needs_map(const body_shape& s) const { return !planar_ && s.moments[0] > 0 && !symmetric_top(s.moments); }

bool same_shape(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double big = std::max({a[0], a[1], a[2], b[0], b[1], b[2]});
  for (std::size_t k = 0; k < 3; ++k)
    if (std::abs(a[k] - b[k]) > shape_tolerance * big) return false;
  return true;
}

std::string body_shapes_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " body shape" : " body shapes"); }

bool symmetric_top(const std::array<double, 3>& I) {
  return I[1] - I[0] <= shape_tolerance * I[2] || I[2] - I[1] <= shape_tolerance * I[2];
}

std::string rotor_values_help() { return "auto (chosen per body shape from the shipped maps), " + runs::rotor_values_text(); }

rotor_request parse_rotor(const std::string& value) {
  if (value.empty()) throw runs::bad_input("rotor needs a value: " + rotor_values_help());
  if (models::is_closed_form_rotor(value)) return {rotor_request::kind::closed_form, value};
  if (value == "auto") return {rotor_request::kind::automatic, ""};
  return {rotor_request::kind::table, value};
}

const body_shape* body_rotors::shape_of(const std::array<double, 3>& moments) const {
  for (const auto& s : shapes_)
    if (same_shape(s.moments, moments)) return &s;
  return nullptr;
}

// A shape as text, the same on every rank: a first line `closed NAME` (a listed rotor), `fallback WHY`, `table` (the
// table's text follows) or `error WHY` (a refusal, thrown by every rank alike in take_text).
std::string body_rotors::resolved_text(const body_shape& s, const shipped_map_lines* maps, const std::string& no_maps) const {
  const bool automatic = request_.what == rotor_request::kind::automatic;
  try {
    if (!(s.moments[0] > 0)) return "closed exact\n";  // linear: the fix's closed form
    if (request_.what == rotor_request::kind::closed_form) return "closed " + request_.name + "\n";
    if (!automatic) return "table\n" + schemes::format_scheme_table(checked_table(request_.name, s.moments, s.first_body));
    if (planar_) return "fallback " + planar_reason + "\n";
    if (symmetric_top(s.moments)) return "fallback " + symmetric_reason + "\n";
    if (!maps) return "fallback " + no_maps + "\n";
    const auto lines = maps->at(nearest_grid_point(s.moments));
    return "table\n" + schemes::format_scheme_table(table_from_maps(exact_shape(s.moments), lines));
  } catch (const std::exception& e) {
    return (automatic ? "fallback the solver failed: " : "error ") + runs::one_line(e.what()) + "\n";
  }
}

void body_rotors::take_text(body_shape& s, const std::string& text) const {
  const auto end = text.find('\n');
  const std::string first = text.substr(0, end), rest = end == std::string::npos ? "" : text.substr(end + 1);
  const auto word = first.substr(0, first.find(' ')), why = first.size() > word.size() ? first.substr(word.size() + 1) : "";
  s.table_name = s.closed_form = "exact";
  if (word == "error") throw runs::bad_input(why);
  if (word == "fallback") s.fallback = why;
  if (word == "closed") s.table_name = s.closed_form = why;
  if (word == "table") {
    s.table = schemes::parse_scheme_table(rest);
    s.table_name = s.table->name;
  }
}

void body_rotors::resolve_shapes(const std::vector<std::pair<std::array<double, 3>, long>>& bodies, const shape_sharing& share,
                                 const std::function<void(const std::string&)>& progress) {
  shapes_.clear();
  rotors_.clear();
  new_shapes_.clear();
  new_shapes_taken_ = 0;
  for (const auto& [I, id] : bodies)
    if (!shape_of(I)) shapes_.push_back({I, id, std::nullopt, "", ""});
  // rotor auto: the maps' lines at the grid bodies of this rank's shapes, read in one pass
  std::optional<shipped_map_lines> maps;
  std::string no_maps;
  if (request_.what == rotor_request::kind::automatic) {
    std::vector<std::pair<int, int>> points;
    for (std::size_t k = 0; k < shapes_.size(); ++k)
      if (share.mine(k) && needs_map(shapes_[k])) points.push_back(nearest_grid_point(shapes_[k].moments));
    const auto asked = std::count_if(shapes_.begin(), shapes_.end(), [&](const auto& s) { return needs_map(s); });
    if (progress && asked > 0)
      progress(shipped_maps_present()
                   ? "rotor auto: choosing the rotors of " + body_shapes_text(static_cast<std::size_t>(asked)) +
                         " from the shipped maps (maps-K200: the nearest grid body's best, one system solved per shape)"
                   : "rotor auto: the shipped maps (maps-K200) are not found: the exact rotor runs every shape");
    try {
      if (!points.empty()) maps.emplace(points);
    } catch (const std::exception& e) {
      no_maps = runs::one_line(e.what());
    }
  }
  std::vector<std::string> texts(shapes_.size());
  for (std::size_t k = 0; k < shapes_.size(); ++k)
    if (share.mine(k)) texts[k] = resolved_text(shapes_[k], maps ? &*maps : nullptr, no_maps);
  share.exchange(texts);
  for (std::size_t k = 0; k < shapes_.size(); ++k) take_text(shapes_[k], texts[k]);
}

std::string body_rotors::fallback_note() const {
  std::vector<std::pair<std::string, int>> reasons;  // in the order the shapes meet them
  int count = 0;
  for (const auto& s : shapes_) {
    if (s.fallback.empty()) continue;
    ++count;
    auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto& r) { return r.first == s.fallback; });
    if (it == reasons.end()) reasons.emplace_back(s.fallback, 1);
    else ++it->second;
  }
  if (count == 0) return "";
  std::ostringstream line;
  line << "rotor auto: the exact rotor runs " << count << " of " << body_shapes_text(shapes_.size()) << ":";
  for (std::size_t k = 0; k < reasons.size(); ++k)
    line << (k ? ";" : "") << " " << reasons[k].first << " (" << reasons[k].second << (reasons[k].second == 1 ? " shape)" : " shapes)");
  return line.str();
}

std::vector<body_shape> body_rotors::take_new_shapes() {
  std::vector<body_shape> out(new_shapes_.begin() + static_cast<std::ptrdiff_t>(new_shapes_taken_), new_shapes_.end());
  new_shapes_taken_ = new_shapes_.size();
  return out;
}

const body_rotor& body_rotors::rotor_for(const std::array<double, 3>& moments, long body_id) {
  auto it = rotors_.find(moments);
  if (it != rotors_.end()) return *it->second;
  const body_shape* s = shape_of(moments);
  if (!s) {
    const auto known = std::find_if(new_shapes_.begin(), new_shapes_.end(), [&](const auto& n) { return same_shape(n.moments, moments); });
    if (known == new_shapes_.end()) new_shapes_.push_back({moments, body_id, std::nullopt, "exact", ""});
  }
  models::vec3<double> I{moments[0], moments[1], moments[2]};
  std::unique_ptr<body_rotor> r;
  if (s && s->table)
    r = std::make_unique<rotor_of<models::table_rotor<double>>>(models::table_rotor<double>(*s->table, I));
  else  // a listed rotor; a shape met during a run, the one asked for if it is listed, else the exact one
    r = models::with_closed_form_rotor<double>(s ? s->closed_form : request_.what == rotor_request::kind::closed_form ? request_.name : "exact",
                                               [&](auto rotor) -> std::unique_ptr<body_rotor> {
      using R = typename decltype(rotor)::type;
      return std::make_unique<rotor_of<R>>(R(I));
    });
  return *rotors_.emplace(moments, std::move(r)).first->second;
}

}  // namespace rotlie::lammps
