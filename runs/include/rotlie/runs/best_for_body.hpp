#pragma once
// The best integrator for one body (`rotlie best`): the best N, R and P integrators by analytic
// remainder ‖H_R5‖ (eq. 64), the reference RS4 S5 McLachlan at its best permutation and the gain
// predicted at equal cost — the map's answer (LV section 5) for a body off the grid; and, unless
// analytic only, every real solution and every reference scheme measured by the protocol at the
// fixed reduced step h/C = 1/1980 (measured_best.hpp).
#include <cln/rational.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/runs/measured_best.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::runs {

/// --inertia of `best`: exact moments of an asymmetric body (a symmetric top is outside the maps).
/// Throws bad_input.
lie::moments_of_inertia best_body(const std::string& text);

struct measured_candidate {
  std::string name;
  double remainder = 0, error = 0;
};

struct measured_family {
  std::vector<measured_candidate> candidates;  ///< every real solution, by ascending measured error
  double analytic_best_error = 0;              ///< the measured error of the analytic best
};

struct best_result {
  lie::moments_of_inertia body;
  cln::cl_RA s, t;                          ///< the body's place in the triangle of section 5
  std::vector<solver::map_point> points;    ///< one per family (N, R, P)
  std::string reference;                    ///< RS4-S5-McLachlan:PERM at its best analytic permutation
  std::string recommended;                  ///< the largest predicted gain, or the reference
  bool measured = false;                    ///< the measured columns below are filled
  std::vector<measured_family> measured_families;  ///< one per point
  std::vector<measured_reference> references;
  std::optional<measured_reference> rs4, best_reference;
  std::string recommended_measured;
  double cpu_seconds = 0;
};

best_result best_for_body(const lie::moments_of_inertia& body, bool analytic_only,
                          const std::function<void(const std::string&)>& progress = {});

}  // namespace rotlie::runs
