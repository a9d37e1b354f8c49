// Rigid bodies at a temperature (thermostats/): the O-step's exact Ornstein–Uhlenbeck moments, free
// bodies thermalised to Maxwell–Boltzmann (Kolmogorov–Smirnov), the Nosé–Hoover chains' kept quantity,
// (the configurational bias: thermostat_bias_test).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "rotlie/models/configurational_temperature.hpp"
#include "rotlie/models/ensemble_statistics.hpp"
#include "rotlie/models/md_integrators.hpp"
#include "rotlie/models/real_units.hpp"
#include "rotlie/models/scenes/dipole_in_field.hpp"
#include "rotlie/models/scenes/water.hpp"
#include "rotlie/models/scenes/zero_potential.hpp"

using namespace rotlie::models;
using rotlie::schemes::thermostat_placement;

namespace {

const md_integrator sier2 = md_integrator_of("SIER2", "Strang-TV", "exact");
const md_integrator sier4 = md_integrator_of("SIER4", "PEFRL-TV", "exact");
const vec3<double> moments{0.6, 1.2, 1.7};
constexpr double mass = 3;

rigid_bodies_state<double> resting_bodies(std::size_t n) {
  rigid_bodies_state<double> s;
  s.bodies.resize(n);
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(thermostat_test)

BOOST_AUTO_TEST_CASE(the_o_step_has_the_ornstein_uhlenbeck_mean_and_variance) {
  // one O-step of t from the same (p, G) for 200,000 bodies: each component is a₀x₀ + N(0, (1 − a²)σ²)
  thermostat_parameters bath;
  bath.kT = 0.7, bath.friction = 1.3, bath.seed = 11;
  const double t = 0.4, a = std::exp(-1.3 * 0.4);
  const vec3<double> p0{1.0, -2.0, 0.5}, G0{0.3, -0.1, 2.0};
  with_thermostatted_integrator(sier2, thermostat_placement::middle, bath, {{mass, moments}}, zero_potential<double>{},
                                unit_system<double>::natural(), [&](const auto& method) {
    auto s = resting_bodies(200000);
    for (auto& b : s.bodies) b.p = p0, b.rot.G = G0;
    method.system().langevin(t, s);
    BOOST_TEST(s.bath.draws == 1u);
    const double n = static_cast<double>(s.bodies.size());
    for (int c = 0; c < 6; ++c) {
      const double x0 = c < 3 ? p0[c] : G0[c - 3], var = (1 - a * a) * (c < 3 ? mass : moments[c - 3]) * bath.kT;
      double sum = 0, sq = 0;
      for (const auto& b : s.bodies) {
        const double x = c < 3 ? b.p[c] : b.rot.G[c - 3];
        sum += x, sq += (x - a * x0) * (x - a * x0);
      }
      const double mean = sum / n, v = sq / n;
      BOOST_TEST_CONTEXT("component " << c << ": mean " << mean << " against " << a * x0 << ", variance " << v << " against " << var) {
        BOOST_TEST(std::abs(mean - a * x0) < 5 * std::sqrt(var / n));
        BOOST_TEST(std::abs(v - var) < 5 * var * std::sqrt(2 / n));
      }
    }
    return 0;
  });
}

BOOST_AUTO_TEST_CASE(the_noise_depends_on_seed_stage_and_body_only) {
  auto a = langevin_noise(5, 7, 3), b = langevin_noise(5, 7, 3), c = langevin_noise(5, 8, 3), d = langevin_noise(6, 7, 3);
  const double x = a.normal();
  BOOST_TEST(x == b.normal());
  BOOST_TEST(x != c.normal());
  BOOST_TEST(x != d.normal());
  const auto f = ou_factors_for(1e-12, 1.0);  // no cancellation for a tiny γt: 1 − a² ≈ 2γt
  BOOST_TEST(f.spread * f.spread == 2e-12, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(free_bodies_thermalise_to_maxwell_boltzmann) {
  // 4,000 free bodies from rest, 40 friction times of each placement on SIER2 and SIER4 with the exact
  // rotor: every scaled component p_i/√(m kT) and G_i/√(I_i kT) is standard normal
  for (const auto& [spec, placement] : {std::pair{sier2, thermostat_placement::middle}, std::pair{sier2, thermostat_placement::ends},
                                        std::pair{sier4, thermostat_placement::middle}}) {
    thermostat_parameters bath;
    bath.kT = 2.5, bath.friction = 2, bath.seed = 2024;
    with_thermostatted_integrator(spec, placement, bath, {{mass, moments}}, zero_potential<double>{}, unit_system<double>::natural(),
                                  [&](const auto& method) {
      auto s = resting_bodies(4000);
      for (int k = 0; k < 200; ++k) method.step(s, 0.1);
      std::vector<double> p, G;
      for (const auto& b : s.bodies)
        for (int i = 0; i < 3; ++i) {
          p.push_back(b.p[i] / std::sqrt(mass * bath.kT));
          G.push_back(b.rot.G[i] / std::sqrt(moments[i] * bath.kT));
        }
      BOOST_TEST_CONTEXT(method.table().name) {
        BOOST_TEST(normal_ks_distance(p) < ks_critical_0_001(p.size()));
        BOOST_TEST(normal_ks_distance(G) < ks_critical_0_001(G.size()));
      }
      return 0;
    });
  }
}

BOOST_AUTO_TEST_CASE(a_start_far_from_rest_forgets_itself) {
  // the same from a hot start: every body spinning at 100 kT about its middle axis (the exact rotor's hardest case)
  thermostat_parameters bath;
  bath.kT = 1, bath.friction = 3, bath.seed = 7;
  with_thermostatted_integrator(sier2, thermostat_placement::middle, bath, {{mass, moments}}, zero_potential<double>{},
                                unit_system<double>::natural(), [&](const auto& method) {
    auto s = resting_bodies(4000);
    for (auto& b : s.bodies) b.rot.G = {1e-3, std::sqrt(200 * moments[1]), 0};
    for (int k = 0; k < 300; ++k) method.step(s, 0.05);
    std::vector<double> G;
    for (const auto& b : s.bodies)
      for (int i = 0; i < 3; ++i) G.push_back(b.rot.G[i] / std::sqrt(moments[i] * bath.kT));
    BOOST_TEST(normal_ks_distance(G) < ks_critical_0_001(G.size()));
    return 0;
  });
}

BOOST_AUTO_TEST_CASE(the_same_seed_gives_the_same_run) {
  thermostat_parameters bath;
  bath.kT = 1, bath.friction = 1, bath.seed = 3;
  auto run = [&](std::uint64_t seed) {
    bath.seed = seed;
    return with_thermostatted_integrator(sier2, thermostat_placement::ends, bath, {{mass, moments}}, zero_potential<double>{},
                                         unit_system<double>::natural(), [&](const auto& method) {
      auto s = resting_bodies(10);
      for (int k = 0; k < 20; ++k) method.step(s, 0.1);
      return s.bodies[9].rot.G[2];
    });
  };
  BOOST_TEST(run(3) == run(3));
  BOOST_TEST(run(3) != run(4));
}

namespace {

// Dipoles (water's 1.84 D along its C2 axis) in a field of x kT/μ along z, in real units at 300 K.
dipole_in_field<double> dipoles_in_field(double x) {
  const double kT = real_units::boltz<double>() * 300, mu = 1.84 * real_units::debye<double>() * real_units::qe2f<double>();
  return {1.84 * real_units::debye<double>(), water::c2_axis, {0, 0, x * kT / mu}};
}

// n bodies at momenta of thermal size (about √(m kT) and √(I kT)), all different.
rigid_bodies_state<double> warm_bodies(std::size_t n) {
  auto s = resting_bodies(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = double(i % 7) / 7 - 0.4, b = double(i % 5) / 5 - 0.4, c = double(i % 3) / 3 - 0.3;
    s.bodies[i].p = {0.1 * a, 0.1 * b, 0.1 * c};
    s.bodies[i].rot.G = {0.04 * b, 0.04 * c, 0.04 * a};
  }
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(nose_hoover_chains_keep_their_extended_energy) {
  // 64 dipoles with SIER2-NHC: the kept quantity's largest excursion falls as h² (round-off at small h)
  // and does not drift at a large h (its second half's excursion no larger than the first's times 1.5)
  thermostat_parameters bath;
  bath.kT = real_units::boltz<double>() * 300, bath.tau = 100, bath.seed = 1;
  std::vector<double> excursion;
  for (const double h : {0.25, 0.5, 1.0, 20.0})
    with_thermostatted_integrator(sier2, thermostat_placement::chain, bath, {{water::mass<double>(), water::moments<double>()}}, dipoles_in_field(5),
                                  unit_system<double>::real(), [&](const auto& method) {
      auto s = warm_bodies(64);
      const auto& sys = method.system();
      const double H0 = sys.extended_energy(s);
      const long steps = long(2000 / h);
      double first = 0, second = 0;
      for (long k = 0; k < steps; ++k) {
        method.step(s, h);
        const double e = std::abs(sys.extended_energy(s) - H0);
        (k < steps / 2 ? first : second) = std::max(k < steps / 2 ? first : second, e);
      }
      excursion.push_back(std::max(first, second) / std::abs(H0));
      BOOST_TEST_MESSAGE("h = " << h << ": max |dH|/H = " << excursion.back() << " (halves " << first << ", " << second << ")");
      if (h == 20.0) BOOST_TEST(second < 1.5 * first);
      return 0;
    });
  BOOST_TEST(std::log2(excursion[0] / excursion[1]) < -1.8);  // h²
  BOOST_TEST(std::log2(excursion[1] / excursion[2]) < -1.8);
}

BOOST_AUTO_TEST_CASE(on_free_bodies_the_chains_keep_it_to_round_off) {
  // without forces the bodies' flights are exact and the chains' Suzuki–Yoshida flow is all the error
  // there is, of order 4: it falls 2⁴-fold from h = τ/250 to τ/500 and is round-off (growing by the step) at τ/2000; at h = τ/10
  // it stays bounded
  thermostat_parameters bath;
  bath.kT = 0.6, bath.tau = 100;
  std::vector<double> excursion;
  for (const double h : {0.4, 0.2, 0.05, 10.0})
    with_thermostatted_integrator(sier2, thermostat_placement::chain, bath, {{water::mass<double>(), water::moments<double>()}}, zero_potential<double>{},
                                  unit_system<double>::real(), [&](const auto& method) {
      auto s = warm_bodies(64);
      const auto& sys = method.system();
      const double H0 = sys.extended_energy(s);
      double first = 0, second = 0;
      const long steps = std::lround(5000 / h);
      for (long k = 0; k < steps; ++k) {
        method.step(s, h);
        double& e = k < steps / 2 ? first : second;
        e = std::max(e, std::abs(sys.extended_energy(s) - H0) / H0);
      }
      BOOST_TEST_MESSAGE("free bodies, h = " << h << " fs: max |dH|/H = " << first << ", " << second);
      BOOST_TEST(std::isfinite(sys.extended_energy(s)));
      excursion.push_back(std::max(first, second));
      if (h > 1) BOOST_TEST(second < 1.5 * first);
      return 0;
    });
  BOOST_TEST(excursion[0] / excursion[1] > 12);
  // round-off: the momenta are rescaled every step, so it grows with the steps; below one ε per step (10⁵ steps)
  BOOST_TEST(excursion[2] < 100000 * std::numeric_limits<double>::epsilon());
}

BOOST_AUTO_TEST_CASE(nose_hoover_chains_hold_the_temperature) {
  // 500 dipoles at x = 2 over 200 ps: ⟨2K_rot⟩/(3N k) and ⟨2K_trans⟩/((3N − 3) k) within 2 % of 300 K
  thermostat_parameters bath;
  bath.kT = real_units::boltz<double>() * 300, bath.tau = 200;
  with_thermostatted_integrator(sier2, thermostat_placement::chain, bath, {{water::mass<double>(), water::moments<double>()}}, dipoles_in_field(2),
                                unit_system<double>::real(), [&](const auto& method) {
    auto s = warm_bodies(500);
    const auto& sys = method.system();
    double rot = 0, trans = 0;
    const long burn = 5000, steps = 20000;
    for (long k = 0; k < burn + steps; ++k) {
      method.step(s, 10);
      if (k < burn) continue;
      rot += 2 * sys.rotational_energy(s) / (sys.rotational_dof(s) * real_units::boltz<double>()) / steps;
      trans += 2 * sys.translational_energy(s) / (sys.translational_dof(s) * real_units::boltz<double>()) / steps;
    }
    BOOST_TEST_MESSAGE("T_rot " << rot << " K, T_trans " << trans << " K");
    BOOST_TEST(std::abs(rot / 300 - 1) < 0.02);
    BOOST_TEST(std::abs(trans / 300 - 1) < 0.02);
    return 0;
  });
}

BOOST_AUTO_TEST_CASE(the_configurational_temperature_of_dipoles_is_the_bath_s) {
  // ⟨Σ|τ|²⟩ / ⟨Σ_k X_k² V⟩ / k_B over 500 dipoles at x = 5 sampled by BAOAB at 5 fs (its bias there is
  // 3e-4 in ⟨cos θ⟩, thermostat_bias_test): 300 K within 3 %; the probes' Laplacian against the closed
  // form Σ_k X_k² (−μ·E) = 2 μ·E for each dipole (X_k² turns μ about ê_k twice: Σ_k ê_k × (ê_k × μ) = −2μ)
  thermostat_parameters bath;
  bath.kT = real_units::boltz<double>() * 300, bath.friction = 0.01, bath.seed = 5, bath.momentum_conserved = false;
  const auto field = dipoles_in_field(5);
  with_thermostatted_integrator(sier2, thermostat_placement::middle, bath, {{water::mass<double>(), water::moments<double>()}}, field,
                                unit_system<double>::real(), [&](const auto& method) {
    auto s = warm_bodies(500);
    seeded_random random(3);
    std::vector<rigid_body_state<double>> scratch;
    double tau2 = 0, laplacian = 0, exact = 0;
    for (long k = 0; k < 24000; ++k) {
      method.step(s, 5);
      if (k < 4000 || k % 20) continue;
      method.system().bodies().ensure_forces(s);
      const auto c = probe_configurational(field, s.bodies, s.force, s.torque, random, scratch);
      exact += -2 * method.system().potential_energy(s);  // 2 μ·E = −2 V
      tau2 += c.torque_squared, laplacian += c.rotation_laplacian;
    }
    const double T = tau2 / laplacian / real_units::boltz<double>();
    BOOST_TEST_MESSAGE("configurational temperature of the rotations " << T << " K; the probes' Laplacian " << laplacian << " against " << exact);
    BOOST_TEST(std::abs(T / 300 - 1) < 0.03);
    BOOST_TEST(std::abs(laplacian / exact - 1) < 0.01);  // Hutchinson's estimate summed over 1,000 probes of 500 dipoles
    return 0;
  });
}

BOOST_AUTO_TEST_CASE(bad_parameters_are_refused) {
  thermostat_parameters bath;
  bath.kT = 1;
  auto make = [&](thermostat_placement p) {
    with_thermostatted_integrator(sier2, p, bath, {{mass, moments}}, zero_potential<double>{}, unit_system<double>::natural(),
                                  [](const auto&) { return 0; });
  };
  BOOST_CHECK_THROW(make(thermostat_placement::middle), std::invalid_argument);  // no friction
  BOOST_CHECK_THROW(make(thermostat_placement::chain), std::invalid_argument);   // no period
  bath.friction = 1, bath.tau = 1, bath.kT = std::nan("");
  BOOST_CHECK_THROW(make(thermostat_placement::ends), std::invalid_argument);
  bath.kT = 1, bath.chain_order = 4;
  BOOST_CHECK_THROW(make(thermostat_placement::chain), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
