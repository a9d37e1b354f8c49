#pragma once
// The cells a body-set map is drawn with (Figs. 7–10): each body of the grid of K a quadrilateral
// between the midpoints to its grid neighbours, i.e. the grid points (2i ± 1, 2j ± 1) of the grid 2K
// (clamped to it) placed in (I1, I2), so that the cells tile the triangle and a map is drawn
// continuously, without gaps where the placement stretches.
#include <map>
#include <utility>
#include <vector>

namespace rotlie::reports {

class body_cells {
 public:
  explicit body_cells(int K) : K_(K) {}
  /// Appends the five points (four corners, the first repeated) of the cell of body (i, j).
  void add(int i, int j, std::vector<double>& x, std::vector<double>& y);

 private:
  std::pair<double, double> corner(int a, int b);
  int K_;
  std::map<std::pair<int, int>, std::pair<double, double>> placed_;  // corners placed once
};

}  // namespace rotlie::reports
