#pragma once
// Sparse polynomials in G1, G2, G3 with coefficients in a ring R (exact rationals,
// GiNaC expressions or doubles), stored in the monomial order of monomial.hpp.
#include <map>
#include <utility>

#include "rotlie/lie/coefficient_ring.hpp"
#include "rotlie/lie/monomial.hpp"

namespace rotlie::lie {

template <class R>
class polynomial {
 public:
  using coefficient_type = R;
  using term_map = std::map<monomial, R>;
  using traits = ring_traits<R>;

  polynomial() = default;
  static polynomial term(const monomial& m, R c) {
    polynomial p;
    p.add_term(m, std::move(c));
    return p;
  }
  /// G_i^e as a polynomial, i in {1,2,3}.
  static polynomial power_of(int i, std::uint32_t e) {
    monomial m;
    m.exponent[static_cast<std::size_t>(i - 1)] = e;
    return term(m, traits::from_int(1));
  }

  /// Adds c·m, normalising the coefficient and dropping it if it cancels to zero.
  void add_term(const monomial& m, R c) {
    auto [it, inserted] = terms_.try_emplace(m, std::move(c));
    if (!inserted) it->second += c;
    traits::normalize(it->second);
    if (traits::is_zero(it->second)) terms_.erase(it);
  }

  /// Adds k·c·m through R::add_multiple (no temporary k·c), for rings that have it.
  void add_term_multiple(const monomial& m, const R& c, long k) {
    auto [it, inserted] = terms_.try_emplace(m);
    it->second.add_multiple(c, k);
    traits::normalize(it->second);
    if (traits::is_zero(it->second)) terms_.erase(it);
  }

  const term_map& terms() const { return terms_; }
  bool is_zero() const { return terms_.empty(); }
  std::size_t size() const { return terms_.size(); }
  R coefficient(const monomial& m) const {
    auto it = terms_.find(m);
    return it == terms_.end() ? traits::from_int(0) : it->second;
  }
  /// The largest monomial in the order of monomial.hpp; precondition: not zero.
  const monomial& leading_monomial() const { return terms_.rbegin()->first; }

  polynomial& operator+=(const polynomial& o) {
    for (const auto& [m, c] : o.terms_) add_term(m, c);
    return *this;
  }
  polynomial& operator-=(const polynomial& o) {
    for (const auto& [m, c] : o.terms_) add_term(m, traits::from_int(-1) * c);
    return *this;
  }
  polynomial& operator*=(const R& s) {
    term_map scaled;
    for (auto& [m, c] : terms_) {
      R v = c * s;
      traits::normalize(v);
      if (!traits::is_zero(v)) scaled.emplace(m, std::move(v));
    }
    terms_ = std::move(scaled);
    return *this;
  }
  friend polynomial operator+(polynomial a, const polynomial& b) { return a += b; }
  friend polynomial operator-(polynomial a, const polynomial& b) { return a -= b; }
  friend polynomial operator*(polynomial a, const R& s) { return a *= s; }
  friend polynomial operator*(const R& s, polynomial a) { return a *= s; }
  friend polynomial operator*(const polynomial& a, const polynomial& b) {
    polynomial p;
    for (const auto& [ma, ca] : a.terms_)
      for (const auto& [mb, cb] : b.terms_)
        p.add_term(monomial(ma[0] + mb[0], ma[1] + mb[1], ma[2] + mb[2]), ca * cb);
    return p;
  }
  /// Exact equality: the difference has no term left.
  friend bool operator==(const polynomial& a, const polynomial& b) { return (a - b).is_zero(); }

 private:
  term_map terms_;
};

/// G² = G1² + G2² + G3², the Casimir of the Lie–Poisson bracket.
template <class R>
polynomial<R> casimir() {
  return polynomial<R>::power_of(1, 2) + polynomial<R>::power_of(2, 2) + polynomial<R>::power_of(3, 2);
}

}  // namespace rotlie::lie
