#pragma once
// GUBAS's polyhedron files (Davis & Scheeres): a vertex CSV, one "id, x, y, z" row per vertex in metres
// (the first column ignored, as GUBAS does), and a facet CSV, one row of three 1-based vertex numbers
// per facet (empty fields after them allowed: GUBAS's own files end each row with ",,"). GUBAS takes
// |det| of each facet's tetrahedron, so its files carry no agreed turn: the facets are turned outward.
#include <string>

#include "rotlie/models/scenes/polyhedron_check.hpp"

namespace rotlie::runs::shape_formats {

/// The model in km from the two files' texts; `name` names them in messages. Throws bad_input naming the
/// file and line of a row that is not numbers, or a model enclosing no volume.
models::polyhedron parse_gubas_shape(const std::string& vertices_text, const std::string& facets_text, const std::string& vertices_name,
                                     const std::string& facets_name);

}  // namespace rotlie::runs::shape_formats
