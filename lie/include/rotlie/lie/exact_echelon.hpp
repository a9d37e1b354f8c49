#pragma once
// Incremental row echelon form over Q (CLN rationals) of sparse polynomials:
// exact rank, exact membership, and a basis.
#include <map>
#include <vector>

#include "rotlie/lie/polynomial.hpp"

namespace rotlie::lie {

class exact_echelon {
 public:
  /// Keeps v (reduced) if it is independent of the rows so far; returns whether it was.
  bool add(const polynomial<cln::cl_RA>& v);
  /// Whether v lies in the span of the rows so far.
  bool contains(const polynomial<cln::cl_RA>& v) const;
  std::size_t rank() const { return pivots_.size(); }
  /// The kept rows, each with leading coefficient 1, in increasing order of leading monomial.
  std::vector<polynomial<cln::cl_RA>> basis() const;

 private:
  polynomial<cln::cl_RA> reduce(polynomial<cln::cl_RA> v) const;
  std::map<monomial, polynomial<cln::cl_RA>> pivots_;
};

}  // namespace rotlie::lie
