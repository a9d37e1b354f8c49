#pragma once
// Pieces of the row continuation shared by the two fast paths of the maps (continued_map.hpp,
// screened_map.hpp): a system's state at one body, the exact solve of one system, one continuation
// step along a row, and the map point assembled from the states of every system.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continuation.hpp"
#include "rotlie/solver/family_systems.hpp"

namespace rotlie::solver::detail {

using body_point = std::array<long double, 2>;  ///< (w1, w2) = (1/I1, 1/I2) at I3 = 1

body_point inverse_moments(const grid_body& g);

bool by_first_coefficient(const point3& a, const point3& b);

/// The same solution: every coefficient within 1e-8 relative.
bool same_point(const point3& x, const point3& y);

/// One system at one body: its real solutions from the exact solver, or carried along a chain.
struct system_state {
  std::vector<point3> x;  ///< exact: sorted by x_0; carried: in the order of the chain's start
  bool exact = false;
  bool can_seed = false;  ///< not singular: a start for continuation
  /// Every real solution is known: exact, or carried whole from a complete state with the same count
  /// of real eliminant roots (screened_map.cpp)
  bool complete = false;
  int count = -1;  ///< R, P, when complete: distinct real roots of the eliminant (−1: not known)
  std::vector<dedicated_solution> solutions;  ///< exact only: the exact solver's, with their remainders
  system_report report;                       ///< exact only
};

system_state solve_system_exactly(const body_system& sys, const grid_body& g);

/// The solutions carried from w_from to w_to in 1, 2, …, 2^finest_level equal steps (the first that
/// holds at every step), from a linear extrapolation of the chain when `before` is given; nullopt
/// when none holds.
std::optional<std::vector<point3>> carry(const body_system& system, const std::vector<point3>& from,
                                         const std::vector<point3>* before, body_point w_from, body_point w_to,
                                         int finest_level = 6);

/// The map point of one body from the states of its systems, as solve_dedicated + summarize_family build it.
map_point assemble(const grid_body& g, body_point w, const std::string& family, const std::vector<body_system>& systems,
                   const std::vector<const system_state*>& states);

}  // namespace rotlie::solver::detail
