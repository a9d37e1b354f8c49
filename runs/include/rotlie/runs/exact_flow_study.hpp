#pragma once
// The measurements of the report's section "Exact free-body flow near the unstable axis and in the
// other hard regimes": the double-precision exact flow (models/exact_free_body.hpp) against its float128
// instance over the middle-axis offset, near-spherical, thin and flat bodies, the scale of |G| and long
// times, with the flow's own error estimate. Plain numbers; reports/exact_flow_section formats and draws them.
#include <string>
#include <vector>

#include "rotlie/models/small_matrix.hpp"

namespace rotlie::runs {

/// One case: its family and parameter as shown, body, G(0), T.
struct exact_flow_regime {
  std::string family, parameter;
  models::vec3<double> I, G;
  double T;
  double x = 0;  ///< the chart's abscissa (offset or anisotropy), 0 when not charted
};

/// Max abs entry error of Q and of G/|G| over 16 times in (0, T], the flow's largest estimate there,
/// and the attitude error of the flow composed of two halves at T.
struct exact_flow_measured {
  double mc = 0, q = 0, g = 0, estimate = 0, composed = 0;
};

struct exact_flow_case {
  exact_flow_regime regime;
  exact_flow_measured measured;
};

/// Every regime measured (`quick`: fewer offsets and anisotropies).
std::vector<exact_flow_case> exact_flow_study(bool quick);

}  // namespace rotlie::runs
