// The computation behind the report's section "Remainder formulas" (see remainder_study.hpp).
#include "rotlie/runs/remainder_study.hpp"

#include <chrono>
#include <utility>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/lie/theorems.hpp"

namespace rotlie::runs {
namespace {

const GiNaC::symbol& x_symbol() {
  static const GiNaC::symbol x("x");
  return x;
}
const GiNaC::symbol& y_symbol() {
  static const GiNaC::symbol y("y");
  return y;
}

struct paper_form {
  bch::scheme_layout layout;
  bch::coefficient_symbols coefficients;
  std::vector<GiNaC::symbol> symbols;  // free coefficients, then x, y
  bch::modified_hamiltonian k;
};

// H_Rk in the paper's variables, scaled by 2I1 = 1 (eqs. 42–43 for RS, 53–54 for ABC).
paper_form in_paper_variables(std::string_view scheme, int order) {
  const auto named = bch::find_named_scheme(scheme);
  paper_form p;
  p.layout = bch::layout_scheme(named->word, named->split);
  p.coefficients = bch::make_coefficients(p.layout);
  for (const auto& name : p.layout.free_coefficients) p.symbols.push_back(p.coefficients.free.at(name));
  p.symbols.push_back(x_symbol());
  p.symbols.push_back(y_symbol());
  const auto w = named->split == bch::splitting::abc ? bch::inverse_inertia::abc_paper(x_symbol(), y_symbol())
                                                     : bch::inverse_inertia::rs_paper(x_symbol(), y_symbol());
  p.k = bch::compute_modified_hamiltonian(bch::stage_elements(p.layout, p.coefficients, w), order);
  return p;
}

const lie::monomial third_order_monomials[] = {lie::monomial(2, 2, 0), lie::monomial(2, 0, 2), lie::monomial(0, 2, 2)};

}  // namespace

remainder_study_result remainder_study(bool quick) {
  remainder_study_result out;
  const auto start = std::chrono::steady_clock::now();
  for (const char* scheme : {"RSRSRSR", "SRSRSRS", "N4"}) {
    const auto p = in_paper_variables(scheme, 3);
    remainder_third_order t{scheme, p.symbols, {}};
    for (std::size_t i = 0; i < 3; ++i) t.P[i] = p.k.remainder[3].coefficient(third_order_monomials[i]);
    out.third_order.push_back(std::move(t));
  }
  const std::vector<std::pair<std::string, std::string>> eliminations = {
      {"N1", "b1"}, {"N2", "a2"}, {"N3", "b1"}, {"N4", "b1"}, {"N5", "c1"}, {"N6", "b1"}, {"N7", "c1"}};
  for (const auto& [scheme, v2_name] : eliminations) {
    if (quick && scheme != "N4") continue;
    const auto p = in_paper_variables(scheme, 3);
    const GiNaC::symbol v2 = p.coefficients.free.at(v2_name);
    out.eliminations.push_back({scheme, v2, p.symbols,
                                GiNaC::resultant(p.k.remainder[3].coefficient(lie::monomial(2, 2, 0)).expand(),
                                                 p.k.remainder[3].coefficient(lie::monomial(2, 0, 2)).expand(), v2)});
  }
  // H_R5 structure (62)–(63) for every named scheme, symbolic in the moments.
  for (const auto& n : bch::named_schemes()) {
    if (quick && n.name != "N4" && n.name != "P1" && n.name != "R") continue;
    const auto layout = bch::layout_scheme(n.word, n.split);
    const auto c = bch::make_coefficients(layout);
    const auto k = bch::compute_modified_hamiltonian(bch::stage_elements(layout, c, bch::inverse_inertia::symbolic()), 5);
    remainder_structure r{std::string(n.name), std::string(n.word), k.remainder[5].size(), true, true};
    for (const auto& [m, q] : k.remainder[5].terms()) r.support = r.support && lie::theorem1_allows(5, m);
    r.reduction = bch::theorem2_pairing(k.remainder[5]).is_zero();
    out.structure.push_back(std::move(r));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rotlie::runs
