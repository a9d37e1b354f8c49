#include "rotlie/solver/sixth_order_scan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <istream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <cln/dfloat.h>
#include <cln/float.h>
#include <cln/rational.h>
#include <cln/real.h>

namespace rotlie::solver {
namespace {

// One seed per system, so that systems can be scanned in any order and resumed independently.
std::uint64_t system_seed(const scanned_system& r, std::uint64_t seed) {
  std::uint64_t h = 14695981039346656037ULL;  // FNV-1a: the same on every platform
  for (const char c : r.word + ":" + r.permutation) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return seed ^ h;
}

bool same_root(const std::vector<long double>& a, const std::vector<long double>& b) {
  long double distance = 0, scale = 1;
  for (std::size_t i = 0; i < a.size(); ++i) {
    distance = std::max(distance, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(a[i]));
  }
  return distance < 1e-8L * scale;
}

}  // namespace

double unseen_mass(const scanned_system& r) {
  if (r.converged == 0) return 1;
  int once = 0;
  for (const auto& root : r.roots) once += root.hits == 1;
  return static_cast<double>(once) / r.converged;
}

void continue_scan(const sixth_order_system& s, scanned_system& r, const scan_rule& rule) {
  while (r.starts < rule.budget && !r.finished) {
    search_options o;
    o.seed = system_seed(r, rule.seed);
    o.first_start = r.starts;
    o.starts = std::min(rule.batch, rule.budget - r.starts);
    const auto found = newton_search(s, o);
    r.starts += found.starts;
    r.converged += found.converged;
    for (const auto& root : found.roots) {
      auto known = std::find_if(r.roots.begin(), r.roots.end(), [&](const auto& k) { return same_root(k.x, root.x); });
      if (known != r.roots.end())
        known->hits += root.hits;
      else
        r.roots.push_back({root.x, root.hits});
    }
    r.finished = r.converged >= rule.min_converged && unseen_mass(r) <= rule.unseen_target;
  }
}

hit_statistics statistics_of(const std::vector<scanned_system>& systems) {
  hit_statistics h;
  for (const auto& r : systems) {
    ++h.systems;
    h.with_roots += !r.roots.empty();
    h.starts += r.starts;
    h.converged += r.converged;
    for (const auto& root : r.roots) {
      ++h.roots;
      h.hit_once += root.hits == 1;
      h.hit_twice += root.hits == 2;
      h.hit_more += root.hits > 2;
    }
  }
  h.unseen = h.converged == 0 ? 1 : static_cast<double>(h.hit_once) / h.converged;
  const double f1 = h.hit_once, f2 = h.hit_twice;
  h.chao1 = h.roots + (f2 > 0 ? f1 * f1 / (2 * f2) : f1 * (f1 - 1) / 2);
  return h;
}

double ranked_root::remainder7_at_equal_cost() const { return remainder7 * std::pow(static_cast<double>(cost), 6); }

std::vector<ranked_root> rank_roots(const std::vector<scanned_system>& systems, const lie::moments_of_inertia& body,
                                    bch::splitting split) {
  std::vector<ranked_root> out;
  for (const auto& r : systems) {
    if (r.roots.empty()) continue;
    sixth_order_system s;  // the layout is all that all_coefficients needs
    s.layout = bch::layout_scheme(r.word, split, r.permutation);
    for (const auto& root : r.roots) {
      std::vector<cln::cl_RA> x;
      for (long double v : root.x) x.push_back(cln::rational(cln::cl_DF(static_cast<double>(v))));
      std::map<std::string, double> values;
      double largest = 0;
      for (const auto& [name, v] : all_coefficients(s, x, 20)) {
        values[name] = cln::double_approx(v);
        largest = std::max(largest, std::abs(values[name]));
      }
      ranked_root k{r.word, r.permutation, root.x, root.hits, remainder7_norm(s.layout, body, values), largest, 0};
      const int stages = static_cast<int>(s.layout.stages.size());
      k.cost = split == bch::splitting::abc ? stages : stages + 1;
      out.push_back(std::move(k));
    }
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.remainder7 < b.remainder7; });
  return out;
}

void write_scan_state(std::ostream& out, const std::vector<scanned_system>& systems) {
  out << "# rotlie sixth scan state: system WORD PERM STARTS CONVERGED FINISHED, then root HITS x1 ... xn\n";
  for (const auto& r : systems) {
    out << "system " << r.word << " " << r.permutation << " " << r.starts << " " << r.converged << " " << (r.finished ? 1 : 0)
        << "\n";
    for (const auto& root : r.roots) {
      out << "root " << root.hits;
      for (long double v : root.x) out << " " << std::setprecision(21) << v;
      out << "\n";
    }
  }
}

std::vector<scanned_system> read_scan_state(std::istream& in) {
  std::vector<scanned_system> out;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string key;
    s >> key;
    auto fail = [&] { throw std::invalid_argument("scan state line " + std::to_string(number) + " is malformed"); };
    if (key == "system") {
      scanned_system r;
      int finished = 0;
      if (!(s >> r.word >> r.permutation >> r.starts >> r.converged >> finished) || r.starts < 0 || r.converged < 0 ||
          r.converged > r.starts)
        fail();
      r.finished = finished != 0;
      out.push_back(std::move(r));
    } else if (key == "root") {
      if (out.empty()) fail();
      scanned_root root;
      if (!(s >> root.hits) || root.hits < 1) fail();
      for (long double v; s >> v;) root.x.push_back(v);
      if (!s.eof() || root.x.empty()) fail();
      out.back().roots.push_back(std::move(root));
    } else {
      fail();
    }
  }
  return out;
}

}  // namespace rotlie::solver
