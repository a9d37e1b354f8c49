#include "rotlie/bch/lyndon_projection.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>

namespace rotlie::bch {
namespace {

constexpr int lanes = 16;  // words of a class evaluated together (one AVX-512 register of int32)

struct node {
  std::uint32_t a11, a12, a21, a22;  // value = X[a11]·X[a12] − X[a21]·X[a22]
};

// The straight-line program of one multidegree class.
class class_program {
 public:
  class_program(const lyndon_basis& basis, int degree, std::vector<std::uint32_t>& slot_table)
      : basis_(basis), n_(degree), slot_(slot_table) {}

  std::uint32_t leaves() const { return static_cast<std::uint32_t>(basis_.letters() * n_); }

  // Node for <P_u, w[o : o+|u|]>, created with its children first.
  std::uint32_t node_of(std::uint32_t u, int o) {
    if (basis_.length(u) == 1) return static_cast<std::uint32_t>(basis_.letter(u, 0) * n_ + o);
    const std::size_t key = static_cast<std::size_t>(u) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(o);
    if (slot_[key] != 0) return slot_[key];
    const std::uint32_t left = basis_.left(u), right = basis_.right(u);
    const int lu = basis_.length(left), lv = basis_.length(right);
    const node x{node_of(left, o), node_of(right, o + lu), node_of(right, o), node_of(left, o + lv)};
    nodes_.push_back(x);
    touched_.push_back(key);
    return slot_[key] = leaves() + static_cast<std::uint32_t>(nodes_.size() - 1);
  }
  void release() {
    for (const auto k : touched_) slot_[k] = 0;
    touched_.clear();
  }
  const std::vector<node>& nodes() const { return nodes_; }

 private:
  const lyndon_basis& basis_;
  int n_;
  std::vector<std::uint32_t>& slot_;
  std::vector<node> nodes_;
  std::vector<std::size_t> touched_;
};

// Runs the program on `count` ≤ lanes words at once up to node `stop` (inclusive).
__attribute__((target_clones("avx512f", "avx2", "default"))) void run_program(const std::vector<node>& nodes, std::uint32_t leaves, std::uint32_t stop, const lyndon_basis& basis,
                 const std::uint32_t* words, int count, int n, std::vector<std::int32_t>& x) {
  for (std::uint32_t leaf = 0; leaf < leaves; ++leaf) {
    const auto letter = static_cast<std::uint8_t>(leaf / static_cast<std::uint32_t>(n));
    const int o = static_cast<int>(leaf % static_cast<std::uint32_t>(n));
    for (int k = 0; k < lanes; ++k)
      x[leaf * lanes + static_cast<std::uint32_t>(k)] = k < count && basis.letter(words[k], o) == letter;
  }
  std::int32_t* v = x.data();
  for (std::uint32_t p = leaves; p <= stop; ++p) {
    const node& q = nodes[p - leaves];
    const std::int32_t* a = v + q.a11 * lanes;
    const std::int32_t* b = v + q.a12 * lanes;
    const std::int32_t* c = v + q.a21 * lanes;
    const std::int32_t* d = v + q.a22 * lanes;
    std::int32_t* out = v + p * lanes;
    for (int k = 0; k < lanes; ++k) out[k] = a[k] * b[k] - c[k] * d[k];
  }
}

void solve_class(const lyndon_basis& basis, int n, const std::vector<std::uint32_t>& members,
                 std::vector<int128>& coefficients, std::vector<std::uint32_t>& slot_table,
                 std::vector<std::int32_t>& values) {
  class_program program(basis, n, slot_table);
  std::vector<std::uint32_t> root(members.size());
  std::vector<std::uint32_t> stop(members.size());  // stop[j]: last node needed by the roots before j
  std::uint32_t highest = program.leaves();
  for (std::size_t i = 0; i < members.size(); ++i) {
    stop[i] = highest;
    root[i] = program.node_of(members[i], 0);
    highest = std::max(highest, root[i]);
  }
  program.release();
  const auto& nodes = program.nodes();
  values.resize((static_cast<std::size_t>(program.leaves()) + nodes.size()) * lanes);
  long double largest = 0;  // max |c| so far, for the bound
  const long double limit = std::ldexp(1.0L, 126);
  for (std::size_t j0 = 0; j0 < members.size(); j0 += lanes) {
    const int count = static_cast<int>(std::min<std::size_t>(lanes, members.size() - j0));
    run_program(nodes, program.leaves(), stop[j0 + static_cast<std::size_t>(count) - 1], basis, members.data() + j0, count,
                n, values);
    // Words before the block: one contiguous row of `lanes` values per earlier root.
    std::array<int128, lanes> sum{};
    std::array<std::int64_t, lanes> weight{};  // Σ |M[l][w]| per word, for the bound
    for (std::size_t i = 0; i < j0; ++i) {
      const std::int32_t* row = values.data() + static_cast<std::size_t>(root[i]) * lanes;
      const int128 c = coefficients[members[i]];
      if (c == 0) continue;
      for (int k = 0; k < count; ++k)
        if (const std::int32_t m = row[k]; m != 0) {
          sum[static_cast<std::size_t>(k)] += c * m;
          weight[static_cast<std::size_t>(k)] += m < 0 ? -static_cast<std::int64_t>(m) : m;
        }
    }
    // Then the triangle inside the block, in order.
    for (int k = 0; k < count; ++k) {
      const std::size_t j = j0 + static_cast<std::size_t>(k);
      for (std::size_t i = j0; i < j; ++i) {
        const std::int32_t m = values[static_cast<std::size_t>(root[i]) * lanes + static_cast<std::size_t>(k)];
        if (m == 0) continue;
        sum[static_cast<std::size_t>(k)] += coefficients[members[i]] * m;
        weight[static_cast<std::size_t>(k)] += m < 0 ? -static_cast<std::int64_t>(m) : m;
      }
      int128& c = coefficients[members[j]];
      if (!(largest * static_cast<long double>(weight[static_cast<std::size_t>(k)]) + static_cast<long double>(magnitude(c)) < limit))
        throw std::overflow_error("a Lyndon coordinate is beyond the proven 128-bit range");
      c -= sum[static_cast<std::size_t>(k)];
      largest = std::max(largest, static_cast<long double>(magnitude(c)));
    }
  }
}

}  // namespace

void solve_lyndon_coordinates(const lyndon_basis& basis, int d, std::vector<int128>& coefficients, int threads) {
  if (d < 2) return;  // the letters are their own coordinates
  std::map<std::uint32_t, std::vector<std::uint32_t>> classes;  // content → members in lexicographic order
  for (std::size_t i = basis.begin(d); i < basis.end(d); ++i) classes[basis.content(i)].push_back(static_cast<std::uint32_t>(i));
  std::vector<const std::vector<std::uint32_t>*> work;
  for (const auto& [content, members] : classes)
    if (members.size() > 1) work.push_back(&members);  // a class of one word is its own coordinate
  std::sort(work.begin(), work.end(), [](auto* a, auto* b) { return a->size() > b->size(); });
  std::atomic<std::size_t> next{0};
  std::mutex guard;
  std::exception_ptr failure;
  auto worker = [&] {
    try {
      std::vector<std::uint32_t> slots(basis.size() * static_cast<std::size_t>(d), 0);
      std::vector<std::int32_t> values;
      for (std::size_t k; (k = next++) < work.size();) solve_class(basis, d, *work[k], coefficients, slots, values);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(guard);
      if (!failure) failure = std::current_exception();
      next = work.size();
    }
  };
  const int helpers = std::max(0, std::min<int>(threads, static_cast<int>(work.size())) - 1);
  std::vector<std::thread> pool;
  for (int t = 0; t < helpers; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rotlie::bch
