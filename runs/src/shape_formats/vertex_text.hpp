#pragma once
// One vertex of a shape model as text: three finite coordinates in km, each at most 1e20 in size.
// Shared by the shape formats (OBJ, the plain form, ICQ), so each refuses a coordinate alike.
#include <functional>
#include <istream>
#include <string>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs::shape_formats {

/// The largest coordinate a shape model may hold, km (its integrals to degree 4 stay in double's range).
inline constexpr double largest_coordinate = 1e20;

/// The next three words of `words` as a vertex; `refuse` (which throws) is told why one is not usable.
models::vec3<double> vertex_of(std::istream& words, const std::function<void(const std::string&)>& refuse);

}  // namespace rotlie::runs::shape_formats
