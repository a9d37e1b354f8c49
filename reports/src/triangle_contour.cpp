#include "rotlie/reports/triangle_contour.hpp"

#include <array>
#include <vector>

namespace rotlie::reports {

chart moments_plane_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                          std::pair<double, double> x_range, std::pair<double, double> y_range) {
  chart c;
  c.title = title;
  c.x_label = x_label;
  c.y_label = y_label;
  c.log_x = c.log_y = false;
  c.equal_axes = true;
  c.x_range = x_range;
  c.y_range = y_range;
  return c;
}

chart triangle_chart(const std::string& title) { return moments_plane_chart(title, "I1 / I3", "I2 / I3", {0.0, 1.0}, {0.48, 1.02}); }

chart_series zero_contour(const std::map<std::pair<int, int>, double>& level, int K, const std::string& name) {
  const auto body_at = [](double s, double t) {  // issue 14's grid: I2 = 1/2 + s/2, I1 = (1 − I2) + t (2 I2 − 1)
    const double I2 = 0.5 + s / 2;
    return std::pair((1 - I2) + t * (2 * I2 - 1), I2);
  };
  chart_series c;
  c.name = name;
  c.segments = true;
  const double k = K;
  for (const auto& [ij, v00] : level) {
    const auto [i, j] = ij;
    const auto a = level.find({i + 1, j}), b = level.find({i, j + 1}), d = level.find({i + 1, j + 1});
    if (a == level.end() || b == level.end() || d == level.end()) continue;
    // the corners in order around the cell: (s, t, value)
    const std::array<std::array<double, 3>, 4> corner = {{{i / k, j / k, v00},
                                                          {(i + 1) / k, j / k, a->second},
                                                          {(i + 1) / k, (j + 1) / k, d->second},
                                                          {i / k, (j + 1) / k, b->second}}};
    std::vector<std::pair<double, double>> crossings;
    for (std::size_t e = 0; e < 4; ++e) {
      const auto& p = corner[e];
      const auto& q = corner[(e + 1) % 4];
      if ((p[2] < 0) == (q[2] < 0)) continue;
      const double f = p[2] / (p[2] - q[2]);
      crossings.push_back(body_at(p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1])));
    }
    for (std::size_t n = 0; n + 1 < crossings.size(); n += 2) {
      c.x.insert(c.x.end(), {crossings[n].first, crossings[n + 1].first});
      c.y.insert(c.y.end(), {crossings[n].second, crossings[n + 1].second});
    }
  }
  return c;
}

}  // namespace rotlie::reports
