// Our own term order: the printed text does not depend on GiNaC's internal order (symbol
// creation order, hashing), and reads as expected.
#include <boost/test/unit_test.hpp>

#include "rotlie/runs/expression_io.hpp"

BOOST_AUTO_TEST_SUITE(expression_io_test)

using namespace rotlie::runs;

BOOST_AUTO_TEST_CASE(independent_of_symbol_creation_order) {
  std::string first;
  for (int round = 0; round < 2; ++round) {
    // create the symbols in a different order each round, which changes GiNaC's canonical order
    std::vector<GiNaC::symbol> made;
    if (round == 0)
      made = {GiNaC::symbol("a1"), GiNaC::symbol("b1"), GiNaC::symbol("x")};
    else {
      const GiNaC::symbol x("x"), b1("b1"), a1("a1");
      made = {a1, b1, x};
    }
    const auto &a1 = made[0], &b1 = made[1], &x = made[2];
    const GiNaC::ex e = -GiNaC::numeric(1, 3) + 2 * b1 - 8 * a1 * b1 + 4 * a1 * a1 - x + GiNaC::pow(x, 2) * b1 / 3;
    const std::string text = format_expression(e, made, expression_style::text);
    if (round == 0)
      first = text;
    else
      BOOST_TEST(text == first);
  }
  BOOST_TEST(first == "-1/3 + 2*b1 - x + 4*a1^2 - 8*a1*b1 + b1*x^2/3");
}

BOOST_AUTO_TEST_CASE(laurent_terms_and_latex) {
  const GiNaC::symbol a1("a1"), I1("I1"), I2("I2");
  const std::vector<GiNaC::symbol> order = {a1, I1, I2};
  const GiNaC::ex e = GiNaC::numeric(1, 12) / (I1 * I2) - a1 / (2 * I1 * I1);
  BOOST_TEST(format_expression(e, order, expression_style::text) == "1/(12*I1*I2) - a1/(2*I1^2)");
  BOOST_TEST(format_expression(e, order, expression_style::latex) == "\\frac{1}{12 I_{1} I_{2}} - \\frac{a_{1}}{2 I_{1}^{2}}");
  BOOST_TEST(format_expression(0, order, expression_style::text) == "0");
  BOOST_TEST(format_monomial(rotlie::lie::monomial(2, 0, 4), expression_style::latex) == "G_1^{2} G_3^{4}");
  const GiNaC::symbol stranger("q");
  BOOST_CHECK_THROW(format_expression(stranger + 1, order, expression_style::text), std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()  // expression_io_test
