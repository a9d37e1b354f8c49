#pragma once
// The body-set maps as JSON lines (one per body, written as computed): a header line that names
// the map (family, grid), then one line per body in the grid's order. A file is resumable: its
// header says which map it belongs to, and every body line says which body it is.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::reports {

inline constexpr int map_format_version = 1;

/// {"rotlie_map":1,"family":"N","grid":200,"bodies":39800,"reference":"RS4-S5-McLachlan","method":"fast"}
/// method: "fast" (continuation confirmed by the exact solver) or "exact" (a header without it: exact).
nlohmann::ordered_json map_header(const std::string& family, int K, std::size_t bodies, const std::string& method);

/// One body: s, t and I as exact fractions, the best integrator as SCHEME:PERM:LABEL, its ‖H_R5‖,
/// the reference at its best permutation, the equal-cost ratio, the singular systems (SCHEME:PERM),
/// and the best per permutation.
nlohmann::ordered_json map_line(const solver::grid_body& g, const solver::map_point& p);

/// A body whose exact solve failed (the map goes on; the line says why).
nlohmann::ordered_json map_failure_line(const solver::grid_body& g, const std::string& family, const std::string& why);

/// The grid indices (i, j) a body line stands for, checked against the grid K: nullopt when the
/// line is not a body line of that grid.
std::optional<std::pair<int, int>> map_line_indices(const nlohmann::json& line, int K);

/// "14/25": an exact rational as text.
std::string fraction_text(const cln::cl_RA& x);

}  // namespace rotlie::reports
