#include "rotlie/schemes/reference_schemes.hpp"

#include <boost/multiprecision/float128.hpp>

#include <algorithm>
#include <stdexcept>

namespace rotlie::schemes {
namespace {

using quad = boost::multiprecision::float128;

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
  const std::vector<std::pair<std::string, std::vector<quad> (*)()>> s_type = {{"S4-McLachlan", mclachlan_s4},
                                                                               {"S5-McLachlan", mclachlan_s5}};
  for (const auto& [suffix, coefficients] : s_type) {
    const auto x = coefficients();
    if (name == "RS4-" + suffix) {
      for (std::size_t i = 0; i < x.size(); ++i) word += i % 2 == 0 ? 'R' : 'S';  // R outer (REFERENCE.md §1.4)
      return make(name, split::rs, 4, word, x, "McLachlan (1995) type S");
    }
    if (name == "ABC4-" + suffix) {
      compose_adjoint(x, word, c);
      return make(name, split::abc, 4, word, c, "McLachlan (1995) type S, adjoint composition phi = ABC, phi* = CBA");
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

const std::vector<std::string>& reference_tv_scheme_names() {
  static const std::vector<std::string> names = {"Strang-TV", "PEFRL-TV"};
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
  if (std::find(names.begin(), names.end(), name) == names.end() &&
      std::find(tv_names.begin(), tv_names.end(), name) == tv_names.end())
    return std::nullopt;
  scheme_table t = build(name);
  check_scheme_table(t);
  if (const auto colon = full.find(':'); colon != std::string_view::npos) return permuted(std::move(t), std::string(full.substr(colon + 1)));
  return t;
}

}  // namespace rotlie::schemes
