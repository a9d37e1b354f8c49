// SPDX-License-Identifier: GPL-2.0-or-later
#include "body_rotors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/exact_free_rotation.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/models/table_rotor.hpp"
#include "rotlie/runs/best_for_body.hpp"
#include "rotlie/runs/scheme_names.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::lammps {
namespace {

template <class Rotor>
class rotor_of final : public body_rotor {
 public:
  explicit rotor_of(Rotor r) : r_(std::move(r)) {}
  void advance(models::body_state<double>& s, double t) const override { r_.advance(s, t); }

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

// Whether a table solved for `inertia` (its `inertia` line) fits moments I: the ratios agree.
bool table_fits(const schemes::scheme_table& t, const std::array<double, 3>& I) {
  if (t.inertia.empty()) return true;  // a reference scheme: every body
  const auto J = models::moments_from_text<double>(t.inertia);
  // compared up to a common factor, as the solver's tables are (H_R3 is homogeneous in the moments)
  const double scale = I[2] / J[2];
  for (std::size_t k = 0; k < 3; ++k)
    if (std::abs(J[k] * scale - I[k]) > shape_tolerance * I[2]) return false;
  return true;
}

}  // namespace

bool same_shape(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double big = std::max({a[0], a[1], a[2], b[0], b[1], b[2]});
  for (std::size_t k = 0; k < 3; ++k)
    if (std::abs(a[k] - b[k]) > shape_tolerance * big) return false;
  return true;
}

rotor_request parse_rotor(const std::string& value) {
  if (value.empty()) throw runs::bad_input("rotor needs a value: exact, auto, a scheme name or a scheme-table file");
  if (value == "exact") return {rotor_request::kind::exact, ""};
  if (value == "auto") return {rotor_request::kind::automatic, ""};
  return {rotor_request::kind::table, value};
}

const body_shape* body_rotors::shape_of(const std::array<double, 3>& moments) const {
  for (const auto& s : shapes_)
    if (same_shape(s.moments, moments)) return &s;
  return nullptr;
}

void body_rotors::resolve_shapes(const std::vector<std::pair<std::array<double, 3>, long>>& bodies) {
  shapes_.clear();
  rotors_.clear();
  for (const auto& [I, id] : bodies) {
    if (shape_of(I)) continue;
    body_shape s;
    s.moments = I;
    s.first_body = id;
    const bool linear = !(I[0] > 0);  // the closed-form rotation runs linear bodies (the fix)
    if (request_.what == rotor_request::kind::table && !linear) {
      s.table = runs::scheme_named(request_.name, exact_shape(I), runs::foreign_table::use_with_warning,
                                   [](const std::string&) {});  // checked below, with LAMMPS's tolerance
      if (s.table->splitting == schemes::split::tv)
        throw runs::bad_input("rotor " + request_.name + ": a TV table is an integrator, not a free rotation (ABC or RS)");
      if (!table_fits(*s.table, I))
        throw runs::bad_input("rotor " + request_.name + ": the table was solved for moments (" + s.table->inertia +
                              "), not for body " + std::to_string(id) + " with moments " + moments_text(I));
      s.table_name = s.table->name;
    } else if (request_.what == rotor_request::kind::automatic && !linear) {
      try {
        const auto best = runs::best_for_body(exact_shape(I), true);
        s.table = runs::scheme_named(best.recommended, best.body);
        s.table_name = best.recommended;
      } catch (const runs::bad_input&) {
        s.table_name = "exact";  // a symmetric top is outside the maps: the exact rotation
      }
    } else {
      s.table_name = "exact";
    }
    shapes_.push_back(std::move(s));
  }
}

const body_rotor& body_rotors::rotor_for(const std::array<double, 3>& moments, long body_id) {
  auto it = rotors_.find(moments);
  if (it != rotors_.end()) return *it->second;
  const body_shape* s = shape_of(moments);
  if (!s)
    throw runs::bad_input("rotor: body " + std::to_string(body_id) + " with moments " + moments_text(moments) +
                          " appeared after the shapes were resolved (a new body shape during a run)");
  models::vec3<double> I{moments[0], moments[1], moments[2]};
  std::unique_ptr<body_rotor> r;
  if (s->table)
    r = std::make_unique<rotor_of<models::table_rotor<double>>>(models::table_rotor<double>(*s->table, I));
  else
    r = std::make_unique<rotor_of<models::exact_free_rotation<double>>>(models::exact_free_rotation<double>(I));
  return *rotors_.emplace(moments, std::move(r)).first->second;
}

}  // namespace rotlie::lammps
