#include "rotlie/bch/lyndon_projection.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <immintrin.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <thread>
#include <utility>

namespace rotlie::bch {
namespace {

constexpr int lanes = 16;  // words of a class evaluated together (one AVX-512 register of int32)
constexpr std::uint32_t none = ~std::uint32_t{0};

// value[out] = value[a11]·value[a12] − value[a21]·value[a22], each value a row of `lanes` int32.
template <class Row>
struct step_of {
  Row out, a11, a12, a21, a22;
};
using step = step_of<std::uint32_t>;
using short_step = step_of<std::uint16_t>;  // the same in half the memory, when the rows allow

// Loads the leaves of `count` ≤ lanes words: x[letter·n + o][k] = [w_k[o] = letter].
void load_leaves(const lyndon_basis& basis, const std::uint32_t* words, int count, int n, std::int32_t* x) {
  const int bits = basis.bits_per_letter();
  const std::uint64_t mask = (std::uint64_t{1} << bits) - 1;
  for (int k = 0; k < lanes; ++k) {
    const std::uint64_t code = k < count ? basis.code(words[k]) : 0;
    for (int o = 0; o < n; ++o) {
      const auto letter = static_cast<int>((code >> (bits * (n - 1 - o))) & mask);
      for (int a = 0; a < basis.letters(); ++a) x[(a * n + o) * lanes + k] = k < count && letter == a;
    }
  }
}

// x: rows of `lanes` int32, 64-byte aligned (one cache line, one AVX-512 register each).
template <class Step>
[[gnu::always_inline]] inline void run_steps(const Step* program, std::size_t steps, std::int32_t* rows) {
  auto* const x = static_cast<std::int32_t*>(__builtin_assume_aligned(rows, 64));
  for (std::size_t p = 0; p < steps; ++p) {
    const Step& q = program[p];
    const std::int32_t* a = x + std::size_t{q.a11} * lanes;
    const std::int32_t* b = x + std::size_t{q.a12} * lanes;
    const std::int32_t* c = x + std::size_t{q.a21} * lanes;
    const std::int32_t* d = x + std::size_t{q.a22} * lanes;
    std::int32_t* out = x + std::size_t{q.out} * lanes;
    std::array<std::int32_t, lanes> v;
    for (int k = 0; k < lanes; ++k) v[static_cast<std::size_t>(k)] = a[k] * b[k] - c[k] * d[k];
    for (int k = 0; k < lanes; ++k) out[k] = v[static_cast<std::size_t>(k)];
  }
}

// The first `steps` steps of a program, one version per instruction set.
__attribute__((target_clones("avx512f", "avx2", "default"))) void run_program(const step* program, std::size_t steps,
                                                                               std::int32_t* x) {
  run_steps(program, steps, x);
}
__attribute__((target_clones("avx512f", "avx2", "default"))) void run_short_program(const short_step* program,
                                                                                     std::size_t steps, std::int32_t* x) {
  run_steps(program, steps, x);
}

// Node ids by key (u, o), for the words u of length 2 … n − 1 of the basis and the offsets
// 0 … n − |u|: one dense table, zero for a node not yet made. Taken from calloc, so that only the
// pages of the keys met are ever touched.
class node_table {
 public:
  node_table(const lyndon_basis& basis, int n) : basis_(basis), base_(static_cast<std::size_t>(n) + 1, 0) {
    for (int len = 2; len < n; ++len)
      base_[static_cast<std::size_t>(len) + 1] =
          base_[static_cast<std::size_t>(len)] + (basis.end(len) - basis.begin(len)) * static_cast<std::size_t>(n - len + 1);
    ids_.reset(static_cast<std::uint32_t*>(std::calloc(std::max<std::size_t>(1, base_.back()), sizeof(std::uint32_t))));
    if (!ids_) throw std::bad_alloc();
  }
  std::uint32_t& operator()(std::uint32_t u, int len, int o) {
    const auto n = static_cast<std::size_t>(base_.size() - 1);
    return ids_[base_[static_cast<std::size_t>(len)] + (u - basis_.begin(len)) * (n - static_cast<std::size_t>(len) + 1) +
                static_cast<std::size_t>(o)];
  }

 private:
  struct release {
    void operator()(std::uint32_t* p) const { std::free(p); }
  };
  const lyndon_basis& basis_;
  std::vector<std::size_t> base_;
  std::unique_ptr<std::uint32_t[], release> ids_;
};

// The straight-line program of one multidegree class: node (u, o) holds <P_u, w[o : o+|u|]> for
// the words w evaluated. The members come in groups of `lanes` (a block of words evaluated
// together needs the roots of its own group and of the groups before); inside a group the new
// steps are ordered by height, so that consecutive steps seldom wait for each other.
// Values live in rows: first the leaves (letter, position), then one row per member's root (kept,
// for the dot products), then rows reused once their node is no longer read.
class class_program {
 public:
  class_program(const lyndon_basis& basis, int degree, const std::vector<std::uint32_t>& members)
      : basis_(basis), n_(degree) {
    steps_.reserve(7 * members.size() + 64);  // about 6 steps per member (two letters, up to degree 19)
    root_step_.reserve(members.size());
    {
      node_table table(basis, degree);
      for (std::size_t j = 0; j < members.size(); ++j) {
        root_step_.push_back(node_of(members[j], 0, table) - leaves());
        if ((j + 1) % lanes == 0 || j + 1 == members.size()) group_end_.push_back(steps_.size());
      }
    }
    order_by_height();
    assign_rows();
    if (rows_ <= 65536) {
      short_steps_.reserve(steps_.size());
      for (const auto& x : steps_)
        short_steps_.push_back({static_cast<std::uint16_t>(x.out), static_cast<std::uint16_t>(x.a11), static_cast<std::uint16_t>(x.a12),
                                static_cast<std::uint16_t>(x.a21), static_cast<std::uint16_t>(x.a22)});
      steps_ = {};
    }
  }

  std::uint32_t leaves() const { return static_cast<std::uint32_t>(basis_.letters() * n_); }
  std::uint32_t rows() const { return rows_; }
  std::uint32_t root_row(std::size_t j) const { return leaves() + static_cast<std::uint32_t>(j); }
  /// Evaluates the roots of the members of the block starting at member j0 and before on the
  /// words of the block (x: rows() rows of `lanes`).
  void run(std::size_t j0, const std::uint32_t* words, int count, std::int32_t* x) const {
    load_leaves(basis_, words, count, n_, x);
    const std::size_t steps = group_end_[j0 / lanes];
    if (short_steps_.empty())
      run_program(steps_.data(), steps, x);
    else
      run_short_program(short_steps_.data(), steps, x);
  }

 private:
  // Node id (leaves first, then steps) of <P_u, w[o : o+|u|]>, created with its children first.
  std::uint32_t node_of(std::uint32_t u, int o, node_table& table) {
    const int len = basis_.length(u);
    if (len == 1) return static_cast<std::uint32_t>(basis_.letter(u, 0) * n_ + o);
    std::uint32_t* known = len < n_ ? &table(u, len, o) : nullptr;  // a root is met once
    if (known && *known != 0) return *known - 1;
    const std::uint32_t left = basis_.left(u), right = basis_.right(u);
    const int lu = basis_.length(left), lv = basis_.length(right);
    const step x{none, node_of(left, o, table), node_of(right, o + lu, table), node_of(right, o, table),
                 node_of(left, o + lv, table)};
    steps_.push_back(x);
    const auto id = leaves() + static_cast<std::uint32_t>(steps_.size() - 1);
    if (known) *known = id + 1;
    return id;
  }

  // Stable counting sort of each group's steps by height (a leaf has height 0), node ids renamed.
  void order_by_height() {
    const std::uint32_t first = leaves();
    std::vector<std::uint8_t> height(steps_.size());
    std::vector<std::uint32_t> position(steps_.size());
    std::size_t begin = 0;
    for (const std::size_t end : group_end_) {
      std::array<std::uint32_t, 64> at{};  // heights ≤ length ≤ 31
      for (std::size_t p = begin; p < end; ++p) {
        std::uint8_t h = 0;
        for (const auto c : {steps_[p].a11, steps_[p].a12, steps_[p].a21, steps_[p].a22})
          if (c >= first) h = std::max(h, height[c - first]);
        height[p] = static_cast<std::uint8_t>(h + 1);
        ++at[height[p]];
      }
      std::uint32_t next = static_cast<std::uint32_t>(begin);
      for (auto& a : at) next += std::exchange(a, next);
      for (std::size_t p = begin; p < end; ++p) position[p] = at[height[p]]++;
      begin = end;
    }
    for (auto& s : steps_)
      for (auto* c : {&s.a11, &s.a12, &s.a21, &s.a22})
        if (*c >= first) *c = first + position[*c - first];
    for (auto& r : root_step_) r = position[r];
    for (std::size_t p = 0; p < steps_.size(); ++p)  // the permutation, cycle by cycle
      while (position[p] != p) {
        const std::uint32_t q = position[p];
        std::swap(steps_[p], steps_[q]);
        std::swap(position[p], position[q]);
      }
  }

  // Rewrites node ids as rows: a step's row is taken before its inputs' rows are released, and a
  // row is released after the last step that reads it (roots are never released).
  void assign_rows() {
    const std::uint32_t first = leaves();
    std::vector<std::uint32_t> last_read(steps_.size(), 0), row(steps_.size(), none);
    for (std::uint32_t p = 0; p < steps_.size(); ++p)
      for (const auto c : {steps_[p].a11, steps_[p].a12, steps_[p].a21, steps_[p].a22})
        if (c >= first) last_read[c - first] = p;
    for (std::size_t j = 0; j < root_step_.size(); ++j) row[root_step_[j]] = root_row(j);
    const std::uint32_t shared = first + static_cast<std::uint32_t>(root_step_.size());  // the first reused row
    std::vector<std::uint32_t> free_rows;
    rows_ = shared;
    for (std::uint32_t p = 0; p < steps_.size(); ++p) {
      step& s = steps_[p];
      if (row[p] == none) {
        if (free_rows.empty()) {
          row[p] = rows_++;
        } else {
          row[p] = free_rows.back();
          free_rows.pop_back();
        }
      }
      s.out = row[p];
      for (auto* c : {&s.a11, &s.a12, &s.a21, &s.a22}) {
        if (*c < first) continue;
        const std::uint32_t q = *c - first;
        *c = row[q];
        if (last_read[q] == p && row[q] >= shared) {
          free_rows.push_back(row[q]);
          last_read[q] = none;  // a node read twice by one step is released once
        }
      }
    }
  }

  const lyndon_basis& basis_;
  int n_;
  std::vector<step> steps_;
  std::vector<short_step> short_steps_;  // steps_ moved here when the rows fit in 16 bits
  std::vector<std::uint32_t> root_step_;
  std::vector<std::size_t> group_end_;  // steps made by the groups of members up to each
  std::uint32_t rows_ = 0;
};

// A coordinate as four signed 32-bit limbs, c = Σ_t limb[t] · 2^(32t) (|c| < 2^126 fits).
struct limbs {
  std::array<std::int32_t, 4> limb;
};

limbs to_limbs(int128 c) {
  limbs r{};
  for (std::size_t t = 0; t < 3; ++t) {
    r.limb[t] = static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<uint128>(c)));
    c = (c - r.limb[t]) >> 32;  // exact
  }
  r.limb[3] = static_cast<std::int32_t>(c);
  return r;
}

// Σ_i c_i · row_i[k] and Σ_i |row_i[k]| for the rows i < count of nonzero c_i (contiguous rows of
// `lanes`). Each limb's products are summed in 64 bits, `interval` rows at a time (so that no
// partial sum overflows), then carried into the 128-bit sums: modulo 2^128, exact whenever the
// bound checked afterwards holds. One version per instruction set, chosen once (dot_rows below).
using dot_function = void (*)(const std::int32_t*, const limbs*, std::size_t, std::size_t, uint128*, std::int64_t*);

bool is_zero(const limbs& c) { return (c.limb[0] | c.limb[1] | c.limb[2] | c.limb[3]) == 0; }

// Adds one interval's 64-bit limb sums and 32-bit weights to the totals.
void carry(const std::int64_t (&part)[4][lanes], const std::int32_t (&w)[lanes], uint128* sum, std::int64_t* weight) {
  for (int k = 0; k < lanes; ++k) {
    for (int t = 0; t < 4; ++t) sum[k] += static_cast<uint128>(static_cast<int128>(part[t][k])) << (32 * t);
    weight[k] += w[k];
  }
}

void dot_rows_plain(const std::int32_t* rows, const limbs* c, std::size_t count, std::size_t interval, uint128* sum,
                    std::int64_t* weight) {
  for (std::size_t i0 = 0; i0 < count; i0 += interval) {
    std::int64_t part[4][lanes] = {};
    std::int32_t w[lanes] = {};
    for (std::size_t i = i0; i < std::min(count, i0 + interval); ++i) {
      if (is_zero(c[i])) continue;
      for (int k = 0; k < lanes; ++k) {
        const std::int32_t m = rows[i * lanes + static_cast<std::size_t>(k)];
        for (std::size_t t = 0; t < 4; ++t) part[t][k] += static_cast<std::int64_t>(c[i].limb[t]) * m;
        w[k] += m < 0 ? -m : m;
      }
    }
    carry(part, w, sum, weight);
  }
}

__attribute__((target("avx2"))) void dot_rows_avx2(const std::int32_t* rows, const limbs* c, std::size_t count,
                                                   std::size_t interval, uint128* sum, std::int64_t* weight) {
  for (std::size_t i0 = 0; i0 < count; i0 += interval) {
    std::int64_t part[4][lanes];
    std::int32_t w[lanes];
    for (int half = 0; half < 2; ++half) {  // lanes 8·half … 8·half + 7
      __m256i p[8], a = _mm256_setzero_si256();
      for (auto& x : p) x = _mm256_setzero_si256();
      for (std::size_t i = i0; i < std::min(count, i0 + interval); ++i) {
        if (is_zero(c[i])) continue;
        const __m256i m = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(rows + i * lanes + 8 * half));
        const __m256i lo = _mm256_cvtepi32_epi64(_mm256_castsi256_si128(m));
        const __m256i hi = _mm256_cvtepi32_epi64(_mm256_extracti128_si256(m, 1));
        for (std::size_t t = 0; t < 4; ++t) {
          const __m256i x = _mm256_set1_epi64x(c[i].limb[t]);
          p[2 * t] = _mm256_add_epi64(p[2 * t], _mm256_mul_epi32(lo, x));
          p[2 * t + 1] = _mm256_add_epi64(p[2 * t + 1], _mm256_mul_epi32(hi, x));
        }
        a = _mm256_add_epi32(a, _mm256_abs_epi32(m));
      }
      for (std::size_t t = 0; t < 4; ++t) {
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(&part[t][8 * half]), p[2 * t]);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(&part[t][8 * half + 4]), p[2 * t + 1]);
      }
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(&w[8 * half]), a);
    }
    carry(part, w, sum, weight);
  }
}

// GCC 12's AVX-512 intrinsics start from _mm512_undefined_*(), which -Wmaybe-uninitialized
// mistakes for a read of an uninitialised value (GCC bug 105593).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
__attribute__((target("avx512f"))) void dot_rows_avx512(const std::int32_t* rows, const limbs* c, std::size_t count,
                                                        std::size_t interval, uint128* sum, std::int64_t* weight) {
  for (std::size_t i0 = 0; i0 < count; i0 += interval) {
    __m512i p[8], a = _mm512_setzero_si512();
    for (auto& x : p) x = _mm512_setzero_si512();
    for (std::size_t i = i0; i < std::min(count, i0 + interval); ++i) {
      if (is_zero(c[i])) continue;
      const __m512i m = _mm512_loadu_si512(rows + i * lanes);
      const __m512i lo = _mm512_cvtepi32_epi64(_mm512_castsi512_si256(m));
      const __m512i hi = _mm512_cvtepi32_epi64(_mm512_extracti64x4_epi64(m, 1));
      for (std::size_t t = 0; t < 4; ++t) {
        const __m512i x = _mm512_set1_epi64(c[i].limb[t]);
        p[2 * t] = _mm512_add_epi64(p[2 * t], _mm512_mul_epi32(lo, x));
        p[2 * t + 1] = _mm512_add_epi64(p[2 * t + 1], _mm512_mul_epi32(hi, x));
      }
      a = _mm512_add_epi32(a, _mm512_abs_epi32(m));
    }
    std::int64_t part[4][lanes];
    std::int32_t w[lanes];
    for (std::size_t t = 0; t < 4; ++t) {
      _mm512_storeu_si512(&part[t][0], p[2 * t]);
      _mm512_storeu_si512(&part[t][8], p[2 * t + 1]);
    }
    _mm512_storeu_si512(w, a);
    carry(part, w, sum, weight);
  }
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

void dot_rows(const std::int32_t* rows, const limbs* c, std::size_t count, std::size_t interval, uint128* sum,
              std::int64_t* weight) {
  static const dot_function best = __builtin_cpu_supports("avx512f") ? dot_rows_avx512
                                   : __builtin_cpu_supports("avx2")  ? dot_rows_avx2
                                                                     : dot_rows_plain;
  best(rows, c, count, interval, sum, weight);
}

// The first 64-byte boundary in a buffer of rows + 1 rows.
std::int32_t* aligned_rows(std::vector<std::int32_t>& buffer) {
  const auto address = reinterpret_cast<std::uintptr_t>(buffer.data());
  return buffer.data() + ((64 - address % 64) % 64) / sizeof(std::int32_t);
}

void solve_class(const lyndon_basis& basis, int n, const std::vector<std::uint32_t>& members,
                 std::vector<int128>& coefficients) {
  const class_program program(basis, n, members);
  std::vector<std::int32_t> buffer((static_cast<std::size_t>(program.rows()) + 1) * lanes);
  const auto values = aligned_rows(buffer);
  std::vector<limbs> solved(members.size());
  // |M[l][w]| ≤ 2^(n−1) and |limb| ≤ 2^31: 2^(31−n) rows keep Σ |M| in 31 bits and each limb's sum in 63
  const std::size_t interval = std::size_t{1} << (31 - std::min(n, 31));
  long double largest = 0;  // max |c| so far, for the bound
  const long double limit = std::ldexp(1.0L, 126);
  for (std::size_t j0 = 0; j0 < members.size(); j0 += lanes) {
    const int count = static_cast<int>(std::min<std::size_t>(lanes, members.size() - j0));
    // the roots of this block and of the ones before
    program.run(j0, members.data() + j0, count, values);
    // Words before the block: one contiguous row of `lanes` values per earlier root.
    std::array<uint128, lanes> sum{};
    std::array<std::int64_t, lanes> weight{};  // Σ |M[l][w]| per word, for the bound
    dot_rows(values + static_cast<std::size_t>(program.root_row(0)) * lanes, solved.data(), j0, interval,
             sum.data(), weight.data());
    // Then the triangle inside the block, in order.
    for (int k = 0; k < count; ++k) {
      const std::size_t j = j0 + static_cast<std::size_t>(k);
      for (std::size_t i = j0; i < j; ++i) {
        const std::int32_t m = values[static_cast<std::size_t>(program.root_row(i)) * lanes + static_cast<std::size_t>(k)];
        if (m == 0) continue;
        sum[static_cast<std::size_t>(k)] += static_cast<uint128>(coefficients[members[i]] * m);
        weight[static_cast<std::size_t>(k)] += m < 0 ? -static_cast<std::int64_t>(m) : m;
      }
      int128& c = coefficients[members[j]];
      if (!(largest * static_cast<long double>(weight[static_cast<std::size_t>(k)]) + static_cast<long double>(magnitude(c)) < limit))
        throw std::overflow_error("a Lyndon coordinate is beyond the proven 128-bit range");
      c -= static_cast<int128>(sum[static_cast<std::size_t>(k)]);
      largest = std::max(largest, static_cast<long double>(magnitude(c)));
      solved[j] = to_limbs(c);
    }
  }
}

}  // namespace

void solve_lyndon_coordinates(const lyndon_basis& basis, int d, std::vector<int128>& coefficients, int threads) {
  if (d < 2) return;  // the letters are their own coordinates
  std::map<std::uint32_t, std::vector<std::uint32_t>> classes;  // content → members in lexicographic order
  {
    std::map<std::uint32_t, std::size_t> sizes;  // for vectors of the exact size
    for (std::size_t i = basis.begin(d); i < basis.end(d); ++i) ++sizes[basis.content(i)];
    for (const auto& [content, size] : sizes) classes[content].reserve(size);
  }
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
      for (std::size_t k; (k = next++) < work.size();) solve_class(basis, d, *work[k], coefficients);
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
#ifdef __GLIBC__
  // The classes' buffers, freed, stay in glibc's heap (its mmap threshold rises to their size),
  // resident under the numerators of the next degrees: give them back.
  malloc_trim(0);
#endif
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rotlie::bch
