#pragma once
// A Nosé–Hoover chain (Martyna, Klein & Tuckerman 1992) on a set of momenta with dof degrees of
// freedom, kinetic energy K (2K = Σ p²/m in the energy's units), target kT:
//   dp/dt = F − v₁ p,   dη_k/dt = v_k,   dv₁/dt = (2K − dof kT)/Q₁ − v₁ v₂,
//   dv_k/dt = (Q_{k−1} v_{k−1}² − kT)/Q_k − v_k v_{k+1},   dv_M/dt = (Q_{M−1} v_{M−1}² − kT)/Q_M,
// with Q₁ = dof kT τ², Q_k = kT τ² (τ the thermostat's period). advance() is the chain's own part
// of the flow (F = 0) for time t, as Kamberaj, Low & Neal (2005) place it around the step of the
// bodies (and LAMMPS's rigid/nvt/small with it): a symmetric sweep (v_M half, v_{M−1} … v₁ halves,
// the momenta scaled by e^{−v₁δ}, back), composed with the Suzuki–Yoshida weights (order 1, 3 or 5)
// and `iterations` substeps, as Martyna, Tuckerman, Tobias & Klein (1996) do. It returns the factor
// the caller scales its momenta by. The quantity kept by the whole flow is
//   H + Σ Q_k v_k²/2 + dof kT η₁ + kT Σ_{k≥2} η_k            (extended_energy).
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rotlie::models {

struct nose_hoover_chain_state {
  std::vector<double> eta, v;  ///< the chain's positions and velocities, v in 1/time
};

class nose_hoover_chain {
 public:
  nose_hoover_chain() = default;
  /// dof > 0 degrees of freedom at kT > 0 with period tau > 0; a chain of `length` ≥ 1; Suzuki–Yoshida
  /// `order` 1, 3 or 5; `iterations` ≥ 1 substeps. Throws std::invalid_argument otherwise.
  nose_hoover_chain(double dof, double kT, double tau, int length = 3, int order = 3, int iterations = 1)
      : dof_(dof), kT_(kT), length_(length), iterations_(iterations) {
    if (!(dof > 0) || !(kT > 0) || !(tau > 0) || !std::isfinite(dof * kT * tau * tau))
      throw std::invalid_argument("a Nose-Hoover chain needs positive, finite degrees of freedom, temperature and period");
    if (length < 1 || length > 100) throw std::invalid_argument("a Nose-Hoover chain's length must be 1 to 100");
    if (iterations < 1 || iterations > 100) throw std::invalid_argument("a Nose-Hoover chain's substeps must be 1 to 100");
    if (order == 1) weights_ = {1.0};
    else if (order == 3) {
      const double w = 1 / (2 - std::cbrt(2.0));
      weights_ = {w, 1 - 2 * w, w};
    } else if (order == 5) {
      const double w = 1 / (4 - std::pow(4.0, 1.0 / 3));
      weights_ = {w, w, 1 - 4 * w, w, w};
    } else
      throw std::invalid_argument("a Nose-Hoover chain's Suzuki-Yoshida order must be 1, 3 or 5");
    Q_.assign(static_cast<std::size_t>(length), kT * tau * tau);
    Q_[0] *= dof;
  }

  int length() const { return length_; }
  double dof() const { return dof_; }
  double kT() const { return kT_; }
  void set_kT(double kT) {  // a ramped target: the masses keep their values (LAMMPS's rigid/nvt/small does the same)
    if (!(kT > 0) || !std::isfinite(kT)) throw std::invalid_argument("a Nose-Hoover chain's temperature must be positive");
    kT_ = kT;
  }

  /// The chain at rest.
  nose_hoover_chain_state rest() const { return {std::vector<double>(Q_.size(), 0.0), std::vector<double>(Q_.size(), 0.0)}; }

  /// The chain's flow for time t with the momenta's 2K = two_K at its start; returns the factor the
  /// momenta are scaled by over t (2K ends at two_K times its square).
  double advance(nose_hoover_chain_state& s, double two_K, double t) const {
    if (s.v.size() != Q_.size()) s = rest();
    const std::size_t M = Q_.size();
    double scale = 1;
    auto force = [&](std::size_t k) {
      return k == 0 ? (two_K * scale * scale - dof_ * kT_) / Q_[0] : (Q_[k - 1] * s.v[k - 1] * s.v[k - 1] - kT_) / Q_[k];
    };
    for (int n = 0; n < iterations_; ++n)
      for (const double w : weights_) {
        const double d = w * t / iterations_;
        s.v[M - 1] += force(M - 1) * d / 2;
        for (std::size_t k = M - 1; k-- > 0;) {
          const double a = std::exp(-s.v[k + 1] * d / 4);
          s.v[k] = (s.v[k] * a + force(k) * d / 2) * a;
        }
        scale *= std::exp(-s.v[0] * d);
        for (std::size_t k = 0; k < M; ++k) s.eta[k] += s.v[k] * d;
        for (std::size_t k = 0; k + 1 < M; ++k) {
          const double a = std::exp(-s.v[k + 1] * d / 4);
          s.v[k] = (s.v[k] * a + force(k) * d / 2) * a;
        }
        s.v[M - 1] += force(M - 1) * d / 2;
      }
    return scale;
  }

  /// The chain's share of the kept quantity: Σ Q_k v_k²/2 + dof kT η₁ + kT Σ_{k≥2} η_k.
  double energy(const nose_hoover_chain_state& s) const {
    if (Q_.empty() || s.v.size() != Q_.size()) return 0;  // a chain not yet built, or at rest
    double e = dof_ * kT_ * s.eta[0];
    for (std::size_t k = 0; k < Q_.size(); ++k) e += Q_[k] * s.v[k] * s.v[k] / 2 + (k > 0 ? kT_ * s.eta[k] : 0.0);
    return e;
  }

 private:
  double dof_ = 1, kT_ = 1;
  int length_ = 3, iterations_ = 1;
  std::vector<double> Q_, weights_;
};

}  // namespace rotlie::models
