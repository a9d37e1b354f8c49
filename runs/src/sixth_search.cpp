#include "rotlie/runs/sixth_search.hpp"

#include <cln/real.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "rotlie/models/cpu_time.hpp"
#include "rotlie/runs/exclusive_use.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/solver/sixth_order_search.hpp"

namespace rotlie::runs {
namespace {

namespace fs = std::filesystem;


std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream s(text);
  for (std::string item; std::getline(s, item, ',');) out.push_back(item);
  return out;
}

// What a scan state belongs to: the body as typed (exact moments) and the splitting. A state is
// refused for any other problem (it would mix two bodies' roots in one folder).
std::string problem_of(const sixth_search_request& q) {
  return "inertia " + lie::inertia_text(q.body) + " split " + (q.split == bch::splitting::abc ? "ABC" : "RS");
}

// The state written whole or not at all, through a temporary of this process's own.
void save_state(const fs::path& file, const std::string& problem, const std::vector<solver::scanned_system>& done) {
  std::ostringstream out;
  out << "problem " << problem << "\n";
  solver::write_scan_state(out, done);
  write_file_atomically(file, out.str());
}

constexpr std::uintmax_t largest_state_bytes = 256u << 20;  // far above any scan's state; /dev/zero is refused
constexpr long double largest_coefficient = 1e6L;           // the starts lie in a box of a few units

// Every root of a system has one value per free coefficient of its word, each finite and of the
// size a scheme's coefficient can have; anything else is a state this program did not write.
void check_roots(const solver::scanned_system& r, bch::splitting split, const std::string& where) {
  const auto layout = bch::layout_scheme(r.word, split, r.permutation);
  for (const auto& root : r.roots) {
    bool fits = root.x.size() == layout.free_coefficients.size();
    for (long double v : root.x) fits = fits && std::isfinite(v) && std::abs(v) <= largest_coefficient;
    if (!fits)
      throw bad_input(where + ": a root of " + r.word + ":" + r.permutation + " is not " +
                      std::to_string(layout.free_coefficients.size()) +
                      " finite coefficients of a scheme (the file is damaged; remove it to start again)");
  }
}

// Systems already in the state file keep their starts and roots; a state of another problem, or one
// that is not a state, is refused and left as it is.
std::vector<solver::scanned_system> resumed_state(const fs::path& state, const sixth_search_request& q) {
  if (state.empty() || !fs::exists(state)) return {};
  const std::string where = "--out: " + one_line(state.string());
  if (!fs::is_regular_file(state)) throw bad_input(where + " is not a regular file");
  if (fs::file_size(state) > largest_state_bytes) throw bad_input(where + " is larger than any scan state (remove it to start again)");
  std::istringstream in;
  try {
    in.str(read_bounded_file(state, largest_state_bytes));
  } catch (const std::runtime_error& e) {
    throw bad_input(std::string("--out: ") + e.what());
  }
  std::string first;
  std::getline(in, first);
  if (first.rfind("problem ", 0) != 0)
    throw bad_input(where + " names no problem (an older rotlie wrote it, or it is not a scan state); remove it to start again");
  const std::string problem = first.substr(8);
  if (problem != problem_of(q))
    throw bad_input(where + " is the scan of " + one_line(problem) + ", not of " + problem_of(q) +
                    ": choose another --out, or remove it to start again");
  std::vector<solver::scanned_system> systems;
  try {
    systems = solver::read_scan_state(in);
  } catch (const std::invalid_argument& e) {
    throw bad_input(where + ": " + e.what() + " (remove it to start again)");
  }
  for (const auto& r : systems) {
    try {
      check_roots(r, q.split, where);
    } catch (const std::invalid_argument& e) {  // a word or permutation that is not one
      if (dynamic_cast<const bad_input*>(&e)) throw;
      throw bad_input(where + ": the system " + one_line(r.word + ":" + r.permutation) + " is not one of this splitting (remove it to start again)");
    }
  }
  return systems;
}

// A root polished to the digits asked for and written as a table, or why it could not be (a root
// whose Jacobian is singular is not isolated: a family).
sixth_order_table polished_table(const solver::ranked_root& r, const sixth_search_request& q, int label) {
  sixth_order_table t;
  t.word = r.word;
  t.permutation = r.permutation;
  t.remainder7 = r.remainder7;
  const auto system = solver::sixth_order_conditions(bch::layout_scheme(r.word, q.split, r.permutation), q.body);
  std::vector<cln::cl_RA> x;
  try {
    x = solver::polished_root(system, r.x, q.digits);
  } catch (const std::runtime_error& e) {
    t.why = e.what();
    t.jacobian_ratio = solver::jacobian_condition_ratio(system, r.x);
    long double smallest = std::numeric_limits<long double>::infinity();
    for (long double v : r.x) smallest = std::min(smallest, std::abs(v));
    t.smallest_free_coefficient = static_cast<double>(smallest);
    return t;
  }
  t.polished = true;
  t.jacobian_ratio = solver::jacobian_condition_ratio(system, r.x);
  t.residual = cln::double_approx(solver::sixth_order_residual(system, x, q.digits));
  t.remainder7_at_equal_cost = r.remainder7_at_equal_cost();
  t.cost = r.cost;
  t.max_coefficient = r.max_coefficient;
  t.hits = r.hits;
  t.name = "D6:" + r.word + ":" + r.permutation + ":" + std::to_string(label);
  if (!q.out.empty()) {
    t.file = (q.out / ("D6-" + r.word + "-" + r.permutation + "-" + std::to_string(label) + ".table")).string();
    write_file_atomically(t.file, solver::sixth_order_table_text(system, x, q.digits, q.body, t.name,
                                                                 "rotlie sixth: H_R3 = H_R5 = 0 solved by Newton from random starts, polished"));
  }
  return t;
}

}  // namespace

std::vector<solver::scanned_system> sixth_order_systems(const std::string& words, bool all, bch::splitting split,
                                                        bool sphere) {
  const int length = split == bch::splitting::abc ? 21 : 19;
  const auto all_words = solver::palindromic_words(length, split);
  const std::vector<std::string> perms = sphere ? std::vector<std::string>{"ABC"} : bch::permutation_names();
  std::vector<solver::scanned_system> out;
  if (all) {
    for (const auto& w : all_words)
      for (const auto& p : perms) out.push_back({w, p});
    return out;
  }
  for (const auto& item : split_list(words)) {
    const auto colon = item.find(':');
    const std::string word = item.substr(0, colon);
    if (std::find(all_words.begin(), all_words.end(), word) == all_words.end())
      throw bad_input("--words: '" + one_line(word) + "' is not a " + std::to_string(length) +
                      "-stage palindrome in first-appearance naming (letters " +
                      (split == bch::splitting::abc ? "ABC, starting AB" : "RS, starting R") + ", no letter twice in a row)");
    if (colon == std::string::npos) {
      for (const auto& p : perms) out.push_back({word, p});
    } else {
      const std::string perm = item.substr(colon + 1);
      if (!bch::is_permutation_name(perm)) throw bad_input("--words: unknown permutation '" + one_line(perm) + "' in '" + one_line(item) + "'");
      out.push_back({word, perm});
    }
  }
  return out;
}

sixth_search_result sixth_search(const sixth_search_request& q, const std::function<void(const std::string&)>& progress) {
  const fs::path state = q.out.empty() ? fs::path() : q.out / "scan-state.txt";
  std::optional<exclusive_use> lock;  // one scan at a time in a folder, held until its tables are written
  if (!q.out.empty()) {
    fs::create_directories(q.out);
    lock.emplace(q.out, "--out");
  }
  const std::string problem = problem_of(q);
  auto done = resumed_state(state, q);
  solver::scan_rule rule;
  rule.budget = q.starts;
  const double cpu0 = models::thread_cpu_seconds();
  std::size_t index = 0;
  for (const auto& a : q.systems) {
    ++index;
    auto it = std::find_if(done.begin(), done.end(), [&](const auto& d) { return d.word == a.word && d.permutation == a.permutation; });
    if (it == done.end()) {
      done.push_back(a);
      it = std::prev(done.end());
    }
    if (it->finished || it->starts >= rule.budget) continue;
    if (progress)
      progress("sixth: system " + std::to_string(index) + " of " + std::to_string(q.systems.size()) + ", " + a.word + ":" + a.permutation);
    const auto system = solver::sixth_order_conditions(bch::layout_scheme(a.word, q.split, a.permutation), q.body);
    solver::continue_scan(system, *it, rule);
    if (!state.empty()) save_state(state, problem, done);
  }
  // Only the systems asked for are reported (the state may hold more).
  std::vector<solver::scanned_system> reported;
  for (const auto& d : done)
    if (std::any_of(q.systems.begin(), q.systems.end(), [&](const auto& a) { return a.word == d.word && a.permutation == d.permutation; }))
      reported.push_back(d);
  sixth_search_result result;
  result.stats = solver::statistics_of(reported);
  int written = 0;
  std::map<std::string, int> labels;  // the k-th best root of a system is label k
  for (const auto& r : solver::rank_roots(reported, q.body, q.split)) {
    if (written >= q.best) break;
    const int label = labels[r.word + ":" + r.permutation] + 1;
    auto t = polished_table(r, q, label);
    if (t.polished) {
      ++written;
      labels[r.word + ":" + r.permutation] = label;
    }
    result.best.push_back(std::move(t));
  }
  result.cpu_seconds = models::thread_cpu_seconds() - cpu0;
  return result;
}

}  // namespace rotlie::runs
