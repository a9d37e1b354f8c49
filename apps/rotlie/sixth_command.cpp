// rotlie sixth: dedicated 6th-order schemes for one body. Scans palindromic words of 21 stages (ABC)
// or 19 (RS) in every permutation by Newton from random starts (resumable from --out), ranks the roots
// by ‖H_R7‖, polishes the best ones to --digits and writes them as order-6 scheme tables that
// `integrate --scheme FILE` accepts. --references lists the general 6th-order compositions instead.
#include <nlohmann/json.hpp>

#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/solver/sixth_order_scan.hpp"

namespace rotlie::app {
namespace {

namespace fs = std::filesystem;

std::string scientific(double x, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << std::scientific << x;
  return s.str();
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream s(text);
  for (std::string item; std::getline(s, item, ',');) out.push_back(item);
  return out;
}

int list_references(bool json) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& name : schemes::reference_sixth_order_scheme_names()) {
    const auto t = *schemes::reference_scheme(name);
    if (json) {
      j.push_back({{"name", name}, {"order", t.order}, {"stages", t.stages.size()}, {"cost", schemes::cost_in_rotations(t)},
                   {"source", t.source}});
    } else {
      std::cout << name << "  order " << t.order << ", " << t.stages.size() << " stages, cost " << schemes::cost_in_rotations(t)
                << " rotations  (" << t.source << ")\n";
    }
  }
  if (json) std::cout << j.dump(2) << "\n";
  return 0;
}

// The systems asked for: WORD or WORD:PERM items, or every palindrome of the splitting's length.
std::vector<solver::scanned_system> systems_asked(const sixth_options& o, bch::splitting split, bool sphere) {
  const int length = split == bch::splitting::abc ? 21 : 19;
  const auto all_words = solver::palindromic_words(length, split);
  const std::vector<std::string> perms = sphere ? std::vector<std::string>{"ABC"} : bch::permutation_names();
  std::vector<solver::scanned_system> out;
  if (o.all) {
    for (const auto& w : all_words)
      for (const auto& p : perms) out.push_back({w, p});
    return out;
  }
  for (const auto& item : split_list(o.words)) {
    const auto colon = item.find(':');
    const std::string word = item.substr(0, colon);
    if (std::find(all_words.begin(), all_words.end(), word) == all_words.end())
      throw usage_error("--words: '" + one_line(word) + "' is not a " + std::to_string(length) +
                        "-stage palindrome in first-appearance naming (letters " +
                        (split == bch::splitting::abc ? "ABC, starting AB" : "RS, starting R") + ", no letter twice in a row)");
    if (colon == std::string::npos) {
      for (const auto& p : perms) out.push_back({word, p});
    } else {
      const std::string perm = item.substr(colon + 1);
      if (!bch::is_permutation_name(perm)) throw usage_error("--words: unknown permutation '" + one_line(perm) + "' in '" + one_line(item) + "'");
      out.push_back({word, perm});
    }
  }
  return out;
}

void save_state(const fs::path& file, const std::vector<solver::scanned_system>& done) {
  const fs::path temporary = file.string() + ".part";
  {
    std::ofstream out(temporary);
    solver::write_scan_state(out, done);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, file);
}

}  // namespace

int run_sixth(const sixth_options& o) {
  if (o.references) return list_references(o.json);
  if (o.inertia.empty()) throw usage_error("--inertia is required (I1,I2,I3, water or sphere), or --references");
  lie::moments_of_inertia body;
  try {
    body = lie::parse_moments(o.inertia);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what());
  }
  if (o.all == !o.words.empty()) throw usage_error("give exactly one of --words LIST and --all");
  bch::splitting split;
  if (o.split == "ABC") split = bch::splitting::abc;
  else if (o.split == "RS") split = bch::splitting::rs;
  else throw usage_error("--split must be ABC or RS, got '" + one_line(o.split) + "'");
  const long starts = parse_integer_in_range(o.starts, "--starts", 1, 1000000);
  const long best = parse_integer_in_range(o.best, "--best", 0, 1000);
  const long digits = parse_integer_in_range(o.digits, "--digits", 40, 200);
  const bool sphere = lie::symmetry_of(body) == "I1 = I2 = I3";
  auto asked = systems_asked(o, split, sphere);

  // Resume: systems already in the state file keep their starts and roots.
  std::vector<solver::scanned_system> done;
  fs::path state;
  if (!o.out.empty()) {
    fs::create_directories(o.out);
    state = fs::path(o.out) / "scan-state.txt";
    if (fs::exists(state)) {
      std::ifstream in(state);
      try {
        done = solver::read_scan_state(in);
      } catch (const std::invalid_argument& e) {
        throw usage_error(state.string() + ": " + e.what() + " (remove it to start again)");
      }
    }
  }
  solver::scan_rule rule;
  rule.budget = static_cast<int>(starts);
  const double cpu0 = cpu_seconds();
  {
    progress_line progress;
    std::size_t index = 0;
    for (const auto& a : asked) {
      ++index;
      auto it = std::find_if(done.begin(), done.end(), [&](const auto& d) { return d.word == a.word && d.permutation == a.permutation; });
      if (it == done.end()) {
        done.push_back(a);
        it = std::prev(done.end());
      }
      if (it->finished || it->starts >= rule.budget) continue;
      progress.show("sixth: system " + std::to_string(index) + " of " + std::to_string(asked.size()) + ", " + a.word + ":" + a.permutation);
      const auto system = solver::sixth_order_conditions(bch::layout_scheme(a.word, split, a.permutation), body);
      solver::continue_scan(system, *it, rule);
      if (!state.empty()) save_state(state, done);
    }
  }
  // Only the systems asked for are reported (the state may hold more).
  std::vector<solver::scanned_system> reported;
  for (const auto& d : done)
    if (std::any_of(asked.begin(), asked.end(), [&](const auto& a) { return a.word == d.word && a.permutation == d.permutation; }))
      reported.push_back(d);
  const auto stats = solver::statistics_of(reported);
  const auto ranked = solver::rank_roots(reported, body, split);

  // Polish the best roots; a root whose Jacobian is singular is not isolated (a family) and is skipped.
  nlohmann::ordered_json tables = nlohmann::ordered_json::array();
  std::ostringstream table_lines;
  int written = 0;
  std::map<std::string, int> labels;  // the k-th best root of a system is label k
  for (const auto& r : ranked) {
    if (written >= best) break;
    const auto system = solver::sixth_order_conditions(bch::layout_scheme(r.word, split, r.permutation), body);
    std::vector<cln::cl_RA> x;
    try {
      x = solver::polished_root(system, r.x, static_cast<int>(digits));
    } catch (const std::runtime_error& e) {
      const double ratio = solver::jacobian_condition_ratio(system, r.x);
      long double smallest = std::numeric_limits<long double>::infinity();
      for (long double v : r.x) smallest = std::min(smallest, std::abs(v));
      table_lines << "  " << r.word << ":" << r.permutation << "  ‖H_R7‖ = " << scientific(r.remainder7)
                  << "  not polished: " << e.what() << "; Jacobian σmin/σmax = " << scientific(ratio, 2)
                  << ", smallest |free coefficient| = " << scientific(static_cast<double>(smallest), 2) << "\n";
      tables.push_back({{"word", r.word}, {"permutation", r.permutation}, {"remainder7", r.remainder7}, {"polished", false},
                        {"why", e.what()}, {"jacobian_condition_ratio", ratio},
                        {"smallest_free_coefficient", static_cast<double>(smallest)}});
      continue;
    }
    const double jacobian_ratio = solver::jacobian_condition_ratio(system, r.x);
    const double residual = cln::double_approx(solver::sixth_order_residual(system, x, static_cast<int>(digits)));
    ++written;
    const int label = ++labels[r.word + ":" + r.permutation];
    const std::string name = "D6:" + r.word + ":" + r.permutation + ":" + std::to_string(label);
    std::string file;
    if (!o.out.empty()) {
      file = (fs::path(o.out) / ("D6-" + r.word + "-" + r.permutation + "-" + std::to_string(label) + ".table")).string();
      std::ofstream out(file);
      out << solver::sixth_order_table_text(system, x, static_cast<int>(digits), body, name,
                                            "rotlie sixth: H_R3 = H_R5 = 0 solved by Newton from random starts, polished");
      if (!out) throw std::runtime_error("cannot write " + file);
    }
    table_lines << "  " << name << "  ‖H_R7‖ = " << scientific(r.remainder7) << "  ‖H_R7‖·C^6 = " << scientific(r.remainder7_at_equal_cost())
                << "  C = " << r.cost << "  max|c| = " << scientific(r.max_coefficient, 2) << "  hits " << r.hits
                << "  residual " << scientific(residual, 2) << "  σmin/σmax " << scientific(jacobian_ratio, 2) << (file.empty() ? "" : "  " + file) << "\n";
    tables.push_back({{"name", name}, {"word", r.word}, {"permutation", r.permutation}, {"remainder7", r.remainder7},
                      {"remainder7_at_equal_cost", r.remainder7_at_equal_cost()}, {"cost", r.cost},
                      {"max_coefficient", r.max_coefficient}, {"hits", r.hits}, {"residual", residual}, {"jacobian_condition_ratio", jacobian_ratio}, {"polished", true},
                      {"file", file}});
  }
  const double cpu = cpu_seconds() - cpu0;
  if (o.json) {
    nlohmann::ordered_json j;
    j["inertia"] = lie::inertia_text(body);
    j["split"] = o.split;
    j["systems"] = stats.systems;
    j["systems_with_roots"] = stats.with_roots;
    j["starts"] = stats.starts;
    j["converged"] = stats.converged;
    j["roots"] = stats.roots;
    j["roots_hit_once"] = stats.hit_once;
    j["roots_hit_twice"] = stats.hit_twice;
    j["roots_hit_more"] = stats.hit_more;
    j["good_turing_unseen"] = stats.unseen;
    j["chao1_roots"] = stats.chao1;
    j["cpu_seconds"] = cpu;
    j["best"] = tables;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::cout << "systems " << stats.systems << " (" << stats.with_roots << " with real roots), starts " << stats.starts
            << ", converged " << stats.converged << ", distinct roots " << stats.roots << "\n"
            << "hits: " << stats.hit_once << " roots once, " << stats.hit_twice << " twice, " << stats.hit_more
            << " more; Good-Turing unseen mass f1/N = " << scientific(stats.unseen, 2)
            << "; Chao1 estimate of the roots reachable = " << scientific(stats.chao1, 2) << "\n"
            << "best by ‖H_R7‖ (body scaled to I3 = 1):\n"
            << table_lines.str() << "CPU " << scientific(cpu, 3) << " s\n";
  return 0;
}

}  // namespace rotlie::app
