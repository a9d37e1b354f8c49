#pragma once
// Formats whose facets carry no agreed turn (ICQ's faces may be laid either way round, GUBAS's facet
// lists are read with |det|) are turned outward by the sign of the volume they enclose.
#include "rotlie/models/scenes/polyhedron_check.hpp"

namespace rotlie::runs::shape_formats {

/// Reverses every facet when the enclosed volume is negative. False when the volume is zero or not
/// finite (nothing enclosed). A mesh turned inconsistently stays so, for polyhedron_body to refuse.
bool turn_outward(models::polyhedron& p);

}  // namespace rotlie::runs::shape_formats
