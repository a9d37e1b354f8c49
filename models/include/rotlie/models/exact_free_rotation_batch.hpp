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

/// Every body of the block ← its exact free motion over its time (lanes 0 … n−1; the lanes after them
/// are the block's scratch: the last vector's padding). Counts of the two paths in `vectorised` and
/// `one_by_one` when not null.
void advance_block(const exact_free_rotation<double>& rotor, free_body_block& block, std::size_t* vectorised = nullptr,
                   std::size_t* one_by_one = nullptr);

/// The same with each body's own rotor, rotors[i] for lane i: bodies of one shape whose moments differ
/// in their last digits (LAMMPS computes each molecule's moments from its atoms), each advanced as
/// advance_block would with its rotor alone, the vector step reading each lane's constants. A lane
/// whose rotor orders its axes otherwise than rotors[0]'s, or has another accuracy, takes its scalar step.
void advance_block(const exact_free_rotation<double>* const* rotors, free_body_block& block, std::size_t* vectorised = nullptr,
                   std::size_t* one_by_one = nullptr);

/// The vector target the blocks use on this CPU ("AVX2", "AVX3", …), or "none" (one by one).
std::string batch_target();

namespace detail {
// Bodies 0 … n−1, state(i) each, copied into blocks of 64, each block advanced by advance(first, block)
// and copied back; estimate(i, e) receives each error estimate when given.
template <class State, class Advance>
void advance_in_blocks(std::size_t n, State&& state, double t, const std::function<void(std::size_t, double)>& estimate, Advance&& advance) {
  free_body_block block;
  for (std::size_t first = 0; first < n; first += free_body_block::capacity) {
    block.n = std::min(free_body_block::capacity, n - first);
    for (std::size_t i = 0; i < block.n; ++i) {
      const body_state<double>& s = state(first + i);
      for (std::size_t k = 0; k < 3; ++k) block.G[k][i] = s.G[k];
      for (std::size_t e = 0; e < 9; ++e) block.Q[e][i] = s.Q.a[e];
      block.t[i] = t;
    }
    advance(first, block);
    for (std::size_t i = 0; i < block.n; ++i) {
      body_state<double>& s = state(first + i);
      for (std::size_t k = 0; k < 3; ++k) s.G[k] = block.G[k][i];
      for (std::size_t e = 0; e < 9; ++e) s.Q.a[e] = block.Q[e][i];
      if (estimate) estimate(first + i, block.estimate[i]);
    }
  }
}
}  // namespace detail

/// Bodies 0 … n−1 of one kind, each given by state(i) (a body_state<double>&), advanced over the same
/// time t, block by block; estimate(i, e) receives each error estimate when given.
template <class State>
void advance_all(const exact_free_rotation<double>& rotor, std::size_t n, State&& state, double t,
                 const std::function<void(std::size_t, double)>& estimate = {}) {
  detail::advance_in_blocks(n, state, t, estimate, [&](std::size_t, free_body_block& block) { advance_block(rotor, block); });
}

/// The same with each body's own rotor, rotors[i] (advance_block's lanes of own rotors).
template <class State>
void advance_all(const exact_free_rotation<double>* const* rotors, std::size_t n, State&& state, double t,
                 const std::function<void(std::size_t, double)>& estimate = {}) {
  detail::advance_in_blocks(n, state, t, estimate, [&](std::size_t first, free_body_block& block) { advance_block(rotors + first, block); });
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
