#pragma once
// Table 1 of Laskar & Vaillant: per order, the dimension of the Lie algebra, the number of
// order conditions (non-symmetric NS, symmetric S, per order and cumulative) and the number
// of stages, for a general Hamiltonian split in two or three parts and for the free rigid body
// with the RS and ABC splittings (section 2.4).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rotlie::lie {

struct stage_row {
  int order = 0;
  std::optional<std::int64_t> dim, equations_ns, total_ns, equations_s, total_s, stages_ns, stages_s;
  /// Where the two stage cells come from: "rule" (N equations → N stages NS, 2·N_sym − 1 stages S),
  /// or the literature reference the paper quotes for that cell.
  std::string stages_ns_source, stages_s_source;
};

struct stage_block {
  std::string name;   ///< general-2, general-3, rigid-RS, rigid-ABC
  std::string title;  ///< the heading the paper gives the block
  std::vector<stage_row> rows;
};

/// The largest order for which every cell fits in 64 bits (the 3-letter free Lie algebra grows as 3^k/k).
inline constexpr int max_stage_table_order = 40;

/// All four blocks for orders 1 … max_order. rigid_dims[k−1] is the true dimension of L_k
/// (from lie_poisson_algebra); it must hold at least max_order values.
std::vector<stage_block> stage_table(int max_order, const std::vector<std::size_t>& rigid_dims);

/// Closed forms (38)–(40) for the rigid-body equation counts; rs = true subtracts the RS relation.
std::int64_t equations_even_order(int n, bool rs);      ///< N(2n),     eq. (38)
std::int64_t equations_odd_order(int n, bool rs);       ///< N(2n+1),   eq. (39)
std::int64_t equations_symmetric(int n, bool rs);       ///< N_sym(2n), eq. (40)

}  // namespace rotlie::lie
