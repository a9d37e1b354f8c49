// exact_free_rotation::advance, the step of SIER2/SIER4, against exact_free_body (the trajectory
// form it must reproduce) and against the float128 flow (its estimate must stay honest): random
// states of water, generic, thin, near-symmetric and flat bodies; the flow property
// φ_t2 ∘ φ_t1 = φ_(t1+t2); time symmetry φ_−t ∘ φ_t = id; long double and float128 steps; the addition
// theorems the step is built on, each against a direct evaluation; the regimes that must take the
// general path (and so equal exact_free_body to the bit), and bad input.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "free_body_samples.hpp"
#include "model_support.hpp"
#include "random_seed.hpp"
#include "rotlie/models/exact_free_rotation.hpp"

BOOST_AUTO_TEST_SUITE(exact_free_rotation_test)

using namespace rotlie;
using models::body_state;
using models::vec3;
using rotlie::quad;
using test::entry_error;
using test::norm;
using test::sample;
using test::sampler;

namespace {

const vec3<double> water{10220.0 / 29376, 19187.0 / 29376, 1};

template <class T, class A>
vec3<T> to(const vec3<A>& v) {
  return {T(v[0]), T(v[1]), T(v[2])};
}

template <class T, class A>
body_state<T> to_state(const body_state<A>& s) {
  body_state<T> r;
  for (std::size_t i = 0; i < 9; ++i) r.Q.a[i] = T(s.Q.a[i]);
  r.G = to<T>(s.G);
  return r;
}

std::string exact(double x) {  // 17 significant digits: reads back as x, for replay
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_step_is_the_closed_form_within_its_estimate) {
  // advance(s, t) against exact_free_body(I, s).evaluate(t) (within both estimates) and against the
  // float128 flow (within the step's estimate: honesty); the common regime is the fast one
  sampler draw("exact_free_rotation step");
  double worst_honesty = 0, worst_agreement = 0;
  int fast = 0, fast_water_short = 0, water_short = 0;
  for (int it = 0; it < 3000; ++it) {
    const auto x = draw.next(it);
    const models::exact_free_rotation<double> rotor(x.I);
    const models::detail::free_flight_step<double> step(x.I);
    auto s = x.s, probe = x.s;
    double probe_estimate = 0;
    const bool took_fast = step.advance(probe, x.t, 1e-12, probe_estimate);
    const double e = rotor.advance(s, x.t);
    const auto old = models::exact_free_body<double>(x.I, x.s).evaluate(x.t);
    const auto q = models::exact_free_body<quad>(to<quad>(x.I), to_state<quad>(x.s)).evaluate(quad(x.t));
    const double g = norm(x.s.G);
    const double honesty = entry_error(s, q.state, g) / (e + static_cast<double>(q.error_estimate));
    const double agreement = entry_error(s, old.state, g) / (e + old.error_estimate);
    worst_honesty = std::max(worst_honesty, honesty);
    worst_agreement = std::max(worst_agreement, agreement);
    const std::string where = x.kind + ", I = (" + exact(x.I[0]) + ", " + exact(x.I[1]) + ", " + exact(x.I[2]) + "), G = (" +
                              exact(x.s.G[0]) + ", " + exact(x.s.G[1]) + ", " + exact(x.s.G[2]) + "), t = " + exact(x.t);
    BOOST_TEST(honesty <= 1, where << ": error " << entry_error(s, q.state, g) << ", estimate " << e);
    BOOST_TEST(agreement <= 1, where << ": from exact_free_body " << entry_error(s, old.state, g) << " (its estimate " << old.error_estimate
                                     << ", its error " << entry_error(old.state, q.state, g) << "; this step's estimate " << e
                                     << ", error " << entry_error(s, q.state, g) << ")");
    if (q.error_estimate < 1e-20) BOOST_TEST(entry_error(s, q.state, g) < 1e-12, where);
    if (took_fast) {
      ++fast;
      BOOST_TEST(entry_error(probe, s, g) == 0.0, where);  // advance took this very path
      BOOST_TEST(probe_estimate == e);
    }
    if (x.kind == "water" && std::abs(x.t) * g / water[0] <= 0.3) {
      ++water_short;
      fast_water_short += took_fast;
    }
  }
  BOOST_TEST_MESSAGE("3000 random steps (" << fast << " by the common-regime path): largest error / estimate against float128 "
                                           << worst_honesty << ", largest distance to exact_free_body / both estimates "
                                           << worst_agreement);
  BOOST_TEST(fast_water_short == water_short, "water steps of |ω| t ≤ 0.3 rad on the fast path: " << fast_water_short << " of "
                                                                                                   << water_short);
}

BOOST_AUTO_TEST_CASE(composition_and_time_symmetry) {
  // φ_t2(φ_t1(s)) = φ_(t1+t2)(s) and φ_−t(φ_t(s)) = s. Over these times (|ω| t ≤ 2 rad) the flow moves an
  // error of the first step into the second at most by the size of its own derivative, ≤ 2 here
  // (printed): the tolerance is that factor on the first estimate plus the others.
  sampler draw("exact_free_rotation composition");
  double worst_composition = 0, worst_symmetry = 0;
  for (int it = 0; it < 1200; ++it) {
    const auto x = draw.next(it);
    const models::exact_free_rotation<double> rotor(x.I);
    const double g = norm(x.s.G);
    const double t1 = x.t * 0.37, t2 = x.t - t1;
    auto two = x.s, one = x.s;
    const double e1 = rotor.advance(two, t1), e2 = rotor.advance(two, t2), e12 = rotor.advance(one, x.t);
    const double composition = entry_error(two, one, g) / (2 * e1 + e2 + e12);
    auto back = x.s;
    const double f = rotor.advance(back, x.t), b = rotor.advance(back, -x.t);
    const double symmetry = entry_error(back, x.s, g) / (2 * f + b);
    worst_composition = std::max(worst_composition, composition);
    worst_symmetry = std::max(worst_symmetry, symmetry);
    BOOST_TEST(composition <= 1, x.kind << ", t = " << x.t << ": composition off by " << entry_error(two, one, g));
    BOOST_TEST(symmetry <= 1, x.kind << ", t = " << x.t << ": back by " << entry_error(back, x.s, g));
  }
  BOOST_TEST_MESSAGE("largest composition gap / tolerance " << worst_composition << ", time-symmetry gap / tolerance "
                                                            << worst_symmetry);
}

BOOST_AUTO_TEST_CASE(wider_scalars_agree_within_the_double_estimate) {
  // the same steps in long double and float128 (each its own rotor, constants in its own scalar)
  sampler draw("exact_free_rotation scalars");
  for (int it = 0; it < 300; ++it) {
    const auto x = draw.next(it);
    auto d = x.s;
    auto ld = to_state<long double>(x.s);
    auto q = to_state<quad>(x.s);
    const double ed = models::exact_free_rotation<double>(x.I).advance(d, x.t);
    const long double eld = models::exact_free_rotation<long double>(to<long double>(x.I)).advance(ld, static_cast<long double>(x.t));
    const quad eq = models::exact_free_rotation<quad>(to<quad>(x.I)).advance(q, quad(x.t));
    const double g = norm(x.s.G);
    BOOST_TEST(entry_error(d, q, g) <= ed + static_cast<double>(eq), x.kind << ", t = " << x.t);
    BOOST_TEST(entry_error(ld, q, g) <= static_cast<double>(eld) + static_cast<double>(eq), x.kind << ", t = " << x.t);
    BOOST_TEST(static_cast<double>(eq) * 1e6 < ed, x.kind << ": float128 estimate " << eq);
  }
}

BOOST_AUTO_TEST_CASE(addition_theorems_against_direct_evaluation) {
  // sn cn dn of u + v and D(u + v) − D(u) − D(v), D = Π − F, from the step's formulas against the
  // functions and R_J evaluated at u + v directly (float128, |u|, |v|, |u + v| ≤ K/2)
  namespace el = models::elliptic;
  std::mt19937_64 rng(test::test_seed("exact_free_rotation addition"));
  std::uniform_real_distribution<double> uniform(0, 1);
  auto U = [&] { return uniform(rng); };
  quad worst_jacobi = 0, worst_third = 0;
  for (int it = 0; it < 400; ++it) {
    const quad mc = quad(std::pow(10.0, -30 * U())), m = 1 - mc;
    const quad n = -quad(std::pow(10.0, 8 * U() - 4));
    const quad K = el::complete_first_kind(mc);
    const quad u = K * quad(U() - 0.5) / 2, v = K * quad(U() - 0.5) / 2;  // |u + v| ≤ K/2: direct values accurate
    auto at = [&](const quad& w) {
      auto j = el::jacobi_functions(abs(w), m, mc);
      if (w < 0) j.sn = -j.sn;
      return j;
    };
    auto D = [&](const el::jacobi_triple<quad>& j) { return el::third_minus_first(j, n, 1 - n * j.sn * j.sn); };
    const auto ju = at(u), jv = at(v), direct = at(u + v), sum = el::jacobi_sum(ju, jv, m);
    worst_jacobi = std::max({worst_jacobi, abs(sum.sn - direct.sn), abs(sum.cn - direct.cn), abs(sum.dn - direct.dn)});
    const quad term = el::third_kind_sum_term(ju, jv, sum, n, m), exact = D(direct) - D(ju) - D(jv);
    worst_third = std::max(worst_third, abs(term - exact) / (1 + abs(exact)));
  }
  BOOST_TEST_MESSAGE("float128: sn cn dn by the addition theorem off by " << worst_jacobi << ", the third-kind term off by "
                                                                          << worst_third);
  BOOST_TEST(static_cast<double>(worst_jacobi) < 1e-31);
  BOOST_TEST(static_cast<double>(worst_third) < 1e-30);
}

BOOST_AUTO_TEST_CASE(gauss_transformation_against_the_agm) {
  // two independent algorithms for sn cn dn: the Gauss transformation (the step's) and the descending
  // AGM / ascending Landen (exact_free_body's), on (0, π/4], relative errors; double against float128
  namespace el = models::elliptic;
  for (const double mc : {1.0, 0.9, 0.5, 0.25, 0.1, 1e-3}) {
    const quad mq = 1 - quad(mc);
    double worst_double = 0;
    quad worst_quad = 0;
    for (int i = 1; i <= 200; ++i) {
      const double u = 0.7853981633974483 * i / 200;
      const auto g = el::jacobi_functions_gauss(quad(u), mq, quad(mc)), a = el::jacobi_functions(quad(u), mq, quad(mc));
      const auto d = el::jacobi_functions_gauss(u, 1 - mc, mc);
      worst_quad = std::max({worst_quad, abs(g.sn / a.sn - 1), abs(g.cn / a.cn - 1), abs(g.dn / a.dn - 1)});
      worst_double = std::max({worst_double, std::abs(static_cast<double>(quad(d.sn) / a.sn - 1)),
                               std::abs(static_cast<double>(quad(d.cn) / a.cn - 1)), std::abs(static_cast<double>(quad(d.dn) / a.dn - 1))});
    }
    BOOST_TEST_MESSAGE("m_c = " << mc << ": Gauss against AGM in float128 " << worst_quad << ", double Gauss " << worst_double);
    BOOST_TEST(static_cast<double>(worst_quad) < 1e-32);
    BOOST_TEST(worst_double < 8 * std::numeric_limits<double>::epsilon());
  }
}

BOOST_AUTO_TEST_CASE(hard_regimes_take_the_general_path) {
  // these states are not the common regime: advance must give exact_free_body's answer to the bit
  struct hard {
    std::string label;
    vec3<double> I, G;
    double t;
  };
  const std::vector<hard> cases{
      {"on the separatrix", {3, 3.75, 5}, {1, 0.5, -1}, 0.1},
      {"spherical", {1, 1, 1}, {0.3, 1, 0.7}, 0.1},
      {"steady about the largest axis", water, {0, 0, 1.3}, 0.1},
      {"steady about the middle axis", water, {0, 1.3, 0}, 0.1},
      {"wobble below the underflow threshold", water, {1e-300, 1e-300, 1}, 0.1},
      {"long time: float128 redo", water, {1, 1, 1}, 1e6},
      {"large phase step", water, {1, 1, 1}, 3.0},
  };
  for (const auto& c : cases) {
    body_state<double> s;
    s.G = c.G;
    s.Q = models::rotation<double>({0.6, 0, 0.8}, 0.7);
    const models::detail::free_flight_step<double> step(c.I);
    auto probe = s;
    double estimate = 0;
    BOOST_TEST(!step.advance(probe, c.t, 1e-12, estimate), c.label);
    BOOST_TEST(entry_error(probe, s, 1) == 0.0, c.label << ": a declined step leaves the state alone");
    const auto old = models::exact_free_body<double>(c.I, s).evaluate(c.t);
    const double e = models::exact_free_rotation<double>(c.I).advance(s, c.t);
    BOOST_TEST(entry_error(s, old.state, 1) == 0.0, c.label);
    BOOST_TEST(e == old.error_estimate, c.label);
  }
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused) {
  const models::exact_free_rotation<double> rotor(water);
  body_state<double> s;
  s.G = {1, 1, 1};
  auto nan_state = s;
  nan_state.G[1] = std::nan("");
  BOOST_CHECK_THROW(rotor.advance(nan_state, 0.1), std::invalid_argument);
  auto inf_attitude = s;
  inf_attitude.Q(1, 2) = HUGE_VAL;
  BOOST_CHECK_THROW(rotor.advance(inf_attitude, 0.1), std::invalid_argument);
  auto copy = s;
  BOOST_CHECK_THROW(rotor.advance(copy, std::nan("")), std::domain_error);
  BOOST_CHECK_THROW(rotor.advance(copy, HUGE_VAL), std::domain_error);
  BOOST_CHECK_THROW(rotor.advance(copy, 1e300), std::domain_error);
  BOOST_CHECK_THROW(models::exact_free_rotation<double>({1, 1, 3}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()  // exact_free_rotation_test
