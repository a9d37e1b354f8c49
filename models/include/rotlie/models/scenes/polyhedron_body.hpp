#pragma once
// A homogeneous polyhedron (a shape model: vertices and triangular facets, counter-clockwise seen from
// outside) as a gravitating body: its inertia integrals to degree 4, exact. Each facet (a, b, c) and
// the origin span a tetrahedron of signed volume det[a b c]/6; over a tetrahedron with vertices 0, v₁,
// v₂, v₃ the barycentric moments ∫ λ^α dV = 6V α!/(|α|+3)! give
//   ∫ ρ^⊗k dV = 6V/(k+3)! Σ_{j₁…j_k ∈ {1,2,3}} α(j)! v_{j₁} ⊗ … ⊗ v_{j_k},
// and the signed tetrahedra sum to the solid for a closed, outward-oriented surface that does not meet
// itself (polyhedron_check.hpp says which meshes are such; edges of four facets are). The integrals are
// taken about the centroid, then turned into the principal axes (sorted as an ellipsoid's a ≥ b ≥ c
// along x, y, z: the moments ascending).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "rotlie/models/scenes/inertia_integrals.hpp"
#include "rotlie/models/scenes/polyhedron_check.hpp"
#include "rotlie/models/scenes/polyhedron_moments.hpp"
#include "rotlie/models/small_matrix.hpp"

namespace rotlie::models {

/// A homogeneous polyhedron's body and where its principal frame sits in the shape's frame.
template <class T>
struct polyhedron_integrals {
  gravitating_body<T> body;  // in the principal frame, about the centroid
  T volume{};
  vec3<T> centroid{};  // in the shape's frame
  mat3<T> axes{};      // columns: the principal axes in the shape's frame (det +1)
};

namespace polyhedron_detail {

/// Σ over facets of the tetrahedra's ∫ ρ^⊗k dV, degree k = 0…4 at std::get<k> (the volume, the first
/// moments, the second, …), the vertices shifted by −origin and turned by Rᵀ.
template <class T>
using raw_integrals = std::tuple<tensor3<T, 0>, tensor3<T, 1>, tensor3<T, 2>, tensor3<T, 3>, tensor3<T, 4>>;

template <class T, int K>
void add_degree(tensor3<T, K>& sum, const vec3<T> (&v)[3], const T& weight) {
  // Σ_{j ∈ {0,1,2}^K} α(j)! Π v_{j_m}[i_m], for every index tuple i
  constexpr std::size_t sequences = power_of_three(K);
  for (std::size_t i = 0; i < sum.size(); ++i) {
    T total = 0;
    for (std::size_t j = 0; j < sequences; ++j) {
      int count[3] = {0, 0, 0};
      T product = 1;
      std::size_t ri = i, rj = j;
      for (int m = 0; m < K; ++m, ri /= 3, rj /= 3) {
        ++count[rj % 3];
        product *= v[rj % 3][ri % 3];
      }
      const int factorial[5] = {1, 1, 2, 6, 24};
      total += T(factorial[count[0]] * factorial[count[1]] * factorial[count[2]]) * product;
    }
    sum[i] += weight * total;
  }
}

template <class T>
raw_integrals<T> integrate(const polyhedron& shape, const vec3<T>& origin, const mat3<T>& R) {
  raw_integrals<T> out;
  for (const auto& t : shape.facets) {
    vec3<T> v[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const auto& p = shape.vertices[static_cast<std::size_t>(t[k])];
      const vec3<T> shifted{T(p[0]) - origin[0], T(p[1]) - origin[1], T(p[2]) - origin[2]};
      v[k] = transpose(R) * shifted;
    }
    const T six_volume = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) - v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0]) +
                         v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
    const T weight[5] = {six_volume / 6, six_volume / 24, six_volume / 120, six_volume / 720, six_volume / 5040};  // 6V/(k + 3)!
    [&]<std::size_t... K>(std::index_sequence<K...>) {
      (add_degree<T, static_cast<int>(K)>(std::get<K>(out), v, weight[K]), ...);
    }(std::make_index_sequence<5>{});
  }
  return out;
}

/// The eigenvectors of a symmetric 3×3 matrix by cyclic Jacobi rotations (columns), any scalar.
template <class T>
mat3<T> symmetric_eigenvectors(mat3<T> a) {
  using std::abs;
  using std::sqrt;
  mat3<T> v = mat3<T>::identity();
  for (int sweep = 0; sweep < 64; ++sweep) {
    const T off = abs(a(0, 1)) + abs(a(0, 2)) + abs(a(1, 2));
    const T diagonal = abs(a(0, 0)) + abs(a(1, 1)) + abs(a(2, 2));
    if (off <= diagonal * std::numeric_limits<T>::epsilon() / 8 || off == T(0)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a(p, q) == T(0)) continue;
        const T theta = (a(q, q) - a(p, p)) / (2 * a(p, q));
        const T t = (theta >= 0 ? T(1) : T(-1)) / (abs(theta) + sqrt(theta * theta + 1));
        const T c = 1 / sqrt(t * t + 1), s = t * c;
        mat3<T> J = mat3<T>::identity();
        J(p, p) = c, J(q, q) = c, J(p, q) = s, J(q, p) = -s;
        a = transpose(J) * a * J;
        v = v * J;
      }
  }
  return v;
}

}  // namespace polyhedron_detail

/// The homogeneous polyhedron of this density (kg per km³ when the vertices are in km) as a body,
/// its integrals exact to round-off, to `degree` (above 4 as moments too). Throws std::invalid_argument
/// for a mesh check_polyhedron refuses or one whose volume is not positive (facets facing inward).
template <class T>
polyhedron_integrals<T> polyhedron_body(const polyhedron& shape, const T& density, int degree = 4) {
  using namespace polyhedron_detail;
  check_polyhedron(shape);
  if (!(density > 0)) throw std::invalid_argument("polyhedron: the density must be positive");
  const auto identity = mat3<T>::identity();
  const auto about_origin = integrate<T>(shape, vec3<T>{}, identity);
  const T volume = std::get<0>(about_origin)[0];
  if (!(volume > 0))
    throw std::invalid_argument("polyhedron: the volume is not positive (the facets face inward, or the solid is flat)");
  polyhedron_integrals<T> out;
  out.volume = volume;
  for (std::size_t k = 0; k < 3; ++k) out.centroid[k] = std::get<1>(about_origin)[k] / volume;
  const auto central = integrate<T>(shape, out.centroid, identity);
  mat3<T> J;
  J.a = std::get<2>(central);
  auto axes = symmetric_eigenvectors(J);
  // sort by the second moment along each axis, descending (the moments of inertia ascending)
  std::array<int, 3> order{0, 1, 2};
  const auto along = [&](int k) { return dot(vec3<T>{axes(0, k), axes(1, k), axes(2, k)}, J * vec3<T>{axes(0, k), axes(1, k), axes(2, k)}); };
  std::sort(order.begin(), order.end(), [&](int x, int y) { return along(x) > along(y); });
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) out.axes(i, k) = axes(i, order[static_cast<std::size_t>(k)]);
  const T det = out.axes(0, 0) * (out.axes(1, 1) * out.axes(2, 2) - out.axes(1, 2) * out.axes(2, 1)) -
                out.axes(0, 1) * (out.axes(1, 0) * out.axes(2, 2) - out.axes(1, 2) * out.axes(2, 0)) +
                out.axes(0, 2) * (out.axes(1, 0) * out.axes(2, 1) - out.axes(1, 1) * out.axes(2, 0));
  if (det < 0)
    for (int i = 0; i < 3; ++i) out.axes(i, 2) = -out.axes(i, 2);
  const auto principal = integrate<T>(shape, out.centroid, out.axes);
  auto& body = out.body;
  body.mass = density * std::get<0>(principal)[0];
  mat3<T> second;
  second.a = std::get<2>(principal);
  const T trace = second(0, 0) + second(1, 1) + second(2, 2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) body.inertia(i, j) = density * ((i == j ? trace : T(0)) - second(i, j));
  for (std::size_t i = 0; i < body.third.size(); ++i) body.third[i] = density * std::get<3>(principal)[i];
  for (std::size_t i = 0; i < body.fourth.size(); ++i) body.fourth[i] = density * std::get<4>(principal)[i];
  body.degree = 4;
  if (degree > 4) {
    body.moments = polyhedron_monomial_moments(shape, out.centroid, out.axes, degree);
    for (auto& x : body.moments) x *= density;
    body.degree = degree;
  } else {  // the tensors' own, read once here rather than at each evaluation
    body.moments.resize(static_cast<std::size_t>(monomials_up_to(4)));
    moments_from_tensors(body, 4, body.moments.data());
  }
  return out;
}

}  // namespace rotlie::models
