// The free-water and dipole-field experiments in float128 (md_experiments.hpp; one file per scalar, compiled in parallel).
#include "md_experiments.hpp"

namespace rotlie::models {

template free_water_result run_free_water(const free_water<quad>&, const md_run_options&, int);
template dipole_field_result run_dipole_field(const dipole_field<quad>&, const md_run_options&);

}  // namespace rotlie::models
