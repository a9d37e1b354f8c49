// The loops of rotlie.integrate and rotlie.exact_flow written directly in C++ against the library,
// for the Python package's benchmark (python/bench/python_vs_cpp.py runs both and states the ratio):
//   integrate: 10^5 water bodies × 100 steps of RS4-S5-McLachlan:CBA, h = 0.01, in double;
//   exact_flow: 10^6 states of water at t = 1, in double (the free-flight step, blocks of rows at once).
// The states are the same pseudo-random ones the script builds (a fixed linear congruential
// sequence), read from and written to flat arrays as the extension does. Prints JSON: the least
// CPU seconds of five runs of each loop.
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <vector>

#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_rotation_batch.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/schemes/reference_schemes.hpp"

namespace {

using namespace rotlie;

constexpr const char* water = "10220/29376 19187/29376 1";

std::vector<double> momenta(std::size_t n) {
  std::vector<double> G(3 * n);
  unsigned long long x = 12345;
  for (auto& g : G) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    g = static_cast<double>(x >> 11) * 0x1.0p-53 * 2 - 1;
  }
  return G;
}

models::body_state<double> state_at(const std::vector<double>& G, std::size_t row) {
  models::body_state<double> s;
  for (std::size_t j = 0; j < 3; ++j) s.G[j] = G[3 * row + j];
  return s;
}

// The least CPU time of the process over `repeats` runs (CPU rather than wall time: the figure of a
// shared machine is then the loop's own).
template <class F>
double best_seconds(F&& f, int repeats = 5) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const std::clock_t start = std::clock();
    f();
    best = std::min(best, static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
  }
  return best;
}

}  // namespace

int main() {
  const std::size_t bodies = 100'000, states = 1'000'000;
  const long steps = 100;
  const auto I = models::moments_from_text<double>(water);

  const auto method = models::free_body_method(*schemes::reference_scheme("RS4-S5-McLachlan:CBA"), I);
  const auto G0 = momenta(bodies);
  std::vector<double> G(3 * bodies), Q(9 * bodies);
  const double integrate_s = best_seconds([&] {
    for (std::size_t row = 0; row < bodies; ++row) {
      auto x = state_at(G0, row);
      for (long k = 0; k < steps; ++k) method.step(x, 0.01);
      for (std::size_t j = 0; j < 3; ++j) G[3 * row + j] = x.G[j];
      for (std::size_t j = 0; j < 9; ++j) Q[9 * row + j] = x.Q.a[j];
    }
  });

  const auto E0 = momenta(states);
  std::vector<double> EG(3 * states), EQ(9 * states);
  // as the extension: the step of SIER's free flights, many rows at once (exact_free_rotation_batch.hpp)
  const models::exact_free_rotation<double> rotor(I);
  std::vector<models::body_state<double>> flights(states);
  const double exact_s = best_seconds([&] {
    for (std::size_t row = 0; row < states; ++row) flights[row] = state_at(E0, row);
    models::advance_all(rotor, states, [&](std::size_t row) -> models::body_state<double>& { return flights[row]; }, 1.0);
    for (std::size_t row = 0; row < states; ++row) {
      for (std::size_t j = 0; j < 3; ++j) EG[3 * row + j] = flights[row].G[j];
      for (std::size_t j = 0; j < 9; ++j) EQ[9 * row + j] = flights[row].Q.a[j];
    }
  });
  std::printf("{\"integrate_s\": %.6f, \"exact_flow_s\": %.6f, \"check\": %.17g}\n", integrate_s, exact_s,
              G[0] + Q[8] + EG[0] + EQ[8]);
  return 0;
}
