// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// The free rotation of the `rotor` keyword for bodies of any shape. A body is known by its principal
// moments in LAMMPS's order (decreasing, as fix rigid/small's eigensolver returns them); rotlie's
// rotors take them increasing. Bodies whose moments agree to shape_tolerance (relative) are one
// shape: a table is resolved once per shape (solved for it, chosen from the shipped maps for it, or
// checked against it), and each body then runs it with its own moments, as LAMMPS's own fixes use
// each body's own moments. Shapes are resolved as text (a scheme table's format), so that the ranks
// of a fix can each resolve a share and hand the others the very same tables.
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::models {
template <class T>
class exact_free_rotation;
}  // namespace rotlie::models

namespace rotlie::lammps {

class shipped_map_lines;

/// Relative agreement of moments (and of a table's moment ratios) that makes one shape: LAMMPS
/// computes each body's moments from its atoms' coordinates, so bodies of one shape differ by the
/// rounding of those coordinates (data files carry 8–17 digits).
inline constexpr double shape_tolerance = 1e-6;

/// A free rotor for one body, in rotlie's frame (moments increasing; see lammps_frame.hpp).
class body_rotor {
 public:
  virtual ~body_rotor() = default;
  virtual void advance(models::body_state<double>& s, double t) const = 0;
  /// The exact rotor behind this one, or nullptr: the fix advances the bodies of one shape together,
  /// each with its own moments (models::advance_all with each body's rotor).
  virtual const models::exact_free_rotation<double>* exact() const { return nullptr; }
};

/// What `rotor VALUE` asks for.
struct rotor_request {
  enum class kind { closed_form, table, automatic } what = kind::closed_form;
  std::string name = "exact";  ///< a listed rotor's name (closed_form_rotors.hpp), or the table: a reference
                               ///< name, SCHEME:PERM:LABEL or a scheme-table file
};

/// The values of the rotor keyword: auto and the registry's rotors (runs/methods.hpp), for messages.
std::string rotor_values_help();

/// Reads VALUE (a listed rotor such as exact, auto, or a table name); throws runs::bad_input for an empty value.
rotor_request parse_rotor(const std::string& value);

/// One shape: its moments (rotlie's increasing order, of its first body) and what runs it.
struct body_shape {
  std::array<double, 3> moments{};
  long first_body = 0;  ///< the ID of a body of this shape (for messages)
  std::optional<schemes::scheme_table> table;
  std::string table_name;  ///< as resolved: the reference or dedicated scheme's name, or the listed rotor's
  std::string fallback;    ///< why the exact rotor runs a shape `rotor auto` found no table for; else empty
  std::string closed_form = "exact";  ///< the listed rotor that runs the shape when it has no table
};

/// How the ranks of a fix share the resolving: whether this rank resolves shape k (of the list every
/// rank holds), and the exchange after which every rank holds every shape's text (each rank has
/// filled in those it resolved). The default: one process resolves every shape.
struct shape_sharing {
  std::function<bool(std::size_t)> mine = [](std::size_t) { return true; };
  std::function<void(std::vector<std::string>&)> exchange = [](std::vector<std::string>&) {};
};

/// The rotors of one fix: shapes resolved up front (resolve_shapes, identical on every rank), then a
/// rotor per distinct set of moments, built on first use.
class body_rotors {
 public:
  explicit body_rotors(rotor_request request) : request_(std::move(request)) {}

  /// Resolves a table for each shape (moments in rotlie's increasing order, with a body ID each);
  /// shapes within shape_tolerance of each other are one. `rotor auto` chooses from the shipped maps
  /// (map_choice.hpp) and falls back to the exact rotor for symmetric tops, or when the maps are not
  /// found or the solver fails (body_shape::fallback says why). `progress` receives one line before
  /// the maps are read. Throws runs::bad_input with one line naming the body whose shape a table does
  /// not fit, or a name that resolves to nothing: the same on every rank.
  void resolve_shapes(const std::vector<std::pair<std::array<double, 3>, long>>& bodies, const shape_sharing& share = {},
                      const std::function<void(const std::string&)>& progress = {});

  /// The rotor of a body with these moments (rotlie's order). A body of a shape that appeared after
  /// resolve_shapes (a body added during a run: fix deposit, fix pour) runs the exact rotor: resolving
  /// a table would need every rank, and only the ranks that own such a body get here.
  const body_rotor& rotor_for(const std::array<double, 3>& moments, long body_id);

  /// The shapes that appeared after resolve_shapes and were not yet taken (one note each).
  std::vector<body_shape> take_new_shapes();

  /// One line on the shapes that fell back to the exact rotor (how many, and why), or empty.
  std::string fallback_note() const;

  /// A 2-d system: every body turns about the plane's normal, a principal axis, by its closed form
  /// (the fix's steady rotation), so `rotor auto` resolves no table (the exact rotor, one note).
  void set_planar(bool planar) { planar_ = planar; }

  const std::vector<body_shape>& shapes() const { return shapes_; }
  const rotor_request& request() const { return request_; }

  /// The resolved shape of moments (within shape_tolerance), or nullptr.
  const body_shape* shape_of(const std::array<double, 3>& moments) const;

 private:
  std::string resolved_text(const body_shape& s, const shipped_map_lines* maps, const std::string& no_maps) const;
  bool needs_map(const body_shape& s) const;
  void take_text(body_shape& s, const std::string& text) const;

  rotor_request request_;
  bool planar_ = false;
  std::vector<body_shape> shapes_;
  std::vector<body_shape> new_shapes_;  ///< appeared after resolve_shapes
  std::size_t new_shapes_taken_ = 0;
  std::map<std::array<double, 3>, std::unique_ptr<body_rotor>> rotors_;
};

/// "1 body shape", "3 body shapes": for the fix's lines.
std::string body_shapes_text(std::size_t n);

/// Whether two sets of moments are one shape: each agrees to shape_tolerance of the largest.
bool same_shape(const std::array<double, 3>& a, const std::array<double, 3>& b);

/// Whether a body (moments increasing) is a symmetric top: two moments agree to shape_tolerance of
/// the largest. The maps leave such bodies out (their dedicated systems are singular).
bool symmetric_top(const std::array<double, 3>& moments);

}  // namespace rotlie::lammps
