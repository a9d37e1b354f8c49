#include "rotlie/lie/coefficient_polynomial.hpp"

#include <cln/integer.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "rotlie/lie/sparse_terms.hpp"

namespace rotlie::lie {
namespace {

constexpr int bits = 8;
constexpr std::uint32_t mask = (1u << bits) - 1;

int exponent_of(std::uint32_t key, int k) { return static_cast<int>((key >> (bits * k)) & mask); }

bool is_zero_term(const coefficient_polynomial::term& t) { return cln::zerop(t.c); }

}  // namespace

coefficient_polynomial::coefficient_polynomial(const cln::cl_RA& constant) {
  if (!cln::zerop(constant)) terms_.push_back({0, constant});
}

coefficient_polynomial coefficient_polynomial::unknown(int k) {
  if (k < 0 || k >= max_unknowns) throw std::invalid_argument("coefficient_polynomial: unknown index out of range");
  exponents e{};
  e[static_cast<std::size_t>(k)] = 1;
  return monomial(e, 1);
}

coefficient_polynomial coefficient_polynomial::monomial(const exponents& e, const cln::cl_RA& c) {
  coefficient_polynomial p;
  if (!cln::zerop(c)) p.terms_.push_back({pack(e), c});
  return p;
}

coefficient_polynomial coefficient_polynomial::from_terms(std::vector<term> terms) {
  coefficient_polynomial p;
  p.combine_sorted(std::move(terms));
  return p;
}

coefficient_polynomial::exponents coefficient_polynomial::unpack(std::uint32_t key) {
  exponents e{};
  for (int k = 0; k < max_unknowns; ++k) e[static_cast<std::size_t>(k)] = exponent_of(key, k);
  return e;
}

std::uint32_t coefficient_polynomial::pack(const exponents& e) {
  std::uint32_t key = 0;
  for (int k = 0; k < max_unknowns; ++k) {
    const int x = e[static_cast<std::size_t>(k)];
    if (x < 0 || x > static_cast<int>(mask)) throw std::overflow_error("coefficient_polynomial: exponent out of range");
    key |= static_cast<std::uint32_t>(x) << (bits * k);
  }
  return key;
}

int coefficient_polynomial::degree(int k) const {
  int d = -1;
  for (const auto& t : terms_) d = std::max(d, exponent_of(t.key, k));
  return d;
}

int coefficient_polynomial::total_degree() const {
  int d = -1;
  for (const auto& t : terms_) {
    int s = 0;
    for (int k = 0; k < max_unknowns; ++k) s += exponent_of(t.key, k);
    d = std::max(d, s);
  }
  return d;
}

coefficient_polynomial coefficient_polynomial::coefficient(int k, int power) const {
  coefficient_polynomial out;
  const std::uint32_t shift = static_cast<std::uint32_t>(power) << (bits * k);
  for (const auto& t : terms_)
    if (exponent_of(t.key, k) == power) out.terms_.push_back({t.key - shift, t.c});
  std::sort(out.terms_.begin(), out.terms_.end(), [](const term& a, const term& b) { return a.key < b.key; });
  return out;
}

coefficient_polynomial coefficient_polynomial::derivative(int k) const {
  coefficient_polynomial out;
  const std::uint32_t one = 1u << (bits * k);
  for (const auto& t : terms_)
    if (const int e = exponent_of(t.key, k); e > 0) out.terms_.push_back({t.key - one, e * t.c});
  return out;  // subtracting the same amount from every key keeps the order
}

coefficient_polynomial coefficient_polynomial::substitute(int k, const cln::cl_RA& value) const {
  std::vector<term> out;
  for (const auto& t : terms_) {
    const int e = exponent_of(t.key, k);
    out.push_back({t.key - (static_cast<std::uint32_t>(e) << (bits * k)), t.c * cln::expt(value, e)});
  }
  coefficient_polynomial p;
  p.combine_sorted(std::move(out));
  return p;
}

coefficient_polynomial coefficient_polynomial::primitive_integer() const {
  cln::cl_I denominators = 1, numerators = 0;
  for (const auto& t : terms_) {
    denominators = cln::lcm(denominators, cln::denominator(t.c));
    numerators = cln::gcd(numerators, cln::numerator(t.c));
  }
  coefficient_polynomial out(*this);
  if (!terms_.empty()) out *= cln::cl_RA(denominators) / numerators;
  return out;
}

cln::cl_RA coefficient_polynomial::operator()(const std::vector<cln::cl_RA>& x) const {
  cln::cl_RA s = 0;
  for (const auto& t : terms_) {
    cln::cl_RA v = t.c;
    for (int k = 0; k < max_unknowns; ++k)
      if (const int e = exponent_of(t.key, k); e > 0) v = v * cln::expt(x.at(static_cast<std::size_t>(k)), e);
    s = s + v;
  }
  return s;
}

double coefficient_polynomial::evaluate(const std::vector<double>& x) const {
  double s = 0;
  for (const auto& t : terms_) {
    double v = cln::double_approx(t.c);
    for (int k = 0; k < max_unknowns; ++k)
      for (int e = exponent_of(t.key, k); e > 0; --e) v *= x.at(static_cast<std::size_t>(k));
    s += v;
  }
  return s;
}

void coefficient_polynomial::combine_sorted(std::vector<term>&& unsorted) {
  sort_and_combine_terms(unsorted, [](term& into, const term& t) { into.c = into.c + t.c; }, is_zero_term);
  terms_ = std::move(unsorted);
}

coefficient_polynomial& coefficient_polynomial::operator+=(const coefficient_polynomial& o) {
  terms_ = merge_sorted_terms(
      terms_, o.terms_, [](term& t) { return std::move(t); }, [](const term& t) { return t; },
      [](const term& a, const term& b) { return term{a.key, a.c + b.c}; }, is_zero_term);
  return *this;
}

coefficient_polynomial& coefficient_polynomial::operator-=(const coefficient_polynomial& o) {
  return *this += o * coefficient_polynomial(cln::cl_RA(-1));
}

coefficient_polynomial& coefficient_polynomial::operator*=(const cln::cl_RA& s) {
  if (cln::zerop(s)) terms_.clear();
  for (auto& t : terms_) t.c = t.c * s;
  return *this;
}

coefficient_polynomial operator*(const coefficient_polynomial& a, const coefficient_polynomial& b) {
  coefficient_polynomial out;
  if (a.is_zero() || b.is_zero()) return out;
  if (b.terms_.size() == 1 && b.terms_[0].key == 0) return coefficient_polynomial(a) *= b.terms_[0].c;
  if (a.terms_.size() == 1 && a.terms_[0].key == 0) return coefficient_polynomial(b) *= a.terms_[0].c;
  // Keys add without carries while every exponent of the product stays below 256: checked once.
  for (int k = 0; k < coefficient_polynomial::max_unknowns; ++k)
    if (a.degree(k) + b.degree(k) > static_cast<int>(mask)) throw std::overflow_error("coefficient_polynomial: exponent out of range");
  std::vector<coefficient_polynomial::term> products;
  products.reserve(a.terms_.size() * b.terms_.size());
  for (const auto& x : a.terms_)
    for (const auto& y : b.terms_) products.push_back({x.key + y.key, x.c * y.c});
  out.combine_sorted(std::move(products));
  return out;
}

bool operator==(const coefficient_polynomial& a, const coefficient_polynomial& b) {
  if (a.terms_.size() != b.terms_.size()) return false;
  for (std::size_t i = 0; i < a.terms_.size(); ++i)
    if (a.terms_[i].key != b.terms_[i].key || a.terms_[i].c != b.terms_[i].c) return false;
  return true;
}

coefficient_polynomial power(const coefficient_polynomial& p, int n) {
  if (n < 0) throw std::invalid_argument("coefficient_polynomial: negative power");
  coefficient_polynomial r(1), base = p;
  for (; n > 0; n >>= 1, base = base * base)
    if (n & 1) r = r * base;
  return r;
}

bool divide_exactly(const coefficient_polynomial& p, const coefficient_polynomial& f, coefficient_polynomial& q) {
  if (f.is_zero()) return false;
  using term = coefficient_polynomial::term;
  const term& lead = f.terms().back();  // the largest key
  const auto divides = [](std::uint32_t a, std::uint32_t b) {  // every exponent of a ≤ that of b
    for (int k = 0; k < coefficient_polynomial::max_unknowns; ++k)
      if (exponent_of(a, k) > exponent_of(b, k)) return false;
    return true;
  };
  std::map<std::uint32_t, cln::cl_RA> rest;
  for (const auto& t : p.terms()) rest.emplace(t.key, t.c);
  std::vector<term> quotient;
  while (!rest.empty()) {
    const auto top = std::prev(rest.end());
    if (!divides(lead.key, top->first)) return false;
    const std::uint32_t key = top->first - lead.key;
    const cln::cl_RA c = top->second / lead.c;
    quotient.push_back({key, c});
    for (const auto& t : f.terms()) {
      const auto [at, fresh] = rest.emplace(t.key + key, -c * t.c);
      if (!fresh) at->second = at->second - c * t.c;
      if (cln::zerop(at->second)) rest.erase(at);
    }
  }
  q = coefficient_polynomial::from_terms(std::move(quotient));
  return true;
}

}  // namespace rotlie::lie
