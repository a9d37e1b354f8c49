#include "rotlie/solver/body_grid.hpp"

#include <algorithm>
#include <stdexcept>

namespace rotlie::solver {

grid_body grid_point(int K, int i, int j) {
  if (K < 1 || K > max_grid_divisions)
    throw std::invalid_argument("the grid needs 1 to " + std::to_string(max_grid_divisions) + " divisions, got " +
                                std::to_string(K));
  if (i < 0 || i > K || j < 0 || j > K) throw std::invalid_argument("grid index outside 0 … K");
  grid_body g;
  g.i = i;
  g.j = j;
  g.s = cln::cl_RA(i) / K;
  g.t = cln::cl_RA(j) / K;
  const cln::cl_RA I2 = cln::cl_RA(1) / 2 + g.s / 2;
  const cln::cl_RA I1 = (1 - I2) + g.t * (2 * I2 - 1);
  g.body = {{I1, I2, cln::cl_RA(1)}};
  g.symmetric = I1 == I2 || I2 == 1;  // I1 ≤ I2 ≤ 1 on the whole triangle
  g.flat = I1 + I2 == 1;
  return g;
}

std::vector<grid_body> body_grid(int K) {
  grid_point(K, 0, 0);  // checks K
  std::vector<grid_body> out;
  out.reserve(static_cast<std::size_t>(K + 1) * static_cast<std::size_t>(K + 1));
  for (int i = 0; i <= K; ++i)
    for (int j = 0; j <= K; ++j) out.push_back(grid_point(K, i, j));
  return out;
}

std::vector<grid_body> asymmetric_grid(int K) {
  auto all = body_grid(K);
  std::erase_if(all, [](const grid_body& g) { return g.symmetric; });
  return all;
}

std::pair<cln::cl_RA, cln::cl_RA> triangle_coordinates(const lie::moments_of_inertia& body) {
  lie::validate_moments(body);
  auto m = body.I;
  std::sort(m.begin(), m.end());
  const cln::cl_RA I1 = m[0] / m[2], I2 = m[1] / m[2];
  if (I1 == I2 || I2 == 1) throw std::invalid_argument("a symmetric top has no place in the maps (two equal moments)");
  const cln::cl_RA s = 2 * I2 - 1;
  return {s, (I1 - (1 - I2)) / (2 * I2 - 1)};
}

}  // namespace rotlie::solver
