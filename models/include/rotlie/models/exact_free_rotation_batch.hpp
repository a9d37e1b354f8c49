#pragma once
// The exact free rotation of many bodies of one kind at once (the free flights of SIER2/SIER4 in a
// liquid, a LAMMPS rank's molecules, rows of Python's exact_flow). Bodies are copied into blocks of
// 64 in structure-of-arrays form; a block's bodies in the common regime of the step (what
// exact_free_rotation::advance takes without exact_free_body) go through one evaluation vectorised
// across bodies, each with its own frame, depth of the Gauss transformation and Carlson duplications
// under masks; the others (near the separatrix or a sphere, an energy difference that needs the
// exact sum, an estimate above the accuracy, which exact_free_body then redoes in float128) go
// through exact_free_rotation::advance one by one, as do all of them on a CPU without AVX2 and FMA.
// A body's result does not depend on the other bodies of its block (each lane computes alone, one
// body alone takes the vector path too), only on the CPU: vector or scalar, equal to round-off.
// The vector code is chosen at run time (Highway: AVX2 or AVX-512 where the CPU has it), so the
// binary stays generic x86-64. A body's result equals advance's to round-off: the same formulas,
// with Highway's sin, cos and atan (≤ 3 ulp) for glibc's and Carlson's R_J written here for Boost's.
#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <type_traits>

#include "rotlie/models/exact_free_rotation.hpp"

namespace rotlie::models {

/// Up to 64 bodies of one kind in structure-of-arrays form: G[k][i] is G_k of body i, Q[3r + c][i]
/// the entry (r, c) of its attitude, t[i] its time; estimate[i] is written.
struct free_body_block {
  static constexpr std::size_t capacity = 64;
  alignas(64) double G[3][capacity];
  alignas(64) double Q[9][capacity];
  alignas(64) double t[capacity];
  alignas(64) double estimate[capacity];
  std::size_t n = 0;
};

/// Every body of the block ← its exact free motion over its time. The lanes from n up to the next
/// multiple of 8 are padding (finite values, computed and ignored); the rest are not read. Counts of the two paths in `vectorised`
/// and `one_by_one` when not null.
void advance_block(const exact_free_rotation<double>& rotor, free_body_block& block, std::size_t* vectorised = nullptr,
                   std::size_t* one_by_one = nullptr);

/// The vector target the blocks use on this CPU ("AVX2", "AVX3", …), or "none" (one by one).
std::string batch_target();

/// Bodies 0 … n−1 of one kind, each given by state(i) (a body_state<double>&), advanced over the same
/// time t, block by block; estimate(i, e) receives each error estimate when given.
template <class State>
void advance_all(const exact_free_rotation<double>& rotor, std::size_t n, State&& state, double t,
                 const std::function<void(std::size_t, double)>& estimate = {}) {
  free_body_block block;
  for (std::size_t first = 0; first < n; first += free_body_block::capacity) {
    block.n = std::min(free_body_block::capacity, n - first);
    const std::size_t filled = std::min(free_body_block::capacity, (block.n + 7) / 8 * 8);
    for (std::size_t i = 0; i < filled; ++i) {
      const body_state<double>& s = state(first + (i < block.n ? i : 0));  // padding: copies of the first
      for (std::size_t k = 0; k < 3; ++k) block.G[k][i] = s.G[k];
      for (std::size_t e = 0; e < 9; ++e) block.Q[e][i] = s.Q.a[e];
      block.t[i] = t;
    }
    advance_block(rotor, block);
    for (std::size_t i = 0; i < block.n; ++i) {
      body_state<double>& s = state(first + i);
      for (std::size_t k = 0; k < 3; ++k) s.G[k] = block.G[k][i];
      for (std::size_t e = 0; e < 9; ++e) s.Q.a[e] = block.Q[e][i];
      if (estimate) estimate(first + i, block.estimate[i]);
    }
  }
}

/// Bodies 0 … n−1 of one kind, each state(i), advanced over t by their rotor: all at once for the
/// exact rotor in double, one by one with the rotor's own advance for any other (the tables' rotors
/// are a few cheap stages; long double and float128 keep the scalar step).
template <class Rotor, class State, class T>
void advance_bodies(const Rotor& rotor, std::size_t n, State&& state, const T& t) {
  if constexpr (std::is_same_v<Rotor, exact_free_rotation<double>> && std::is_same_v<T, double>) {
    advance_all(rotor, n, state, t);
  } else {
    for (std::size_t i = 0; i < n; ++i) rotor.advance(state(i), t);
  }
}

}  // namespace rotlie::models
