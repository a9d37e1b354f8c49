#include "icq_shape.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "rotlie/runs/user_input.hpp"
#include "orientation.hpp"
#include "vertex_text.hpp"

namespace rotlie::runs::shape_formats {

namespace {

// Gaskell's models go to Q = 512; four times that is 25 million vertex lines, near the shape file's size limit.
constexpr long largest_q = 2048;

// One side of a shared edge: a face and how its I and J run as the edge's index K goes 0 … Q.
enum class runs_as { zero, q, k, q_minus_k };
struct edge_side {
  int face;
  runs_as i, j;
};
struct shared_edge {
  edge_side a, b;
};

// The twelve edges where two faces meet, each written once by both (the PDS's ICQ description);
// the corners follow from them.
constexpr shared_edge shared_edges[12] = {
    {{6, runs_as::k, runs_as::q}, {4, runs_as::q_minus_k, runs_as::q}},
    {{6, runs_as::k, runs_as::zero}, {2, runs_as::k, runs_as::q}},
    {{5, runs_as::k, runs_as::zero}, {1, runs_as::q, runs_as::q_minus_k}},
    {{4, runs_as::k, runs_as::zero}, {1, runs_as::q_minus_k, runs_as::zero}},
    {{3, runs_as::k, runs_as::zero}, {1, runs_as::zero, runs_as::k}},
    {{2, runs_as::k, runs_as::zero}, {1, runs_as::k, runs_as::q}},
    {{6, runs_as::q, runs_as::k}, {5, runs_as::k, runs_as::q}},
    {{5, runs_as::q, runs_as::k}, {4, runs_as::zero, runs_as::k}},
    {{4, runs_as::q, runs_as::k}, {3, runs_as::zero, runs_as::k}},
    {{3, runs_as::q, runs_as::k}, {2, runs_as::zero, runs_as::k}},
    {{6, runs_as::zero, runs_as::k}, {3, runs_as::q_minus_k, runs_as::q}},
    {{5, runs_as::zero, runs_as::k}, {2, runs_as::q, runs_as::k}},
};

class labels {
 public:
  explicit labels(long q) : q_(q), parent_(static_cast<std::size_t>(6 * (q + 1) * (q + 1))) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }
  /// v(I, J, F)'s place in the file's order (F from 1).
  std::size_t at(long i, long j, int face) const { return static_cast<std::size_t>(((face - 1) * (q_ + 1) + j) * (q_ + 1) + i); }
  std::size_t at(const edge_side& s, long k) const { return at(value(s.i, k), value(s.j, k), s.face); }
  std::size_t root(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void join(std::size_t x, std::size_t y) {
    x = root(x), y = root(y);
    if (x != y) parent_[std::max(x, y)] = std::min(x, y);  // the first written copy stands for all
  }
  std::size_t size() const { return parent_.size(); }

 private:
  long value(runs_as r, long k) const { return r == runs_as::zero ? 0 : r == runs_as::q ? q_ : r == runs_as::k ? k : q_ - k; }
  long q_;
  std::vector<std::size_t> parent_;
};

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

}  // namespace

bool looks_like_icq(const std::string& first_line) {
  std::istringstream words(first_line);
  long q = 0;
  std::string extra;
  return (words >> q) && !(words >> extra);
}

models::polyhedron parse_icq_shape(const std::vector<std::string>& lines, std::size_t first, const std::string& name) {
  std::istringstream head(lines[first]);
  long q = 0;
  head >> q;
  if (q < 1 || q > largest_q)
    throw bad_input(name + ": ICQ resolution Q = " + std::to_string(q) + " is out of range (1 to " + std::to_string(largest_q) + ")");
  std::vector<std::size_t> vertex_lines;  // the lines that are not blank, after Q
  for (std::size_t i = first + 1; i < lines.size(); ++i)
    if (!blank(lines[i])) vertex_lines.push_back(i);
  labels label(q);
  if (vertex_lines.size() != label.size())
    throw bad_input(name + ": an ICQ model of Q = " + std::to_string(q) + " has 6(Q+1)^2 = " + std::to_string(label.size()) + " vertex lines, this file " +
                    std::to_string(vertex_lines.size()));
  for (const auto& e : shared_edges)
    for (long k = 0; k <= q; ++k) label.join(label.at(e.a, k), label.at(e.b, k));

  models::polyhedron p;
  std::vector<int> id(label.size(), -1);
  for (std::size_t n = 0; n < label.size(); ++n) {
    const std::size_t line = vertex_lines[n];
    const auto refuse = [&](const std::string& why) { throw bad_input(name + ", line " + std::to_string(line + 1) + ": " + why); };
    std::istringstream words(lines[line]);
    const auto v = vertex_of(words, refuse);
    if (std::string extra; words >> extra) refuse("an ICQ vertex line holds three numbers, not '" + one_line(extra) + "' after them");
    const std::size_t r = label.root(n);
    if (r == n) {
      id[n] = static_cast<int>(p.vertices.size());
      p.vertices.push_back(v);
    } else if (p.vertices[static_cast<std::size_t>(id[r])] != v) {
      refuse("the faces' shared vertex written on line " + std::to_string(vertex_lines[r] + 1) + " is written differently here");
    } else {
      id[n] = id[r];
    }
  }
  for (int face = 1; face <= 6; ++face)
    for (long j = 0; j < q; ++j)
      for (long i = 0; i < q; ++i) {
        const int a = id[label.at(i, j, face)], b = id[label.at(i, j + 1, face)], c = id[label.at(i + 1, j + 1, face)], d = id[label.at(i + 1, j, face)];
        p.facets.push_back({a, b, c});
        p.facets.push_back({a, c, d});
      }

  if (!turn_outward(p)) throw bad_input(name + ": the ICQ model encloses no volume");
  return p;
}

}  // namespace rotlie::runs::shape_formats
