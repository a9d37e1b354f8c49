#include "rotlie/bch/word_series.hpp"

#include <stdexcept>

namespace rotlie::bch {

void word_series::add(const word& w, const cln::cl_RA& c) {
  if (w.size() >= by_degree_.size()) return;  // truncated
  auto& terms = by_degree_[w.size()];
  auto [it, inserted] = terms.try_emplace(w, c);
  if (!inserted) it->second = it->second + c;
  if (cln::zerop(it->second)) terms.erase(it);
}

word_series word_series::one(int max_degree) {
  word_series s(max_degree);
  s.add(word{}, 1);
  return s;
}

word_series word_series::exp_of_letter(std::uint8_t letter, int max_degree) {
  word_series s(max_degree);
  cln::cl_RA factorial = 1;
  for (int k = 0; k <= max_degree; ++k) {
    if (k > 0) factorial = factorial * k;
    s.add(word(static_cast<std::size_t>(k), letter), cln::recip(factorial));
  }
  return s;
}

word_series operator*(const word_series& a, const word_series& b) {
  const int n = std::min(a.max_degree(), b.max_degree());
  word_series out(n);
  for (int i = 0; i <= n; ++i)
    for (const auto& [wa, ca] : a.degree(i))
      for (int j = 0; i + j <= n; ++j)
        for (const auto& [wb, cb] : b.degree(j)) {
          word w = wa;
          w.insert(w.end(), wb.begin(), wb.end());
          out.add(w, ca * cb);
        }
  return out;
}

word_series& word_series::operator+=(const word_series& o) {
  for (int d = 0; d <= std::min(max_degree(), o.max_degree()); ++d)
    for (const auto& [w, c] : o.degree(d)) add(w, c);
  return *this;
}

word_series& word_series::operator*=(const cln::cl_RA& s) {
  for (auto& terms : by_degree_)
    for (auto& [w, c] : terms) c = c * s;
  return *this;
}

word_series log(const word_series& x) {
  const int n = x.max_degree();
  const auto& constant = x.degree(0);
  if (constant.size() != 1 || constant.begin()->second != 1) throw std::invalid_argument("log needs constant term 1");
  word_series y = x;  // y = x − 1
  y += word_series::one(n) *= cln::cl_RA(-1);
  word_series result(n), power = word_series::one(n);
  for (int k = 1; k <= n; ++k) {  // y^k has no term below degree k
    power = power * y;
    word_series term = power;
    term *= cln::cl_RA(k % 2 ? 1 : -1) / k;
    result += term;
  }
  return result;
}

}  // namespace rotlie::bch
