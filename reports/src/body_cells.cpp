#include "rotlie/reports/body_cells.hpp"

#include <algorithm>
#include <array>

#include "rotlie/runs/maps_study.hpp"

namespace rotlie::reports {

void body_cells::add(int i, int j, std::vector<double>& x, std::vector<double>& y) {
  const std::array<std::pair<int, int>, 5> corners = {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}};
  for (const auto& [di, dj] : corners) {
    const auto p = corner(std::clamp(2 * i + di, 0, 2 * K_), std::clamp(2 * j + dj, 0, 2 * K_));
    x.push_back(p.first);
    y.push_back(p.second);
  }
}

std::pair<double, double> body_cells::corner(int a, int b) {
  auto [it, fresh] = placed_.try_emplace({a, b});
  if (fresh) it->second = runs::grid_moments(2 * K_, a, b);
  return it->second;
}

}  // namespace rotlie::reports
