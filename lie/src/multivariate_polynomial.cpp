#include "rotlie/lie/multivariate_polynomial.hpp"

#include <cln/rational_io.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "rotlie/lie/sparse_terms.hpp"

namespace rotlie::lie {
namespace {

using term = multivariate_polynomial::term;

bool is_zero_term(const term& t) { return cln::zerop(t.numerator); }

// Sorted by key with equal keys summed and zeros dropped, in place: the numerators are mostly
// fixnums (immediate values), whose copies are free.
void combine(std::vector<term>& v) {
  sort_and_combine_terms(v, [](term& into, const term& t) { into.numerator = into.numerator + t.numerator; }, is_zero_term);
}

cln::cl_RA monomial_value(std::uint64_t key, const std::vector<cln::cl_RA>& x) {
  cln::cl_RA v = 1;
  for (int k = 0; k < multivariate_polynomial::max_unknowns; ++k)
    if (const int e = multivariate_polynomial::exponent(key, k); e > 0) v = v * cln::expt(x.at(static_cast<std::size_t>(k)), e);
  return v;
}

}  // namespace

multivariate_polynomial::multivariate_polynomial(const cln::cl_RA& constant) {
  if (cln::zerop(constant)) return;
  denominator_ = cln::denominator(constant);
  terms_.push_back({0, cln::numerator(constant)});
}

multivariate_polynomial multivariate_polynomial::unknown(int k) {
  if (k < 0 || k >= max_unknowns) throw std::invalid_argument("multivariate_polynomial: unknown index out of range");
  multivariate_polynomial p;
  p.terms_.push_back({std::uint64_t{1} << (4 * k), cln::cl_I(1)});
  return p;
}

int multivariate_polynomial::key_degree(std::uint64_t key) {
  int d = 0;
  for (; key != 0; key >>= 4) d += static_cast<int>(key & 15u);
  return d;
}

int multivariate_polynomial::total_degree() const {
  int d = -1;
  for (const auto& t : terms_) d = std::max(d, key_degree(t.key));
  return d;
}

std::vector<std::pair<std::uint64_t, cln::cl_RA>> multivariate_polynomial::rational_terms() const {
  std::vector<std::pair<std::uint64_t, cln::cl_RA>> out;
  out.reserve(terms_.size());
  for (const auto& t : terms_) out.emplace_back(t.key, t.numerator / denominator_);
  return out;
}

cln::cl_RA multivariate_polynomial::operator()(const std::vector<cln::cl_RA>& x) const {
  cln::cl_RA s = 0;
  for (const auto& t : terms_) s = s + t.numerator * monomial_value(t.key, x);
  return s / denominator_;
}

cln::cl_RA multivariate_polynomial::term_size(const std::vector<cln::cl_RA>& x) const {
  cln::cl_RA s = 0;
  for (const auto& t : terms_) s = s + cln::abs(t.numerator * monomial_value(t.key, x));
  return s / denominator_;
}

void multivariate_polynomial::reduce() {
  cln::cl_I g = denominator_;
  for (const auto& t : terms_) {
    if (g == 1) return;
    g = cln::gcd(g, t.numerator);
  }
  if (g == 1) return;
  denominator_ = cln::exquopos(denominator_, g);
  for (auto& t : terms_) t.numerator = cln::exquo(t.numerator, g);
}

multivariate_polynomial& multivariate_polynomial::operator+=(const multivariate_polynomial& o) { return add_multiple(o, 1); }

multivariate_polynomial& multivariate_polynomial::add_multiple(const multivariate_polynomial& o, long k) {
  if (o.terms_.empty() || k == 0) return *this;
  if (terms_.empty()) {
    *this = o;
    if (k != 1)
      for (auto& t : terms_) t.numerator = t.numerator * k;
    return *this;
  }
  // Over the least common denominator: this side scaled by fa, the other by fb (k included).
  cln::cl_I fa = 1, fb = k;
  if (denominator_ != o.denominator_) {
    const cln::cl_I g = cln::gcd(denominator_, o.denominator_);
    fa = cln::exquopos(o.denominator_, g);
    fb = cln::exquopos(denominator_, g) * k;
    denominator_ = denominator_ * fa;
  }
  // Most sums in a bracket expansion add terms whose monomials are already present: then the sum
  // is done in place, without a new vector (allocation was a third of the expansion's time).
  bool all_present = o.terms_.size() <= terms_.size();
  for (auto a = terms_.cbegin(), b = o.terms_.cbegin(); all_present && b != o.terms_.cend(); ++b) {
    while (a != terms_.cend() && a->key < b->key) ++a;
    all_present = a != terms_.cend() && a->key == b->key;
  }
  if (all_present) {
    bool zero = false;
    auto a = terms_.begin();
    for (const auto& t : o.terms_) {
      for (; a->key < t.key; ++a)
        if (fa != 1) a->numerator = a->numerator * fa;
      a->numerator = (fa == 1 ? a->numerator : a->numerator * fa) + (fb == 1 ? t.numerator : t.numerator * fb);
      zero = zero || cln::zerop(a->numerator);
      ++a;
    }
    if (fa != 1)
      for (; a != terms_.end(); ++a) a->numerator = a->numerator * fa;
    if (zero)
      terms_.erase(std::remove_if(terms_.begin(), terms_.end(), [](const term& t) { return cln::zerop(t.numerator); }), terms_.end());
    if (terms_.empty()) denominator_ = 1;
    return *this;
  }
  const auto scaled_a = [&](const term& t) { return fa == 1 ? t.numerator : t.numerator * fa; };
  const auto scaled_b = [&](const term& t) { return fb == 1 ? t.numerator : t.numerator * fb; };
  terms_ = merge_sorted_terms(
      terms_, o.terms_, [&](term& t) { return term{t.key, fa == 1 ? std::move(t.numerator) : t.numerator * fa}; },
      [&](const term& t) { return term{t.key, scaled_b(t)}; },
      [&](const term& a, const term& b) { return term{a.key, scaled_a(a) + scaled_b(b)}; }, is_zero_term);
  if (terms_.empty()) denominator_ = 1;
  return *this;
}

multivariate_polynomial& multivariate_polynomial::operator-=(const multivariate_polynomial& o) { return *this += -o; }

multivariate_polynomial& multivariate_polynomial::operator*=(const cln::cl_RA& s) {
  if (cln::zerop(s)) {
    terms_.clear();
    denominator_ = 1;
    return *this;
  }
  const cln::cl_I n = cln::numerator(s);
  if (n != 1)
    for (auto& t : terms_) t.numerator = t.numerator * n;
  denominator_ = denominator_ * cln::denominator(s);
  if (cln::integer_length(denominator_) > 64) reduce();
  return *this;
}

multivariate_polynomial operator*(const multivariate_polynomial& a, const multivariate_polynomial& b) {
  multivariate_polynomial out;
  if (a.is_zero() || b.is_zero()) return out;
  // Keys add without carries while every exponent stays ≤ 15: guaranteed by the total degree.
  if (a.total_degree() + b.total_degree() > multivariate_polynomial::max_degree)
    throw std::overflow_error("multivariate_polynomial: total degree above 15");
  out.denominator_ = a.denominator_ * b.denominator_;
  const auto& small = a.terms_.size() <= b.terms_.size() ? a : b;
  const auto& large = a.terms_.size() <= b.terms_.size() ? b : a;
  if (small.terms_.size() == 1) {  // a monomial: adding its key keeps the order
    const auto& [k, n] = small.terms_.front();
    out.terms_.reserve(large.terms_.size());
    for (const auto& t : large.terms_) out.terms_.push_back({t.key + k, t.numerator * n});
  } else {
    out.terms_.reserve(a.terms_.size() * b.terms_.size());
    for (const auto& x : large.terms_)
      for (const auto& y : small.terms_) out.terms_.push_back({x.key + y.key, x.numerator * y.numerator});
    combine(out.terms_);
    if (out.terms_.empty()) out.denominator_ = 1;
  }
  if (cln::integer_length(out.denominator_) > 64) out.reduce();
  return out;
}

multivariate_polynomial multivariate_polynomial::sum_of_products(const std::vector<product_term>& summands) {
  multivariate_polynomial out;
  std::vector<cln::cl_I> denominators;
  denominators.reserve(summands.size());
  cln::cl_I common = 1;
  int degree = 0;
  std::size_t size = 0;
  for (const auto& s : summands) {
    cln::cl_I d = cln::denominator(s.factor) * s.a->denominator_;
    if (s.b) d = d * s.b->denominator_;
    common = cln::lcm(common, d);
    denominators.push_back(std::move(d));
    degree = std::max(degree, s.a->total_degree() + (s.b ? s.b->total_degree() : 0));
    size += s.a->terms_.size() * (s.b ? s.b->terms_.size() : 1);
  }
  if (degree > max_degree) throw std::overflow_error("multivariate_polynomial: total degree above 15");
  out.terms_.reserve(size);
  for (std::size_t i = 0; i < summands.size(); ++i) {
    const auto& s = summands[i];
    const cln::cl_I scale = cln::numerator(s.factor) * cln::exquopos(common, denominators[i]);
    if (cln::zerop(scale)) continue;
    if (!s.b) {
      for (const auto& x : s.a->terms_) out.terms_.push_back({x.key, x.numerator * scale});
      continue;
    }
    for (const auto& x : s.a->terms_) {
      const cln::cl_I xs = x.numerator * scale;
      for (const auto& y : s.b->terms_) out.terms_.push_back({x.key + y.key, xs * y.numerator});
    }
  }
  combine(out.terms_);
  out.denominator_ = out.terms_.empty() ? cln::cl_I(1) : common;
  if (cln::integer_length(out.denominator_) > 64) out.reduce();
  return out;
}

bool operator==(const multivariate_polynomial& a, const multivariate_polynomial& b) {
  if (a.terms_.size() != b.terms_.size()) return false;
  for (std::size_t i = 0; i < a.terms_.size(); ++i)
    if (a.terms_[i].key != b.terms_[i].key || a.terms_[i].numerator * b.denominator_ != b.terms_[i].numerator * a.denominator_)
      return false;
  return true;
}

std::string multivariate_polynomial::to_string(const std::vector<std::string>& names) const {
  if (terms_.empty()) return "0";
  std::ostringstream out;
  bool first = true;
  for (const auto& [key, value] : rational_terms()) {
    cln::cl_RA c = value;
    if (!first) out << (cln::minusp(c) ? " - " : " + ");
    else if (cln::minusp(c)) out << "-";
    c = cln::abs(c);
    first = false;
    bool printed = false;
    if (key == 0 || c != 1) {
      out << c;
      printed = true;
    }
    for (int k = 0; k < max_unknowns; ++k)
      if (const int e = exponent(key, k); e > 0) {
        out << (printed ? "*" : "")
            << (static_cast<std::size_t>(k) < names.size() ? names[static_cast<std::size_t>(k)] : "x" + std::to_string(k));
        if (e > 1) out << "^" << e;
        printed = true;
      }
  }
  return out.str();
}

}  // namespace rotlie::lie
