#pragma once
// GUBAS's configuration file (Davis & Scheeres's full two-body code; its Python driver reads it with
// configparser: [sections], "key: value" lines, keys in any case) as a `rotlie binary` request, its SI
// units turned into rotlie's: G in m³ kg⁻¹ s⁻² × 1e-9, densities in g/cm³ × 1000 (kg/m³), semi-axes,
// vertices and the relative position in m / 1000 (km), the relative velocity in m/s / 1000 (km/s),
// spins in rad/s as they are. GUBAS writes r and v in the primary's frame A, the primary's attitude
// as "A into N" and the secondary's as "B into A"; rotlie's start is inertial: r = C_AN r_A,
// Q1 = C_AN, Q2 = C_AN C_BA (each times the body's principal axes when a polyhedron's file frame is
// not principal, its spin turned alike). What rotlie cannot run as GUBAS would is refused by name.
#include <filesystem>
#include <map>
#include <string>

#include "rotlie/runs/binary_run.hpp"

namespace rotlie::runs {

struct gubas_mapping {
  binary_request request;                    ///< bodies, densities, G, order, integrator, h, T, the start (state_text)
  std::map<std::string, std::string> source;  ///< each binary field set (by name) and the GUBAS option it comes from
};

/// Reads the file (the shape files it names are relative to its folder, where GUBAS runs). Throws
/// bad_input in one line naming the GUBAS option: missing, not a number, or without a rotlie
/// counterpart (the ABM integrator, Fahnestock's input files, a start time other than 0, the flyby,
/// heliocentric orbit, solar gravity and tides, a body truncated at an order of its own).
gubas_mapping read_gubas_config(const std::filesystem::path& path);

/// The same from the file's text; `folder` is where its shape files are, `where` names it in messages.
gubas_mapping parse_gubas_config(const std::string& text, const std::filesystem::path& folder, const std::string& where);

}  // namespace rotlie::runs
