// The free-water and dipole-field experiments in double (md_experiments.hpp; one file per scalar, compiled in parallel).
#include "md_experiments.hpp"

namespace rotlie::models {

template free_water_result run_free_water(const free_water<double>&, const md_run_options&, int);
template dipole_field_result run_dipole_field(const dipole_field<double>&, const md_run_options&);

}  // namespace rotlie::models
