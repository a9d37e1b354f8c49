#include "rotlie/lie/stage_table.hpp"

#include <map>
#include <stdexcept>

#include "rotlie/lie/free_lie_dimension.hpp"

namespace rotlie::lie {
namespace {

struct quoted_cell {
  std::int64_t value;
  const char* source;
};
using quote_map = std::map<int, quoted_cell>;

// Stage counts of the general (not rigid-body) blocks are literature values that the paper
// quotes in Table 1 (footnotes a–e); they do not follow from the equation counts.
const quote_map general2_ns{{1, {2, "Koseleff (1993), quoted in LV Table 1 (a)"}},
                            {2, {3, "Koseleff (1993), quoted in LV Table 1 (a)"}},
                            {3, {6, "Koseleff (1993), quoted in LV Table 1 (a)"}},
                            {4, {7, "Koseleff (1993), quoted in LV Table 1 (a)"}}};
const quote_map general2_s{{2, {3, "Koseleff (1993), quoted in LV Table 1 (a)"}},
                           {4, {7, "Koseleff (1993), quoted in LV Table 1 (a)"}},
                           {6, {15, "Koseleff (1993), quoted in LV Table 1 (a)"}},
                           {8, {31, "Koseleff (1993), quoted in LV Table 1 (a)"}}};
const quote_map general3_ns{{1, {3, "quoted in LV Table 1"}}, {2, {5, "quoted in LV Table 1"}}};
const quote_map general3_s{{2, {5, "quoted in LV Table 1"}},
                           {4, {13, "Koseleff (1993, 1996); Tang (2002), quoted in LV Table 1 (b)"}},
                           {6, {29, "Yoshida (1990), quoted in LV Table 1 (c)"}},
                           {8, {61, "Yoshida (1990), quoted in LV Table 1 (d)"}},
                           {10, {125, "Sofroniou and Spaletta (2005), quoted in LV Table 1 (e)"}}};

void set_quote(const quote_map& quotes, int order, std::optional<std::int64_t>& cell, std::string& source) {
  if (auto it = quotes.find(order); it != quotes.end()) {
    cell = it->second.value;
    source = it->second.source;
  }
}

// Equation columns shared by all blocks: order 1 has `first_order_equations` conditions,
// order k ≥ 2 has dim L_k; a symmetric scheme only meets the odd orders.
std::vector<stage_row> equation_rows(const std::vector<std::int64_t>& dims, std::int64_t first_order_equations) {
  std::vector<stage_row> rows;
  std::int64_t total_ns = 0, total_s = 0;
  for (std::size_t i = 0; i < dims.size(); ++i) {
    stage_row r;
    r.order = static_cast<int>(i) + 1;
    r.dim = dims[i];
    r.equations_ns = r.order == 1 ? first_order_equations : dims[i];
    total_ns += *r.equations_ns;
    r.total_ns = total_ns;
    if (r.order % 2 == 1) {
      r.equations_s = r.equations_ns;
      total_s += *r.equations_s;
    } else {
      r.total_s = total_s;
    }
    rows.push_back(r);
  }
  return rows;
}

stage_block general_block(int letters, int max_order) {
  std::vector<std::int64_t> dims;
  for (int k = 1; k <= max_order; ++k) dims.push_back(free_lie_dimension(letters, k));
  stage_block b;
  b.name = "general-" + std::to_string(letters);
  b.title = letters == 2 ? "General case (splitting in two parts)" : "General case (splitting in three parts)";
  b.rows = equation_rows(dims, dims.front());
  const auto& ns = letters == 2 ? general2_ns : general3_ns;
  const auto& s = letters == 2 ? general2_s : general3_s;
  for (auto& r : b.rows) {
    set_quote(ns, r.order, r.stages_ns, r.stages_ns_source);
    set_quote(s, r.order, r.stages_s, r.stages_s_source);
  }
  return b;
}

stage_block rigid_block(bool rs, const std::vector<std::size_t>& rigid_dims, int max_order) {
  std::vector<std::int64_t> dims(rigid_dims.begin(), rigid_dims.begin() + max_order);
  stage_block b;
  b.name = rs ? "rigid-RS" : "rigid-ABC";
  b.title = rs ? "Free rigid body (splitting in two parts, RS)" : "Free rigid body (splitting in three parts, ABC)";
  // RS: β_1,010 = β_1,001 because S carries G2² and G3² with one coefficient (section 2.4).
  b.rows = equation_rows(dims, rs ? 2 : 3);
  for (auto& r : b.rows) {
    r.stages_ns = r.total_ns;  // N equations → N stages
    r.stages_ns_source = "rule";
    if (r.total_s) {
      r.stages_s = 2 * *r.total_s - 1;  // symmetric: 2N_sym − 1 stages (section 2.3)
      r.stages_s_source = "rule";
    }
  }
  return b;
}

}  // namespace

std::vector<stage_block> stage_table(int max_order, const std::vector<std::size_t>& rigid_dims) {
  if (max_order < 1 || max_order > max_stage_table_order)
    throw std::invalid_argument("the order must be between 1 and " + std::to_string(max_stage_table_order) +
                                ", got " + std::to_string(max_order));
  if (rigid_dims.size() < static_cast<std::size_t>(max_order))
    throw std::invalid_argument("stage_table needs the rigid-body dimensions up to the requested order");
  return {general_block(2, max_order), general_block(3, max_order), rigid_block(true, rigid_dims, max_order),
          rigid_block(false, rigid_dims, max_order)};
}

std::int64_t equations_even_order(int n, bool rs) {
  return static_cast<std::int64_t>(n) * (2 * n * n + 9 * n - 11) / 6 + 4 - (rs ? 1 : 0);
}
std::int64_t equations_odd_order(int n, bool rs) {
  return static_cast<std::int64_t>(n) * (n * n + 6 * n + 2) / 3 + 3 - (rs ? 1 : 0);
}
std::int64_t equations_symmetric(int n, bool rs) {
  return static_cast<std::int64_t>(n) * (n * n + 6 * n - 13) / 6 + 4 - (rs ? 1 : 0);
}

}  // namespace rotlie::lie
