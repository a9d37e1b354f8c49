#pragma once
// The certificate behind a table's `order 4`: at the coefficients as the table writes them (decimals
// read back as exact rationals), the first-order conditions and every coefficient of H_R2 and H_R3
// (and H_R4 for a word that is not a palindrome) vanish relative to the size of their terms:
// |c(x)| ≤ tolerance · Σ_t |t(x)| over the terms t of each coefficient polynomial c. The test is
// exact (CLN rationals) and scale-free: H_Rk is homogeneous in 1/I, so the body's unit drops out.
#include <cln/rational.h>

#include <map>
#include <string>
#include <string_view>

#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/rigid_body.hpp"

namespace rotlie::solver {

struct order_certificate {
  int order = 0;          ///< highest order whose conditions all pass (at most 4, the dedicated claim)
  cln::cl_RA residual;    ///< max over the conditions up to order 4 of |value| / Σ|terms| at the coefficients
  std::string failure;    ///< empty when order 4 holds; else the first condition that fails, in words
};

/// The tolerance a table of `digits` significant digits is held to: 10^-(digits - 5).
cln::cl_RA certificate_tolerance(int digits);

/// x as a table of `digits` significant digits states it: its decimal text read back exactly.
cln::cl_RA written_value(const cln::cl_RA& x, int digits);

/// values: every coefficient name of the layout → its exact value. Throws std::invalid_argument when
/// a name is missing or the word has more free coefficients than the exact expansion takes.
order_certificate certify_order_four(const bch::scheme_layout& layout, const lie::moments_of_inertia& body,
                                     const std::map<std::string, cln::cl_RA>& values, int digits);

/// The same for the text of a scheme table (docs/scheme_table_format.md): its scheme, split,
/// permutation, inertia, digits and stage decimals. Throws std::invalid_argument when the text is
/// not such a table or its stages disagree with its word.
order_certificate certify_scheme_table_text(std::string_view text);

}  // namespace rotlie::solver
