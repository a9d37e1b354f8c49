// Appendix A: the systems (78)–(84) for N1–N7, checked against the engine's H_R3: every root of
// f with the second coefficient from g solves P'_1 = P'_2 = 0, and f divides the resultant.
#include <boost/test/unit_test.hpp>

#include "paper_support.hpp"

BOOST_AUTO_TEST_SUITE(appendix_test)


using namespace rotlie;
using namespace rotlie::test;
using GiNaC::ex;
using GiNaC::pow;

namespace {

struct appendix_system {
  std::string scheme, v1, v2;
  std::vector<ex> f, g;  // f_0, f_1, …; g_0, g_1 (coefficient of v2), g_2, … (of v1, v1², …)
};

}  // namespace

// The paper's x, y are the symbols of paper_third_order; rebuild f, g with those symbols.
#define SYSTEM_TEST(NAME, V1, V2, FBODY, GBODY)                                       \
  BOOST_AUTO_TEST_CASE(NAME) {                                                        \
    const auto t = paper_third_order(std::string(bch::find_named_scheme(#NAME)->word), \
                                     bch::splitting::abc);                            \
    const ex x = t.x, y = t.y;                                                        \
    appendix_system s{#NAME, V1, V2, FBODY, GBODY};                                   \
    check_with(t, s);                                                                 \
  }

namespace {
void check_with(const third_order& t, const appendix_system& s) {
  const GiNaC::symbol v1 = t.coefficients.free.at(s.v1), v2 = t.coefficients.free.at(s.v2);
  ex f = 0, g = s.g[0] + v2 * s.g[1];
  for (std::size_t i = 0; i < s.f.size(); ++i) f += s.f[i] * pow(v1, static_cast<int>(i));
  for (std::size_t i = 2; i < s.g.size(); ++i) g += s.g[i] * pow(v1, static_cast<int>(i - 1));
  check_elimination(t, s.v1, s.v2, f, g, s.scheme);
}
}  // namespace

// eq. (78)
SYSTEM_TEST(N1, "a1", "b1",
            (std::vector<ex>{-1 - 3 * y - 3 * y * y - 2 * x * y * y - 3 * x * x * y - 12 * x * x * y * y - 12 * x * x * pow(y, 3) - 4 * x * x * pow(y, 4),
                             6 + 18 * y + 24 * y * y - 12 * x * y + 12 * x * y * y - 18 * x * x - 78 * x * x * y - 72 * x * x * y * y - 24 * x * x * pow(y, 3),
                             -12 - 36 * y - 72 * y * y - 48 * x - 72 * x * y - 168 * x * y * y - 48 * x * pow(y, 3) - 36 * x * x + 12 * x * x * y,
                             -24 - 72 * y - 144 * x * y - 48 * x * y * y + 72 * x * x + 24 * x * x * y}),
            (std::vector<ex>{-1 - y - 4 * x - 6 * x * y - 2 * x * y * y - 3 * x * x - 5 * x * x * y - 2 * x * x * y * y,
                             4 + 6 * y + 10 * x + 18 * x * y + 4 * x * y * y + 6 * x * x + 12 * x * x * y + 4 * x * x * y * y,
                             -2 - 6 * y - 12 * x * y - 4 * x * y * y + 6 * x * x + 2 * x * x * y}))

// eq. (79)
SYSTEM_TEST(N2, "a1", "a2",
            (std::vector<ex>{1 + 3 * y - 3 * pow(y, 3) - 8 * x * y * y - 12 * x * pow(y, 3) + x * x * y - 3 * x * x * y * y - 9 * x * x * pow(y, 3) + x * x * pow(y, 4) - 4 * pow(x, 3) * pow(y, 3) + pow(x, 4) * y * y,
                             -6 - 30 * y - 18 * y * y + 18 * pow(y, 3) - 48 * x * y - 48 * x * y * y + 48 * x * pow(y, 3) + 6 * x * x - 30 * x * x * y - 78 * x * x * y * y + 30 * x * x * pow(y, 3) - 48 * pow(x, 3) * y * y + 12 * pow(x, 4) * y,
                             36 * y + 36 * y * y - 36 * pow(y, 3) - 36 * x + 36 * x * y + 180 * x * y * y - 36 * x * pow(y, 3) - 72 * x * x - 144 * x * x * y + 144 * x * x * y * y - 144 * pow(x, 3) * y + 36 * pow(x, 4)}),
            (std::vector<ex>{-1 - 3 * y - 3 * y * y - 2 * x * y * y + x * x * y, 6 + 12 * y + 6 * y * y, 6 * y * y - 12 * x * y + 6 * x * x}))

// eq. (80)
SYSTEM_TEST(N3, "a1", "b1",
            (std::vector<ex>{1 + 3 * y - 3 * pow(y, 3) - 4 * x * y * y - 6 * x * pow(y, 3) + x * x * pow(y, 4),
                             -6 - 30 * y - 18 * y * y + 18 * pow(y, 3) - 24 * x * y - 24 * x * y * y + 24 * x * pow(y, 3) + 12 * x * x * pow(y, 3),
                             60 * y + 72 * y * y - 36 * pow(y, 3) - 24 * x + 36 * x * y + 144 * x * y * y - 12 * x * pow(y, 3) + 48 * x * x * y * y,
                             24 - 72 * y * y + 72 * x + 144 * x * y - 24 * x * y * y + 48 * x * x * y}),
            (std::vector<ex>{-3 - 18 * y - 39 * y * y - 36 * pow(y, 3) - 12 * pow(y, 4) - 2 * x - 15 * x * y - 39 * x * y * y - 41 * x * pow(y, 3) - 15 * x * pow(y, 4) - 2 * x * x * y * y - 3 * x * x * pow(y, 3) + x * x * pow(y, 5),
                             2 + 12 * y + 30 * y * y + 36 * pow(y, 3) + 18 * pow(y, 4) + 2 * x + 12 * x * y + 34 * x * y * y + 48 * x * pow(y, 3) + 30 * x * pow(y, 4) + 4 * x * x * y * y + 12 * x * x * pow(y, 3) + 14 * x * x * pow(y, 4) + 2 * pow(x, 3) * pow(y, 4),
                             2 + 30 * y + 84 * y * y + 78 * pow(y, 3) + 18 * pow(y, 4) - 6 * x + 6 * x * y + 78 * x * y * y + 102 * x * pow(y, 3) + 24 * x * pow(y, 4) + 4 * x * x * y + 30 * x * x * y * y + 48 * x * x * pow(y, 3) + 10 * x * x * pow(y, 4) + 4 * pow(x, 3) * pow(y, 3),
                             12 + 24 * y - 24 * y * y - 72 * pow(y, 3) - 36 * pow(y, 4) + 36 * x + 144 * x * y + 168 * x * y * y + 48 * x * pow(y, 3) - 12 * x * pow(y, 4) + 24 * x * x * y + 48 * x * x * y * y + 24 * x * x * pow(y, 3)}))

// eq. (81)
SYSTEM_TEST(N4, "a1", "b1",
            (std::vector<ex>{1 + 3 * y - 3 * pow(y, 3) - 4 * x * y * y - 6 * x * pow(y, 3) + x * x * pow(y, 4),
                             -6 - 30 * y - 18 * y * y + 18 * pow(y, 3) - 24 * x * y - 24 * x * y * y + 24 * x * pow(y, 3) + 12 * x * x * pow(y, 3),
                             60 * y + 72 * y * y - 36 * pow(y, 3) - 24 * x + 36 * x * y + 144 * x * y * y - 12 * x * pow(y, 3) + 48 * x * x * y * y,
                             24 - 72 * y * y + 72 * x + 144 * x * y - 24 * x * y * y + 48 * x * x * y}),
            (std::vector<ex>{-1 - y - 2 * x - 3 * x * y - x * y * y, 2 + 6 * y + 6 * y * y + 2 * x + 6 * x * y + 8 * x * y * y + 2 * x * x * y * y,
                             2 - 6 * y * y + 6 * x + 12 * x * y - 2 * x * y * y + 4 * x * x * y}))

// eq. (82)
SYSTEM_TEST(N5, "a1", "c1",
            (std::vector<ex>{1 + 3 * y - 6 * x * y * y - x * x * y - 6 * x * x * y * y + pow(x, 4) * y * y,
                             -6 - 30 * y - 36 * x * y + 36 * x * y * y - 6 * x * x - 42 * x * x * y + 24 * x * x * y * y + 12 * pow(x, 4) * y,
                             84 * y - 48 * x + 144 * x * y - 72 * x * y * y - 36 * x * x + 180 * x * x * y - 24 * x * x * y * y + 24 * pow(x, 3) * y + 36 * pow(x, 4),
                             24 - 72 * y + 144 * x - 144 * x * y + 48 * x * y * y + 216 * x * x - 168 * x * x * y + 144 * pow(x, 3)}),
            (std::vector<ex>{1 + 4 * y + x + 9 * x * y - 8 * x * y * y - 3 * x * x + 4 * x * x * y - 25 * x * x * y * y - 6 * pow(x, 3) - 7 * pow(x, 3) * y - 30 * pow(x, 3) * y * y - 2 * pow(x, 3) * pow(y, 3) - 3 * pow(x, 4) - 9 * pow(x, 4) * y - 12 * pow(x, 4) * y * y - 2 * pow(x, 4) * pow(y, 3) - 6 * pow(x, 5) * y + pow(x, 5) * y * y - 3 * pow(x, 6) * y,
                             2 + 2 * y + 12 * x + 12 * x * y + 30 * x * x + 34 * x * x * y + 4 * x * x * y * y + 36 * pow(x, 3) + 48 * pow(x, 3) * y + 12 * pow(x, 3) * y * y + 18 * pow(x, 4) + 30 * pow(x, 4) * y + 14 * pow(x, 4) * y * y + 2 * pow(x, 4) * pow(y, 3),
                             -4 - 30 * y - 6 * x - 114 * x * y + 28 * x * y * y - 6 * x * x - 210 * x * x * y + 66 * x * x * y * y - 18 * pow(x, 3) - 210 * pow(x, 3) * y + 48 * pow(x, 3) * y * y + 4 * pow(x, 3) * pow(y, 3) - 36 * pow(x, 4) - 96 * pow(x, 4) * y - 2 * pow(x, 4) * y * y - 36 * pow(x, 5) - 18 * pow(x, 6),
                             -12 + 36 * y - 96 * x + 144 * x * y - 24 * x * y * y - 264 * x * x + 264 * x * x * y - 48 * x * x * y * y - 360 * pow(x, 3) + 240 * pow(x, 3) * y - 24 * pow(x, 3) * y * y - 252 * pow(x, 4) + 84 * pow(x, 4) * y - 72 * pow(x, 5)}))

// eq. (83)
SYSTEM_TEST(N6, "a1", "b1",
            (std::vector<ex>{1 + 3 * y + 3 * y * y - 3 * pow(y, 3) + 8 * x * y * y - 3 * x * x * y + 3 * x * x * y * y + 3 * x * x * pow(y, 3) + x * x * pow(y, 4),
                             -6 - 18 * y - 42 * y * y + 18 * pow(y, 3) + 48 * x * y - 48 * x * y * y - 18 * x * x + 42 * x * x * y + 18 * x * x * y * y + 6 * x * x * pow(y, 3),
                             12 + 36 * y + 180 * y * y - 36 * pow(y, 3) + 12 * x - 252 * x * y + 132 * x * y * y + 12 * x * pow(y, 3) + 144 * x * x - 48 * x * x * y,
                             -288 * y * y + 576 * x * y - 288 * x * x, 144 * y * y - 288 * x * y + 144 * x * x}),
            (std::vector<ex>{-2 * y - 6 * y * y + 4 * x + 11 * x * y - x * y * y + x * pow(y, 3) + x * pow(y, 4) + 3 * x * x + 13 * x * x * y + 7 * x * x * y * y + x * x * pow(y, 3),
                             -4 - 10 * y - 6 * y * y - 6 * pow(y, 3) - 6 * pow(y, 4) - 10 * x - 28 * x * y - 16 * x * y * y - 4 * x * pow(y, 3) - 6 * x * pow(y, 4) - 6 * x * x - 18 * x * x * y - 10 * x * x * y * y + 2 * x * x * pow(y, 3),
                             4 + 14 * y + 42 * y * y + 6 * pow(y, 3) + 6 * pow(y, 4) + 2 * x - 42 * x * y + 14 * x * y * y - 6 * x * pow(y, 3) + 24 * x * x - 4 * x * x * y + 4 * x * x * y * y,
                             -84 * y * y - 12 * pow(y, 3) + 168 * x * y + 24 * x * y * y - 84 * x * x - 12 * x * x * y,
                             48 * y * y - 96 * x * y + 48 * x * x}))

// eq. (84)
SYSTEM_TEST(N7, "b1", "c1",
            (std::vector<ex>{-1 - 3 * y - 3 * x - 15 * x * y - 6 * x * y * y - 17 * x * x * y - 12 * x * x * y * y + 3 * pow(x, 3) - 3 * pow(x, 3) * y - 6 * pow(x, 3) * y * y - pow(x, 4) * y * y,
                             12 + 30 * y + 42 * x + 150 * x * y + 36 * x * y * y + 30 * x * x + 222 * x * x * y + 84 * x * x * y * y - 18 * pow(x, 3) + 114 * pow(x, 3) * y + 60 * pow(x, 3) * y * y - 18 * pow(x, 4) + 12 * pow(x, 4) * y + 12 * pow(x, 4) * y * y,
                             -48 - 84 * y - 204 * x - 420 * x * y - 72 * x * y * y - 300 * x * x - 708 * x * x * y - 192 * x * x * y * y - 180 * pow(x, 3) - 492 * pow(x, 3) * y - 168 * pow(x, 3) * y * y - 36 * pow(x, 4) - 120 * pow(x, 4) * y - 48 * pow(x, 4) * y * y,
                             48 + 72 * y + 216 * x + 360 * x * y + 48 * x * y * y + 360 * x * x + 648 * x * x * y + 144 * x * x * y * y + 264 * pow(x, 3) + 504 * pow(x, 3) * y + 144 * pow(x, 3) * y * y + 72 * pow(x, 4) + 144 * pow(x, 4) * y + 48 * pow(x, 4) * y * y}),
            (std::vector<ex>{y - x + 3 * x * y + 2 * x * y * y - 3 * x * x - 2 * x * x * y, 2 + 2 * y + 6 * x + 6 * x * y + 6 * x * x + 8 * x * x * y + 2 * x * x * y * y,
                             -4 - 6 * y - 10 * x - 18 * x * y - 4 * x * y * y - 6 * x * x - 12 * x * x * y - 4 * x * x * y * y}))

BOOST_AUTO_TEST_SUITE_END()  // appendix_test
