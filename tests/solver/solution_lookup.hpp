#pragma once
// Finding a labelled solution in a solver result and comparing its coefficients to printed digits.
#include <boost/test/unit_test.hpp>

#include <cln/real.h>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"

namespace rotlie::test {

inline const solver::dedicated_solution& find(const solver::family_result& r, const std::string& scheme,
                                              const std::string& perm, int label) {
  for (const auto& s : r.solutions)
    if (s.scheme == scheme && s.permutation == perm && s.label == label) return s;
  BOOST_FAIL("no solution " << scheme << " " << perm << " (" << label << ")");
  throw std::logic_error("unreachable");
}

inline cln::cl_RA value(const solver::dedicated_solution& s, const std::string& name) {
  for (const auto& [n, v] : s.coefficients)
    if (n == name) return v;
  throw std::logic_error("no coefficient " + name);
}

/// |ours − want| ≤ 10^-35 · max(1, |want|)
inline bool agrees_to_35_digits(const cln::cl_RA& ours, const cln::cl_RA& want) {
  const cln::cl_RA tolerance = cln::max(cln::cl_RA(1), cln::abs(want)) / cln::expt(cln::cl_RA(10), 35);
  return cln::abs(ours - want) <= tolerance;
}

inline cln::cl_RA number(const char* text) { return *lie::parse_exact_number(text); }

}  // namespace rotlie::test
