// How far a binary run can be trusted (runs/binary_estimate.hpp, issue 46): the estimate at twice the
// step sees the phase errors the energy cannot. On Didymos, SIER2 at h = 3600 s keeps its energy bounded
// while the secondary drifts tens of degrees: the estimate must flag it; at converged steps it must not,
// and at both it must be within a small factor of the error measured against a reference run.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "rotlie/runs/binary_run.hpp"

BOOST_AUTO_TEST_SUITE(binary_estimate_test)

using namespace rotlie;

namespace {

runs::binary_result didymos(const std::string& integrator, const std::string& h, bool estimate = true) {
  runs::binary_request r;
  r.system = "didymos", r.integrator = integrator, r.h = h, r.T = "86400", r.no_error_estimate = !estimate;
  return runs::binary_run(runs::binary_setup_of(r));
}

double position_error(const runs::binary_result& run, const runs::binary_result& reference) {
  const auto& a = run.end.x.r;
  const auto& b = reference.end.x.r;
  return models::norm(models::vec3<double>{a[0] - b[0], a[1] - b[1], a[2] - b[2]}) / models::norm(b);
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_drifting_phase_is_flagged_and_a_converged_run_is_not) {
  const auto reference = didymos("KEPLER4", "15", false);
  const auto coarse = didymos("SIER2", "3600");
  BOOST_TEST_REQUIRE(coarse.error_estimate.has_value());
  const double true_coarse = position_error(coarse, reference);
  BOOST_TEST_MESSAGE("SIER2 h = 3600 s: estimated " << coarse.error_estimate->position_rel << ", measured " << true_coarse << ", energy error "
                                                     << coarse.check.max_rel_energy_error);
  BOOST_TEST(!coarse.check.unstable);  // the energy criterion alone would pass it
  BOOST_TEST(coarse.check.inaccurate);
  BOOST_TEST(true_coarse > 0.5);  // the case: the secondary tens of degrees off

  const auto fine = didymos("SIER4", "120");
  const double true_fine = position_error(fine, reference);
  BOOST_TEST_MESSAGE("SIER4 h = 120 s: estimated " << fine.error_estimate->position_rel << ", measured " << true_fine);
  BOOST_TEST(!fine.check.inaccurate);
  BOOST_TEST(fine.error_estimate->order == 4);
  // Richardson at a converged step: within a factor 2 of the measured error
  BOOST_TEST(fine.error_estimate->position_rel / true_fine > 0.5);
  BOOST_TEST(fine.error_estimate->position_rel / true_fine < 2.0);
}

BOOST_AUTO_TEST_CASE(adaptive_runs_and_opted_out_runs_carry_no_estimate) {
  BOOST_TEST(!didymos("odeint-rkf78:1e-10", "600").error_estimate.has_value());
  BOOST_TEST(!didymos("SIER4", "600", false).error_estimate.has_value());
  const auto lgvi = didymos("LGVI", "120");
  BOOST_TEST_REQUIRE(lgvi.error_estimate.has_value());
  BOOST_TEST(lgvi.error_estimate->order == 2);
}

BOOST_AUTO_TEST_SUITE_END()
