#pragma once
// Charts over the triangle of bodies (LV section 5, issue 14's grid): the frame in (I1, I2) with
// I3 = 1, and the contour where a gridded value changes sign.
#include <map>
#include <string>
#include <utility>

#include "rotlie/reports/chart.hpp"

namespace rotlie::reports {

/// An empty chart of bodies in a plane of moments: linear, equal axes, the given ranges.
chart moments_plane_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                          std::pair<double, double> x_range, std::pair<double, double> y_range);

/// An empty chart over the triangle: I1/I3 across, I2/I3 up, equal axes.
chart triangle_chart(const std::string& title);

/// The level 0 of values at the grid points (i, j) of the grid K (s = i/K, t = j/K), by marching
/// squares on the (s, t) cells, drawn in (I1, I2): segments, two points each.
chart_series zero_contour(const std::map<std::pair<int, int>, double>& level, int K, const std::string& name);

}  // namespace rotlie::reports
