#include "rotlie/runs/expression_io.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

namespace rotlie::runs {
namespace {

struct term {
  GiNaC::numeric coefficient;
  std::vector<int> exponent;
};

term decompose(const GiNaC::ex& t, const std::vector<GiNaC::symbol>& symbols) {
  term out{1, std::vector<int>(symbols.size(), 0)};
  auto factor = [&](const GiNaC::ex& f) {
    GiNaC::ex base = f;
    int power = 1;
    if (GiNaC::is_a<GiNaC::numeric>(f)) {
      out.coefficient *= GiNaC::ex_to<GiNaC::numeric>(f);
      return;
    }
    if (GiNaC::is_a<GiNaC::power>(f)) {
      base = f.op(0);
      if (!GiNaC::is_a<GiNaC::numeric>(f.op(1)) || !GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_integer())
        throw std::logic_error("format_expression: non-integer power");
      power = GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int();
    }
    if (!GiNaC::is_a<GiNaC::symbol>(base)) throw std::logic_error("format_expression: not a polynomial term");
    const auto it = std::find_if(symbols.begin(), symbols.end(), [&](const GiNaC::symbol& s) { return base.is_equal(s); });
    if (it == symbols.end()) throw std::logic_error("format_expression: unexpected symbol");
    out.exponent[static_cast<std::size_t>(it - symbols.begin())] += power;
  };
  if (GiNaC::is_a<GiNaC::mul>(t))
    for (const auto& f : t) factor(f);
  else
    factor(t);
  return out;
}

std::string number_text(const GiNaC::numeric& n, expression_style style) {
  std::ostringstream s;
  if (style == expression_style::latex && !n.is_integer())
    s << "\\frac{" << n.numer() << "}{" << n.denom() << "}";
  else
    s << n;
  return s.str();
}

std::string symbol_text(const GiNaC::symbol& sym, int e, expression_style style) {
  std::string name = sym.get_name();
  if (style == expression_style::latex) {
    const auto digit = std::find_if(name.begin(), name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (digit != name.begin() && digit != name.end())
      name = std::string(name.begin(), digit) + "_{" + std::string(digit, name.end()) + "}";
    return e == 1 ? name : name + "^{" + std::to_string(e) + "}";
  }
  return e == 1 ? name : name + "^" + std::to_string(e);
}

}  // namespace

std::string format_expression(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& symbols, expression_style style) {
  const GiNaC::ex expanded = e.expand();
  if (expanded.is_zero()) return "0";
  std::vector<term> terms;
  if (GiNaC::is_a<GiNaC::add>(expanded))
    for (const auto& t : expanded) terms.push_back(decompose(t, symbols));
  else
    terms.push_back(decompose(expanded, symbols));
  std::sort(terms.begin(), terms.end(), [](const term& a, const term& b) {
    int da = 0, db = 0;
    for (std::size_t i = 0; i < a.exponent.size(); ++i) da += a.exponent[i], db += b.exponent[i];
    if (da != db) return da < db;
    return a.exponent > b.exponent;
  });
  std::string out;
  const std::string times = style == expression_style::latex ? " " : "*";
  for (const auto& t : terms) {
    const bool negative = t.coefficient < 0;
    const GiNaC::numeric magnitude = negative ? -t.coefficient : t.coefficient;
    std::vector<std::string> up, down;  // symbol powers with positive and negative exponents
    for (std::size_t i = 0; i < symbols.size(); ++i) {
      if (t.exponent[i] > 0) up.push_back(symbol_text(symbols[i], t.exponent[i], style));
      if (t.exponent[i] < 0) down.push_back(symbol_text(symbols[i], -t.exponent[i], style));
    }
    // numerator: |p| (unless 1 with symbols) and the positive powers; denominator: q and the negative powers
    std::vector<std::string> num, den;
    if (!(magnitude.numer() == 1 && !up.empty())) num.push_back(number_text(magnitude.numer(), style));
    num.insert(num.end(), up.begin(), up.end());
    if (magnitude.denom() != 1) den.push_back(number_text(magnitude.denom(), style));
    den.insert(den.end(), down.begin(), down.end());
    auto product = [&](const std::vector<std::string>& f) {
      std::string p;
      for (const auto& x : f) p += (p.empty() ? "" : times) + x;
      return p.empty() ? std::string("1") : p;
    };
    std::string body;
    if (den.empty())
      body = product(num);
    else if (style == expression_style::latex)
      body = "\\frac{" + product(num) + "}{" + product(den) + "}";
    else
      body = product(num) + "/" + (den.size() > 1 ? "(" + product(den) + ")" : den.front());
    if (out.empty())
      out = (negative ? "-" : "") + body;
    else
      out += (negative ? " - " : " + ") + body;
  }
  return out;
}

std::string format_monomial(const lie::monomial& m, expression_style style) {
  std::string out;
  for (int i = 0; i < 3; ++i) {
    if (m[i] == 0) continue;
    if (style == expression_style::latex) {
      out += (out.empty() ? "" : " ") + std::string("G_") + std::to_string(i + 1);
      if (m[i] > 1) out += "^{" + std::to_string(m[i]) + "}";
    } else {
      out += (out.empty() ? "" : "*") + std::string("G") + std::to_string(i + 1);
      if (m[i] > 1) out += "^" + std::to_string(m[i]);
    }
  }
  return out.empty() ? "1" : out;
}

}  // namespace rotlie::runs
