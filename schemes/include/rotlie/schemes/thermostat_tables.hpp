#pragma once
// Thermostats as letters of a TV table: O, the exact Ornstein–Uhlenbeck step of a Langevin splitting
// (Leimkuhler & Matthews 2013), and N, the flow of a Nosé–Hoover chain (Martyna, Klein & Tuckerman
// 1992). A TV table may hold either (check_scheme_table: Σ = 1 for each letter present); the deterministic
// table is what is left when they are removed. The placements:
//   middle  O for h in the middle of the step, the middle stage split around it: on Strang-TV
//           (V T V) this is BAOAB, V ½ T ½ O 1 T ½ V ½; on PEFRL-TV the middle stage is a kick;
//   ends    O for h/2 before and after the step: on Strang-TV, OBABO;
//   chain   N for h/2 before and after the step (Kamberaj, Low & Neal 2005's placement of the chain
//           around NO_SQUISH's step; LAMMPS's rigid/nvt/small).
#include <string>

#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::schemes {

enum class thermostat_placement { middle, ends, chain };

/// The letter a placement inserts: 'O' (middle, ends) or 'N' (chain).
char thermostat_letter(thermostat_placement p);

/// The TV table `tv` (no thermostat letters yet) with its thermostat at `placement`; its name is
/// tv's with "+BAOAB", "+OBABO" or "+NHC". Throws std::invalid_argument for a table that is not TV.
scheme_table thermostatted_table(const scheme_table& tv, thermostat_placement placement);

/// Whether a stage letter is a thermostat's (O, N).
inline bool is_thermostat_letter(char part) { return part == 'O' || part == 'N'; }

}  // namespace rotlie::schemes
