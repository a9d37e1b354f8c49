#pragma once
// The broad search for dedicated 6th-order schemes: every (palindromic word, permutation) system of a
// splitting, Newton from random starts (sixth_order_search), resumable from a plain-text state, with
// the hit statistics that say how much of each system's real solution set the starts have reached.
//
// Stopping rule, per system: starts are spent in batches; a system stops when it has used its budget
// or when the Good–Turing estimate of the unseen root mass, f1 / N (f1 roots hit once, N converged
// starts), falls to `unseen_target` with N ≥ `min_converged`: the chance that the next converged start
// finds a new root is then below the target. Chao1, S + f1² / (2 f2), estimates the total number of
// roots that the starting box reaches (f2 roots hit twice; S + f1 (f1 − 1) / 2 when f2 = 0).
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "rotlie/solver/sixth_order_search.hpp"

namespace rotlie::solver {

struct scanned_root {
  std::vector<long double> x;  ///< free coefficients (the search's double root)
  int hits = 1;
};

struct scanned_system {
  std::string word, permutation;
  int starts = 0, converged = 0;
  std::vector<scanned_root> roots{};
  bool finished = false;  ///< the stopping rule was met before the budget
};

struct scan_rule {
  int budget = 40;              ///< starts per system
  int batch = 20;
  double unseen_target = 0.05;  ///< Good–Turing f1 / N at which a system stops
  int min_converged = 20;
  std::uint64_t seed = 1;
};

/// Continues one system up to the rule's budget (the same start sequence as an uninterrupted run).
void continue_scan(const sixth_order_system& s, scanned_system& r, const scan_rule& rule);

/// Good–Turing's unseen mass f1 / N of one system (1 when nothing converged).
double unseen_mass(const scanned_system& r);

struct hit_statistics {
  int systems = 0, with_roots = 0, roots = 0, starts = 0, converged = 0;
  int hit_once = 0, hit_twice = 0, hit_more = 0;
  double unseen = 1;  ///< pooled Good–Turing f1 / N
  double chao1 = 0;   ///< pooled estimate of the roots reachable from the box
};
hit_statistics statistics_of(const std::vector<scanned_system>& systems);

/// A root of the scan with its measures: ‖H_R7‖ (remainder7_norm) and the cost C in rotations per step
/// (the stage count for ABC, stages + 1 for RS, as schemes::cost_in_rotations).
struct ranked_root {
  std::string word, permutation;
  std::vector<long double> x;
  int hits = 1;
  double remainder7 = 0, max_coefficient = 0;
  int cost = 0;
  double remainder7_at_equal_cost() const;  ///< ‖H_R7‖ · C^6
};
/// Every root of the scan, by ascending ‖H_R7‖.
std::vector<ranked_root> rank_roots(const std::vector<scanned_system>& systems, const lie::moments_of_inertia& body,
                                    bch::splitting split);

/// Plain-text state: "system WORD PERM STARTS CONVERGED FINISHED" then "root HITS x1 … xn" lines.
void write_scan_state(std::ostream& out, const std::vector<scanned_system>& systems);
/// Throws std::invalid_argument naming the line on malformed text.
std::vector<scanned_system> read_scan_state(std::istream& in);

}  // namespace rotlie::solver
