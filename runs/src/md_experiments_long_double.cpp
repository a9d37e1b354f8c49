// The free-water and dipole-field experiments in long double (md_experiments.hpp; one file per scalar, compiled in parallel).
#include "md_experiments.hpp"

namespace rotlie::models {

template free_water_result run_free_water(const free_water<long double>&, const md_run_options&, int);
template dipole_field_result run_dipole_field(const dipole_field<long double>&, const md_run_options&);

}  // namespace rotlie::models
