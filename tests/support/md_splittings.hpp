#pragma once
// The splittings the numeric tests run, by their parts: tests/models build without the library floor,
// where names are parsed (runs/methods.hpp). method_registry_test (tests/runs) checks that each of these
// is what the registry resolves its name into.
#include <stdexcept>
#include <string>
#include <vector>

#include "rotlie/models/md_integrators.hpp"

namespace rotlie::test {

inline const std::vector<models::md_integrator>& md_splittings() {
  static const std::vector<models::md_integrator> all = {
      models::md_integrator_of("SIER2", "Strang-TV", "exact"),
      models::md_integrator_of("SIER4", "PEFRL-TV", "exact"),
      models::md_integrator_of("SIER6", "KahanLi6-TV", "exact"),
      models::md_integrator_of("MRDL", "Strang-TV", models::mrdl_rotor_table),
      models::md_integrator_of("MRDL-reversed", "Strang-TV", models::mrdl_reversed_rotor_table),
      models::md_integrator_of("SEJ4", "Strang-TV", "sej4"),
      models::md_integrator_of("SIER4/sej4", "PEFRL-TV", "sej4"),
      models::md_integrator_of("SIER2/ABCBA2:BAC", "Strang-TV", "ABCBA2:BAC"),
      models::md_integrator_of("SIER4/ABCBA2:CBA", "PEFRL-TV", "ABCBA2:CBA"),
      models::md_integrator_of("SIER2/ABCBA4-SS3-Yoshida:ABC", "Strang-TV", "ABCBA4-SS3-Yoshida:ABC"),
      models::md_integrator_of("SIER4/ABCBA4-SS3-Yoshida:ABC", "PEFRL-TV", "ABCBA4-SS3-Yoshida:ABC"),
      models::md_integrator_of("SIER2/RS4-S5-McLachlan:CBA", "Strang-TV", "RS4-S5-McLachlan:CBA"),
      models::md_integrator_of("SIER4/RS4-S5-McLachlan:CBA", "PEFRL-TV", "RS4-S5-McLachlan:CBA"),
  };
  return all;
}

/// One of md_splittings() by the name it was listed with (a test's fixture, not a user's text).
inline const models::md_integrator& splitting(const std::string& name) {
  for (const auto& s : md_splittings())
    if (s.name == name) return s;
  throw std::logic_error("no test splitting is called " + name);
}

}  // namespace rotlie::test
