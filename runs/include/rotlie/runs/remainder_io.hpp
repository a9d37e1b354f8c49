#pragma once
// Writers for `rotlie remainder`: text, LaTeX and JSON of H_R2 … H_RK, terms in our own order
// (monomials in lie's order, coefficient terms by format_expression).
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/bch/remainder_request.hpp"

namespace rotlie::runs {

/// {"word", "split", "perm", "free", "orders": [{"order", "terms": [{"G": [3 exponents], "coeff"}]}], "scheme"
/// (when named)}
nlohmann::json remainder_json(const bch::remainder_result& r);
/// A title line, then for each order "H_R<k> =" and one line per term.
std::string remainder_text(const bch::remainder_result& r);
/// A LaTeX comment with the title, then an align* block: one row per order, one line per term.
std::string remainder_latex(const bch::remainder_result& r);

}  // namespace rotlie::runs
