#pragma once
// A homogeneous polyhedron's monomial moments ∫ x^α dV to any degree, exact to round-off. Over the
// tetrahedron spanned by the origin and a facet's vertices v₁, v₂, v₃ (signed volume V)
//   ∫ x^α dV = 6V α!/(|α|+3)! Σ_{β₁+β₂+β₃=α} Π_j (|β_j|!/β_j!) v_j^β_j
// (the coefficient of ℓ^α in the simplex's ∫ (ℓ·x)^n dV = 6V n!/(n+3)! h_n(ℓ·v₁, ℓ·v₂, ℓ·v₃)), the sum a
// product of three truncated power series in the monomials (polyhedron_body.hpp has the same formula on
// full tensors to degree 4); the tetrahedra sum to the solid.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/scenes/monomial_moments.hpp"
#include "rotlie/models/scenes/mutual_gravity_series.hpp"
#include "rotlie/models/scenes/polyhedron_check.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// ∫ x^α dV over the shape, every |α| ≤ degree, its vertices shifted by −origin and turned by Rᵀ.
template <class T>
std::vector<T> polyhedron_monomial_moments(const polyhedron& shape, const vec3<T>& origin, const mat3<T>& R, int degree) {
  if (degree < 0 || degree > max_gravity_order)
    throw std::invalid_argument("polyhedron moments: degree " + std::to_string(degree) + " (0 to " + std::to_string(max_gravity_order) + ")");
  const auto& table = monomial_table::get();
  const auto& sums = series_detail::monomial_sums::get();
  const auto count = static_cast<std::size_t>(monomials_up_to(degree));
  std::vector<T> out(count, T(0)), power[3], pair(count), triple(count);
  for (auto& p : power) p.resize(count);
  // a tetrahedron's weight per degree n: 6V/(n+3)! times α!, and α! per monomial
  std::vector<T> per_degree(static_cast<std::size_t>(degree) + 1);
  const auto product = [&](const std::vector<T>& x, const std::vector<T>& y, std::vector<T>& xy) {
    for (auto& z : xy) z = 0;
    for (int g = 0; g <= degree; ++g)
      for (int m = 0; g + m <= degree; ++m) {
        const int* sum = sums.of(g, m);
        const int columns = monomials_of_degree(m);
        for (int i = first_monomial(g), row = 0; i < first_monomial(g + 1); ++i, ++row)
          for (int j = 0; j < columns; ++j)
            xy[static_cast<std::size_t>(sum[row * columns + j])] += x[static_cast<std::size_t>(i)] * y[static_cast<std::size_t>(first_monomial(m) + j)];
      }
  };
  std::vector<T> multinomial(count);  // |β|!/β!
  for (std::size_t i = 0; i < count; ++i) {
    const auto& e = table.exponents[i];
    T f = 1;
    for (int q = 2; q <= e[0] + e[1] + e[2]; ++q) f *= q;
    multinomial[i] = f / T(table.factorial[i]);
  }
  for (const auto& t : shape.facets) {
    vec3<T> v[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const auto& p = shape.vertices[static_cast<std::size_t>(t[k])];
      v[k] = transpose(R) * vec3<T>{T(p[0]) - origin[0], T(p[1]) - origin[1], T(p[2]) - origin[2]};
    }
    const T six_volume = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) - v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0]) +
                         v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
    for (std::size_t k = 0; k < 3; ++k) {
      auto& p = power[k];
      p[0] = 1;
      for (std::size_t i = 1; i < count; ++i) {
        auto e = table.exponents[i];
        const std::size_t axis = e[0] > 0 ? 0 : e[1] > 0 ? 1 : 2;
        --e[axis];
        p[i] = p[static_cast<std::size_t>(monomial_index(e[0], e[1], e[2]))] * v[k][axis];
      }
      for (std::size_t i = 1; i < count; ++i) p[i] *= multinomial[i];
    }
    product(power[0], power[1], pair);
    product(pair, power[2], triple);
    T weight = six_volume / 6;  // 6V/3!
    for (int n = 0; n <= degree; ++n) {
      if (n > 0) weight /= n + 3;
      per_degree[static_cast<std::size_t>(n)] = weight;
    }
    for (std::size_t i = 0; i < count; ++i) {
      const auto& e = table.exponents[i];
      out[i] += per_degree[static_cast<std::size_t>(e[0] + e[1] + e[2])] * T(table.factorial[i]) * triple[i];
    }
  }
  return out;
}

}  // namespace rotlie::models
