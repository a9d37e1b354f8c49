// The common regime of exact_free_rotation's step, vectorised across the bodies of a block (one
// body per lane, Highway, the target chosen at run time). Every line mirrors detail::free_flight_step
// (exact_free_rotation.hpp) with the same operations in the same order (this file is compiled with
// -ffp-contract=off, so nothing is fused that the scalar step rounds twice); where they differ:
// Highway's sin, cos, atan (≤ 3 ulp), tanh (≤ 4 ulp) and sech = 2/(eᵘ + e⁻ᵘ) from its exp for glibc's.
// So the estimate's gate, which reads the atan terms, may decide a lane within a few ulps of the
// accuracy otherwise than the scalar step (either answer is within the accuracy); every other test is
// the same arithmetic. The vector code refuses a little more: |ψ| > 39000 (Highway's sin and cos),
// more than 6 Gauss or Landen levels, and every lane whose D_y needs the exact sum. A lane that leaves
// the common regime at any test is not stored and goes through exact_free_rotation::advance
// afterwards, as do all lanes on a target without FMA (the products of the energy difference need it).
// Highway's Max and Min do not propagate NaN as std::max does; no NaN reaches them (refused first).
#ifndef HWY_DISABLED_TARGETS
// the vector path needs FMA: AVX2 and AVX-512 (and the baseline, which only dispatches to the loop)
#define HWY_DISABLED_TARGETS (HWY_SSSE3 | HWY_SSE4)
#endif

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "rotlie/models/exact_free_rotation_batch.hpp"

#ifndef ROTLIE_BATCH_CONSTANT_TABLES
#define ROTLIE_BATCH_CONSTANT_TABLES
namespace rotlie::models::batch_detail {

using frame_constants = detail::free_flight_step<double>::frame_constants;
using body_constants = detail::free_flight_step<double>::body_constants;

// A working frame's constants as numbered fields: the vector step reads them by number, either one
// body's for every lane or each lane's own body's.
enum frame_field : std::size_t {
  f_n, f_dzx, f_dzy, f_dyx, f_amplification, f_x_amplitude, f_y_amplitude, f_z_amplitude, f_wp_sign, f_wp_square,
  f_psi_factor, f_rate_factor, f_small_n, f_usable, f_Iw, f_to_x = f_Iw + 3, f_to_z = f_to_x + 3, frame_fields = f_to_z + 3
};
// The body's scaled moments along the working x, y, z (the order of its axes) and the smallest.
enum body_field : std::size_t { b_Ix, b_Iy, b_Iz, b_Imin, body_fields };

inline void flatten(const frame_constants& f, double* out) {
  out[f_n] = f.n, out[f_dzx] = f.dzx, out[f_dzy] = f.dzy, out[f_dyx] = f.dyx, out[f_amplification] = f.amplification;
  out[f_x_amplitude] = f.x_amplitude, out[f_y_amplitude] = f.y_amplitude, out[f_z_amplitude] = f.z_amplitude;
  out[f_wp_sign] = f.wp_sign, out[f_wp_square] = f.wp_square, out[f_psi_factor] = f.psi_factor, out[f_rate_factor] = f.rate_factor;
  out[f_small_n] = f.small_n ? 1.0 : 0.0, out[f_usable] = f.usable ? 1.0 : 0.0;
  for (std::size_t r = 0; r < 3; ++r) out[f_Iw + r] = f.Iw[r], out[f_to_x + r] = f.to_x[r], out[f_to_z + r] = f.to_z[r];
}

inline void flatten(const body_constants& c, double* out) {
  const auto at = [&](int k) { return c.I[static_cast<std::size_t>(c.order[static_cast<std::size_t>(k)])]; };
  out[b_Ix] = at(0), out[b_Iy] = at(1), out[b_Iz] = at(2), out[b_Imin] = c.Imin;
}

// One body's constants, for every lane.
struct shared_table {
  double frame[2][frame_fields];
  double body[body_fields];
  std::int64_t eI;
  explicit shared_table(const body_constants& c) : eI(c.eI) {
    flatten(c.frames[0], frame[0]);
    flatten(c.frames[1], frame[1]);
    flatten(c, body);
  }
};

// Each lane's own body's constants (structure of arrays).
struct lane_table {
  alignas(64) double frame[2][frame_fields][free_body_block::capacity];
  alignas(64) double body[body_fields][free_body_block::capacity];
  alignas(64) std::int64_t eI[free_body_block::capacity];
};

// Whether two bodies' steps share their structure: the order of the axes and the working frames'
// axes and signs (the vector step's branches and permutations); the numbers may differ.
inline bool same_structure(const body_constants& a, const body_constants& b) {
  if (a.order != b.order || a.spherical != b.spherical) return false;
  for (std::size_t f = 0; f < 2; ++f)
    if (a.frames[f].axis != b.frames[f].axis || a.frames[f].sign != b.frames[f].sign) return false;
  return true;
}

}  // namespace rotlie::models::batch_detail
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "exact_free_rotation_batch.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace rotlie {
namespace models {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;
using constants = detail::free_flight_step<double>::body_constants;

// The scalar step of one lane (outside the common regime, or on a target without FMA).
void advance_one(const exact_free_rotation<double>& rotor, free_body_block& b, std::size_t i) {
  body_state<double> s;
  for (std::size_t k = 0; k < 3; ++k) s.G[k] = b.G[k][i];
  for (std::size_t e = 0; e < 9; ++e) s.Q.a[e] = b.Q[e][i];
  b.estimate[i] = rotor.advance(s, b.t[i]);
  for (std::size_t k = 0; k < 3; ++k) b.G[k][i] = s.G[k];
  for (std::size_t e = 0; e < 9; ++e) b.Q[e][i] = s.Q.a[e];
}

#if HWY_TARGET <= HWY_AVX2 && HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
#define ROTLIE_BATCH_VECTOR 1

using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

struct jacobi {
  V sn, cn, dn;
};

// a where the mask is set, else b, for the three functions at once.
HWY_INLINE jacobi select(M mask, const jacobi& a, const jacobi& b) {
  return {hn::IfThenElse(mask, a.sn, b.sn), hn::IfThenElse(mask, a.cn, b.cn), hn::IfThenElse(mask, a.dn, b.dn)};
}

using DI = hn::RebindToSigned<D>;
using VI = hn::Vec<DI>;
using namespace batch_detail;

// Where the lanes' constants come from: one body's for every lane …
struct one_body_source {
  const shared_table& t;
  // the field of frame 1 where the lane uses it, else of frame 0
  HWY_INLINE V frame(M f1, std::size_t field, std::size_t) const {
    const D d;
    return hn::IfThenElse(f1, hn::Set(d, t.frame[1][field]), hn::Set(d, t.frame[0][field]));
  }
  HWY_INLINE V body(std::size_t field, std::size_t) const { return hn::Set(D(), t.body[field]); }
  HWY_INLINE VI eI(std::size_t) const { return hn::Set(DI(), t.eI); }
};

// … or each lane's own body's (lanes i … i + Lanes − 1 of the table).
struct lane_source {
  const lane_table& t;
  HWY_INLINE V frame(M f1, std::size_t field, std::size_t i) const {
    const D d;
    return hn::IfThenElse(f1, hn::Load(d, t.frame[1][field] + i), hn::Load(d, t.frame[0][field] + i));
  }
  HWY_INLINE V body(std::size_t field, std::size_t i) const { return hn::Load(D(), t.body[field] + i); }
  HWY_INLINE VI eI(std::size_t i) const { return hn::Load(DI(), t.eI + i); }
};

// a·b·c·(d − e) in double-double (exact_energy_difference.hpp's product_pair)
HWY_INLINE void product_pair(V a, V b, V c, V dd, V e, V& hi, V& lo) {
  const V p = hn::Mul(a, b), q = hn::MulSub(a, b, p);
  const V dh = hn::Sub(dd, e), dz = hn::Sub(dh, dd), dl = hn::Add(hn::Sub(dd, hn::Sub(dh, dz)), hn::Sub(hn::Neg(e), dz));
  const V h = hn::Mul(p, c), l = hn::Add(hn::MulSub(p, c, h), hn::Mul(q, c));
  hi = hn::Mul(h, dh);
  lo = hn::Add(hn::MulSub(h, dh, hi), hn::Add(hn::Mul(h, dl), hn::Mul(l, dh)));
}

// The descent both transformations share, lane by lane while x > limit (at most 6 levels): with
// k' = √x', r = x/(1 + k')², it takes u ← u/(1 + r), x ← r², x' ← 4k'/(1 + k')², and keeps r, the new x'
// and the lanes that moved for the way back. Gauss: (x, x') = (m, m_c); Landen: (m_c, m).
struct landen_descent {
  static constexpr int max_levels = 6;
  V root_mu[max_levels], other[max_levels];
  M active[max_levels];
  int levels = 0;

  HWY_INLINE void run(V& u, V& x, V& x_other, V limit) {
    const D d;
    const V one = hn::Set(d, 1.0), four = hn::Set(d, 4.0);
    for (; levels < max_levels; ++levels) {
      const M a = hn::Gt(x, limit);
      if (hn::AllFalse(d, a)) break;
      const V k = hn::Sqrt(x_other), k1 = hn::Add(one, k), k1_2 = hn::Mul(k1, k1);
      const V r = hn::Div(x, k1_2);
      root_mu[levels] = r;
      other[levels] = hn::Div(hn::Mul(four, k), k1_2);
      active[levels] = a;
      u = hn::IfThenElse(a, hn::Div(u, hn::Add(one, r)), u);
      x = hn::IfThenElse(a, hn::Mul(r, r), x);
      x_other = hn::IfThenElse(a, other[levels], x_other);
    }
  }
};

// sn cn dn of (u | m) by the descending Gauss transformation, u ≥ 0 (jacobi_functions_gauss): each
// lane descends while its parameter is above √ε/8, then the first order in μ, then the ascent.
HWY_INLINE jacobi gauss_functions(V u, V m, V mc, M& ok) {
  const D d;
  const V one = hn::Set(d, 1.0), threshold = hn::Set(d, std::sqrt(std::numeric_limits<double>::epsilon()) / 8);
  landen_descent down;
  down.run(u, m, mc, threshold);
  ok = hn::AndNot(hn::Gt(m, threshold), ok);  // deeper than max_levels: one by one
  const int levels = down.levels;
  const V* root_mu = down.root_mu;
  const M* active = down.active;
  const V s = hn::Sin(d, u), c = hn::Cos(d, u);
  const V q = hn::Mul(hn::Mul(m, hn::Set(d, 0.25)), hn::Sub(u, hn::Mul(s, c)));
  jacobi j{hn::Sub(s, hn::Mul(q, c)), hn::Add(c, hn::Mul(q, s)), hn::Sub(one, hn::Mul(hn::Mul(hn::Mul(m, hn::Set(d, 0.5)), s), s))};
  for (int level = levels - 1; level >= 0; --level) {
    const V r = root_mu[level];
    const V s2 = hn::Mul(hn::Mul(r, j.sn), j.sn), inv = hn::Div(one, hn::Add(one, s2));
    const jacobi up{hn::Mul(hn::Mul(hn::Add(one, r), j.sn), inv), hn::Mul(hn::Mul(j.cn, j.dn), inv), hn::Mul(hn::Sub(one, s2), inv)};
    j = select(active[level], up, j);
  }
  return j;
}

// sn cn dn of (u | m) for m_c < 1/4 by the ascending Landen transformation, u ≥ 0 (jacobi_functions):
// each lane ascends while m_c > ε, then the first order about m = 1 (tanh, sech), then back.
HWY_INLINE jacobi landen_functions(V u, V m, V mc, M& ok) {
  const D d;
  const V one = hn::Set(d, 1.0), eps = hn::Set(d, std::numeric_limits<double>::epsilon());
  landen_descent down;
  down.run(u, mc, m, eps);  // the same transformation with the parameter's roles exchanged
  ok = hn::AndNot(hn::Gt(mc, eps), ok);  // deeper than max_levels: one by one
  const int levels = down.levels;
  const V* root_mu = down.root_mu;
  const V* mu = down.other;
  const M* active = down.active;
  const V e = hn::Exp(d, u);
  const V th = hn::Tanh(d, u), sech = hn::Div(hn::Set(d, 2.0), hn::Add(e, hn::Div(one, e))), sh = hn::Div(th, sech);
  const V q = hn::Mul(mc, hn::Set(d, 0.25));
  jacobi j{hn::Add(th, hn::Mul(q, hn::Sub(th, hn::Mul(hn::Mul(u, sech), sech)))),
           hn::Sub(sech, hn::Mul(hn::Mul(q, th), hn::Sub(sh, hn::Mul(u, sech)))),
           hn::Add(sech, hn::Mul(hn::Mul(q, th), hn::Add(sh, hn::Mul(u, sech))))};
  for (int level = levels - 1; level >= 0; --level) {
    const V r = root_mu[level], dn2 = hn::Mul(j.dn, j.dn);
    const jacobi up{hn::Div(hn::Mul(hn::Mul(hn::Add(one, r), j.sn), j.cn), j.dn),
                    hn::Div(hn::Mul(hn::Div(hn::Add(one, r), mu[level]), hn::Sub(dn2, r)), j.dn),
                    hn::Div(hn::Mul(hn::Div(hn::Sub(one, r), mu[level]), hn::Add(dn2, r)), j.dn)};
    j = select(active[level], up, j);
  }
  return j;
}

// sn cn dn of u + v from those of u and v (elliptic::jacobi_sum)
HWY_INLINE jacobi jacobi_sum(const jacobi& a, const jacobi& b, V m) {
  const D d;
  const V r = hn::Div(hn::Set(d, 1.0), hn::Add(hn::Mul(a.cn, a.cn), hn::Mul(hn::Mul(a.sn, a.sn), hn::Mul(b.dn, b.dn))));
  return {hn::Mul(hn::Add(hn::Mul(hn::Mul(a.sn, b.cn), b.dn), hn::Mul(hn::Mul(b.sn, a.cn), a.dn)), r),
          hn::Mul(hn::Sub(hn::Mul(a.cn, b.cn), hn::Mul(hn::Mul(a.sn, b.sn), hn::Mul(a.dn, b.dn))), r),
          hn::Mul(hn::Sub(hn::Mul(a.dn, b.dn), hn::Mul(hn::Mul(m, hn::Mul(a.sn, b.sn)), hn::Mul(a.cn, b.cn))), r)};
}

// Carlson's R_J(x, y, 1, p) for p ≥ x, y, 1 (so every e_m ≥ 0), lane by lane as elliptic::carlson_rj:
// each lane duplicates until 4^−m Q < A_m.
HWY_INLINE V carlson_rj(V x, V y, V p) {
  const D d;
  const V one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), three = hn::Set(d, 3.0), four = hn::Set(d, 4.0), quarter = hn::Set(d, 0.25);
  V z = one;
  const V A0 = hn::Div(hn::Add(hn::Add(hn::Add(x, y), z), hn::Mul(two, p)), hn::Set(d, 5.0));
  const V delta = hn::Mul(hn::Mul(hn::Sub(p, x), hn::Sub(p, y)), hn::Sub(p, z));
  const V dx = hn::Sub(A0, x), dy = hn::Sub(A0, y), dz = hn::Sub(A0, z);  // X, Y, Z below are these over 4^m A_m
  const V spread = hn::Max(hn::Max(hn::Abs(dx), hn::Abs(dy)), hn::Max(hn::Abs(dz), hn::Abs(hn::Sub(A0, p))));
  const V Q = hn::Mul(hn::Set(d, elliptic::carlson_spread_factor<double>()), spread);
  const V rc_bound = hn::Set(d, elliptic::carlson_rc_series_bound<double>());
  const V third = hn::Set(d, 1.0 / 3), fifth = hn::Set(d, 1.0 / 5), seventh = hn::Set(d, 1.0 / 7), ninth = hn::Set(d, 1.0 / 9);
  V A = A0, fac = one, sum = hn::Zero(d);
  for (int k = 0; k < elliptic::carlson_max_duplications; ++k) {
    const M a = hn::Ge(hn::Mul(fac, Q), hn::Abs(A));
    if (hn::AllFalse(d, a)) break;
    const V sx = hn::Sqrt(x), sy = hn::Sqrt(y), sz = hn::Sqrt(z), sp = hn::Sqrt(p);
    const V lambda = hn::Add(hn::Add(hn::Mul(sx, sy), hn::Mul(sx, sz)), hn::Mul(sy, sz));
    const V dm = hn::Mul(hn::Mul(hn::Add(sp, sx), hn::Add(sp, sy)), hn::Add(sp, sz));
    const V em = hn::Div(hn::Mul(hn::Mul(hn::Mul(fac, fac), fac), delta), hn::Mul(dm, dm));
    // R_C(1, 1 + e), e ≥ 0: the series below the bound, atan(√e)/√e above (elliptic::carlson_rc_one)
    const M series_lanes = hn::Lt(hn::Abs(em), rc_bound);
    const V rc_series = hn::Sub(one, hn::Mul(em, hn::Sub(third, hn::Mul(em, hn::Sub(fifth, hn::Mul(em, hn::Sub(seventh, hn::Mul(em, ninth))))))));
    V rc = rc_series;
    if (!hn::AllTrue(d, hn::Or(series_lanes, hn::Not(a)))) {
      const V root_e = hn::Sqrt(hn::IfThenElse(series_lanes, one, em));
      rc = hn::IfThenElse(series_lanes, rc_series, hn::Div(hn::Atan(d, root_e), root_e));
    }
    sum = hn::IfThenElse(a, hn::Add(sum, hn::Div(hn::Mul(fac, rc), dm)), sum);
    A = hn::IfThenElse(a, hn::Mul(hn::Add(A, lambda), quarter), A);
    x = hn::IfThenElse(a, hn::Mul(hn::Add(x, lambda), quarter), x);
    y = hn::IfThenElse(a, hn::Mul(hn::Add(y, lambda), quarter), y);
    z = hn::IfThenElse(a, hn::Mul(hn::Add(z, lambda), quarter), z);
    p = hn::IfThenElse(a, hn::Mul(hn::Add(p, lambda), quarter), p);
    fac = hn::IfThenElse(a, hn::Mul(fac, quarter), fac);
  }
  const V scale = hn::Div(fac, A);
  const V X = hn::Mul(dx, scale), Y = hn::Mul(dy, scale), Z = hn::Mul(dz, scale);
  const V P = hn::Mul(hn::Neg(hn::Add(hn::Add(X, Y), Z)), hn::Set(d, 0.5));
  const V XYZ = hn::Mul(hn::Mul(X, Y), Z), P2 = hn::Mul(P, P), P3 = hn::Mul(P2, P);
  const V E2 = hn::Sub(hn::Add(hn::Add(hn::Mul(X, Y), hn::Mul(X, Z)), hn::Mul(Y, Z)), hn::Mul(three, P2));
  const V E3 = hn::Add(hn::Add(XYZ, hn::Mul(hn::Mul(two, E2), P)), hn::Mul(four, P3));
  const V E4 = hn::Mul(hn::Add(hn::Add(hn::Mul(two, XYZ), hn::Mul(E2, P)), hn::Mul(three, P3)), P);
  const V E5 = hn::Mul(XYZ, P2);
  const elliptic::carlson_rj_series<double> c;
  V series = hn::Sub(one, hn::Mul(hn::Set(d, c.e2), E2));
  series = hn::Add(series, hn::Mul(hn::Set(d, c.e3), E3));
  series = hn::Add(series, hn::Mul(hn::Set(d, c.e22), hn::Mul(E2, E2)));
  series = hn::Sub(series, hn::Mul(hn::Set(d, c.e4), E4));
  series = hn::Sub(series, hn::Mul(hn::Set(d, c.e23), hn::Mul(E2, E3)));
  series = hn::Add(series, hn::Mul(hn::Set(d, c.e5), E5));
  return hn::Add(hn::Mul(hn::Div(fac, hn::Mul(A, hn::Sqrt(A))), series), hn::Mul(hn::Set(d, 6.0), sum));
}

// R1(L) of REFERENCE.md §2.3, row-major (exact_free_rotation's momentum_frame)
HWY_INLINE void momentum_frame(const V L[3], V inverse_length, V F[9]) {
  const D d;
  const V perp = hn::Sqrt(hn::Add(hn::Mul(L[0], L[0]), hn::Mul(L[1], L[1]))), ip = hn::Div(hn::Set(d, 1.0), perp);
  const V ilp = hn::Mul(inverse_length, ip);
  F[0] = hn::Mul(hn::Mul(L[0], L[2]), ilp), F[3] = hn::Mul(hn::Mul(L[1], L[2]), ilp), F[6] = hn::Mul(hn::Neg(perp), inverse_length);
  F[1] = hn::Mul(hn::Neg(L[1]), ip), F[4] = hn::Mul(L[0], ip), F[7] = hn::Zero(d);
  F[2] = hn::Mul(L[0], inverse_length), F[5] = hn::Mul(L[1], inverse_length), F[8] = hn::Mul(L[2], inverse_length);
}

// The lanes [i, i + Lanes) of the block: those in the common regime are stored, `done` marks them.
// c gives the structure (the order of the axes, the frames' axes and signs), shared by every lane; src
// the numbers, the same body's for every lane or each lane's own.
template <class Source>
void advance_lanes(const constants& c, const Source& src, double accuracy, free_body_block& b, std::size_t i, double* done) {
  const D d;
  const DI di;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const auto& F0c = c.frames[0];
  const auto& F1c = c.frames[1];

  V G[3], Q[9];
  M ok = hn::Not(hn::Ne(zero, zero));  // all true
  for (std::size_t k = 0; k < 3; ++k) G[k] = hn::Load(d, b.G[k] + i), ok = hn::And(ok, hn::IsFinite(G[k]));
  for (std::size_t e = 0; e < 9; ++e) Q[e] = hn::Load(d, b.Q[e] + i), ok = hn::And(ok, hn::IsFinite(Q[e]));
  const V t = hn::Load(d, b.t + i);
  ok = hn::And(ok, hn::IsFinite(t));

  // |G| to O(1) by 2^−eG, eG = ilogb(max |G_k|) from the exponent bits (a normal number here)
  const V gmax = hn::Max(hn::Max(hn::Abs(G[0]), hn::Abs(G[1])), hn::Abs(G[2]));
  ok = hn::And(ok, hn::Ge(gmax, hn::Set(d, std::numeric_limits<double>::min())));
  const auto biased = hn::ShiftRight<52>(hn::BitCast(di, gmax));  // 1 … 2046 for normal gmax
  const V eG = hn::ConvertTo(d, hn::Sub(biased, hn::Set(di, 1023)));
  constexpr double max_scaling = std::numeric_limits<double>::max_exponent - 8;
  const VI eI = src.eI(i);
  const V e_time = hn::Sub(eG, hn::ConvertTo(d, eI));
  ok = hn::And(ok, hn::And(hn::Le(hn::Abs(eG), hn::Set(d, max_scaling)), hn::Le(hn::Abs(e_time), hn::Set(d, max_scaling))));
  const auto clamp = [&](auto e) { return hn::Min(hn::Max(e, hn::Set(di, 1)), hn::Set(di, 2046)); };  // valid bits in every lane
  const V down = hn::BitCast(d, hn::ShiftLeft<52>(clamp(hn::Sub(hn::Set(di, 2046), biased))));
  const V up = hn::BitCast(d, hn::ShiftLeft<52>(clamp(biased)));
  const V time_scale = hn::BitCast(d, hn::ShiftLeft<52>(clamp(hn::Sub(biased, eI))));
  const V Gs[3] = {hn::Mul(G[0], down), hn::Mul(G[1], down), hn::Mul(G[2], down)};

  // D_y = L² − 2E I_y (middle_energy_difference); lanes that need the exact sum go one by one
  const std::size_t x = static_cast<std::size_t>(c.order[0]), y = static_cast<std::size_t>(c.order[1]),
                    z = static_cast<std::size_t>(c.order[2]);
  const V Ix = src.body(b_Ix, i), Iy = src.body(b_Iy, i), Iz = src.body(b_Iz, i);
  V ah, al, bh, bl;
  product_pair(Gs[x], Gs[x], Iz, Ix, Iy, ah, al);
  product_pair(Gs[z], Gs[z], Ix, Iz, Iy, bh, bl);
  const V sh = hn::Add(ah, bh), szz = hn::Sub(sh, ah), sl = hn::Add(hn::Sub(ah, hn::Sub(sh, szz)), hn::Sub(bh, szz));
  const V E = hn::Add(sh, hn::Add(hn::Add(sl, al), bl));
  const double eps = std::numeric_limits<double>::epsilon(), least = std::numeric_limits<double>::min();
  ok = hn::And(ok, hn::Ge(hn::Abs(E), hn::Mul(hn::Set(d, 64 * eps), hn::Add(hn::Abs(ah), hn::Abs(bh)))));
  const M lossy = hn::And(hn::Or(hn::Ne(ah, zero), hn::Ne(bh, zero)),
                          hn::And(hn::Lt(hn::Max(hn::Abs(ah), hn::Abs(bh)), hn::Set(d, least / (eps * eps * eps * eps))),
                                  hn::Lt(hn::Abs(E), hn::Set(d, 64 * least))));
  ok = hn::AndNot(lossy, ok);
  const V Dy = hn::Div(E, hn::Mul(Ix, Iz));

  // the working frame: 1 where D_y < 0
  const M f1 = hn::Lt(Dy, zero);
  ok = hn::And(ok, hn::Eq(src.frame(f1, f_usable, i), one));
  V L[3];
  for (std::size_t r = 0; r < 3; ++r)
    L[r] = hn::IfThenElse(f1, hn::Mul(hn::Set(d, F1c.sign[r]), Gs[F1c.axis[r]]), hn::Mul(hn::Set(d, F0c.sign[r]), Gs[F0c.axis[r]]));
  const V l2 = hn::Add(hn::Add(hn::Mul(L[0], L[0]), hn::Mul(L[1], L[1])), hn::Mul(L[2], L[2]));
  const V length = hn::Sqrt(l2);
  V w[3];
  for (std::size_t r = 0; r < 3; ++r) w[r] = hn::Div(L[r], src.frame(f1, f_Iw + r, i));
  const M steady = hn::And(hn::And(hn::Eq(hn::Sub(hn::Mul(L[0], w[1]), hn::Mul(L[1], w[0])), zero),
                                   hn::Eq(hn::Sub(hn::Mul(L[1], w[2]), hn::Mul(L[2], w[1])), zero)),
                           hn::Eq(hn::Sub(hn::Mul(L[2], w[0]), hn::Mul(L[0], w[2])), zero));
  ok = hn::AndNot(steady, ok);
  const V tiny = hn::Mul(hn::Set(d, least * 1152921504606846976.0), l2);
  for (const V& l : L) ok = hn::AndNot(hn::And(hn::Ne(l, zero), hn::Lt(hn::Mul(l, l), tiny)), ok);
  ok = hn::AndNot(hn::Lt(hn::Add(hn::Mul(L[0], L[0]), hn::Mul(L[1], L[1])), tiny), ok);
  V Dx = zero, Dz = zero;
  for (std::size_t r = 0; r < 3; ++r) {
    const V l_2 = hn::Mul(L[r], L[r]);
    Dx = hn::Add(Dx, hn::Mul(l_2, src.frame(f1, f_to_x + r, i)));
    Dz = hn::Add(Dz, hn::Mul(l_2, src.frame(f1, f_to_z + r, i)));
  }
  const V dzy_Dx = hn::Mul(src.frame(f1, f_dzy, i), Dx);
  const V mc = hn::Max(zero, hn::Div(hn::Mul(src.frame(f1, f_dzx, i), Dy), dzy_Dx));
  const V m = hn::Min(one, hn::Div(hn::Mul(src.frame(f1, f_dyx, i), Dz), dzy_Dx));
  ok = hn::And(ok, hn::Gt(mc, zero));
  const V sz = hn::IfThenElse(hn::Lt(L[2], zero), hn::Set(d, -1.0), one);
  const V Lxm = hn::Sqrt(hn::Mul(Dz, src.frame(f1, f_x_amplitude, i)));
  const V Lym = hn::Sqrt(hn::Mul(Dz, src.frame(f1, f_y_amplitude, i)));
  const V Lzm = hn::Mul(sz, hn::Sqrt(hn::Mul(Dx, src.frame(f1, f_z_amplitude, i))));
  const V wp = hn::Mul(hn::Mul(sz, src.frame(f1, f_wp_sign, i)), hn::Sqrt(hn::Mul(Dx, src.frame(f1, f_wp_square, i))));
  const V psi_scale = hn::Div(hn::Mul(length, src.frame(f1, f_psi_factor, i)), wp);
  V sn0 = hn::Mul(L[1], Lxm), cn0 = hn::Mul(L[0], Lym);
  const V big = hn::Max(hn::Abs(sn0), hn::Abs(cn0));
  ok = hn::And(ok, hn::And(hn::Gt(big, zero), hn::And(hn::Ne(wp, zero), hn::IsFinite(psi_scale))));
  sn0 = hn::Div(sn0, big), cn0 = hn::Div(cn0, big);
  const V norm = hn::Sqrt(hn::Add(hn::Mul(sn0, sn0), hn::Mul(cn0, cn0)));
  sn0 = hn::Div(sn0, norm), cn0 = hn::Div(cn0, norm);
  const jacobi at_u0{sn0, cn0, hn::Sqrt(hn::Add(hn::Mul(cn0, cn0), hn::Mul(hn::Mul(mc, sn0), sn0)))};

  // the phase v = ω_p t in scaled units, |v| ≤ π/4 and far from the 2^60 rad limit
  const V tau = hn::Mul(t, time_scale), v = hn::Mul(wp, tau);
  ok = hn::And(ok, hn::Le(hn::Mul(hn::Abs(tau), length), hn::Mul(hn::Set(d, 576460752303423488.0), src.body(b_Imin, i))));
  ok = hn::And(ok, hn::Le(hn::Abs(v), hn::Set(d, boost::math::constants::half_pi<double>() / 2)));
  if (hn::AllFalse(d, ok)) {
    hn::Store(zero, d, done);
    return;
  }
  // lanes already refused compute on harmless values (m = 1/2, v = 0) so that no loop runs long for them
  const V m_safe = hn::IfThenElse(ok, m, hn::Set(d, 0.5)), mc_safe = hn::IfThenElse(ok, mc, hn::Set(d, 0.5));
  const V v_safe = hn::IfThenElse(ok, v, zero), u = hn::Abs(v_safe);
  // sn cn dn at |v|: the Gauss transformation for m_c ≥ 1/4, the ascending Landen one below (functions_at)
  const M gauss = hn::Ge(mc_safe, hn::Set(d, 0.25));
  jacobi at_v;
  if (hn::AllTrue(d, gauss)) {
    at_v = gauss_functions(u, m_safe, mc_safe, ok);
  } else if (hn::AllFalse(d, gauss)) {
    at_v = landen_functions(u, m_safe, mc_safe, ok);
  } else {
    const jacobi g = gauss_functions(u, hn::IfThenElse(gauss, m_safe, hn::Set(d, 0.5)), hn::IfThenElse(gauss, mc_safe, hn::Set(d, 0.5)), ok);
    const jacobi l = landen_functions(u, hn::IfThenElse(gauss, hn::Set(d, 0.9), m_safe), hn::IfThenElse(gauss, hn::Set(d, 0.1), mc_safe), ok);
    at_v = select(gauss, g, l);
  }
  at_v.sn = hn::IfThenElse(hn::Lt(v_safe, zero), hn::Neg(at_v.sn), at_v.sn);
  const jacobi at_u = jacobi_sum(at_u0, at_v, m_safe);

  // D(v) = (n/3) sn³ R_J(cn², dn², 1, 1 − n sn²) and the addition term of the third kind
  const V n = src.frame(f1, f_n, i);
  const V one_minus_n_sn2 = hn::Sub(one, hn::Mul(hn::Mul(n, at_v.sn), at_v.sn));
  const M elliptic_terms = hn::And(hn::Ne(n, zero), hn::Ne(at_v.sn, zero));
  const V rj = carlson_rj(hn::Mul(at_v.cn, at_v.cn), hn::Mul(at_v.dn, at_v.dn), hn::IfThenElse(elliptic_terms, one_minus_n_sn2, hn::Set(d, 2.0)));
  const V D_v = hn::IfThenElseZero(
      elliptic_terms, hn::Mul(hn::Mul(hn::Mul(hn::Mul(hn::Div(n, hn::Set(d, 3.0)), at_v.sn), at_v.sn), at_v.sn), rj));
  const V P = hn::Mul(hn::Mul(at_u0.sn, at_v.sn), at_u.sn);
  const V W = hn::Mul(hn::Add(hn::Add(hn::Mul(at_v.sn, at_v.sn), hn::Mul(at_u.sn, at_u.sn)),
                              hn::Mul(hn::Mul(at_u0.sn, at_u0.sn),
                                      hn::Add(hn::Mul(at_v.cn, at_v.cn), hn::Mul(hn::Mul(at_v.sn, at_v.sn), hn::Mul(at_u.dn, at_u.dn))))),
                      hn::Set(d, 0.5));
  const M n_nonzero = hn::Ne(n, zero);
  const V kappa = hn::Mul(hn::Mul(hn::Neg(n), hn::Sub(one, n)), hn::Sub(m_safe, n));
  const V root_kappa = hn::Sqrt(hn::IfThenElse(n_nonzero, kappa, one));
  const V D_sum = hn::IfThenElseZero(
      n_nonzero, hn::Mul(hn::Div(n, root_kappa), hn::Atan(d, hn::Div(hn::Mul(root_kappa, P), hn::Sub(one, hn::Mul(n, W))))));

  // ψ and the estimate
  const M small_n = hn::Eq(src.frame(f1, f_small_n, i), one);
  const V linear = hn::Mul(hn::Mul(length, src.frame(f1, f_rate_factor, i)), tau);
  const V elliptic_part = hn::Mul(psi_scale, hn::Add(hn::Add(D_v, D_sum), hn::IfThenZeroElse(small_n, v_safe)));
  const V psi = hn::Add(linear, elliptic_part);
  const V phase = hn::Add(hn::Add(hn::Abs(v_safe), hn::Abs(linear)),
                          hn::Mul(hn::Abs(psi_scale), hn::Add(hn::Add(hn::Abs(D_v), hn::Abs(D_sum)), hn::IfThenZeroElse(small_n, hn::Abs(v_safe)))));
  constexpr double factor = detail::free_flight_step<double>::estimate_factor;
  const V estimate = hn::Mul(hn::Set(d, eps), hn::Add(hn::Set(d, 2 * factor), hn::Mul(hn::Mul(hn::Set(d, factor), phase),
                                                                                     src.frame(f1, f_amplification, i))));
  ok = hn::And(ok, hn::Le(estimate, hn::Set(d, accuracy)));
  ok = hn::And(ok, hn::Le(hn::Abs(psi), hn::Set(d, 39000.0)));  // Highway's sin and cos hold there

  // the momentum at u₀ + v, the attitude Q ← Q Wᵀ R1(L₀) Z(ψ)ᵀ R1(L)ᵀ W, G in the body frame
  const V L1[3] = {hn::Mul(Lxm, at_u.cn), hn::Mul(Lym, at_u.sn), hn::Mul(Lzm, at_u.dn)};
  const V inverse_length = hn::Div(one, length);
  V F0[9], F1[9];
  momentum_frame(L, inverse_length, F0);
  momentum_frame(L1, inverse_length, F1);
  const V cp = hn::Cos(d, psi), sp = hn::Sin(d, psi);
  V R[9];
  for (int r = 0; r < 3; ++r) {
    const V a = hn::Add(hn::Mul(F0[3 * r], cp), hn::Mul(F0[3 * r + 1], sp)), bb = hn::Sub(hn::Mul(F0[3 * r + 1], cp), hn::Mul(F0[3 * r], sp));
    const V cc = F0[3 * r + 2];
    for (int col = 0; col < 3; ++col)
      R[3 * r + col] = hn::Add(hn::Add(hn::Mul(a, F1[3 * col]), hn::Mul(bb, F1[3 * col + 1])), hn::Mul(cc, F1[3 * col + 2]));
  }
  // body = Wᵀ R W for the lane's frame: body(axis[r], axis[s]) = sign_r sign_s R(r, s)
  V body[9];
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t s = 0; s < 3; ++s) {
      body[3 * F0c.axis[r] + F0c.axis[s]] = hn::Mul(hn::Set(d, F0c.sign[r] * F0c.sign[s]), R[3 * r + s]);
    }
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t s = 0; s < 3; ++s) {
      const std::size_t e = 3 * F1c.axis[r] + F1c.axis[s];
      body[e] = hn::IfThenElse(f1, hn::Mul(hn::Set(d, F1c.sign[r] * F1c.sign[s]), R[3 * r + s]), body[e]);
    }
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t col = 0; col < 3; ++col) {
      const V q = hn::Add(hn::Add(hn::Mul(Q[3 * r], body[col]), hn::Mul(Q[3 * r + 1], body[3 + col])), hn::Mul(Q[3 * r + 2], body[6 + col]));
      hn::BlendedStore(q, ok, d, b.Q[3 * r + col] + i);
    }
  V Gout[3];
  for (std::size_t k = 0; k < 3; ++k) Gout[F0c.axis[k]] = hn::Mul(hn::Mul(hn::Set(d, F0c.sign[k]), L1[k]), up);
  for (std::size_t k = 0; k < 3; ++k)
    Gout[F1c.axis[k]] = hn::IfThenElse(f1, hn::Mul(hn::Mul(hn::Set(d, F1c.sign[k]), L1[k]), up), Gout[F1c.axis[k]]);
  for (std::size_t k = 0; k < 3; ++k) hn::BlendedStore(Gout[k], ok, d, b.G[k] + i);
  hn::BlendedStore(estimate, ok, d, b.estimate + i);
  hn::Store(hn::IfThenElseZero(ok, one), d, done);
}
#endif

// The whole block: vectors of lanes, then the lanes they did not take one by one. Lane i's rotor is
// rotors[i], or `rotor` for every lane when rotors is null.
void AdvanceBlock(const exact_free_rotation<double>& rotor, const exact_free_rotation<double>* const* rotors, free_body_block& b,
                  std::size_t* vectorised, std::size_t* one_by_one) {
  const auto rotor_of = [&](std::size_t i) -> const exact_free_rotation<double>& { return rotors ? *rotors[i] : rotor; };
  std::size_t fast = 0;
#ifdef ROTLIE_BATCH_VECTOR
  const D d;
  const std::size_t lanes = hn::Lanes(d);
  const exact_free_rotation<double>& first = rotor_of(0);
  const auto& c = first.constants();
  // a lone body takes the vector step too (a whole vector for it: about 19 rotation stages against the
  // scalar step's 14–18), so that a body's result never depends on how many bodies share its block
  if (!c.spherical) {
    // the last vector's lanes beyond n: copies of lane 0 (finite values, computed and ignored); 64 is a
    // multiple of every vector width
    const std::size_t filled = (b.n + lanes - 1) / lanes * lanes;
    for (std::size_t i = b.n; i < filled; ++i) {
      for (std::size_t k = 0; k < 3; ++k) b.G[k][i] = b.G[k][0];
      for (std::size_t e = 0; e < 9; ++e) b.Q[e][i] = b.Q[e][0];
      b.t[i] = b.t[0];
    }
    HWY_ALIGN double done[free_body_block::capacity];
    if (!rotors) {
      const shared_table table(c);
      const one_body_source src{table};
      for (std::size_t i = 0; i < b.n; i += lanes) advance_lanes(c, src, first.accuracy(), b, i, done + i);
    } else {
      // each lane's numbers; a lane whose step is built otherwise than lane 0's (another order of the
      // axes, another accuracy) is marked unusable in both frames: the vector code leaves it to its rotor
      lane_table table;
      double frame[2][frame_fields], body[body_fields];
      for (std::size_t i = 0; i < filled; ++i) {
        const exact_free_rotation<double>& r = rotor_of(i < b.n ? i : 0);
        const auto& ci = r.constants();
        const bool alike = same_structure(ci, c) && r.accuracy() == first.accuracy();
        flatten(ci.frames[0], frame[0]);
        flatten(ci.frames[1], frame[1]);
        flatten(ci, body);
        for (std::size_t f = 0; f < 2; ++f) {
          if (!alike) frame[f][f_usable] = 0;
          for (std::size_t field = 0; field < frame_fields; ++field) table.frame[f][field][i] = frame[f][field];
        }
        for (std::size_t field = 0; field < body_fields; ++field) table.body[field][i] = body[field];
        table.eI[i] = ci.eI;
      }
      const lane_source src{table};
      for (std::size_t i = 0; i < b.n; i += lanes) advance_lanes(c, src, first.accuracy(), b, i, done + i);
    }
    for (std::size_t i = 0; i < b.n; ++i)
      if (done[i] != 0) ++fast;
      else advance_one(rotor_of(i), b, i);
  } else {
    for (std::size_t i = 0; i < b.n; ++i) advance_one(rotor_of(i), b, i);
  }
#else
  for (std::size_t i = 0; i < b.n; ++i) advance_one(rotor_of(i), b, i);
#endif
  if (vectorised) *vectorised = fast;
  if (one_by_one) *one_by_one = b.n - fast;
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

#undef ROTLIE_BATCH_VECTOR
}  // namespace HWY_NAMESPACE
}  // namespace models
}  // namespace rotlie
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rotlie::models {

HWY_EXPORT(AdvanceBlock);
HWY_EXPORT(TargetName);

namespace {
void check_count(const free_body_block& block) {
  if (block.n > free_body_block::capacity)
    throw std::invalid_argument("advance_block: " + std::to_string(block.n) + " bodies in a block of " +
                                std::to_string(free_body_block::capacity));
}
}  // namespace

void advance_block(const exact_free_rotation<double>& rotor, free_body_block& block, std::size_t* vectorised, std::size_t* one_by_one) {
  check_count(block);
  HWY_DYNAMIC_DISPATCH(AdvanceBlock)(rotor, nullptr, block, vectorised, one_by_one);
}

void advance_block(const exact_free_rotation<double>* const* rotors, free_body_block& block, std::size_t* vectorised,
                   std::size_t* one_by_one) {
  check_count(block);
  if (block.n == 0) {
    if (vectorised) *vectorised = 0;
    if (one_by_one) *one_by_one = 0;
    return;
  }
  HWY_DYNAMIC_DISPATCH(AdvanceBlock)(*rotors[0], rotors, block, vectorised, one_by_one);
}

std::string batch_target() {
  const std::string name = HWY_DYNAMIC_DISPATCH(TargetName)();
  return name == "AVX2" || name.rfind("AVX3", 0) == 0 ? name : "none";
}

}  // namespace rotlie::models
#endif
