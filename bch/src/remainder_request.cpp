#include "rotlie/bch/remainder_request.hpp"

#include <algorithm>
#include <stdexcept>

namespace rotlie::bch {
namespace {

const GiNaC::symbol& inertia_symbol(int i) {
  static const GiNaC::symbol I1("I1"), I2("I2"), I3("I3");
  return i == 1 ? I1 : i == 2 ? I2 : I3;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s.empty() ? "none" : s;
}

}  // namespace

remainder_result compute_remainder(const remainder_request& request) {
  remainder_result result;
  std::string stages = request.scheme;
  splitting split = request.split.value_or(splitting::abc);
  if (const auto named = find_named_scheme(request.scheme)) {
    result.name = request.scheme;
    stages = std::string(named->word);
    if (request.split && *request.split != named->split)
      throw std::invalid_argument(request.scheme + " is an " + (named->split == splitting::abc ? "ABC" : "RS") +
                                  " scheme; it does not exist in the other splitting");
    split = named->split;
  } else if (!request.split && !stages.empty() && stages.find_first_not_of("RS") == std::string::npos) {
    split = splitting::rs;
  }
  if (request.order < 1 || request.order > max_remainder_order)
    throw std::invalid_argument("--order must be between 1 and " + std::to_string(max_remainder_order) + ", got " +
                                std::to_string(request.order));
  result.layout = layout_scheme(stages, split, request.permutation);
  if (const auto most = max_remainder_stages(request.order, result.layout.symmetric); result.layout.stages.size() > most)
    throw std::invalid_argument("a " + std::string(result.layout.symmetric ? "palindromic" : "non-palindromic") + " word of " +
                                std::to_string(result.layout.stages.size()) + " stages is too long for order " +
                                std::to_string(request.order) + ": at most " + std::to_string(most) + " stages");
  auto coefficients = make_coefficients(result.layout);

  GiNaC::lst values;
  for (const auto& [name, value] : request.coefficients) {
    const auto& free = result.layout.free_coefficients;
    if (std::find(free.begin(), free.end(), name) == free.end()) {
      const auto& fixed = result.layout.eliminated;
      if (std::find(fixed.begin(), fixed.end(), name) != fixed.end())
        throw std::invalid_argument("coefficient '" + name + "' is fixed by the first-order conditions (free: " +
                                    joined(free) + ")");
      throw std::invalid_argument("'" + name + "' is not a coefficient of " + stages + " (free: " + joined(free) + ")");
    }
    values.append(coefficients.free.at(name) == GiNaC::numeric(cln::cl_N(value)));
  }
  for (auto& [name, v] : coefficients.value) v = v.subs(values).expand();
  for (const auto& name : result.layout.free_coefficients)
    if (std::none_of(request.coefficients.begin(), request.coefficients.end(), [&](const auto& c) { return c.first == name; })) {
      result.free.push_back(name);
      result.symbols.push_back(coefficients.free.at(name));
    }

  inverse_inertia w;
  if (request.inertia) {
    const auto& I = request.inertia->I;
    w = {GiNaC::numeric(cln::cl_N(cln::recip(I[0]))), GiNaC::numeric(cln::cl_N(cln::recip(I[1]))),
         GiNaC::numeric(cln::cl_N(cln::recip(I[2])))};
  } else {
    w = {1 / inertia_symbol(1), 1 / inertia_symbol(2), 1 / inertia_symbol(3)};
    for (int i = 1; i <= 3; ++i) result.symbols.push_back(inertia_symbol(i));
  }
  result.k = compute_modified_hamiltonian(stage_elements(result.layout, coefficients, w), request.order);
  return result;
}

}  // namespace rotlie::bch
