#include "rotlie/solver/screened_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "continued_rows.hpp"
#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/solver/critical_points.hpp"

namespace rotlie::solver {
namespace {

using namespace detail;

void add_new(std::vector<point3>& to, const std::vector<point3>& from) {
  for (const auto& y : from)
    if (std::none_of(to.begin(), to.end(), [&](const point3& x) { return same_point(x, y); })) to.push_back(y);
}

// One step of a chain where carrying every solution at once failed: in `substeps` equal steps, each
// solution on its own (continue_each), those Newton refuses dropped; two that reach one solution
// are kept once.
std::vector<point3> carry_each(const body_system& system, std::vector<point3> x, body_point a, body_point b, int& dropped) {
  constexpr int substeps = 8;
  for (int step = 1; step <= substeps && !x.empty(); ++step) {
    const long double f = static_cast<long double>(step) / substeps;
    const auto numeric = evaluate_system(system, a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]));
    std::vector<point3> distinct;
    for (const auto& moved : continue_each(numeric, x))
      if (moved) add_new(distinct, {*moved});
    dropped += static_cast<int>(x.size() - distinct.size());
    x = std::move(distinct);
  }
  return x;
}

// The smallest ‖H_R5‖ at the points (infinity for none).
long double lowest_remainder(const body_system& system, const std::vector<point3>& x, body_point w) {
  long double best = std::numeric_limits<long double>::infinity();
  if (x.empty()) return best;
  const auto numeric = evaluate_system(system, w[0], w[1]);
  for (const auto& p : x) best = std::min(best, remainder_norm(numeric, p));
  return best;
}

// The chain of one system over the row in one direction: at an exact body it restarts from the
// exact solutions (none where the system is singular: the next body is then solved exactly).
// Returns the carried solutions at every body (the exact ones at exact bodies).
std::vector<std::vector<point3>> chain(const body_system& system, const std::vector<grid_body>& row,
                                       const std::vector<body_point>& w, std::vector<std::optional<system_state>>& exact,
                                       bool forward, screening_counts& counts) {
  const std::size_t n = row.size();
  std::vector<std::vector<point3>> out(n);
  std::vector<point3> current, previous;
  bool started = false, has_previous = false;  // a chain holds `current`; `previous` is one body back
  for (std::size_t step = 0; step < n; ++step) {
    const std::size_t k = forward ? step : n - 1 - step;
    if (!exact[k] && started) {
      const std::size_t from = forward ? k - 1 : k + 1;
      const std::vector<point3>* before = has_previous && previous.size() == current.size() ? &previous : nullptr;
      // A failing step is mostly a solution dying at a fold: after 1, 2 and 4 pieces the solutions
      // go on one by one (the full subdivision down to 64 pieces made the failures the costly part).
      auto next = carry(system, current, before, w[from], w[k], 2);
      std::vector<point3> moved = next ? std::move(*next) : carry_each(system, current, w[from], w[k], counts.dropped);
      previous = std::move(current);
      has_previous = true;
      current = std::move(moved);
    }
    if (!exact[k] && !started) {  // no chain yet: the body before was singular for this system
      exact[k] = solve_system_exactly(system, row[k]);
      ++counts.system_solves;
    }
    if (exact[k]) {
      has_previous = false;
      started = exact[k]->can_seed;
      current = started ? exact[k]->x : std::vector<point3>();
    }
    out[k] = current;
  }
  return out;
}

// The smallest ‖H_R5‖ of a state: the exact solver's where exact, else at the carried solutions.
long double smallest_remainder(const system_state& s, const body_system& system, body_point w) {
  long double best = std::numeric_limits<long double>::infinity();
  if (s.exact) {
    for (const auto& sol : s.solutions) best = std::min(best, static_cast<long double>(sol.analytic_remainder));
    return best;
  }
  return lowest_remainder(system, s.x, w);
}

// The distinct real roots of the eliminant of one system at one body, as the exact solver would
// isolate them (the same conditions, built the same way), without solving.
int candidate_count(const body_system& system, const grid_body& g) {
  const auto unit = scaled_to_unit_I3(g.body);
  const std::array<cln::cl_RA, 3> w{cln::recip(unit.I[0]), cln::recip(unit.I[1]), cln::cl_RA(1)};
  const order_conditions c = conditions_of(bch::compute_exact_modified_hamiltonian(system.layout, w, 5));
  return count_critical_candidates(c.norm_squared, c.p1, c.p2);
}

// Makes the state of one system at body k complete: carried whole from its complete state at the
// body before when the count of real eliminant roots is unchanged (no solution born or dead in
// between: a birth or death changes it by two, and a death alone also stops the chain), else by
// the exact solver.
void complete_state(const body_system& system, const grid_body& g, body_point w, const system_state* before,
                    body_point w_before, system_state& state, screening_counts& counts, int finest_level = 2) {
  if (before && before->complete && before->count >= 0 && before->can_seed) {
    if (auto carried = carry(system, before->x, nullptr, w_before, w, finest_level)) {
      const int count = candidate_count(system, g);
      ++counts.counts;
      if (count == before->count) {
        system_state s;
        s.x = std::move(*carried);
        std::sort(s.x.begin(), s.x.end(), by_first_coefficient);
        s.can_seed = true;
        s.complete = true;
        s.count = count;
        state = std::move(s);
        return;
      }
    }
  }
  state = solve_system_exactly(system, g);
  ++counts.system_solves;
}

// Completes, at body k, the states of the systems (among `which`) holding the smallest remainder
// and of those within 1e-9 of it, until every one of them is complete.
void confirm_best(const std::vector<body_system>& systems, const std::vector<std::size_t>& which, const grid_body& g,
                  body_point w, std::vector<system_state>& states, const std::vector<system_state>* before,
                  body_point w_before, std::vector<long double>& smallest, screening_counts& counts) {
  for (;;) {
    long double best = std::numeric_limits<long double>::infinity();
    for (const std::size_t s : which) best = std::min(best, smallest[s]);
    if (!std::isfinite(best)) return;
    bool all_complete = true;
    for (const std::size_t s : which) {
      if (smallest[s] > best * (1 + 1e-9L) || states[s].complete) continue;
      complete_state(systems[s], g, w, before ? &(*before)[s] : nullptr, w_before, states[s], counts);
      smallest[s] = smallest_remainder(states[s], systems[s], w);
      ++counts.confirmations;
      all_complete = false;
    }
    if (all_complete) return;
  }
}

// Solutions of system s found at body k and missing from the chains, carried to the bodies after
// and before k, each way until none goes on or an exact body is reached; added to the states there.
void carry_unseen(const body_system& system, std::size_t s, std::size_t k, const std::vector<point3>& unseen,
                  const std::vector<body_point>& w, std::vector<std::vector<system_state>>& states, screening_counts& counts) {
  const std::size_t n = states.size();
  for (const int direction : {1, -1}) {
    std::vector<point3> carried = unseen;
    for (std::size_t at = k; !carried.empty();) {
      const std::size_t next = direction > 0 ? at + 1 : at - 1;
      if (next >= n || states[next][s].exact) break;
      auto moved = carry(system, carried, nullptr, w[at], w[next], 2);
      carried = moved ? std::move(*moved) : carry_each(system, carried, w[at], w[next], counts.dropped);
      std::vector<point3> fresh;  // those the chains hold already go on in the chains
      for (const auto& x : carried)
        if (std::none_of(states[next][s].x.begin(), states[next][s].x.end(), [&](const point3& y) { return same_point(x, y); }))
          fresh.push_back(x);
      carried = std::move(fresh);
      add_new(states[next][s].x, carried);
      at = next;
    }
  }
}

// Checkpoints: a minimum born and dying again between the row's ends is in neither chain. Every
// `checkpoint_gap` bodies, each system within a factor `competitive` of the body's best is made
// complete (complete_state, from its complete state at its last checkpoint or the row's start), and
// the solutions it has that the chains lacked are carried both ways until they stop.
void complete_at_checkpoints(const std::vector<body_system>& systems, const std::vector<grid_body>& row,
                             const std::vector<body_point>& w, std::vector<std::vector<system_state>>& states,
                             screening_counts& counts) {
  constexpr std::size_t checkpoint_gap = 20;
  constexpr long double competitive = 2;
  const std::size_t n = row.size();
  std::vector<std::size_t> last_complete(systems.size(), 0);  // the row's first body is exact
  for (std::size_t k = checkpoint_gap; k + 1 < n; k += checkpoint_gap) {
    std::vector<long double> smallest(systems.size());
    long double best = std::numeric_limits<long double>::infinity();
    for (std::size_t s = 0; s < systems.size(); ++s) {
      smallest[s] = smallest_remainder(states[k][s], systems[s], w[k]);
      best = std::min(best, smallest[s]);
    }
    for (std::size_t s = 0; s < systems.size(); ++s) {
      if (states[k][s].complete || !(smallest[s] <= competitive * best)) continue;
      system_state complete;
      const std::size_t from = last_complete[s];
      complete_state(systems[s], row[k], w[k], &states[from][s], w[from], complete, counts, 6);
      ++counts.checkpoints;
      last_complete[s] = k;
      std::vector<point3> unseen;
      for (const auto& x : complete.x)
        if (std::none_of(states[k][s].x.begin(), states[k][s].x.end(), [&](const point3& y) { return same_point(x, y); }))
          unseen.push_back(x);
      states[k][s] = std::move(complete);
      carry_unseen(systems[s], s, k, unseen, w, states, counts);
    }
  }
}

}  // namespace

std::vector<map_point> screened_map_points(const std::vector<grid_body>& row, const std::string& family,
                                           bool per_permutation, screening_counts* counts) {
  for (std::size_t k = 1; k < row.size(); ++k)
    if (row[k].i != row[0].i || row[k].j != row[k - 1].j + 1)
      throw std::invalid_argument("screened_map_points needs consecutive bodies of one grid row");
  if (row.empty()) return {};
  const auto& systems = family_systems(family);
  const std::size_t n = row.size();
  std::vector<body_point> w;
  for (const auto& g : row) w.push_back(inverse_moments(g));
  screening_counts local;

  // states[body][system]
  std::vector<std::vector<system_state>> states(n, std::vector<system_state>(systems.size()));
  for (std::size_t s = 0; s < systems.size(); ++s) {
    std::vector<std::optional<system_state>> exact(n);
    exact[0] = solve_system_exactly(systems[s], row[0]);
    ++local.system_solves;
    if (n > 1) {
      exact[n - 1] = solve_system_exactly(systems[s], row[n - 1]);
      ++local.system_solves;
    }
    const auto forward = chain(systems[s], row, w, exact, true, local);
    const auto backward = chain(systems[s], row, w, exact, false, local);
    for (std::size_t k = 0; k < n; ++k) {
      if (exact[k]) {
        states[k][s] = std::move(*exact[k]);
        continue;
      }
      system_state merged;
      merged.x = forward[k];
      add_new(merged.x, backward[k]);
      merged.can_seed = true;
      states[k][s] = std::move(merged);
    }
  }

  complete_at_checkpoints(systems, row, w, states, local);

  std::vector<map_point> out;
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<long double> smallest(systems.size());
    for (std::size_t s = 0; s < systems.size(); ++s) smallest[s] = smallest_remainder(states[k][s], systems[s], w[k]);
    std::vector<std::size_t> all(systems.size());
    for (std::size_t s = 0; s < systems.size(); ++s) all[s] = s;
    const std::vector<system_state>* before = k > 0 ? &states[k - 1] : nullptr;
    const body_point w_before = k > 0 ? w[k - 1] : w[k];
    confirm_best(systems, all, row[k], w[k], states[k], before, w_before, smallest, local);
    if (per_permutation)
      for (const auto& p : {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"}) {
        std::vector<std::size_t> of;
        for (std::size_t s = 0; s < systems.size(); ++s)
          if (systems[s].permutation == p) of.push_back(s);
        confirm_best(systems, of, row[k], w[k], states[k], before, w_before, smallest, local);
      }
    std::vector<const system_state*> at;
    bool all_complete = true;
    for (const auto& st : states[k]) {
      at.push_back(&st);
      all_complete = all_complete && st.complete;
    }
    map_point point = assemble(row[k], w[k], family, systems, at);
    point.complete = all_complete;
    for (auto& p : point.per_permutation)
      if (p.best)
        for (std::size_t s = 0; s < systems.size(); ++s)
          if (systems[s].scheme == p.best->scheme && systems[s].permutation == p.best->permutation)
            p.confirmed = states[k][s].complete;
    out.push_back(std::move(point));
  }
  if (counts) {
    counts->system_solves += local.system_solves;
    counts->confirmations += local.confirmations;
    counts->dropped += local.dropped;
    counts->counts += local.counts;
    counts->checkpoints += local.checkpoints;
  }
  return out;
}

}  // namespace rotlie::solver
