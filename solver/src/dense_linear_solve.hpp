#pragma once
// A small dense solve by Gaussian elimination with partial pivoting, for the Newton steps of the
// numerical searches (long double while searching, CLN long floats while polishing).
#include <cln/float.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace rotlie::solver::detail {

inline double abs_of(double x) { return std::abs(x); }
inline long double abs_of(long double x) { return std::abs(x); }
inline cln::cl_F abs_of(const cln::cl_F& x) { return cln::abs(x); }
inline bool is_zero(double x) { return x == 0; }
inline bool is_zero(long double x) { return x == 0; }
inline bool is_zero(const cln::cl_F& x) { return cln::zerop(x); }

/// Solves a x = r for the n × n row-major matrix a, x written into r; false when a pivot is
/// exactly zero (the matrix is singular in this arithmetic).
template <class T>
bool solve_linear(std::vector<T> a, std::vector<T>& r, std::size_t n) {
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t i = c + 1; i < n; ++i)
      if (abs_of(a[i * n + c]) > abs_of(a[pivot * n + c])) pivot = i;
    if (is_zero(a[pivot * n + c])) return false;
    if (pivot != c) {
      for (std::size_t j = 0; j < n; ++j) std::swap(a[c * n + j], a[pivot * n + j]);
      std::swap(r[c], r[pivot]);
    }
    for (std::size_t i = c + 1; i < n; ++i) {
      const T f = a[i * n + c] / a[c * n + c];
      if (is_zero(f)) continue;
      for (std::size_t j = c; j < n; ++j) a[i * n + j] = a[i * n + j] - f * a[c * n + j];
      r[i] = r[i] - f * r[c];
    }
  }
  for (std::size_t c = n; c-- > 0;) {
    T s = r[c];
    for (std::size_t j = c + 1; j < n; ++j) s = s - a[c * n + j] * r[j];
    r[c] = s / a[c * n + c];
  }
  return true;
}

}  // namespace rotlie::solver::detail
