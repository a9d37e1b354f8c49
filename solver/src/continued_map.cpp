#include "rotlie/solver/continued_map.hpp"

#include <cln/float.h>
#include <cln/real.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "continued_rows.hpp"
#include "rotlie/solver/continuation.hpp"
#include "rotlie/solver/family_systems.hpp"
#include "rotlie/solver/resultant.hpp"

namespace rotlie::solver {
namespace detail {

body_point inverse_moments(const grid_body& g) {
  const auto unit = scaled_to_unit_I3(g.body);
  return {1.0L / static_cast<long double>(cln::double_approx(unit.I[0])),
          1.0L / static_cast<long double>(cln::double_approx(unit.I[1]))};
}

bool by_first_coefficient(const point3& a, const point3& b) { return a[0] < b[0]; }

bool same_point(const point3& x, const point3& y) {
  for (int c = 0; c < 3; ++c)
    if (std::fabs(x[c] - y[c]) > 1e-8L * (1 + std::fabs(y[c]))) return false;
  return true;
}

system_state solve_system_exactly(const body_system& sys, const grid_body& g) {
  const auto r = solve_dedicated(g.body, {sys.scheme}, {sys.permutation}, map_digits);
  system_state out;
  out.exact = true;
  out.complete = true;
  out.report = r.systems.at(0);
  out.count = out.report.eliminant_real_roots;
  // A singular system has no isolated solutions to carry. Roots the exact solver sets aside (a
  // reduced-system root where the linear solve fails, a root that does not certify order 4) are
  // not carried either: should one become a solution further on, the chain's exact end differs.
  out.can_seed = !out.report.degenerate;
  out.solutions = r.solutions;
  std::sort(out.solutions.begin(), out.solutions.end(), [](const auto& a, const auto& b) { return a.label < b.label; });
  for (const auto& s : out.solutions) {
    point3 x{0, 0, 0};
    for (std::size_t k = 0; k < s.free.size(); ++k)
      for (const auto& [name, value] : s.coefficients)
        if (name == s.free[k]) x[k] = static_cast<long double>(cln::double_approx(value));
    out.x.push_back(x);
  }
  return out;
}


// A chain step (continued_rows.hpp). Subdivision first: a step that fails in one piece may hold in
// smaller ones. nullopt when no subdivision holds: a real solution is born or dies, or runs off,
// near this step; the exact solver decides there.
std::optional<std::vector<point3>> carry(const body_system& system, const std::vector<point3>& from,
                                         const std::vector<point3>* before, body_point w_from, body_point w_to,
                                         int finest_level) {
  for (int level = 0; level <= finest_level; ++level) {
    const int steps = 1 << level;
    std::vector<point3> x = from, predicted;
    if (before && before->size() == from.size()) {
      predicted.resize(from.size());
      for (std::size_t i = 0; i < from.size(); ++i)
        for (int c = 0; c < 3; ++c) predicted[i][c] = from[i][c] + (from[i][c] - (*before)[i][c]) / steps;
    }
    bool held = true;
    for (int step = 1; step <= steps; ++step) {
      const long double f = static_cast<long double>(step) / steps;
      const auto numeric =
          evaluate_system(system, w_from[0] + f * (w_to[0] - w_from[0]), w_from[1] + f * (w_to[1] - w_from[1]));
      auto moved = continue_solutions(numeric, x, predicted);
      if (!moved) {
        held = false;
        break;
      }
      predicted.resize(x.size());
      for (std::size_t i = 0; i < x.size(); ++i)
        for (int c = 0; c < 3; ++c) predicted[i][c] = 2 * (*moved)[i][c] - x[i][c];
      x = std::move(*moved);
    }
    if (held) return x;
  }
  return std::nullopt;
}

}  // namespace detail

namespace {

using namespace detail;

// The carried solutions are the exact ones: as many, each within 1e-8.
bool same_solutions(std::vector<point3> carried, const std::vector<point3>& exact) {
  if (carried.size() != exact.size()) return false;
  std::sort(carried.begin(), carried.end(), by_first_coefficient);
  for (std::size_t i = 0; i < exact.size(); ++i)
    if (!same_point(carried[i], exact[i])) return false;
  return true;
}

// One system along one row. The exact solver runs at both ends. A chain from an exact body that
// stops at a body (a solution dying or running off there) is confirmed at the body before by the
// exact solver, which also solves the body where it stopped. A chain that reaches the exact end with
// other solutions than the exact ones (a solution born on the way, which Newton cannot see) is run
// backwards from that end, where the newborn dies and stops it: the exact solver confirms both
// chains next to that stop. What remains unconfirmed is cut at the middle, down to neighbours.
class system_row {
 public:
  system_row(const body_system& system, const std::vector<grid_body>& row, const std::vector<body_point>& w)
      : system_(system), row_(row), w_(w), state_(row.size()), count_(row.size()) {}

  const std::vector<std::optional<system_state>>& solve(continuation_counts& counts) {
    counts_ = &counts;
    exact(0);
    exact(row_.size() - 1);
    between(0, row_.size() - 1);
    return state_;
  }

 private:
  void exact(std::size_t k) {
    if (state_[k] && state_[k]->exact) return;
    state_[k] = solve_system_exactly(system_, row_[k]);
    ++counts_->system_solves;
  }

  // The chain from exact body `from` towards `to` (either direction), as far as it holds:
  // chain[n] is the solutions at from ± (n + 1).
  std::vector<std::vector<point3>> chain(std::size_t from, std::size_t to) {
    std::vector<std::vector<point3>> out;
    if (!state_[from]->can_seed) return out;
    const long step = to > from ? 1 : -1;
    const std::size_t length = to > from ? to - from : from - to;
    for (std::size_t n = 0; n < length; ++n) {
      const auto& last = n == 0 ? state_[from]->x : out.back();
      const auto* before = n == 1 ? &state_[from]->x : n > 1 ? &out[n - 2] : nullptr;
      const std::size_t here = from + static_cast<std::size_t>(step * static_cast<long>(n));
      const std::size_t there = here + static_cast<std::size_t>(step);
      if (!same_count(here, there)) break;
      auto next = carry(system_, last, before, w_[here], w_[there]);
      if (!next && system_.unknowns == 3) next = carry_past_fold(last, before, here, there);
      if (!next) break;
      out.push_back(std::move(*next));
    }
    return out;
  }

  // Three unknowns (R, P), where no cheap count exists: when a step fails, it may be that two
  // solutions meet and leave the reals (a fold). Candidates are pairs of mutual nearest solutions
  // that have come closer since the body before, closest first (at most three); the first whose
  // removal lets every other solution step on is dropped. A pair dropped wrongly reaches the exact
  // end of the chain missing, and `between` then looks for it from that end.
  std::optional<std::vector<point3>> carry_past_fold(const std::vector<point3>& last, const std::vector<point3>* before,
                                                     std::size_t here, std::size_t there) {
    const std::size_t n = last.size();
    if (n < 2) return std::nullopt;
    const auto gap = [](const point3& x, const point3& y) {
      long double d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::fabs(x[c] - y[c]));
      return d;
    };
    std::vector<std::size_t> nearest(n);
    for (std::size_t i = 0; i < n; ++i) {
      nearest[i] = i == 0 ? 1 : 0;
      for (std::size_t j = 0; j < n; ++j)
        if (j != i && gap(last[i], last[j]) < gap(last[i], last[nearest[i]])) nearest[i] = j;
    }
    const bool with_before = before && before->size() == n;
    std::vector<std::pair<long double, std::pair<std::size_t, std::size_t>>> pairs;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = nearest[i];
      if (j <= i || nearest[j] != i) continue;
      const long double d = gap(last[i], last[j]);
      if (with_before && gap((*before)[i], (*before)[j]) <= d) continue;  // not approaching
      pairs.push_back({d, {i, j}});
    }
    std::sort(pairs.begin(), pairs.end());
    for (std::size_t k = 0; k < std::min<std::size_t>(pairs.size(), 3); ++k) {
      const auto [p, q] = pairs[k].second;
      std::vector<point3> rest, rest_before;
      for (std::size_t i = 0; i < n; ++i)
        if (i != p && i != q) {
          rest.push_back(last[i]);
          if (with_before) rest_before.push_back((*before)[i]);
        }
      if (auto moved = carry(system_, rest, with_before ? &rest_before : nullptr, w_[here], w_[there])) return moved;
    }
    return std::nullopt;
  }

  // Every solution of `part` is one of `all`.
  static bool within(const std::vector<point3>& part, const std::vector<point3>& all) {
    for (const auto& x : part)
      if (std::none_of(all.begin(), all.end(), [&](const point3& y) { return same_point(x, y); })) return false;
    return true;
  }

  // Bodies a < k < b from exact ends a and b.
  void between(std::size_t a, std::size_t b) {
    if (b <= a + 1) return;
    auto forward = chain(a, b);
    const std::size_t reached = a + forward.size();
    if (reached == b && same_solutions(forward.back(), state_[b]->x)) return accept(a, b, forward, false);
    if (reached < b) {
      // The chain stopped entering reached + 1: confirm it at `reached`, go on from reached + 1.
      if (reached > a) {
        exact(reached);
        if (same_solutions(forward[reached - a - 1], state_[reached]->x)) accept(a, reached, forward, false);
        else halve(a, reached);
      }
      exact(reached + 1);
      return between(reached + 1, b);
    }
    // At b the chain lacks solutions born on the way. Seen from b they die going back: the chain
    // from b stops entering the body before their birth.
    auto backward = chain(b, a);
    const std::size_t lowest = b - backward.size();
    if (lowest == a) {
      // Both chains cross the whole stretch (R, P: folds dropped on the way). The forward chain holds
      // what lives since a, the backward one what lives until b; when each ends inside the exact
      // solutions of its far end, their union at a body is its solutions (a pair born and dying
      // again strictly between a and b is in neither).
      if (system_.unknowns == 3 && within(forward.back(), state_[b]->x) && within(backward.back(), state_[a]->x)) {
        for (std::size_t k = a + 1; k < b; ++k) {
          system_state s;
          s.x = forward[k - a - 1];
          for (const auto& y : backward[b - k - 1])
            if (std::none_of(s.x.begin(), s.x.end(), [&](const point3& x) { return same_point(x, y); })) s.x.push_back(y);
          s.can_seed = true;
          state_[k] = std::move(s);
        }
        return;
      }
      return halve(a, b);
    }
    if (lowest < b) {
      exact(lowest);
      if (same_solutions(backward[b - lowest - 1], state_[lowest]->x)) accept(lowest, b, backward, true);
      else halve(lowest, b);
    }
    exact(lowest - 1);
    if (lowest - 1 > a && same_solutions(forward[lowest - 1 - a - 1], state_[lowest - 1]->x))
      accept(a, lowest - 1, forward, false);
    else
      between(a, lowest - 1);
  }

  // Bodies a < k < b from a chain that starts at a (or at b when `backward`).
  void accept(std::size_t a, std::size_t b, std::vector<std::vector<point3>>& chain, bool backward) {
    for (std::size_t k = a + 1; k < b; ++k) {
      system_state s;
      s.x = backward ? chain[b - k - 1] : chain[k - a - 1];
      s.can_seed = true;
      state_[k] = std::move(s);
    }
  }

  void halve(std::size_t a, std::size_t b) {
    const std::size_t m = a + (b - a) / 2;
    exact(m);
    between(a, m);
    between(m, b);
  }

  // Two unknowns (N): the number of distinct real roots of the eliminant Res_v(P1, P2)(u) at body k,
  // exactly (the conditions at the exact body, Descartes' rule); −1 when it vanishes identically. A
  // chain may only step between bodies where it is the same: a pair of real solutions born and dying
  // again between the chain's confirmed ends changes it at the bodies where the pair exists.
  // (Three unknowns: this eliminant is the costly part of the exact solver; no count is kept.)
  int eliminant_count(std::size_t k) {
    if (!count_[k]) {
      const auto unit = scaled_to_unit_I3(row_[k].body);
      const cln::cl_RA w1 = cln::recip(unit.I[0]), w2 = cln::recip(unit.I[1]);
      const auto r = resultant_in(system_.p1.at(w1, w2), system_.p2.at(w1, w2), 1, 0);
      count_[k] = r.is_zero() ? -1 : static_cast<int>(isolate_real_roots(r).size());
    }
    return *count_[k];
  }
  bool same_count(std::size_t k, std::size_t next) {
    return system_.unknowns != 2 || (eliminant_count(k) >= 0 && eliminant_count(k) == eliminant_count(next));
  }

  const body_system& system_;
  const std::vector<grid_body>& row_;
  const std::vector<body_point>& w_;
  std::vector<std::optional<system_state>> state_;
  std::vector<std::optional<int>> count_;
  continuation_counts* counts_ = nullptr;
};

}  // namespace

namespace detail {

// The map point of one body from the states of its systems, as solve_dedicated + summarize_family
// build it: solutions in system order, each system's by label, then a stable sort by ‖H_R5‖.
map_point assemble(const grid_body& g, body_point w, const std::string& family, const std::vector<body_system>& systems,
                   const std::vector<const system_state*>& states) {
  family_result result;
  for (std::size_t k = 0; k < systems.size(); ++k) {
    const auto& sys = systems[k];
    const auto& st = *states[k];
    if (st.exact) {
      result.systems.push_back(st.report);
      for (const auto& s : st.solutions) result.solutions.push_back(s);
      continue;
    }
    system_report report;
    report.scheme = sys.scheme;
    report.permutation = sys.permutation;
    report.real_solutions = static_cast<int>(st.x.size());
    result.systems.push_back(report);
    const auto numeric = evaluate_system(sys, w[0], w[1]);
    std::vector<point3> labelled = st.x;
    std::sort(labelled.begin(), labelled.end(), by_first_coefficient);
    int label = 0;
    for (const auto& x : labelled) {
      dedicated_solution s;
      s.scheme = sys.scheme;
      s.permutation = sys.permutation;
      s.label = ++label;
      s.layout = sys.layout;
      s.free = sys.layout.free_coefficients;
      for (std::size_t c = 0; c < s.free.size(); ++c)  // the free coefficients only, to double precision
        s.coefficients.emplace_back(s.free[c], cln::rational(cln::cl_DF(static_cast<double>(x[c]))));
      s.analytic_remainder = static_cast<double>(remainder_norm(numeric, x));
      result.solutions.push_back(std::move(s));
    }
  }
  std::stable_sort(result.solutions.begin(), result.solutions.end(),
                   [](const auto& a, const auto& b) { return a.analytic_remainder < b.analytic_remainder; });
  return summarize_family(g.body, family, result);
}

}  // namespace detail

std::vector<map_point> continued_map_points(const std::vector<grid_body>& row, const std::string& family,
                                            continuation_counts* counts) {
  for (std::size_t k = 1; k < row.size(); ++k)
    if (row[k].i != row[0].i || row[k].j != row[k - 1].j + 1)
      throw std::invalid_argument("continued_map_points needs consecutive bodies of one grid row");
  if (row.empty()) return {};
  using namespace detail;
  const auto& systems = family_systems(family);
  std::vector<body_point> w;
  for (const auto& g : row) w.push_back(inverse_moments(g));
  continuation_counts local;
  std::vector<std::vector<std::optional<system_state>>> states;  // [system][body]
  for (const auto& sys : systems) states.push_back(system_row(sys, row, w).solve(local));
  std::vector<map_point> out;
  int exact_bodies = 0;
  for (std::size_t j = 0; j < row.size(); ++j) {
    std::vector<const system_state*> at;
    bool all_exact = true;
    for (const auto& s : states) {
      at.push_back(&*s[j]);
      all_exact = all_exact && s[j]->exact;
    }
    exact_bodies += all_exact ? 1 : 0;
    out.push_back(assemble(row[j], w[j], family, systems, at));
  }
  if (counts) {
    counts->system_solves += local.system_solves;
    counts->exact += exact_bodies;
    counts->continued += static_cast<int>(row.size()) - exact_bodies;
  }
  return out;
}

}  // namespace rotlie::solver
