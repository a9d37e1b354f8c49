#pragma once
// A rigid body's inertia integrals of any degree as monomial moments μ_α = ∫ x^a y^b z^c dm (α = (a, b, c)),
// the symmetric tensor T^(k) stored once per monomial: (k+1)(k+2)/2 numbers at degree k instead of 3^k.
// Monomials are ordered by degree, then by descending a, then by ascending c; all degrees 0…n take
// (n+1)(n+2)(n+3)/6 slots. Homogeneous ellipsoids have them in closed form (below); polyhedra exactly
// (polyhedron_moments.hpp).
#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/scenes/inertia_integrals.hpp"

namespace rotlie::models {

/// The highest degree whose monomial tables are built (a series of order N needs N + 1).
constexpr int max_monomial_degree = 24;

constexpr int monomials_of_degree(int n) { return (n + 1) * (n + 2) / 2; }
constexpr int monomials_up_to(int n) { return (n + 1) * (n + 2) * (n + 3) / 6; }
constexpr int first_monomial(int n) { return n * (n + 1) * (n + 2) / 6; }

/// Where x^a y^b z^c sits.
constexpr int monomial_index(int a, int b, int c) {
  const int s = b + c;
  return first_monomial(a + b + c) + s * (s + 1) / 2 + c;
}

/// The exponents of every monomial to max_monomial_degree, in index order, and α! for each.
struct monomial_table {
  std::vector<std::array<int, 3>> exponents;
  std::vector<double> factorial;          // a! b! c!, exact in a double to degree 24
  std::vector<long double> inverse_factorial;  // 1/(a! b! c!)
  static const monomial_table& get() {
    static const monomial_table table = [] {
      monomial_table t;
      for (int n = 0; n <= max_monomial_degree; ++n)
        for (int a = n; a >= 0; --a)
          for (int c = 0; c <= n - a; ++c) t.exponents.push_back({a, n - a - c, c});
      for (const auto& e : t.exponents) {
        double f = 1;
        for (const int p : e)
          for (int q = 2; q <= p; ++q) f *= q;
        t.factorial.push_back(f);
        t.inverse_factorial.push_back(1.0L / static_cast<long double>(f));
      }
      return t;
    }();
    return table;
  }
};

/// The monomial moments of a body given by its mass, inertia and full third- and fourth-degree tensors,
/// degrees 0…min(degree, 4) (the first-degree ones vanish about the centre of mass); `out` has
/// monomials_up_to(degree) slots, those above 4 left as they are.
template <class T>
void moments_from_tensors(const gravitating_body<T>& body, int degree, T* out) {
  out[0] = body.mass;
  for (int i = 1; i < monomials_up_to(std::min(degree, 1)); ++i) out[i] = 0;
  if (degree < 2) return;
  const auto J = second_moments(body.inertia);
  const auto& table = monomial_table::get();
  const auto full_index = [](const std::array<int, 3>& e) {  // the first index tuple with these counts
    std::size_t index = 0;
    for (int axis = 0; axis < 3; ++axis)
      for (int p = 0; p < e[static_cast<std::size_t>(axis)]; ++p) index = 3 * index + static_cast<std::size_t>(axis);
    return index;
  };
  for (int i = first_monomial(2); i < monomials_up_to(std::min(degree, 4)); ++i) {
    const auto& e = table.exponents[static_cast<std::size_t>(i)];
    const int n = e[0] + e[1] + e[2];
    const std::size_t f = full_index(e);
    out[i] = n == 2 ? J.a[f] : n == 3 ? body.third[f] : body.fourth[f];
  }
}

/// Degrees 0…degree of the body's monomial moments: its `moments` when it carries them, else from its
/// tensors (degree ≤ 4). A point mass (no inertia) has zeros above degree 0.
template <class T>
void body_moments(const gravitating_body<T>& body, int degree, T* out) {
  const auto count = static_cast<std::size_t>(monomials_up_to(degree));
  if (body.moments.size() >= count) {
    for (std::size_t i = 0; i < count; ++i) out[i] = body.moments[i];
    return;
  }
  for (std::size_t i = 0; i < count; ++i) out[i] = 0;
  moments_from_tensors(body, std::min(degree, 4), out);
}

/// The homogeneous ellipsoid of semi-axes a, b, c (along x, y, z) and mass M: μ_(2i,2j,2k) =
/// M a^2i b^2j c^2k · 3 (2i−1)!! (2j−1)!! (2k−1)!! / (2n+3)!!, n = i + j + k, the odd ones zero (the unit
/// ball's average of x^2i y^2j z^2k by Γ-functions: ⟨x²⟩ = 1/5, ⟨x⁴⟩ = 3/35, ⟨x²y²⟩ = 1/35).
template <class T>
std::vector<T> ellipsoid_moments(const T& mass, const T& a, const T& b, const T& c, int degree) {
  if (degree < 0 || degree > max_monomial_degree)
    throw std::invalid_argument("ellipsoid moments: degree " + std::to_string(degree) + " (0 to " + std::to_string(max_monomial_degree) + ")");
  const auto& table = monomial_table::get();
  const auto double_factorial = [](int odd) {  // odd!! for odd ≥ −1
    T f = 1;
    for (int q = 3; q <= odd; q += 2) f *= q;
    return f;
  };
  const T axes[3] = {a, b, c};
  std::vector<T> out(static_cast<std::size_t>(monomials_up_to(degree)), T(0));
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& e = table.exponents[i];
    if (e[0] % 2 || e[1] % 2 || e[2] % 2) continue;
    const int n = (e[0] + e[1] + e[2]) / 2;
    T value = 3 * mass / double_factorial(2 * n + 3);
    for (std::size_t k = 0; k < 3; ++k) {
      value *= double_factorial(e[k] - 1);
      for (int p = 0; p < e[k]; ++p) value *= axes[k];
    }
    out[i] = value;
  }
  return out;
}

/// The homogeneous ellipsoid with its integrals to `degree` (≥ 4: the tensors to 4, the moments to degree).
template <class T>
gravitating_body<T> ellipsoid_body(const T& mass, const T& a, const T& b, const T& c, int degree) {
  auto body = ellipsoid_body(mass, a, b, c);
  body.moments = ellipsoid_moments(mass, a, b, c, std::max(degree, 4));
  body.degree = std::max(degree, 4);
  return body;
}

}  // namespace rotlie::models
