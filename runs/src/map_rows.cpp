#include "rotlie/runs/map_rows.hpp"

#include "rotlie/lie/stop_request.hpp"
#include "rotlie/runs/map_file.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continued_map.hpp"
#include "rotlie/solver/screened_map.hpp"

namespace rotlie::runs {

std::string exact_map_line(const solver::grid_body& g, const std::string& family) {
  try {
    return map_line(g, solver::compute_map_point(g.body, family, solver::map_digits)).dump();
  } catch (const std::exception& e) {
    return map_failure_line(g, family, one_line(e.what())).dump();
  }
}

std::vector<std::pair<std::size_t, std::string>> map_row_lines(const std::vector<solver::grid_body>& bodies,
                                                               std::size_t first, std::size_t count,
                                                               const std::vector<char>& done, const std::string& family,
                                                               bch::map_method method) {
  std::vector<std::pair<std::size_t, std::string>> out;
  bool any = false;
  for (std::size_t k = first; k < first + count; ++k) any = any || done[k] == 0;
  if (!any) return out;
  lie::stop_point();
  if (method != bch::map_method::exact) {
    try {
      const std::vector<solver::grid_body> row(bodies.begin() + static_cast<std::ptrdiff_t>(first),
                                               bodies.begin() + static_cast<std::ptrdiff_t>(first + count));
      const auto points = method == bch::map_method::screened ? solver::screened_map_points(row, family)
                                                              : solver::continued_map_points(row, family);
      for (std::size_t k = 0; k < count; ++k)
        if (done[first + k] == 0) out.emplace_back(first + k, map_line(row[k], points[k]).dump());
      return out;
    } catch (const std::exception&) {
      // falls through: body by body, each failure on its own line
    }
  }
  for (std::size_t k = first; k < first + count; ++k)
    if (done[k] == 0) {
      lie::stop_point();
      out.emplace_back(k, exact_map_line(bodies[k], family));
    }
  return out;
}

}  // namespace rotlie::runs
