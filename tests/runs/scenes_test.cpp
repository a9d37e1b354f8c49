// The scene registry: every scene reachable by name, options checked against the scene before
// anything runs, defaults filled in, and a run through the registry equal to the model's own call.
#include <boost/test/unit_test.hpp>

#include <set>

#include <boost/multiprecision/float128.hpp>

#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/scenes/free_water.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/scenes.hpp"
#include "rotlie/runs/user_input.hpp"

using namespace rotlie;

BOOST_AUTO_TEST_SUITE(scenes_test)

BOOST_AUTO_TEST_CASE(every_scene_is_found_by_its_name_and_an_unknown_one_lists_them) {
  std::set<std::string> names;
  for (const auto& s : runs::scenes()) {
    BOOST_TEST(&runs::scene_named(s.name) == &s);
    BOOST_TEST(s.run != nullptr);
    names.insert(s.name);
  }
  BOOST_TEST(names.size() == runs::scenes().size());
  BOOST_TEST(names.count("free-water") == 1u);
  BOOST_TEST(names.count("liquid-water") == 1u);
  try {
    runs::scene_named("moon");
    BOOST_FAIL("an unknown scene was accepted");
  } catch (const runs::bad_input& e) {
    BOOST_TEST(std::string(e.what()) == "--scene must be free-water, dipole-field, liquid-water or spin-orbit, got 'moon'");
  }
}

BOOST_AUTO_TEST_CASE(an_option_of_another_scene_is_refused_before_anything_runs) {
  runs::scene_request r{"free-water", "SIER2", "1", {{"--molecules", "512"}}, {}};
  BOOST_CHECK_EXCEPTION(runs::run_scene(r), runs::bad_input, [](const runs::bad_input& e) {
    return std::string(e.what()) == "--molecules applies to the liquid-water scene only";
  });
  r = {"dipole-field", "SIER2", "1", {{"--temperature", "300"}}, {}};  // the thermostat's option is free-water's and liquid-water's
  BOOST_CHECK_EXCEPTION(runs::run_scene(r), runs::bad_input, [](const runs::bad_input& e) {
    return std::string(e.what()) == "--temperature does not apply to the dipole-field scene";
  });
  r = {"free-water", "SIER2", "1", {{"--bogus", "1"}}, {}};
  BOOST_CHECK_THROW(runs::run_scene(r), runs::bad_input);
}

BOOST_AUTO_TEST_CASE(every_option_is_listed_once_with_each_scenes_default) {
  const auto all = runs::all_scene_options();
  std::set<std::string> names;
  for (const auto& o : all) BOOST_TEST(names.insert(o.name).second, o.name << " listed twice");
  const auto T = std::find_if(all.begin(), all.end(), [](const auto& o) { return o.name == "--T"; });
  BOOST_REQUIRE(T != all.end());
  BOOST_TEST(T->help.find("5 for free-water") != std::string::npos, T->help);
  BOOST_TEST(T->help.find("100 for dipole-field") != std::string::npos, T->help);
  BOOST_TEST(T->help.find("1 for liquid-water") != std::string::npos, T->help);
}

BOOST_AUTO_TEST_CASE(a_run_through_the_registry_equals_the_models_own_call) {
  // dipole-field, SIER2 at 8 fs, 3 runs of 2 ps: the registry (defaults for the dipole and field)
  // against run_dipole_field called directly with the same numbers
  runs::scene_request r{"dipole-field", "SIER2", "8", {{"--runs", "3"}, {"--T", "2"}}, {}};
  const auto result = runs::run_scene(r);
  models::md_run_options o;
  o.integrator = runs::method_named("SIER2", runs::method_system::md).splitting;
  o.h_fs = 8;
  o.T_ps = 2;
  o.runs = 3;
  o.seed = 1;
  const auto direct = models::run_dipole_field(models::dipole_field<double>("1.84", "2.7"), o);
  BOOST_TEST(result.json.at("dH_over_dV_percent")[0].get<double>() == direct.dH.mean);
  BOOST_TEST(result.json.at("dLz_over_Lz")[1].get<double>() == direct.dLz.error);
  BOOST_TEST(result.json.at("steps").get<long>() == direct.steps);
  BOOST_TEST(result.json.at("scene").get<std::string>() == "dipole-field");
  BOOST_TEST(result.warnings.empty());
  BOOST_TEST(result.text.find("dipole in a field, SIER2") == 0u);
}

BOOST_AUTO_TEST_CASE(a_trajectory_every_k_steps_follows_the_exact_free_motion) {
  // free water with SIER2's exact rotor: every sample of the first run lies on the exact free flow from
  // the first sample (a second method: exact_free_body in float128), and the energy is constant
  using quad = boost::multiprecision::float128;
  runs::scene_request r{"free-water", "SIER2", "8", {{"--runs", "2"}, {"--T", "1"}, {"--every", "25"}}, {}};
  const auto json = runs::run_scene(r).json;
  const auto& tr = json.at("trajectory");
  BOOST_TEST(tr.at("every").get<long>() == 25);
  const auto& t = tr.at("t_ps");
  BOOST_TEST(t.size() == 125u / 25 + 1);  // 125 steps of 8 fs, the start included
  BOOST_TEST(t[0].get<double>() == 0.0);
  BOOST_TEST(t[1].get<double>() == 0.2);  // 25 × 8 fs
  const models::vec3<quad> I{quad(models::water::moments<double>()[0]), quad(models::water::moments<double>()[1]),
                             quad(models::water::moments<double>()[2])};
  models::body_state<quad> start;
  for (std::size_t i = 0; i < 9; ++i) start.Q.a[i] = quad(tr.at("Q")[0][i / 3][i % 3].get<double>());
  for (std::size_t i = 0; i < 3; ++i) start.G[i] = quad(tr.at("G")[0][i].get<double>());
  const models::exact_free_body<quad> exact(I, start);
  double worst = 0, energy_change = 0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const auto e = exact.evaluate(quad(1000 * t[k].get<double>()));
    for (std::size_t i = 0; i < 9; ++i)
      worst = std::max(worst, std::abs(tr.at("Q")[k][i / 3][i % 3].get<double>() - static_cast<double>(e.state.Q.a[i])));
    energy_change = std::max(energy_change, std::abs(tr.at("energy")[k].get<double>() - tr.at("energy")[0].get<double>()));
  }
  BOOST_TEST(worst < 1e-12, "largest attitude difference " << worst);
  BOOST_TEST(energy_change < 1e-12 * std::abs(tr.at("energy")[0].get<double>()));
  BOOST_TEST(tr.at("potential")[3].get<double>() == 0.0);  // no forces in free water
  // without --every there is no trajectory; one that would keep too many samples is refused
  BOOST_TEST(!runs::run_scene({"free-water", "SIER2", "8", {{"--runs", "1"}, {"--T", "1"}}, {}}).json.contains("trajectory"));
  BOOST_CHECK_THROW(runs::run_scene({"free-water", "SIER2", "1e-3", {{"--runs", "1"}, {"--T", "20"}, {"--every", "1"}}, {}}),
                    runs::bad_input);
  BOOST_CHECK_THROW(runs::run_scene({"free-water", "SIER2", "8", {{"--every", "-1"}}, {}}), runs::bad_input);
}

BOOST_AUTO_TEST_CASE(a_tau_that_is_not_defined_is_null_with_a_warning) {
  // one step of 10^8 fs: δ saturates at once, no sample lies in the fitted window
  runs::scene_request r{"free-water", "MRDL", "1e8", {{"--runs", "1"}, {"--T", "1e5"}}, {}};
  const auto result = runs::run_scene(r);
  BOOST_TEST(result.json.at("tau_ps").is_null());
  BOOST_TEST(result.json.at("fitted_samples").get<int>() == 0);
  BOOST_REQUIRE(result.warnings.size() == 1u);
  BOOST_TEST(result.warnings[0].find("tau is not defined") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()  // scenes_test
