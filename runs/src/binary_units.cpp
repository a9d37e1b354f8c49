#include "rotlie/runs/binary_units.hpp"

#include <cmath>

#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/message_number.hpp"

namespace rotlie::runs {

namespace {

using schemes::message_number;

constexpr double G_SI = 6.67430e-11;  // m³ kg⁻¹ s⁻²
constexpr double G_slack = 10;
constexpr double density_low = 100, density_high = 30000;  // kg/m³: below any rubble pile, above any metal
constexpr double shortest_period_h = 0.01;                   // 36 s: faster than any asteroid spins

const char* const forced = " (--force runs it as given)";

}  // namespace

void check_G_units(double G, const std::string& text) {
  if (G <= G_slack * G_km && G >= G_km / G_slack) return;
  const bool si = G <= G_slack * G_SI && G >= G_SI / G_slack;
  throw bad_input("--G " + one_line(text) + " is " + message_number(G / G_km) + " times the gravitational constant in km3 kg-1 s-2 (6.6743e-20)" +
                  (si ? ": it is SI's value in m3 kg-1 s-2; rotlie's units are km, kg, s" : ": rotlie's units are km, kg, s") + forced);
}

void check_density_units(double rho, const std::string& option) {
  if (rho >= density_low && rho <= density_high) return;
  if (rho < density_low)
    throw bad_input(option + " " + message_number(rho) + " kg/m3 is lighter than any asteroid: a density in g/cm3? (" + message_number(rho) +
                    " g/cm3 is " + message_number(rho * 1000) + " kg/m3)" + forced);
  throw bad_input(option + " " + message_number(rho) + " kg/m3 is denser than any metal: densities are in kg/m3" + forced);
}

void check_size_units(const binary_body& primary, const binary_body& secondary, double d, const std::string& option) {
  for (const auto* b : {&primary, &secondary})
    if (b->bounding_radius > d)
      throw bad_input(option + ": the " + (b == &primary ? "primary" : "secondary") + " (" + b->spec + ") reaches " + message_number(b->bounding_radius) +
                      " km from its centre, beyond the separation of " + message_number(d) + " km: sizes in metres? (shapes are in km)" + forced);
}

void check_period_units(double hours, const std::string& option) {
  if (hours >= shortest_period_h) return;
  throw bad_input(option + " " + message_number(hours) + " h (" + message_number(hours * 3600) + " s) is faster than any asteroid spins: periods are in hours" +
                  forced);
}

}  // namespace rotlie::runs
