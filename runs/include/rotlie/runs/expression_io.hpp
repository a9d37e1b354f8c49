#pragma once
// Printing of GiNaC polynomials (Laurent in some symbols, rational coefficients) with terms in
// our own fixed order — GiNaC's term order depends on symbol serial numbers and is not
// reproducible between runs.
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "rotlie/lie/monomial.hpp"

namespace rotlie::runs {

enum class expression_style { text, latex };

/// Terms sorted by total degree ascending, then by the exponents of `symbols` (in that order)
/// descending. Throws std::logic_error for a symbol not in the list or a non-polynomial term.
std::string format_expression(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& symbols, expression_style style);

/// "G1^2*G2^2" or "G_1^{2} G_2^{2}".
std::string format_monomial(const lie::monomial& m, expression_style style);

}  // namespace rotlie::runs
