#pragma once
// Gaskell's implicitly connected quadrilateral (ICQ) shape models, the form of the PDS's SPC models:
// a line holding Q, then the vertices v(I, J, F) of six cube faces (F = 1 … 6, J = 0 … Q, I = 0 … Q,
// in that nesting), one "x y z" line each. The faces' edge rows are written once per face; they are
// merged through the format's own table of shared edges (not by comparing coordinates), so the mesh
// is closed. Each quadrilateral v(I,J), v(I,J+1), v(I+1,J+1), v(I+1,J) becomes two triangles, turned
// to face outward (which way the I, J axes turn depends on how the faces were laid on the body).
#include <string>
#include <vector>

#include "rotlie/models/scenes/polyhedron_check.hpp"

namespace rotlie::runs::shape_formats {

/// Whether a shape model's first non-blank line reads as ICQ's: a single integer (OBJ starts with a
/// tag, the plain form with two counts).
bool looks_like_icq(const std::string& first_line);

/// The model whose Q is on lines[first]; `name` names it in messages. Throws bad_input in one line for
/// Q out of 1 … 2048, a count of vertex lines other than 6(Q+1)², a line that is not three finite
/// numbers (named), copies of a shared vertex that differ, or a surface enclosing no volume.
models::polyhedron parse_icq_shape(const std::vector<std::string>& lines, std::size_t first, const std::string& name);

}  // namespace rotlie::runs::shape_formats
