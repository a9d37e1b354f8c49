// SPDX-License-Identifier: GPL-2.0-or-later
#pragma once
// The free rotation of the `rotor` keyword for bodies of any shape. A body is known by its principal
// moments in LAMMPS's order (decreasing, as fix rigid/small's eigensolver returns them); rotlie's
// rotors take them increasing. Bodies whose moments agree to shape_tolerance (relative) are one
// shape: a table is resolved once per shape (solved for it, or checked against it), and each body
// then runs it with its own moments, as LAMMPS's own fixes use each body's own moments.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/models/rigid_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::lammps {

/// Relative agreement of moments (and of a table's moment ratios) that makes one shape: LAMMPS
/// computes each body's moments from its atoms' coordinates, so bodies of one shape differ by the
/// rounding of those coordinates (data files carry 8–17 digits).
inline constexpr double shape_tolerance = 1e-6;

/// A free rotor for one body, in rotlie's frame (moments increasing; see lammps_frame.hpp).
class body_rotor {
 public:
  virtual ~body_rotor() = default;
  virtual void advance(models::body_state<double>& s, double t) const = 0;
};

/// What `rotor VALUE` asks for.
struct rotor_request {
  enum class kind { exact, table, automatic } what = kind::exact;
  std::string name;  ///< the table: a reference name, SCHEME:PERM:LABEL or a scheme-table file
};

/// Reads VALUE (exact, auto, or a table name); throws runs::bad_input for an empty value.
rotor_request parse_rotor(const std::string& value);

/// One shape: its moments (rotlie's increasing order, of its first body) and what runs it.
struct body_shape {
  std::array<double, 3> moments{};
  long first_body = 0;  ///< the ID of a body of this shape (for messages)
  std::optional<schemes::scheme_table> table;
  std::string table_name;  ///< as resolved: the reference or dedicated scheme's name
};

/// The rotors of one fix: shapes resolved up front (resolve_shapes, identical on every rank), then a
/// rotor per distinct set of moments, built on first use.
class body_rotors {
 public:
  explicit body_rotors(rotor_request request) : request_(std::move(request)) {}

  /// Resolves a table for each shape (moments in rotlie's increasing order, with a body ID each);
  /// shapes within shape_tolerance of each other are one. Throws runs::bad_input with one line
  /// naming the body whose shape a table does not fit, or a name that resolves to nothing.
  void resolve_shapes(const std::vector<std::pair<std::array<double, 3>, long>>& bodies);

  /// The rotor of a body with these moments (rotlie's order); throws runs::bad_input when the body
  /// belongs to no resolved shape.
  const body_rotor& rotor_for(const std::array<double, 3>& moments, long body_id);

  const std::vector<body_shape>& shapes() const { return shapes_; }
  const rotor_request& request() const { return request_; }

  /// The shape of moments (within shape_tolerance), or nullptr.
  const body_shape* shape_of(const std::array<double, 3>& moments) const;

 private:
  rotor_request request_;
  std::vector<body_shape> shapes_;
  std::map<std::array<double, 3>, std::unique_ptr<body_rotor>> rotors_;
};

/// Whether two sets of moments are one shape: each agrees to shape_tolerance of the largest.
bool same_shape(const std::array<double, 3>& a, const std::array<double, 3>& b);

}  // namespace rotlie::lammps
