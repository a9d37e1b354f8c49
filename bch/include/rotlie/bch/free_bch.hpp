#pragma once
// BCH-type series in the free Lie algebra, exact, in the Lyndon basis:
//   XY  log(e^X e^Y)            XYX  log(e^X e^Y e^X)
//   SYM log(e^{X/2} e^Y e^{X/2}) XYZ  log(e^X e^Y e^Z)
// (X, Y, Z = letters A, B, C). Coefficients are 128-bit numerators over one denominator per degree.
//
// Only XYX and XYZ are projected onto the Lyndon basis (word coefficients, then a unitriangular
// solve per multidegree, lyndon_projection.hpp). XYX is odd (S(−X,−Y) = −S(X,Y)), so only its odd
// degrees are solved; SYM(X, Y) = XYX(X/2, Y) rescales each coefficient by 2^{−#A}; and
// e^X e^Y = e^{X/2} e^{SYM} e^{−X/2} gives XY = Σ_k ad_{X/2}^k SYM / k!, where ad_A^k P_l = P_{A^k l}
// is again a Lyndon basis element, so XY costs a relabelling of SYM.
#include <cln/rational.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/bch/int128.hpp"
#include "rotlie/bch/lie_series.hpp"
#include "rotlie/bch/lyndon_basis.hpp"

namespace rotlie::bch {

enum class free_series { xy, xyx, sym, xyz };

std::string_view series_name(free_series s);  ///< "XY", "XYX", "SYM", "XYZ"
std::optional<free_series> parse_free_series(std::string_view name);
int series_letters(free_series s);
/// Highest degree computed: 20 with two letters, 14 with three (beyond, the 128-bit bounds of
/// word_coefficients.hpp and lyndon_projection.hpp are not proven, and the time grows about 3× per degree).
int max_series_degree(free_series s);

struct exact_lie_series {
  free_series series = free_series::xy;
  int max_degree = 0;
  std::shared_ptr<const lyndon_basis> basis;
  std::vector<int128> numerator;    ///< by basis index
  std::vector<int128> denominator;  ///< by degree (index 0 unused), positive, the least common one

  std::size_t size() const { return numerator.size(); }
  cln::cl_RA coefficient(std::size_t i) const;
  std::string coefficient_text(std::size_t i) const;  ///< "-1/12", "0"
  std::size_t nonzero_at_degree(int d) const;
};

struct series_options {
  int threads = 1;
  /// Solve the even degrees of XYX (and SYM) too instead of using that they vanish; XY projected
  /// directly instead of derived from SYM. Both are the tests' second method.
  bool direct = false;
};

/// Throws std::invalid_argument for a degree outside 1 … max_series_degree(s).
exact_lie_series compute_free_series(free_series s, int max_degree, const series_options& options = {});

/// The same series as a map of nonzero coefficients (the evaluate() input).
lie_series to_lie_series(const exact_lie_series& s);

}  // namespace rotlie::bch
