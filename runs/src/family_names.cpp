#include "rotlie/runs/family_names.hpp"

#include <algorithm>

#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

const bch::family& family_to_solve(const std::string& name) {
  const auto* f = bch::find_family(name);
  if (f == nullptr) throw bad_input("--family must be " + bch::family_names([](const auto&) { return true; }) + ", got '" + name + "'");
  return *f;
}

const bch::family& family_to_map(const std::string& name) {
  const auto has_map = [](const bch::family& f) { return f.map != bch::map_method::none; };
  const auto* f = bch::find_family(name);
  if (f == nullptr || !has_map(*f)) throw bad_input("--family must be " + bch::family_names(has_map) + ", got '" + name + "'");
  return *f;
}

std::vector<std::string> members_asked(const bch::family& f, const std::string& scheme) {
  std::vector<std::string> all;
  for (const auto& m : f.members) all.emplace_back(m.name);
  if (scheme.empty()) return all;
  if (std::find(all.begin(), all.end(), scheme) == all.end())
    throw bad_input("--scheme '" + scheme + "' is not in the " + std::string(f.name) + " family (" + all.front() +
                    (all.size() > 1 ? " … " + all.back() : std::string()) + ")");
  return {scheme};
}

const bch::family& two_parameter_family(bch::splitting split) {
  for (const auto& f : bch::families())
    if (f.kind == bch::family_kind::two_free_parameters && f.split == split) return f;
  throw std::logic_error("no family of two free parameters in this splitting");
}

std::string two_parameter_name(const solver::two_parameter_entry& e) {
  return std::string(two_parameter_family(e.split).name) + ":" + e.word + ":" + e.permutation;
}

int two_parameter_cost(const solver::two_parameter_entry& e) { return bch::family_cost(two_parameter_family(e.split)); }

bch::map_method map_method_asked(const bch::family& f, int K, bool exact, bool fast) {
  if (fast && !bch::fast_checked(f)) {
    const auto checked = bch::family_names([](const bch::family& g) { return bch::fast_checked(g); }, " and ");
    throw bad_input("--fast: the fast path is checked against the exact solver for the " + checked +
                    " families only; the " + std::string(f.name) + " map uses the exact solver (drop --fast)");
  }
  if (fast && K < f.fast_from_grid)
    throw bad_input("--fast: the " + std::string(f.name) + " map's fast path is checked against the exact solver at --grid " +
                    std::to_string(f.fast_from_grid) + " and finer only (at coarser grids it can miss the best); --grid " +
                    std::to_string(K) + " uses the exact solver (drop --fast)");
  return exact || K < f.fast_from_grid ? bch::map_method::exact : f.map;
}

std::string map_method_name(bch::map_method m) {
  switch (m) {
    case bch::map_method::exact: return "exact";
    case bch::map_method::fast: return "fast";
    case bch::map_method::screened: return "screened";
    case bch::map_method::none: break;
  }
  throw std::logic_error("a family without a map has no map method");
}

}  // namespace rotlie::runs
