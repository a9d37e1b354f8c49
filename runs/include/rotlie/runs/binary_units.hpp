#pragma once
// The binary scene's units (km, kg, s; densities in kg/m³, spin periods in hours) guarded against the
// mistakes a user makes silently: GUBAS's SI constant, a density in g/cm³, sizes in metres, a spin
// period in seconds. Each is refused in one line naming the likely unit, unless forced.
#include <string>

#include "rotlie/runs/binary_bodies.hpp"

namespace rotlie::runs {

/// G in km³ kg⁻¹ s⁻² (CODATA 2018).
inline constexpr double G_km = 6.67430e-20;

/// Throws bad_input naming `option` unless G is within 10× of G_km.
void check_G_units(double G, const std::string& text);

/// Throws bad_input unless ρ is within 100 … 30,000 kg/m³.
void check_density_units(double rho, const std::string& option);

/// Throws bad_input when a body reaches beyond the separation d (km): sizes in metres.
void check_size_units(const binary_body& primary, const binary_body& secondary, double d, const std::string& option);

/// Throws bad_input when a spin period (hours) is under 0.01 h: seconds.
void check_period_units(double hours, const std::string& option);

}  // namespace rotlie::runs
