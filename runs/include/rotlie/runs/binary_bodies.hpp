#pragma once
// The bodies of `rotlie binary` as a user names them: `ellipsoid:a,b,c` (semi-axes in km, a ≥ b ≥ c
// along the body x, y, z) or `polyhedron:FILE` (a shape model in km: Wavefront OBJ `v`/`f` lines, the
// plain form "N_vertices N_facets" then the vertices and the 1-based facets, or Gaskell's ICQ form, Q
// then 6(Q+1)² vertices) or `gubas:VERTICES,FACETS` (GUBAS's CSV pair in metres), homogeneous, of a
// density (kg/m³) or a mass (kg). Each becomes a gravitating body in its principal frame (the
// integrals to degree 4) with what the contact check needs: its bounding and inner radii and points
// of its surface. Named systems hold both bodies and the start.
#include <array>
#include <string>
#include <vector>

#include "rotlie/models/scenes/inertia_integrals.hpp"
#include "rotlie/models/scenes/polyhedron_body.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

struct binary_body {
  std::string spec;                         ///< as typed
  std::string kind;                         ///< "ellipsoid" or "polyhedron"
  std::array<double, 3> semi_axes{};        ///< km (an ellipsoid)
  models::polyhedron shape;                 ///< km, in the principal frame about the centre of mass (a polyhedron)
  models::mat3<double> axes = models::mat3<double>::identity();  ///< the principal axes in the shape file's frame (columns)
  models::vec3<double> centroid{};          ///< the centre of mass in the shape file's frame
  double volume = 0;                        ///< km³
  double density = 0;                       ///< kg/m³
  double bounding_radius = 0;               ///< km: no point of the body lies farther from its centre
  double inner_radius = 0;                  ///< km: a ball about the centre that lies inside the body
  models::gravitating_body<double> body;    ///< kg, kg·km², … in the principal frame
  std::vector<models::vec3<double>> surface;  ///< points of the surface, principal frame (the contact check)
};

/// The shape of `spec` (option names it in messages) without its mass. Throws bad_input.
binary_body binary_shape_named(const std::string& spec, const std::string& option);

/// The shape given its density in kg/m³ (mass = density × 10⁹ × volume in km³) or its mass in kg.
binary_body with_density(binary_body shape, double density_kg_m3);
binary_body with_mass(binary_body shape, double mass_kg);
/// The body with its inertia integrals to `degree` (kg·km^k): above 4 its monomial moments, exact for
/// an ellipsoid (closed form) and a polyhedron (its tetrahedra), after its density is set.
binary_body with_degree(binary_body body, int degree);

/// A shape model's text (OBJ, the plain form or ICQ, told apart by the first line); `name` names it in messages. Throws bad_input naming the
/// line of a coordinate that is not a number or beyond 1e20 km in size, or vertices spanning less than
/// 1e-12 km. (Whether the mesh bounds a solid is polyhedron_body's check.)
models::polyhedron parse_shape_model(const std::string& text, const std::string& name);

/// Whether the two bodies touch at this configuration (Q maps each body's principal frame to inertial,
/// r = centre 2 − centre 1): a point of one body's surface inside the other. Bounding spheres apart
/// answer at once; an ellipsoid is sampled by 1,026 surface points, a polyhedron by its vertices, so
/// contact is seen to the sampling's resolution.
bool bodies_touch(const binary_body& primary, const models::mat3<double>& Q1, const binary_body& secondary, const models::mat3<double>& Q2,
                  const models::vec3<double>& r);

/// A named binary system: both bodies, densities and the circular start.
struct binary_system_preset {
  std::string name;
  std::string primary, secondary;  ///< shape specs
  double density1 = 0, density2 = 0;  ///< kg/m³
  double separation = 0;              ///< km
  double primary_period = 0;          ///< hours
  std::string source;                 ///< where each number comes from
};

/// didymos (see the definition for each number's source).
const std::vector<binary_system_preset>& binary_system_presets();

/// Throws bad_input naming --system.
const binary_system_preset& binary_system_named(const std::string& name);

}  // namespace rotlie::runs
