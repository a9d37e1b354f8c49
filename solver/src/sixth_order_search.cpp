#include "rotlie/solver/sixth_order_search.hpp"

#include "dense_linear_solve.hpp"

#include <cln/float.h>
#include <cln/float_io.h>
#include <cln/real.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "rotlie/bch/modified_hamiltonian.hpp"
#include "rotlie/bch/stage_hamiltonian.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "rotlie/lie/theorems.hpp"

namespace rotlie::solver {
namespace {

using poly = lie::multivariate_polynomial;

// The body scaled to I3 = 1: w = I3 / I (H_Rk is homogeneous in w, the zero set is the same).
std::array<cln::cl_RA, 3> scaled_inverse_moments(const lie::moments_of_inertia& body) {
  return {body.I[2] / body.I[0], body.I[2] / body.I[1], cln::cl_RA(1)};
}

// F (values), Σ|terms| (sizes) and the Jacobian J (row-major) of a square system at x, in T.
template <class T>
void evaluate(const std::vector<compiled_polynomial>& f, const std::vector<T>& x, std::vector<T>& value,
              std::vector<T>& size, std::vector<T>& jacobian) {
  const std::size_t n = x.size();
  std::vector<std::array<T, 16>> power(n);  // power[k][e] = x_k^e
  for (std::size_t k = 0; k < n; ++k) {
    power[k][0] = 1;
    for (std::size_t e = 1; e < 16; ++e) power[k][e] = power[k][e - 1] * x[k];
  }
  value.assign(f.size(), T(0));
  size.assign(f.size(), T(0));
  jacobian.assign(f.size() * n, T(0));
  std::vector<T> prefix(n + 1), suffix(n + 1);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const auto& p = f[i];
    for (std::size_t t = 0; t < p.coefficients.size(); ++t) {
      const std::uint8_t* e = &p.exponents[t * n];
      prefix[0] = 1;
      for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] * power[k][e[k]];
      suffix[n] = 1;
      for (std::size_t k = n; k-- > 0;) suffix[k] = suffix[k + 1] * power[k][e[k]];
      const T c = static_cast<T>(p.coefficients[t]);
      const T term = c * prefix[n];
      value[i] += term;
      size[i] += term < 0 ? -term : term;
      for (std::size_t k = 0; k < n; ++k)
        if (e[k] > 0) jacobian[i * n + k] += c * T(e[k]) * power[k][e[k] - 1] * prefix[k] * suffix[k + 1];
    }
  }
}

using detail::solve_linear;

cln::cl_F power_of(const cln::cl_F& x, int e) {
  cln::cl_F p = x;
  for (int i = 1; i < e; ++i) p = p * x;
  return p;
}

}  // namespace

compiled_polynomial::compiled_polynomial(const lie::multivariate_polynomial& p, int n) : unknowns(n) {
  for (const auto& [key, c] : p.rational_terms()) {
    for (int k = 0; k < n; ++k) exponents.push_back(static_cast<std::uint8_t>(poly::exponent(key, k)));
    coefficients.push_back(static_cast<long double>(cln::double_approx(c)));  // 16 digits suffice for the search
  }
}

sixth_order_system sixth_order_conditions(const bch::scheme_layout& layout, const lie::moments_of_inertia& body) {
  if (!layout.symmetric) throw std::invalid_argument("a 6th-order search needs a palindromic word");
  sixth_order_system s;
  s.layout = layout;
  s.w = scaled_inverse_moments(body);
  const auto k = bch::compute_stage_hamiltonian(layout, s.w, 5);
  const int n = s.free_count();
  for (int order : {3, 5}) {
    const auto monomials = lie::theorem1_monomials(order);
    for (std::size_t i = 0; i < monomials.size(); ++i) {
      const poly c = k.remainder[static_cast<std::size_t>(order)].coefficient(monomials[i]);
      s.all_conditions.push_back(c);
      s.condition_names.push_back("H_R" + std::to_string(order) + " " + lie::compact_text(monomials[i]));
      if (i + 1 < monomials.size()) s.conditions.emplace_back(c, n);  // Theorem 2 fixes the last one
    }
  }
  return s;
}

namespace {

// Σ (F_i / Σ|terms of F_i|)²: smooth, and scale-free like the acceptance test.
double merit(const std::vector<double>& v, const std::vector<double>& sz) {
  double m = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double r = v[i] / std::max(sz[i], 1e-300);
    m += r * r;
  }
  return m;
}

// Levenberg–Marquardt on the scaled residuals r_i = F_i / Σ|terms of F_i| (the sizes held fixed
// within a step): Newton's step when it reduces Σ r², a shorter gradient-leaning one otherwise.
// Returns the final Σ r² (x updated in place); stops when x leaves |x_k| ≤ 100.
double levenberg_marquardt(const sixth_order_system& s, std::vector<double>& x, int max_iterations) {
  const std::size_t n = x.size();
  std::vector<double> f, size, j, trial_f, trial_size, trial_j, normal(n * n), rhs(n);
  evaluate(s.conditions, x, f, size, j);
  double m = merit(f, size);
  double mu = 1e-3;
  for (int it = 0; it < max_iterations && m > 1e-26; ++it) {
    std::vector<double> r(n), js(n * n);
    for (std::size_t i = 0; i < n; ++i) {
      const double sc = 1 / std::max(size[i], 1e-300);
      r[i] = f[i] * sc;
      for (std::size_t k = 0; k < n; ++k) js[i * n + k] = j[i * n + k] * sc;
    }
    for (std::size_t a1 = 0; a1 < n; ++a1) {
      rhs[a1] = 0;
      for (std::size_t i = 0; i < n; ++i) rhs[a1] -= js[i * n + a1] * r[i];
      for (std::size_t b1 = 0; b1 < n; ++b1) {
        double sum = 0;
        for (std::size_t i = 0; i < n; ++i) sum += js[i * n + a1] * js[i * n + b1];
        normal[a1 * n + b1] = sum;
      }
    }
    bool improved = false;
    std::vector<double> y(n);
    for (int attempt = 0; attempt < 8 && !improved; ++attempt) {
      std::vector<double> damped = normal, d = rhs;
      for (std::size_t i = 0; i < n; ++i) damped[i * n + i] *= 1 + mu;
      if (!solve_linear(damped, d, n)) {
        mu *= 10;
        continue;
      }
      for (std::size_t i = 0; i < n; ++i) y[i] = x[i] + d[i];
      evaluate(s.conditions, y, trial_f, trial_size, trial_j);
      const double tm = merit(trial_f, trial_size);
      if (std::isfinite(tm) && tm < m) {
        improved = true;
        x = y, f = trial_f, size = trial_size, j = trial_j, m = tm;
        mu = std::max(mu / 10, 1e-12);
      } else {
        mu *= 10;
      }
    }
    if (!improved) break;
    double largest = 0;
    for (double v : x) largest = std::max(largest, std::abs(v));
    if (largest > 100) break;  // running off: not a root of practical size
  }
  return m;
}

}  // namespace

search_result newton_search(const sixth_order_system& s, const search_options& o) {
  const std::size_t n = static_cast<std::size_t>(s.free_count());
  if (s.conditions.size() != n) throw std::invalid_argument("the system is not square");
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> start(-o.box, o.box);
  search_result out;
  for (long skipped = 0; skipped < static_cast<long>(o.first_start) * static_cast<long>(n); ++skipped) (void)start(rng);
  for (int trial = 0; trial < o.starts; ++trial) {
    ++out.starts;
    std::vector<double> x(n);
    for (auto& v : x) v = start(rng);
    const double m = levenberg_marquardt(s, x, o.max_iterations);
    if (!(m < 1e-26)) continue;
    ++out.converged;
    bool known = false;
    for (auto& r : out.roots) {
      double distance = 0, scale = 1;
      for (std::size_t i = 0; i < n; ++i) {
        distance = std::max(distance, std::abs(static_cast<double>(r.x[i]) - x[i]));
        scale = std::max(scale, std::abs(x[i]));
      }
      if (distance < 1e-8 * scale) {
        ++r.hits;
        known = true;
        break;
      }
    }
    if (!known) out.roots.push_back({std::vector<long double>(x.begin(), x.end()), std::sqrt(m), 1});
  }
  std::sort(out.roots.begin(), out.roots.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  return out;
}

std::vector<cln::cl_RA> polished_root(const sixth_order_system& s, const std::vector<long double>& x0, int digits) {
  const std::size_t n = x0.size();
  const cln::float_format_t format = cln::float_format(static_cast<unsigned>(digits + 25));
  // The independent conditions with long-float coefficients.
  std::vector<std::vector<std::pair<std::uint64_t, cln::cl_F>>> f;
  for (int order_index = 0, i = 0; i < static_cast<int>(s.all_conditions.size()); ++i) {
    (void)order_index;
    const bool last_of_order = i + 1 == static_cast<int>(s.all_conditions.size()) ||
                               s.condition_names[static_cast<std::size_t>(i + 1)].substr(0, 4) !=
                                   s.condition_names[static_cast<std::size_t>(i)].substr(0, 4);
    if (last_of_order) continue;
    std::vector<std::pair<std::uint64_t, cln::cl_F>> terms;
    for (const auto& [key, c] : s.all_conditions[static_cast<std::size_t>(i)].rational_terms())
      terms.emplace_back(key, cln::cl_float(c, format));
    f.push_back(std::move(terms));
  }
  // Long double Newton first (the search's double root is good to about 1e-13 relative), undamped:
  // the root is simple and the start inside its basin.
  std::vector<double> xd(x0.begin(), x0.end());
  if (!(levenberg_marquardt(s, xd, 100) < 1e-24)) throw std::runtime_error("polishing: the start is not near a root");
  // Long double Newton steps while they reduce the residual (a regular root: quadratic convergence).
  std::vector<long double> xl(xd.begin(), xd.end()), fl, sl, jl;
  evaluate(s.conditions, xl, fl, sl, jl);
  auto size_of = [&] {
    long double m = 0;
    for (std::size_t i = 0; i < n; ++i) m = std::max(m, std::abs(fl[i]) / std::max(sl[i], 1e-300L));
    return m;
  };
  for (int iteration = 0; iteration < 4; ++iteration) {
    const long double before = size_of();
    std::vector<long double> d(n), previous = xl;
    for (std::size_t i = 0; i < n; ++i) d[i] = -fl[i];
    if (!solve_linear(jl, d, n)) break;
    for (std::size_t i = 0; i < n; ++i) xl[i] += d[i];
    evaluate(s.conditions, xl, fl, sl, jl);
    if (!(size_of() < before)) {
      xl = previous;
      break;
    }
  }
  std::vector<cln::cl_F> x;
  for (long double v : xl) {  // exactly: the high and low double halves of the long double
    const double hi = static_cast<double>(v), lo = static_cast<double>(v - static_cast<long double>(hi));
    x.push_back(cln::cl_float(hi, format) + cln::cl_float(lo, format));
  }
  const cln::cl_F zero = cln::cl_float(0, format), one = cln::cl_float(1, format);
  for (int iteration = 0; iteration < 12; ++iteration) {
    std::vector<cln::cl_F> value(n, zero), jac(n * n, zero);
    for (std::size_t i = 0; i < n; ++i)
      for (const auto& [key, c] : f[i]) {
        cln::cl_F term = c;
        for (std::size_t k = 0; k < n; ++k)
          if (const int e = poly::exponent(key, static_cast<int>(k)); e > 0) term = term * power_of(x[k], e);
        value[i] = value[i] + term;
        for (std::size_t k = 0; k < n; ++k)
          if (const int e = poly::exponent(key, static_cast<int>(k)); e > 0) {
            cln::cl_F d = c * cln::cl_float(e, format);
            if (e > 1) d = d * power_of(x[k], e - 1);
            for (std::size_t m = 0; m < n; ++m)
              if (m != k)
                if (const int em = poly::exponent(key, static_cast<int>(m)); em > 0) d = d * power_of(x[m], em);
            jac[i * n + k] = jac[i * n + k] + d;
          }
      }
    std::vector<cln::cl_F> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = -value[i];
    if (!solve_linear(jac, d, n)) throw std::runtime_error("polishing: singular Jacobian");
    cln::cl_F step = zero;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = x[i] + d[i];
      step = cln::max(step, cln::abs(d[i]));
    }
    if (cln::zerop(step) || cln::float_exponent(step) < -static_cast<long>(3.33 * (digits + 20))) break;
  }
  std::vector<cln::cl_RA> out;
  for (const auto& v : x) {
    const auto written = lie::parse_exact_number(lie::to_decimal(cln::rational(v), digits));
    if (!written) throw std::runtime_error("polishing: a coefficient cannot be written");
    out.push_back(*written);
  }
  return out;
}

double jacobian_condition_ratio(const sixth_order_system& s, const std::vector<long double>& x) {
  const std::size_t n = x.size();
  std::vector<long double> f, size, j;
  evaluate(s.conditions, x, f, size, j);
  Eigen::MatrixXd m(static_cast<Eigen::Index>(s.conditions.size()), static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < s.conditions.size(); ++i)
    for (std::size_t k = 0; k < n; ++k)
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = static_cast<double>(j[i * n + k] / std::max(size[i], 1e-300L));
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m);
  const auto& sigma = svd.singularValues();
  return sigma(0) > 0 ? sigma(sigma.size() - 1) / sigma(0) : 0;
}

std::map<std::string, cln::cl_RA> all_coefficients(const sixth_order_system& s, const std::vector<cln::cl_RA>& x, int digits) {
  std::map<std::string, cln::cl_RA> values;
  for (std::size_t k = 0; k < x.size(); ++k) values.emplace(s.layout.free_coefficients[k], x[k]);
  bch::solve_first_order_conditions(s.layout, values, [](const cln::cl_RA& v, int m) { return v / m; });
  for (const auto& name : s.layout.eliminated) {
    const auto written = lie::parse_exact_number(lie::to_decimal(values.at(name), digits));
    if (written) values[name] = *written;
  }
  return values;
}

cln::cl_RA sixth_order_residual(const sixth_order_system& s, const std::vector<cln::cl_RA>& x, int digits) {
  cln::cl_RA worst = 0;
  for (const auto& c : s.all_conditions) {
    const cln::cl_RA size = c.term_size(x);
    if (!cln::zerop(size)) worst = cln::max(worst, cln::abs(c(x)) / size);
  }
  // First order at the written values: Σ of each name's stages = 1, relative to Σ|c| + 1.
  const auto values = all_coefficients(s, x, digits);
  std::map<char, std::pair<cln::cl_RA, cln::cl_RA>> sums;
  for (const auto& st : s.layout.stages) {
    auto& [sum, size] = sums[st.coefficient[0]];
    sum = sum + values.at(st.coefficient);
    size = size + cln::abs(values.at(st.coefficient));
  }
  for (const auto& [name, ss] : sums) worst = cln::max(worst, cln::abs(ss.first - 1) / (ss.second + 1));
  return worst;
}

double remainder7_norm(const bch::scheme_layout& layout, const lie::moments_of_inertia& body,
                       const std::map<std::string, double>& values) {
  const auto h = bch::compute_numeric_modified_hamiltonian(layout, scaled_inverse_moments(body), values, 7);
  double sum = 0;
  for (const auto& [m, c] : h[7].terms()) sum += c * c;
  return std::sqrt(sum);
}

std::vector<std::string> palindromic_words(int length, bch::splitting split) {
  std::vector<std::string> out;
  if (length < 1 || length > static_cast<int>(bch::max_word_length)) return out;
  const int half = (length + 1) / 2;  // the first half and the middle letter
  const std::string letters = split == bch::splitting::abc ? "ABC" : "RS";
  std::string w;
  auto extend = [&](auto&& self) -> void {
    if (static_cast<int>(w.size()) == half) {
      std::string full = w;
      for (int i = length / 2; i-- > 0;) full += w[static_cast<std::size_t>(i)];
      bool all = true;
      for (char c : letters) all = all && full.find(c) != std::string::npos;
      if (all) out.push_back(full);
      return;
    }
    // Letters in order of first appearance: the next new letter is the first one not used yet.
    char next_new = 0;
    for (char c : letters)
      if (w.find(c) == std::string::npos) {
        next_new = c;
        break;
      }
    for (char c : letters) {
      if (!w.empty() && w.back() == c) continue;
      if (w.find(c) == std::string::npos && c != next_new) continue;
      w.push_back(c);
      self(self);
      w.pop_back();
    }
  };
  extend(extend);
  // An odd length's middle letter must differ from its neighbours (checked by construction), an even
  // one would repeat its middle letter: no such word.
  if (length % 2 == 0) out.clear();
  return out;
}

std::string sixth_order_table_text(const sixth_order_system& s, const std::vector<cln::cl_RA>& x, int digits,
                                   const lie::moments_of_inertia& body, const std::string& name, const std::string& source) {
  const auto values = all_coefficients(s, x, digits);
  std::map<std::string, double> numeric;
  for (const auto& [k, v] : values) numeric[k] = cln::double_approx(v);
  std::ostringstream remainder;
  remainder << remainder7_norm(s.layout, body, numeric);
  return searched_table_text(s.layout, body, values,
                             {name, 6, digits, sixth_order_residual(s, x, digits),
                              " analytic_remainder: the Euclidean norm of H_R7's coefficients, body scaled to I3 = 1",
                              remainder.str(), source});
}

}  // namespace rotlie::solver
