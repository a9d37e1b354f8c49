#pragma once
// Writers for `rotlie remainder`: text, LaTeX and JSON of H_R2 … H_RK, terms in our own order
// (monomials in lie's order, coefficient terms by format_expression).
#include <nlohmann/json.hpp>

#include <string>

#include "rotlie/bch/remainder_request.hpp"

namespace rotlie::runs {

nlohmann::json remainder_json(const bch::remainder_result& r);
std::string remainder_text(const bch::remainder_result& r);
std::string remainder_latex(const bch::remainder_result& r);

}  // namespace rotlie::runs
