#pragma once
// Liquid water as a potential of the torqued-rigid-body system (vZS section V.C): N rigid water
// molecules in a cubic periodic box, minimum image. Lab forces and torques about each centre of
// mass (vZS eq. 4: τ_i = Σ_a (x_ia − q_i) × f_ia) are summed from the site forces.
//
// Two interactions:
//  - switched_molecular (the scene): for each molecule pair with O–O distance r < r_c, the whole
//    pair energy E_ij (all nine site–site Coulomb terms qqr2e q_a q_b / r_ab and the O–O
//    Lennard-Jones) times a switch S(r) of the O–O distance; every site vector uses the image of
//    the O–O vector. S = 1 below r_c − w and S = 1 − (35y⁴ − 84y⁵ + 70y⁶ − 20y⁷) with
//    y = (r − r_c + w)/w above: S, S′, S″ and S‴ are continuous at both ends (C³), so pairs
//    crossing the switch do not spoil a 4th-order integrator's error expansion at low order.
//    The switch adds −E_ij S′(r) r̂ to the oxygens' forces.
//  - lammps_dsf (for the side-by-side comparison only): the site pair style lj/cut/coul/dsf as
//    LAMMPS (29 Sep 2021) computes it, with its polynomial erfc (Abramowitz & Stegun 7.1.26), the
//    Lennard-Jones shifted to zero at the cutoff (pair_modify shift yes), each site pair at its
//    own minimum image, intramolecular pairs excluded, and LAMMPS's self energy per site. Its
//    force is the derivative of the exact-erfc energy, not of the approximated one.
//
// Neighbours: a cell list on the molecules feeds a molecule-pair list of radius r_c + skin
// (O–O for the molecular cutoff; centres of mass, plus twice the site radius, for DSF), rebuilt
// when an oxygen (molecular cutoff) or any site (DSF) has moved more than skin/2 since the last
// build.
//
// Threads: the pair list is cut into a fixed number of chunks; each chunk sums into its own
// buffers and the chunks are added in chunk order, so the result has the same bits for any
// number of threads. No allocation in a step once the buffers have grown.
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/real_units.hpp"
#include "rotlie/models/rigid_bodies.hpp"
#include "rotlie/models/scenes/molecule_pair_list.hpp"
#include "rotlie/models/scenes/water_model.hpp"
#include "rotlie/models/scenes/worker_pool.hpp"

namespace rotlie::models {

enum class water_interaction { switched_molecular, lammps_dsf };

template <class T>
struct liquid_water_options {
  T box{};                                  ///< side of the cubic box, Å
  T cutoff = 11;                            ///< r_c, Å
  T switch_width = T(3) / 2;                ///< w, Å (switched_molecular)
  T skin = 1;                               ///< pair-list skin, Å
  water_interaction interaction = water_interaction::switched_molecular;
  T dsf_alpha = T(1) / 5;                   ///< DSF damping α, 1/Å (lammps_dsf)
  int threads = 1;
};

template <class T>
class liquid_water {
 public:
  static constexpr int chunks = 8;  ///< fixed: the sums do not depend on the thread count

  liquid_water(water_model<T> model, liquid_water_options<T> options) : model_(std::move(model)), opt_(options) {
    using std::isfinite;
    const auto finite = [](const T& x) { return isfinite(static_cast<double>(x)); };
    if (!finite(opt_.box) || !finite(opt_.cutoff) || !finite(opt_.switch_width) || !finite(opt_.skin) || !finite(opt_.dsf_alpha))
      throw std::invalid_argument("liquid water: box, cutoff, switch width, skin and DSF alpha must be finite");
    if (!(opt_.cutoff > 0) || !(opt_.switch_width > 0) || !(opt_.switch_width < opt_.cutoff) || !(opt_.skin > 0))
      throw std::invalid_argument("liquid water: need 0 < switch width < cutoff and a positive skin");
    if (!(opt_.box > 2 * opt_.cutoff))
      throw std::invalid_argument("the box (" + std::to_string(static_cast<double>(opt_.box)) + " Å) is not larger than twice the cutoff (" +
                                  std::to_string(static_cast<double>(2 * opt_.cutoff)) + " Å): minimum image would miss pairs");
    if (opt_.threads < 1) throw std::invalid_argument("liquid water: at least one thread");
    const T qqr2e = real_units::qqr2e<T>();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) kqq_[a][b] = qqr2e * model_.charge[a] * model_.charge[b];
    r_on_ = opt_.cutoff - opt_.switch_width;
    if (opt_.interaction == water_interaction::lammps_dsf) set_up_dsf();
    ws_ = std::make_shared<workspace>(opt_.threads);
  }

  bool acts() const { return true; }
  const water_model<T>& model() const { return model_; }
  const liquid_water_options<T>& options() const { return opt_; }
  long list_builds() const { return ws_->builds; }
  std::size_t listed_pairs() const { return ws_->list.pairs().size(); }

  /// Lab forces and torques about the centres; returns V (kcal/mol).
  T evaluate(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& force, std::vector<vec3<T>>& torque) const {
    workspace& w = *ws_;
    prepare(bodies);
    const std::size_t n = bodies.size();
    const auto& pairs = w.list.pairs();
    const std::size_t np = pairs.size();
    auto pair_task = [&](int c) {
      auto& F = w.chunk_force[static_cast<std::size_t>(c)];
      auto& Tq = w.chunk_torque[static_cast<std::size_t>(c)];
      std::fill(F.begin(), F.end(), vec3<T>{});
      std::fill(Tq.begin(), Tq.end(), vec3<T>{});
      T e = 0;
      vec3<T> fi[3], fj[3];
      for (std::size_t k = np * static_cast<std::size_t>(c) / chunks; k < np * static_cast<std::size_t>(c + 1) / chunks; ++k) {
        const int i = pairs[k].i, j = pairs[k].j;
        T eij;
        if (!pair_terms(i, j, fi, fj, eij)) continue;  // beyond the cutoff
        e += eij;
        accumulate(i, fi, F[static_cast<std::size_t>(i)], Tq[static_cast<std::size_t>(i)]);
        accumulate(j, fj, F[static_cast<std::size_t>(j)], Tq[static_cast<std::size_t>(j)]);
      }
      w.chunk_energy[static_cast<std::size_t>(c)] = e;
    };
    w.pool.run(chunks, pair_task);
    const std::size_t slice = (n + chunks - 1) / chunks;
    auto sum_task = [&](int c) {
      for (std::size_t i = slice * static_cast<std::size_t>(c); i < std::min(n, slice * static_cast<std::size_t>(c + 1)); ++i) {
        vec3<T> f{}, t{};
        for (int k = 0; k < chunks; ++k)
          for (int a = 0; a < 3; ++a) {
            f[a] += w.chunk_force[static_cast<std::size_t>(k)][i][a];
            t[a] += w.chunk_torque[static_cast<std::size_t>(k)][i][a];
          }
        force[i] = f;
        torque[i] = t;
      }
    };
    w.pool.run(chunks, sum_task);
    T V = 0;
    for (int k = 0; k < chunks; ++k) V += w.chunk_energy[static_cast<std::size_t>(k)];
    return V + self_energy(n);
  }

  /// Site forces (site a of molecule i at 3i + a, lab frame, kcal/mol/Å); returns V. One thread,
  /// for comparisons and tests.
  T evaluate_sites(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& site_force) const {
    prepare(bodies);
    site_force.assign(3 * bodies.size(), vec3<T>{});
    T V = 0;
    vec3<T> fi[3], fj[3];
    for (const auto& p : ws_->list.pairs()) {
      T e;
      if (!pair_terms(p.i, p.j, fi, fj, e)) continue;
      V += e;
      for (int a = 0; a < 3; ++a)
        for (int d = 0; d < 3; ++d) {
          site_force[static_cast<std::size_t>(3 * p.i + a)][d] += fi[a][d];
          site_force[static_cast<std::size_t>(3 * p.j + a)][d] += fj[a][d];
        }
    }
    return V + self_energy(bodies.size());
  }

  /// Lab positions of the sites (3i + a), unwrapped (centre + Q · body site).
  void site_positions(const std::vector<rigid_body_state<T>>& bodies, std::vector<vec3<T>>& x) const {
    x.resize(3 * bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (int a = 0; a < 3; ++a) {
        const vec3<T> r = bodies[i].rot.Q * model_.site[static_cast<std::size_t>(a)];
        for (int d = 0; d < 3; ++d) x[3 * i + static_cast<std::size_t>(a)][d] = bodies[i].q[d] + r[d];
      }
  }

  /// The switch S(r) of the O–O distance and dS/dr (switched_molecular).
  void switch_value(const T& r, T& S, T& dS) const {
    if (r <= r_on_) {
      S = 1;
      dS = 0;
      return;
    }
    if (r >= opt_.cutoff) {
      S = 0;
      dS = 0;
      return;
    }
    const T y = (r - r_on_) / opt_.switch_width, u = 1 - y;
    const T y4 = y * y * y * y;
    S = 1 - y4 * (35 - y * (84 - y * (70 - 20 * y)));
    dS = -140 * y * y * y * u * u * u / opt_.switch_width;
  }

 private:
  struct workspace {
    explicit workspace(int threads) : pool(threads) {}
    worker_pool pool;
    molecule_pair_list<T> list;
    std::vector<vec3<T>> x, offset, x_at_build, reference, centre;
    std::vector<std::vector<vec3<T>>> chunk_force = std::vector<std::vector<vec3<T>>>(chunks);
    std::vector<std::vector<vec3<T>>> chunk_torque = std::vector<std::vector<vec3<T>>>(chunks);
    std::vector<T> chunk_energy = std::vector<T>(chunks);
    long builds = 0;
  };

  /// Site positions and offsets; rebuilds the pair list when a site moved more than skin/2.
  void prepare(const std::vector<rigid_body_state<T>>& bodies) const {
    workspace& w = *ws_;
    const std::size_t n = bodies.size();
    w.x.resize(3 * n);
    w.offset.resize(3 * n);
    w.centre.resize(n);
    for (std::size_t i = 0; i < n; ++i) w.centre[i] = bodies[i].q;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t a = 0; a < 3; ++a) {
        const vec3<T> r = bodies[i].rot.Q * model_.site[a];
        w.offset[3 * i + a] = r;
        for (int d = 0; d < 3; ++d) w.x[3 * i + a][d] = bodies[i].q[d] + r[d];
      }
    bool rebuild = w.x_at_build.size() != w.x.size();
    const T limit = opt_.skin * opt_.skin / 4;
    // the molecular cutoff looks at O–O distances only, so only the oxygens' moves count
    const std::size_t stride = opt_.interaction == water_interaction::switched_molecular ? 3 : 1;
    for (std::size_t k = 0; !rebuild && k < w.x.size(); k += stride) {
      T d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += (w.x[k][d] - w.x_at_build[k][d]) * (w.x[k][d] - w.x_at_build[k][d]);
      rebuild = d2 > limit;
    }
    if (rebuild) {
      w.x_at_build = w.x;
      w.reference.resize(n);
      const bool dsf = opt_.interaction == water_interaction::lammps_dsf;
      for (std::size_t i = 0; i < n; ++i) w.reference[i] = dsf ? bodies[i].q : w.x[3 * i];
      const T radius = opt_.cutoff + opt_.skin + (dsf ? 2 * model_.site_radius : T(0));
      w.list.build(w.reference, opt_.box, radius);
      ++w.builds;
    }
    for (int c = 0; c < chunks; ++c) {
      w.chunk_force[static_cast<std::size_t>(c)].resize(n);
      w.chunk_torque[static_cast<std::size_t>(c)].resize(n);
    }
  }

  void accumulate(int i, const vec3<T> (&f)[3], vec3<T>& F, vec3<T>& tau) const {
    for (int a = 0; a < 3; ++a) {
      const vec3<T>& r = ws_->offset[static_cast<std::size_t>(3 * i + a)];
      const vec3<T> t = cross(r, f[a]);
      for (int d = 0; d < 3; ++d) {
        F[d] += f[a][d];
        tau[d] += t[d];
      }
    }
  }

  /// The pair (i, j): site forces on i's sites (fi) and j's (fj) and the pair energy E; false
  /// (and nothing set) when no site pair is within the cutoff.
  bool pair_terms(int i, int j, vec3<T> (&fi)[3], vec3<T> (&fj)[3], T& E) const {
    for (int a = 0; a < 3; ++a) fi[a] = fj[a] = vec3<T>{};
    return opt_.interaction == water_interaction::lammps_dsf ? dsf_pair(i, j, fi, fj, E) : switched_pair(i, j, fi, fj, E);
  }

  bool switched_pair(int i, int j, vec3<T> (&fi)[3], vec3<T> (&fj)[3], T& E) const {
    using std::nearbyint;
    using std::sqrt;
    const auto& x = ws_->x;
    const vec3<T>& oi = x[static_cast<std::size_t>(3 * i)];
    const vec3<T>& oj = x[static_cast<std::size_t>(3 * j)];
    vec3<T> shift, d;
    for (int k = 0; k < 3; ++k) {
      const T dk = oi[k] - oj[k];
      shift[k] = -opt_.box * nearbyint(dk / opt_.box);
      d[k] = dk + shift[k];
    }
    const T r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (!(r2 < opt_.cutoff * opt_.cutoff)) return false;
    E = 0;
    for (int a = 0; a < 3; ++a) {
      const vec3<T>& xa = x[static_cast<std::size_t>(3 * i + a)];
      for (int b = 0; b < 3; ++b) {
        const vec3<T>& xb = x[static_cast<std::size_t>(3 * j + b)];
        const vec3<T> rab{xa[0] - xb[0] + shift[0], xa[1] - xb[1] + shift[1], xa[2] - xb[2] + shift[2]};
        const T inv = 1 / sqrt(rab[0] * rab[0] + rab[1] * rab[1] + rab[2] * rab[2]);
        const T e = kqq_[a][b] * inv;
        E += e;
        const T s = e * inv * inv;  // −dE/dr / r
        for (int k = 0; k < 3; ++k) {
          fi[a][k] += s * rab[k];
          fj[b][k] -= s * rab[k];
        }
      }
    }
    {  // O–O Lennard-Jones
      const T inv2 = 1 / r2, s2 = model_.sigma * model_.sigma * inv2, s6 = s2 * s2 * s2;
      E += 4 * model_.epsilon * (s6 * s6 - s6);
      const T s = 24 * model_.epsilon * (2 * s6 * s6 - s6) * inv2;
      for (int k = 0; k < 3; ++k) {
        fi[0][k] += s * d[k];
        fj[0][k] -= s * d[k];
      }
    }
    if (r2 > r_on_ * r_on_) {
      const T r = sqrt(r2);
      T S, dS;
      switch_value(r, S, dS);
      const T g = -E * dS / r;
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) {
          fi[a][k] *= S;
          fj[a][k] *= S;
        }
      for (int k = 0; k < 3; ++k) {
        fi[0][k] += g * d[k];
        fj[0][k] -= g * d[k];
      }
      E *= S;
    }
    return true;
  }

  // --- lj/cut/coul/dsf as LAMMPS 29 Sep 2021 computes it (double constants as LAMMPS has them) ---
  void set_up_dsf() {
    const double rc = static_cast<double>(opt_.cutoff), alpha = static_cast<double>(opt_.dsf_alpha);
    const double pis = 1.77245385090551602729;  // √π
    const double erfcc = std::erfc(alpha * rc), erfcd = std::exp(-alpha * alpha * rc * rc);
    f_shift_ = T(-(erfcc / (rc * rc) + 2.0 / pis * alpha * erfcd / rc));
    e_shift_ = T(erfcc / rc - static_cast<double>(f_shift_) * rc);
    const double eps = static_cast<double>(model_.epsilon), sig = static_cast<double>(model_.sigma);
    lj1_ = T(48.0 * eps * std::pow(sig, 12.0));
    lj2_ = T(24.0 * eps * std::pow(sig, 6.0));
    lj3_ = T(4.0 * eps * std::pow(sig, 12.0));
    lj4_ = T(4.0 * eps * std::pow(sig, 6.0));
    const double ratio = sig / rc;
    lj_offset_ = T(4.0 * eps * (std::pow(ratio, 12.0) - std::pow(ratio, 6.0)));
    T self = 0;
    const T qqr2e = real_units::qqr2e<T>();
    for (int a = 0; a < 3; ++a) self += -(e_shift_ / 2 + T(alpha / pis)) * model_.charge[a] * model_.charge[a] * qqr2e;
    dsf_self_per_molecule_ = self;
  }

  T self_energy(std::size_t n) const {
    return opt_.interaction == water_interaction::lammps_dsf ? T(static_cast<double>(n)) * dsf_self_per_molecule_ : T(0);
  }

  bool dsf_pair(int i, int j, vec3<T> (&fi)[3], vec3<T> (&fj)[3], T& E) const {
    using std::exp;
    using std::sqrt;
    const T ewald_p = T(0.3275911), a1 = T(0.254829592), a2 = T(-0.284496736), a3 = T(1.421413741), a4 = T(-1.453152027),
            a5 = T(1.061405429);
    const T pis = T(1.77245385090551602729);
    const T alpha = opt_.dsf_alpha, rc2 = opt_.cutoff * opt_.cutoff;
    const T qqr2e = real_units::qqr2e<T>();
    const auto& x = ws_->x;
    E = 0;
    bool any = false;
    // the image of the centres serves every site pair whose vector stays within half a box;
    // a site pair beyond it (rare: only when L < 2 r_c + 4 r_site) takes its own minimum image
    const T L = opt_.box, half = L / 2;
    const vec3<T>& qi = ws_->centre[static_cast<std::size_t>(i)];
    const vec3<T>& qj = ws_->centre[static_cast<std::size_t>(j)];
    vec3<T> shift;
    T centre2 = 0;
    for (int k = 0; k < 3; ++k) {
      const T dk = qi[k] - qj[k];
      shift[k] = -L * std::nearbyint(dk / L);
      centre2 += (dk + shift[k]) * (dk + shift[k]);
    }
    const T reach = opt_.cutoff + 2 * model_.site_radius;
    if (!(centre2 < reach * reach)) return false;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const vec3<T>& xa = x[static_cast<std::size_t>(3 * i + a)];
        const vec3<T>& xb = x[static_cast<std::size_t>(3 * j + b)];
        vec3<T> d{xa[0] - xb[0] + shift[0], xa[1] - xb[1] + shift[1], xa[2] - xb[2] + shift[2]};
        if (std::abs(d[0]) > half || std::abs(d[1]) > half || std::abs(d[2]) > half) d = minimum_image(d, L);
        const T rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (!(rsq < rc2)) continue;
        any = true;
        const T r2inv = 1 / rsq;
        T forcelj = 0;
        if (a == 0 && b == 0) {
          const T r6inv = r2inv * r2inv * r2inv;
          forcelj = r6inv * (lj1_ * r6inv - lj2_);
          E += r6inv * (lj3_ * r6inv - lj4_) - lj_offset_;
        }
        const T r = sqrt(rsq);
        const T prefactor = qqr2e * model_.charge[a] * model_.charge[b] / r;
        const T erfcd = exp(-alpha * alpha * r * r);
        const T t = 1 / (1 + ewald_p * alpha * r);
        const T erfcc = t * (a1 + t * (a2 + t * (a3 + t * (a4 + t * a5)))) * erfcd;
        const T forcecoul = prefactor * (erfcc / r + 2 * alpha / pis * erfcd + r * f_shift_) * r;
        E += prefactor * (erfcc - r * e_shift_ - rsq * f_shift_);
        const T fpair = (forcecoul + forcelj) * r2inv;
        for (int k = 0; k < 3; ++k) {
          fi[a][k] += d[k] * fpair;
          fj[b][k] -= d[k] * fpair;
        }
      }
    return any;
  }

  water_model<T> model_;
  liquid_water_options<T> opt_;
  T kqq_[3][3]{};
  T r_on_{};
  T f_shift_{}, e_shift_{}, lj1_{}, lj2_{}, lj3_{}, lj4_{}, lj_offset_{}, dsf_self_per_molecule_{};
  std::shared_ptr<workspace> ws_;
};

}  // namespace rotlie::models
