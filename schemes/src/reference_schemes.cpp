#include "rotlie/schemes/reference_schemes.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "rotlie/schemes/quad.hpp"

namespace rotlie::schemes {
namespace {

std::string text(const quad& x) { return x.str(36, std::ios_base::scientific); }

scheme_table make(std::string name, split s, int order, const std::string& word, const std::vector<quad>& c,
                  std::string source) {
  scheme_table t;
  t.name = std::move(name);
  t.splitting = s;
  t.word = word;
  t.order = order;
  t.symmetric = true;
  t.source = std::move(source);
  for (std::size_t i = 0; i < word.size(); ++i) t.stages.push_back({word[i], "s" + std::to_string(i + 1), text(c[i])});
  return t;
}

// S(γ1 h) … S(γs h) with S = X(h/2) Y(h) X(h/2); adjacent X stages merge.
void compose_xyx(const std::vector<quad>& g, char x, char y, std::string& word, std::vector<quad>& c) {
  for (std::size_t i = 0; i < g.size(); ++i) {
    word += x;
    c.push_back(i == 0 ? g[0] / 2 : (g[i - 1] + g[i]) / 2);
    word += y;
    c.push_back(g[i]);
  }
  word += x;
  c.push_back(g.back() / 2);
}

// S = ABCBA = A(h/2) B(h/2) C(h) B(h/2) A(h/2) (LV eq. 13); adjacent A stages merge.
void compose_abcba(const std::vector<quad>& g, std::string& word, std::vector<quad>& c) {
  for (std::size_t i = 0; i < g.size(); ++i) {
    word += 'A';
    c.push_back(i == 0 ? g[0] / 2 : (g[i - 1] + g[i]) / 2);
    word += "BCB";
    c.insert(c.end(), {g[i] / 2, g[i], g[i] / 2});
  }
  word += 'A';
  c.push_back(g.back() / 2);
}

// A palindromic two-part scheme x1 y1 x2 … as φ(α1) φ*(α2) … with φ = A B C and φ* = C B A
// (REFERENCE.md §1.1): α1 = x1, α_{k+1} = c_{k+1} − α_k, the last α must vanish. Adjacent
// equal letters merge, so 2s values of α give 4s + 1 stages.
void compose_adjoint(const std::vector<quad>& two_part, std::string& word, std::vector<quad>& c) {
  std::vector<quad> alpha{two_part[0]};
  for (std::size_t k = 1; k < two_part.size(); ++k) alpha.push_back(two_part[k] - alpha.back());
  if (abs(alpha.back()) > 1e-30) throw std::logic_error("adjoint composition: the last α does not vanish");
  alpha.pop_back();
  for (std::size_t k = 0; k < alpha.size(); ++k) {
    const std::string letters = k % 2 == 0 ? "ABC" : "CBA";
    for (const char l : letters) {
      if (!word.empty() && word.back() == l) {
        c.back() += alpha[k];
      } else {
        word += l;
        c.push_back(alpha[k]);
      }
    }
  }
}

std::vector<quad> mirror(const std::vector<quad>& half, bool odd) {  // x1 … xk → x1 … xk … x1
  std::vector<quad> out = half;
  for (std::size_t i = half.size() - (odd ? 1 : 0); i-- > 0;) out.push_back(half[i]);
  return out;
}

quad cbrt_quad(const quad& x) { return boost::multiprecision::cbrt(x); }

std::vector<quad> yoshida() {
  const quad w1 = 1 / (2 - cbrt_quad(2));
  return {w1, 1 - 2 * w1, w1};
}
std::vector<quad> suzuki() {
  const quad p = 1 / (4 - cbrt_quad(4));
  return {p, p, 1 - 4 * p, p, p};
}
std::vector<quad> mclachlan_ss5() {
  // γ1 = 0.28 exactly; γ2 solves 2γ1³ + 2γ2³ + (1 − 2γ1 − 2γ2)³ = 0 (Σγ³ = 0), Newton from 0.6255.
  const quad g1 = quad(28) / 100;
  quad g2 = quad("0.6254664284676700450");
  for (int i = 0; i < 8; ++i) {
    const quad r = 1 - 2 * g1 - 2 * g2;
    const quad f = 2 * g1 * g1 * g1 + 2 * g2 * g2 * g2 + r * r * r, df = 6 * g2 * g2 - 6 * r * r;
    g2 -= f / df;
  }
  return {g1, g2, 1 - 2 * (g1 + g2), g2, g1};
}
std::vector<quad> mclachlan_s4() {  // x1 y1 x2 y2 x3 y2 x2 y1 x1
  const quad s = boost::multiprecision::sqrt(quad(471));
  const quad x1 = (642 + s) / 3924, x2 = 121 * (12 - s) / 3924, x3 = 1 - 2 * (x1 + x2);
  const quad y1 = quad(6) / 11, y2 = quad(1) / 2 - y1;
  return mirror({x1, y1, x2, y2, x3}, true);
}
std::vector<quad> mclachlan_s5() {  // x1 y1 x2 y2 x3 y3 x3 y2 x2 y1 x1
  const quad s = boost::multiprecision::sqrt(quad(19));
  const quad x1 = (14 - s) / 108, x2 = (20 - 7 * s) / 108, x3 = quad(1) / 2 - (x1 + x2);
  return mirror({x1, quad(2) / 5, x2, quad(-1) / 10, x3, quad(2) / 5}, true);
}

// 6th-order symmetric compositions of a symmetric 2nd-order step, γ1 … γs (outermost first, palindromic).
// Yoshida (1990) eq. (5.4)-(5.5): the triple jump applied twice, 9 steps, w = 1/(2 − 2^{1/(2k+1)}).
std::vector<quad> yoshida_triple_jump6() {
  const quad w4 = 1 / (2 - cbrt_quad(2)), w6 = 1 / (2 - boost::multiprecision::pow(quad(2), quad(1) / 5));
  const std::vector<quad> inner{w4, 1 - 2 * w4, w4}, outer{w6, 1 - 2 * w6, w6};
  std::vector<quad> g;
  for (const quad& o : outer)
    for (const quad& i : inner) g.push_back(o * i);
  return g;
}
// Yoshida (1990) Table 1, solution A: w3, w2, w1 outermost first, w0 = 1 − 2(w1 + w2 + w3) in the middle
// (20 digits as reprinted in McLachlan & Quispel (2002), Acta Numerica, Table of composition methods).
std::vector<quad> yoshida_solution_a() {
  const quad w3("0.78451361047755726382"), w2("0.23557321335935813368"), w1("-1.17767998417887100695");
  return mirror({w3, w2, w1, 1 - 2 * (w1 + w2 + w3)}, true);
}
// Kahan & Li (1997) s9odr6a: γ1 … γ4 to 20 digits, γ5 = 1 − 2(γ1 + … + γ4) in the middle.
std::vector<quad> kahan_li_s9odr6a() {
  const quad g1("0.39216144400731413928"), g2("0.33259913678935943860"), g3("-0.70624617255763935981"),
      g4("0.082213596293550800230");
  return mirror({g1, g2, g3, g4, 1 - 2 * (g1 + g2 + g3 + g4)}, true);
}
// Blanes & Moan (2002), the 6th-order symmetric PRK with 10 stages (S10): b1 a1 b2 a2 … b5 a5 b6 a5 … a1 b1,
// the published 15 digits; a5 = 1/2 − (a1 + … + a4) and b6 = 1 − 2(b1 + … + b5) so that each part sums to 1.
std::vector<quad> blanes_moan_s10() {
  const std::vector<quad> a{quad("0.148816447901042"), quad("-0.132385865767784"), quad("0.067307604692185"),
                            quad("0.432666402578175")};
  const std::vector<quad> b{quad("0.0502627644003922"), quad("0.413514300428344"), quad("0.0450798897943977"),
                            quad("-0.188054853819569"), quad("0.541960678450780")};
  const quad a5 = quad(1) / 2 - (a[0] + a[1] + a[2] + a[3]);
  const quad b6 = 1 - 2 * (b[0] + b[1] + b[2] + b[3] + b[4]);
  return mirror({b[0], a[0], b[1], a[1], b[2], a[2], b[3], a[3], b[4], a5, b6}, true);
}

// van Zon & Schofield eq. (8), the PEFRL scheme of Omelyan, Mryglod & Folk (2002) with the kicks
// (V) on ξ, χ, 1 − 2(χ + ξ) and the free flights (T) on (1 − 2λ)/2, λ. The three printed 16-digit
// decimals are taken as exact; h4 = 1/2 − h2 as printed, and h5 = 1 − 2(h1 + h3), the corrected
// form of the misprinted h − 2(h1 + h2) (REFERENCE.md §1.5, §6.1): only it makes Σ V = 1.
std::vector<quad> pefrl_tv() {
  const quad h1("0.1720865590295143"), h2("0.5915620307551568"), h3("-0.1616217622107222");
  const quad h4 = quad(1) / 2 - h2, h5 = 1 - 2 * (h1 + h3);
  return mirror({h1, h2, h3, h4, h5}, true);
}

scheme_table build(const std::string& name) {
  std::string word;
  std::vector<quad> c;
  if (name == "Strang-TV") return make(name, split::tv, 2, "VTV", {0.5, 1, 0.5}, "generalised Verlet, van Zon & Schofield (2007) eq. (7)");
  if (name == "PEFRL-TV")
    return make(name, split::tv, 4, "VTVTVTVTV", pefrl_tv(),
                "Omelyan, Mryglod & Folk (2002) PEFRL as van Zon & Schofield (2007) eq. (8), with h5 = 1 - 2(h1 + h3)");
  // sixth-order TV compositions of Strang-TV (the rigid bodies of the binary scene): Kahan & Li (1997)'s
  // s9odr6a, nine kicks; Yoshida (1990)'s solution A, seven
  if (name == "KahanLi6-TV" || name == "Yoshida6-TV") {
    compose_xyx(name == "KahanLi6-TV" ? kahan_li_s9odr6a() : yoshida_solution_a(), 'V', 'T', word, c);
    return make(name, split::tv, 6, word, c,
                name == "KahanLi6-TV" ? "Kahan & Li (1997) s9odr6a composition of Strang-TV" : "Yoshida (1990) Table 1 solution A composition of Strang-TV");
  }
  const std::string ss_source = "LV eq. (13) composition of ABCBA / RSR";
  if (name == "ABCBA2") return make(name, split::abc, 2, "ABCBA", {0.5, 0.5, 1, 0.5, 0.5}, "leapfrog, LV eqs. (13)-(15)");
  if (name == "RSR2") return make(name, split::rs, 2, "RSR", {0.5, 1, 0.5}, "leapfrog, LV eqs. (13)-(15)");
  const std::vector<std::pair<std::string, std::vector<quad> (*)()>> ss = {
      {"SS3-Yoshida", yoshida}, {"SS5-Suzuki", suzuki}, {"SS5-McLachlan", mclachlan_ss5}};
  for (const auto& [suffix, gammas] : ss) {
    if (name == "ABCBA4-" + suffix) {
      compose_abcba(gammas(), word, c);
      return make(name, split::abc, 4, word, c, ss_source + " (" + suffix + ")");
    }
    if (name == "RSR4-" + suffix) {
      compose_xyx(gammas(), 'R', 'S', word, c);
      return make(name, split::rs, 4, word, c, ss_source + " (" + suffix + ")");
    }
  }
  const std::vector<std::pair<std::string, std::vector<quad> (*)()>> ss6 = {
      {"SS9-Yoshida", yoshida_triple_jump6}, {"SS7-Yoshida", yoshida_solution_a}, {"SS9-KahanLi", kahan_li_s9odr6a}};
  const std::string ss6_source = "LV eq. (13) composition of ABCBA / RSR";
  const std::vector<std::pair<std::string, std::string>> ss6_cited = {
      {"SS9-Yoshida", "Yoshida (1990) eqs. (5.4)-(5.5), triple jump of triple jumps"},
      {"SS7-Yoshida", "Yoshida (1990) Table 1 solution A"},
      {"SS9-KahanLi", "Kahan & Li (1997) s9odr6a"}};
  for (std::size_t k = 0; k < ss6.size(); ++k) {
    const auto& [suffix, gammas] = ss6[k];
    if (name == "ABCBA6-" + suffix) {
      compose_abcba(gammas(), word, c);
      return make(name, split::abc, 6, word, c, ss6_source + " (" + ss6_cited[k].second + ")");
    }
    if (name == "RSR6-" + suffix) {
      compose_xyx(gammas(), 'R', 'S', word, c);
      return make(name, split::rs, 6, word, c, ss6_source + " (" + ss6_cited[k].second + ")");
    }
  }
  const std::vector<std::tuple<std::string, std::vector<quad> (*)(), int, std::string>> s_type = {
      {"S4-McLachlan", mclachlan_s4, 4, "McLachlan (1995) type S"},
      {"S5-McLachlan", mclachlan_s5, 4, "McLachlan (1995) type S"},
      {"S10-BlanesMoan", blanes_moan_s10, 6, "Blanes & Moan (2002) S10, order 6"}};
  for (const auto& [suffix, coefficients, order, cited] : s_type) {
    const auto x = coefficients();
    const std::string prefix = order == 6 ? "6-" : "4-";
    if (name == "RS" + prefix + suffix) {
      for (std::size_t i = 0; i < x.size(); ++i) word += i % 2 == 0 ? 'R' : 'S';  // R outer (REFERENCE.md §1.4)
      return make(name, split::rs, order, word, x, cited);
    }
    if (name == "ABC" + prefix + suffix) {
      compose_adjoint(x, word, c);
      return make(name, split::abc, order, word, c, cited + ", adjoint composition phi = ABC, phi* = CBA");
    }
  }
  throw std::logic_error("unlisted reference scheme " + name);
}

}  // namespace

const std::vector<std::string>& reference_scheme_names() {
  static const std::vector<std::string> names = {
      "ABCBA2",           "RSR2",           "ABCBA4-SS3-Yoshida", "RSR4-SS3-Yoshida",
      "ABCBA4-SS5-Suzuki", "RSR4-SS5-Suzuki", "ABCBA4-SS5-McLachlan", "RSR4-SS5-McLachlan",
      "ABC4-S4-McLachlan", "RS4-S4-McLachlan", "ABC4-S5-McLachlan",  "RS4-S5-McLachlan"};
  return names;
}

const std::vector<std::string>& reference_sixth_order_scheme_names() {
  static const std::vector<std::string> names = {
      "ABCBA6-SS9-Yoshida", "RSR6-SS9-Yoshida", "ABCBA6-SS7-Yoshida",  "RSR6-SS7-Yoshida",
      "ABCBA6-SS9-KahanLi", "RSR6-SS9-KahanLi", "ABC6-S10-BlanesMoan", "RS6-S10-BlanesMoan"};
  return names;
}

const std::vector<std::string>& reference_tv_scheme_names() {
  static const std::vector<std::string> names = {"Strang-TV", "PEFRL-TV", "KahanLi6-TV", "Yoshida6-TV"};
  return names;
}

scheme_table permuted(scheme_table t, const std::string& permutation) {
  if (t.splitting == split::tv)
    throw std::invalid_argument(printable_text(t.name) + " is a TV table (free flight and kick): it takes no permutation, got '" +
                                printable_text(permutation) + "'");
  static const std::vector<std::string> perms = {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"};
  if (std::find(perms.begin(), perms.end(), permutation) == perms.end())
    throw std::invalid_argument("unknown permutation '" + printable_text(permutation) + "' (ABC, BCA, CAB, ACB, CBA, BAC)");
  if (t.splitting == split::abc) {
    for (auto& c : t.word) c = permutation[static_cast<std::size_t>(c - 'A')];
    for (auto& s : t.stages) s.part = permutation[static_cast<std::size_t>(s.part - 'A')];
  }
  t.permutation = permutation;
  if (t.name.find(':') == std::string::npos) t.name += ":" + permutation;
  return t;
}

std::optional<scheme_table> reference_scheme(std::string_view full) {
  const std::string name(full.substr(0, full.find(':')));
  const auto& names = reference_scheme_names();
  const auto& tv_names = reference_tv_scheme_names();
  const auto& sixth = reference_sixth_order_scheme_names();
  if (std::find(names.begin(), names.end(), name) == names.end() && std::find(sixth.begin(), sixth.end(), name) == sixth.end() &&
      std::find(tv_names.begin(), tv_names.end(), name) == tv_names.end())
    return std::nullopt;
  scheme_table t = build(name);
  check_scheme_table(t);
  if (const auto colon = full.find(':'); colon != std::string_view::npos) return permuted(std::move(t), std::string(full.substr(colon + 1)));
  return t;
}

}  // namespace rotlie::schemes
