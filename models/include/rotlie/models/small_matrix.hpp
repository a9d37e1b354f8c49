#pragma once
// 3-vectors and 3×3 matrices on any scalar, on the stack: the step loop never allocates and
// float128 needs no Eigen NumTraits.
#include <array>
#include <cmath>

namespace rotlie::models {

template <class T>
using vec3 = std::array<T, 3>;

template <class T>
struct mat3 {
  std::array<T, 9> a{};  // row-major
  T& operator()(int i, int j) { return a[static_cast<std::size_t>(3 * i + j)]; }
  const T& operator()(int i, int j) const { return a[static_cast<std::size_t>(3 * i + j)]; }
  static mat3 identity() {
    mat3 m;
    m(0, 0) = m(1, 1) = m(2, 2) = T(1);
    return m;
  }
};

template <class T>
mat3<T> operator*(const mat3<T>& x, const mat3<T>& y) {
  mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = x(i, 0) * y(0, j) + x(i, 1) * y(1, j) + x(i, 2) * y(2, j);
  return r;
}

template <class T>
vec3<T> operator*(const mat3<T>& m, const vec3<T>& v) {
  return {m(0, 0) * v[0] + m(0, 1) * v[1] + m(0, 2) * v[2], m(1, 0) * v[0] + m(1, 1) * v[1] + m(1, 2) * v[2],
          m(2, 0) * v[0] + m(2, 1) * v[1] + m(2, 2) * v[2]};
}

template <class T>
mat3<T> transpose(const mat3<T>& m) {
  mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m(j, i);
  return r;
}

template <class T>
T dot(const vec3<T>& x, const vec3<T>& y) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/// Euclidean length of x.
template <class T>
T norm(const vec3<T>& x) {
  using std::sqrt;
  return sqrt(dot(x, x));
}

/// Frobenius norm of x − y: the paper's attitude error is this for the attitude matrices (R^9).
template <class T>
T distance(const mat3<T>& x, const mat3<T>& y) {
  T s = 0;
  for (std::size_t i = 0; i < 9; ++i) s += (x.a[i] - y.a[i]) * (x.a[i] - y.a[i]);
  using std::sqrt;
  return sqrt(s);
}

/// Active rotation by θ about unit axis u (Rodrigues).
template <class T>
mat3<T> rotation(const vec3<T>& u, const T& theta) {
  using std::cos;
  using std::sin;
  const T c = cos(theta), s = sin(theta), k = 1 - c;
  mat3<T> r;
  r(0, 0) = c + k * u[0] * u[0];
  r(0, 1) = k * u[0] * u[1] - s * u[2];
  r(0, 2) = k * u[0] * u[2] + s * u[1];
  r(1, 0) = k * u[1] * u[0] + s * u[2];
  r(1, 1) = c + k * u[1] * u[1];
  r(1, 2) = k * u[1] * u[2] - s * u[0];
  r(2, 0) = k * u[2] * u[0] - s * u[1];
  r(2, 1) = k * u[2] * u[1] + s * u[0];
  r(2, 2) = c + k * u[2] * u[2];
  return r;
}

}  // namespace rotlie::models
