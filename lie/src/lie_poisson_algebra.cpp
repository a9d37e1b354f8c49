#include "rotlie/lie/lie_poisson_algebra.hpp"

#include <array>
#include <stdexcept>

#include "rotlie/lie/exact_echelon.hpp"
#include "rotlie/lie/modular_rank.hpp"
#include "rotlie/lie/poisson_bracket.hpp"
#include "rotlie/lie/theorems.hpp"

namespace rotlie::lie {
namespace {

using rational_poly = polynomial<cln::cl_RA>;

std::array<rational_poly, 3> alphabet() {
  return {rational_poly::power_of(1, 2), rational_poly::power_of(2, 2), rational_poly::power_of(3, 2)};
}

graded_piece first_order() {
  graded_piece piece;
  piece.order = 1;
  exact_echelon echelon;
  for (const auto& g : alphabet()) {
    echelon.add(g);
    piece.basis.push_back(g);
  }
  piece.dimension = echelon.rank();
  piece.theorem1 = true;
  piece.bound = theorem_bound(1);
  piece.method = rank_method::exact_elimination;
  return piece;
}

// The dimension is certified when rank mod p (a lower bound over Q) reaches the Theorem 1–2
// bound (an upper bound, because every spanning vector was checked exactly to lie in V_k).
bool certify(graded_piece& piece, const std::vector<rational_poly>& spanning) {
  modular_echelon echelon;
  for (const auto& v : spanning) {
    if (!echelon.add(v)) return false;  // a denominator vanished mod p: fall back to exact elimination
    if (echelon.rank() == piece.bound) break;
  }
  if (echelon.rank() != piece.bound) return false;
  piece.dimension = piece.bound;
  piece.method = rank_method::certificate;
  piece.basis = theorem_space_basis(piece.order);  // L_k = V_k, so V_k's basis is a basis of L_k
  return true;
}

graded_piece next_order(const graded_piece& previous, bool exact_only) {
  graded_piece piece;
  piece.order = previous.order + 1;
  piece.bound = theorem_bound(piece.order);

  std::vector<rational_poly> spanning;
  for (const auto& g : alphabet())
    for (const auto& v : previous.basis)
      if (auto b = poisson_bracket(g, v); !b.is_zero()) spanning.push_back(std::move(b));

  // Theorems 1 and 2 are linear statements: checking them on a spanning set checks all of L_k.
  piece.theorem1 = true;
  for (const auto& v : spanning)
    for (const auto& [m, c] : v.terms()) piece.theorem1 = piece.theorem1 && theorem1_allows(piece.order, m);
  if (theorem2_applies(piece.order)) {
    bool holds = true;
    for (const auto& v : spanning) holds = holds && cln::zerop(theorem2_pairing(v));
    piece.theorem2 = holds;
  }

  const bool inside_bound_space = piece.theorem1 && piece.theorem2.value_or(true);
  if (!exact_only && inside_bound_space && certify(piece, spanning)) return piece;

  exact_echelon echelon;
  for (const auto& v : spanning) echelon.add(v);
  piece.dimension = echelon.rank();
  piece.basis = echelon.basis();
  piece.method = rank_method::exact_elimination;
  return piece;
}

}  // namespace

std::string to_string(rank_method m) {
  return m == rank_method::certificate ? "certificate" : "exact-elimination";
}

std::vector<graded_piece> lie_poisson_algebra(int max_order, const algebra_options& options) {
  if (max_order < 1 || max_order > max_supported_order)
    throw std::invalid_argument("the order must be between 1 and " + std::to_string(max_supported_order) + ", got " +
                                std::to_string(max_order));
  std::vector<graded_piece> pieces;
  pieces.reserve(static_cast<std::size_t>(max_order));
  pieces.push_back(first_order());
  if (options.on_order) options.on_order(pieces.back());
  while (pieces.back().order < max_order) {
    pieces.push_back(next_order(pieces.back(), options.exact_only));
    if (options.on_order) options.on_order(pieces.back());
  }
  return pieces;
}

bool in_span(const std::vector<polynomial<cln::cl_RA>>& basis, const polynomial<cln::cl_RA>& v) {
  exact_echelon echelon;
  for (const auto& b : basis) echelon.add(b);
  return echelon.contains(v);
}

}  // namespace rotlie::lie
