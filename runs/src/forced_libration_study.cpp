#include "rotlie/runs/forced_libration_study.hpp"

#include <cmath>
#include <utility>

namespace rotlie::runs {

double forced_libration_3_2(double asphericity, double e) { return 1.5 * asphericity * (1 - 11 * e * e + 959.0 / 48 * std::pow(e, 4)); }

double forced_libration_1_1(double omega0_squared, double e) { return 2 * e * omega0_squared / (1 - omega0_squared); }

std::vector<forced_libration> forced_librations(int orbits) {
  std::vector<forced_libration> out;
  const auto add = [&](const std::string& name, double p, double e, double lo, double hi) {
    const auto body = spin_body_named(name);
    const auto I = spin_moments(body);
    forced_libration f;
    f.body = name, f.p = p, f.e = e;
    f.rate = resonant_rate(body, e, p, lo, hi, 200);
    f.run = resonance(body, e, p, f.rate, orbits, 200);
    f.theory = p == 1 ? forced_libration_1_1(3 * (I[1] - I[0]) / I[2], e) : forced_libration_3_2((I[1] - I[0]) / I[2], e);
    f.ratio = f.run.forced_amplitude / f.theory;
    out.push_back(std::move(f));
  };
  add("Mercury", 1.5, 0.2056, 1.4, 1.6);
  add("Moon", 1.0, 0.0549, 0.9, 1.1);
  return out;
}

}  // namespace rotlie::runs
