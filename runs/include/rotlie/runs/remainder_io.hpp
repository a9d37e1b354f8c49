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

// The Python module (python/src) still spells these rotlie::reports::…, where they lived before; the
// names stay reachable there until its call sites say runs::.
namespace rotlie::reports {
using runs::remainder_json;
using runs::remainder_text;
using runs::remainder_latex;
}  // namespace rotlie::reports
