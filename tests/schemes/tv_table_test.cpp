// TV tables (free flight T, kick V) for bodies under torques: the parser, writer and checks learn
// the split; the cost is the force evaluations f (first-same-as-last); a permutation is refused;
// the reference tables are van Zon & Schofield's eq. (7) and eq. (8) with the corrected h5.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "rotlie/schemes/reference_schemes.hpp"

BOOST_AUTO_TEST_SUITE(tv_table_test)

using namespace rotlie::schemes;

namespace {

const std::string strang =
    "format_version 1\nname s\nsplit TV\nword VTV\norder 2\nsymmetric true\n"
    "stage V v1 0.5\nstage T t1 1\nstage V v1 0.5\n";

std::string refusal(const std::string& text) {
  try {
    parse_scheme_table(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

long double value(const scheme_table& t, std::size_t i) { return std::strtold(t.stages.at(i).value.c_str(), nullptr); }

}  // namespace

BOOST_AUTO_TEST_CASE(a_tv_table_parses_and_writes_back) {
  const auto t = parse_scheme_table(strang);
  BOOST_TEST((t.splitting == split::tv));
  BOOST_TEST(t.permutation == "ABC");
  BOOST_TEST(format_scheme_table(t).find("split TV\n") != std::string::npos);
  BOOST_TEST((parse_scheme_table(format_scheme_table(t)) == t));
  BOOST_TEST(split_name(split::tv) == "TV");
  for (const auto& name : reference_tv_scheme_names()) {
    const auto r = *reference_scheme(name);
    BOOST_TEST((parse_scheme_table(format_scheme_table(r)) == r), name);
  }
}

BOOST_AUTO_TEST_CASE(force_evaluations_share_the_first_and_last_kick) {
  BOOST_TEST(cost_in_rotations(*reference_scheme("Strang-TV")) == 1);
  BOOST_TEST(cost_in_rotations(*reference_scheme("PEFRL-TV")) == 4);
  BOOST_TEST(force_evaluations(*reference_scheme("PEFRL-TV")) == 4);
  // T-first (position Verlet): two free flights around one kick, nothing shared
  const auto tvt = parse_scheme_table(
      "format_version 1\nsplit TV\nword TVT\nstage T t1 0.5\nstage V v1 1\nstage T t1 0.5\n");
  BOOST_TEST(force_evaluations(tvt) == 1);
  // V first, T last: both kicks need their own forces
  const auto vtvt = parse_scheme_table(
      "format_version 1\nsplit TV\nword VTVT\nsymmetric false\nstage V v1 0.5\nstage T t1 0.5\nstage V v2 0.5\nstage T t2 0.5\n");
  BOOST_TEST(force_evaluations(vtvt) == 2);
}

BOOST_AUTO_TEST_CASE(letters_and_permutations_of_other_splits_are_refused) {
  std::string abc_letter = strang;
  abc_letter.replace(abc_letter.find("stage T t1 1"), 12, "stage A t1 1");
  BOOST_TEST(refusal(abc_letter).find("not in the TV splitting") != std::string::npos, refusal(abc_letter));
  BOOST_TEST(refusal(strang + "permutation CBA\n").find("no body axes to permute") != std::string::npos);
  BOOST_TEST(refusal(strang + "permutation ABC\n").empty());
  BOOST_CHECK_THROW(reference_scheme("Strang-TV:CBA"), std::invalid_argument);
  BOOST_CHECK_THROW(permuted(*reference_scheme("PEFRL-TV"), "ABC"), std::invalid_argument);
  std::string bad_split = strang;
  bad_split.replace(bad_split.find("split TV"), 8, "split VT");
  BOOST_TEST(refusal(bad_split).find("ABC, RS or TV") != std::string::npos);
  std::string no_kick = strang;  // Σ V must be 1 like any part
  no_kick.replace(no_kick.rfind("stage V v1 0.5"), 14, "stage V v1 0.4");
  BOOST_TEST(refusal(no_kick).find("part V") != std::string::npos, refusal(no_kick));
}

BOOST_AUTO_TEST_CASE(pefrl_tv_is_eq_8_with_the_corrected_h5) {
  const auto t = *reference_scheme("PEFRL-TV");
  BOOST_TEST(t.word == "VTVTVTVTV");
  BOOST_TEST(t.order == 4);
  const long double tol = 1e-18L;
  BOOST_TEST(std::fabs(value(t, 0) - 0.1720865590295143L) < tol);
  BOOST_TEST(std::fabs(value(t, 1) - 0.5915620307551568L) < tol);
  BOOST_TEST(std::fabs(value(t, 2) + 0.1616217622107222L) < tol);
  // h4 = 1/2 − h2 as printed; h5 = 1 − 2(h1 + h3) (REFERENCE.md §1.5), not the printed 1 − 2(h1 + h2)
  BOOST_TEST(std::fabs(value(t, 3) + 0.0915620307551568L) < tol);
  BOOST_TEST(std::fabs(value(t, 4) - 0.9790704063624158L) < tol);
  const auto s = *reference_scheme("Strang-TV");
  BOOST_TEST(s.word == "VTV");
  BOOST_TEST(value(s, 0) == 0.5L);
  BOOST_TEST(value(s, 1) == 1.0L);
}

BOOST_AUTO_TEST_CASE(the_free_rotation_lists_stay_free_of_tv_tables) {
  for (const auto& name : reference_scheme_names()) BOOST_TEST((reference_scheme(name)->splitting != split::tv), name);
}

BOOST_AUTO_TEST_SUITE_END()  // tv_table_test
