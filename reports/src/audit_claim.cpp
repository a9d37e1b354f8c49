// The verdict of a claim: rotlie's measurement against the paper's value, by the kind of comparison.
#include "rotlie/reports/audit_claim.hpp"

#include <algorithm>
#include <cmath>

namespace rotlie::reports {

bool meets(const expectation& e, const measurement& m) {
  const double x = m.number;
  switch (e.kind) {
    case expect_kind::equal_to: return x == e.paper;
    case expect_kind::relative_within: return std::abs(x / e.paper - 1) <= e.tolerance;
    case expect_kind::absolute_within: return std::abs(x - e.paper) <= e.tolerance;
    case expect_kind::at_most: return x <= e.paper;
    case expect_kind::at_least: return x >= e.paper;
    case expect_kind::below: return x < e.paper;
    case expect_kind::between_0_and: return x > 0 && x < e.paper;
    case expect_kind::each_within:
      return !m.deviations.empty() &&
             std::all_of(m.deviations.begin(), m.deviations.end(), [&](double d) { return std::abs(d) <= e.tolerance; });
    case expect_kind::same_names: return m.names == e.names;
    case expect_kind::same_name_set: {
      auto ours = m.names, paper = e.names;
      std::sort(ours.begin(), ours.end()), std::sort(paper.begin(), paper.end());
      return ours == paper;
    }
    case expect_kind::names_differ: return m.names.size() == 2 && m.names[0] != m.names[1];
    case expect_kind::holds: return m.flag;
    case expect_kind::cannot_check: return false;
  }
  return false;
}

}  // namespace rotlie::reports
