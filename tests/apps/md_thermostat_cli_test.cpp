// `rotlie md` at a temperature (issue 47): free water held at 300 K by each thermostat reaches the
// Maxwell–Boltzmann distribution (Kolmogorov–Smirnov at 0.001 on 200 runs' ends) and the target
// temperatures within their statistical error; the same seed gives the same numbers, another seed
// others; liquid water at a temperature gives the same numbers on one and two threads; each misuse of
// the thermostat's options is refused in one line. About 10 s.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"
#include "md_cli_support.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

BOOST_AUTO_TEST_SUITE(md_thermostat_cli_test)

using namespace rotlie::test_cli;

BOOST_AUTO_TEST_CASE(free_water_reaches_maxwell_boltzmann_with_each_thermostat) {
  for (const std::string integrator : {"SIER2-BAOAB", "SIER2-OBABO", "SIER4-BAOAB", "SIER2-NHC", "MRDL-BAOAB"}) {
    // chains on one molecule (3 + 3 degrees of freedom) wander slowly: their runs are longer (10 ps gave 308 ± 1.9 K)
    const bool chains = integrator.find("NHC") != std::string::npos;
    const auto j = md_json("--scene free-water --integrator " + integrator + " --h 4 --runs 200 --temperature 300" +
                           (chains ? " --T 50 --tau 0.1" : " --T 10 --friction 2"));
    BOOST_TEST_CONTEXT(integrator << ": " << j.dump()) {
      BOOST_TEST(j["ensemble"] == "NVT");
      BOOST_TEST(j["maxwell_boltzmann"].get<bool>());
      BOOST_TEST(j["ks_rotational"].get<double>() < j["ks_critical_0_001"].get<double>());
      for (const char* field : {"translational_K", "rotational_K"}) {
        const double mean = j[field][0], error = j[field][1];
        BOOST_TEST(std::abs(mean - 300) < 4 * error);  // time averages of 200 independent molecules
        BOOST_TEST(error < 6);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(the_same_seed_gives_the_same_numbers) {
  const std::string args = "--scene free-water --integrator SIER2-BAOAB --h 4 --T 1 --runs 20 --friction 5";
  const auto a = md_json(args + " --seed 7"), b = md_json(args + " --seed 7"), c = md_json(args + " --seed 8");
  BOOST_TEST(a["rotational_K"] == b["rotational_K"]);
  BOOST_TEST(a["ks_rotational"] == b["ks_rotational"]);
  BOOST_TEST(a["rotational_K"] != c["rotational_K"]);
}

BOOST_AUTO_TEST_CASE(liquid_water_at_a_temperature_is_the_same_on_one_and_two_threads) {
  // 365 molecules, a short equilibration saved once, then 100 steps of SIER2-BAOAB on each thread count
  const std::string state = (scratch() / "nvt.state").string();
  const std::string args = "--scene liquid-water --integrator SIER2-BAOAB --h 2 --T 0.2 --molecules 365 --equilibrate 0.2 --state " + state +
                           " --temperature 310 --friction 5 --seed 3";
  const auto one = md_json(args + " --threads 1"), two = md_json(args + " --threads 2");
  for (const char* field : {"translational_K", "rotational_K", "configurational_translational_K", "configurational_rotational_K",
                            "potential_kcal_per_mol", "diffusion_1e-5_cm2_per_s", "rdf_first_peak"})
    BOOST_TEST(one[field] == two[field], field << ": " << one[field] << " against " << two[field]);
  BOOST_TEST(one["target_K"] == 310.0);
  BOOST_TEST(one["table"] == "Strang-TV+BAOAB");
  const double T = one["rotational_K"][0], V = one["potential_kcal_per_mol"][0];
  BOOST_TEST((T > 250 && T < 370));
  BOOST_TEST((V > -11 && V < -8.5));
  BOOST_TEST(one["rdf_first_peak"]["r_A"].get<double>() > 2.6);
  BOOST_TEST(one["rdf_first_peak"]["r_A"].get<double>() < 2.9);
}

BOOST_AUTO_TEST_CASE(misused_thermostat_options_are_refused_in_one_line) {
  expect_refusal("md --scene free-water --integrator SIER2 --h 4 --temperature 300", "needs an integrator at a temperature");
  expect_refusal("md --scene free-water --integrator SIER2-NHC --h 4 --friction 2", "takes --tau");
  expect_refusal("md --scene free-water --integrator SIER2-BAOAB --h 4 --tau 2", "takes --friction");
  expect_refusal("md --scene free-water --integrator SIER2-BAOAB --h 4 --temperature -3", "--temperature");
  expect_refusal("md --scene free-water --integrator SIER2-BAOAB --h 4 --friction nan", "--friction");
  expect_refusal("md --scene free-water --integrator SIER2-BAOAB --h 4 --scalar float128", "double");
  expect_refusal("md --scene free-water --integrator SIER2-BAOAB --h 4 --runs 5", "--runs");
  expect_refusal("md --scene dipole-field --integrator SIER2-BAOAB --h 4", "a thermostat runs in");
  expect_refusal("md --scene free-water --integrator SIER2-LANGEVIN --h 4", "unknown integrator");
  expect_refusal("spin --body Moon --e 0.05 --integrator SIER2-BAOAB --h 0.01 --T 1", "a thermostat");
  expect_refusal("md --scene liquid-water --integrator SIER2 --h 4 --tau 0.1", "needs an integrator at a temperature");
}

BOOST_AUTO_TEST_SUITE_END()
