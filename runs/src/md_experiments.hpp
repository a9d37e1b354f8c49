#pragma once
// The free-water and dipole-field experiments compiled once per scalar (md_experiments.cpp): the
// scenes and the vZS study link these instantiations instead of compiling every integrator again.
#include "rotlie/models/experiments/dipole_field_experiment.hpp"
#include "rotlie/models/experiments/free_water_experiment.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::models {

extern template free_water_result run_free_water(const free_water<double>&, const md_run_options&, int);
extern template free_water_result run_free_water(const free_water<long double>&, const md_run_options&, int);
extern template free_water_result run_free_water(const free_water<quad>&, const md_run_options&, int);
extern template dipole_field_result run_dipole_field(const dipole_field<double>&, const md_run_options&);
extern template dipole_field_result run_dipole_field(const dipole_field<long double>&, const md_run_options&);
extern template dipole_field_result run_dipole_field(const dipole_field<quad>&, const md_run_options&);

}  // namespace rotlie::models
