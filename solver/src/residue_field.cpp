#include "rotlie/solver/residue_field.hpp"

#include <stdexcept>

namespace rotlie::solver {
namespace {

// s, t with s a + t b = gcd(a, b) (monic), by the extended Euclidean algorithm over Q.
rational_polynomial inverse_modulo(const rational_polynomial& a, const rational_polynomial& m) {
  rational_polynomial r0 = m, r1 = a, t0, t1({1});
  while (!r1.is_zero()) {
    const rational_polynomial q = quotient(r0, r1);
    rational_polynomial r2 = remainder(r0, r1), t2 = t0 - q * t1;
    r0 = std::move(r1), r1 = std::move(r2), t0 = std::move(t1), t1 = std::move(t2);
  }
  if (r0.degree() != 0) throw std::logic_error("residue_field: not invertible");
  return remainder(t0 * rational_polynomial({cln::recip(r0.coefficients()[0])}), m);
}

}  // namespace

residue_field::residue_field(rational_polynomial modulus, const cln::cl_RA& lo, const cln::cl_RA& hi)
    : modulus_(std::move(modulus)), lo_(lo), hi_(hi) {
  if (!holds_root(modulus_)) throw std::invalid_argument("residue_field: the modulus has no root in the interval");
}

bool residue_field::holds_root(const rational_polynomial& q) const {
  if (q.degree() < 1) return false;
  const cln::cl_RA a = q(lo_), b = q(hi_);
  return cln::zerop(a) || cln::zerop(b) || cln::signum(a) != cln::signum(b);
}

rational_polynomial residue_field::reduce(const rational_polynomial& a) const { return remainder(a, modulus_); }

bool residue_field::is_zero(const rational_polynomial& a) {
  const rational_polynomial r = reduce(a);
  if (r.is_zero()) return true;
  const rational_polynomial h = gcd(r, modulus_);
  if (h.degree() < 1) return false;
  // A zero divisor: keep the factor of the modulus that vanishes at the root.
  if (holds_root(h)) {
    modulus_ = h;
    return true;
  }
  modulus_ = quotient(modulus_, h);
  return false;
}

rational_polynomial residue_field::inverse(const rational_polynomial& a) {
  if (is_zero(a)) throw std::domain_error("residue_field: zero has no inverse");
  return inverse_modulo(reduce(a), modulus_);
}

rational_polynomial residue_field::times(const rational_polynomial& a, const rational_polynomial& b) const {
  return reduce(a * b);
}

std::vector<rational_polynomial> residue_field::quotient_in_v(std::vector<rational_polynomial> a,
                                                              const std::vector<rational_polynomial>& b) {
  if (b.empty()) throw std::domain_error("residue_field: division by the zero polynomial");
  const rational_polynomial lead_inverse = inverse(b.back());
  std::vector<rational_polynomial> q(a.size() >= b.size() ? a.size() - b.size() + 1 : 0);
  while (a.size() >= b.size()) {
    const rational_polynomial f = times(a.back(), lead_inverse);
    const std::size_t shift = a.size() - b.size();
    q[shift] = f;
    for (std::size_t j = 0; j < b.size(); ++j) a[shift + j] = reduce(a[shift + j] - f * b[j]);
    a.pop_back();
  }
  return q;
}

std::vector<rational_polynomial> residue_field::gcd_in_v(std::vector<rational_polynomial> a, std::vector<rational_polynomial> b) {
  const auto trim = [&](std::vector<rational_polynomial>& p) {
    while (!p.empty() && is_zero(p.back())) p.pop_back();
  };
  trim(a);
  trim(b);
  while (!b.empty()) {
    // a ← a mod b, b's leading coefficient inverted in the field
    const rational_polynomial lead_inverse = inverse(b.back());
    while (a.size() >= b.size()) {
      const rational_polynomial f = times(a.back(), lead_inverse);
      const std::size_t shift = a.size() - b.size();
      for (std::size_t j = 0; j < b.size(); ++j) a[shift + j] = reduce(a[shift + j] - f * b[j]);
      a.pop_back();  // cancelled by construction
      trim(a);
    }
    std::swap(a, b);
  }
  if (a.empty()) return a;
  const rational_polynomial lead_inverse = inverse(a.back());
  for (auto& c : a) c = times(c, lead_inverse);
  return a;
}

}  // namespace rotlie::solver
