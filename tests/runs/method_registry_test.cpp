// The method registry (runs/methods.hpp): every name it lists parses for each system it claims and for
// no other, each system's refusal lists exactly its names, the numeric tests' splittings are what the
// registry makes of theirs, and moments reach a table rotor as numbers, not as decimal text.
#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "md_splittings.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/methods.hpp"
#include "rotlie/runs/user_input.hpp"

using namespace rotlie;
using runs::method_system;

namespace {

std::string refusal_of(const std::string& name, method_system s) {
  try {
    runs::method_named(name, s);
  } catch (const runs::bad_input& e) {
    return e.what();
  }
  return "";
}

// The names in a refusal's list: "(SYSTEM: A, B, …; X a rotor: …)".
std::set<std::string> listed_in(const std::string& message, method_system s) {
  const std::string head = "(" + runs::system_name(s) + ": ";
  const auto from = message.find(head);
  BOOST_REQUIRE(from != std::string::npos);
  const auto begin = from + head.size();
  const auto end = message.find_first_of(";)", begin);
  std::set<std::string> names;
  std::string list = message.substr(begin, end - begin);
  for (std::size_t at = 0; at <= list.size();) {
    const auto comma = list.find(", ", at);
    names.insert(list.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (comma == std::string::npos) break;
    at = comma + 2;
  }
  return names;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(method_registry_test)

BOOST_AUTO_TEST_CASE(every_listed_name_parses_for_each_system_it_claims_and_no_other) {
  const std::vector<models::vec3<double>> two_bodies = {{1, 2, 2.5}, {0.5, 0.7, 1}};
  for (const auto& f : runs::method_families()) {
    BOOST_TEST(!f.description.empty(), f.name);
    BOOST_TEST(f.description.find('\n') == std::string::npos, f.name);
    BOOST_TEST(!f.systems.empty(), f.name);
    std::vector<std::string> typed;
    if (f.kind == runs::method_kind::adaptive) {
      typed = {f.name, f.name + ":1e-9"};
    } else {
      typed = {f.name};
      if (f.takes_rotor) typed.insert(typed.end(), {f.name + "/exact", f.name + "/sej4", f.name + "/ABCBA2:BAC"});
    }
    for (auto s : runs::method_systems())
      for (const auto& name : typed) {
        if (!f.steps(s)) {
          BOOST_TEST(!refusal_of(name, s).empty(), name << " in " << runs::system_name(s));
          continue;
        }
        const auto m = s == method_system::binary ? runs::method_named(name, s, two_bodies) : runs::method_named(name, s);
        BOOST_TEST(m.family == &f, name);
        BOOST_TEST(m.name == name);
        if (m.splitting_method()) {
          BOOST_TEST(m.splitting.tv_table == f.tv_table, name);
          BOOST_TEST(m.splitting.f == f.force_evaluations(), name);
          BOOST_TEST(m.splitting.f >= 1, name);
        }
        if (name.ends_with("/ABCBA2:BAC") && s == method_system::binary) {
          BOOST_TEST(m.rotors.size() == 2u);  // one table for each body
          BOOST_TEST((m.rotor_table(0) && m.rotor_table(1)), name);
        }
        if (name.ends_with(":1e-9")) BOOST_TEST(m.tolerance == 1e-9);
        if (name == f.name && m.adaptive()) BOOST_TEST(m.tolerance == runs::default_tolerance(s));
      }
  }
}

BOOST_AUTO_TEST_CASE(each_systems_refusal_lists_exactly_its_names) {
  for (auto s : runs::method_systems()) {
    std::set<std::string> expected;
    for (const auto& f : runs::method_families())
      if (f.steps(s))
        for (const auto& form : f.forms()) expected.insert(form);
    const auto why = refusal_of("VERLET", s);
    BOOST_TEST(why.find("unknown integrator 'VERLET'") != std::string::npos, why);
    BOOST_TEST(why.find('\n') == std::string::npos);
    BOOST_TEST((listed_in(why, s) == expected), why);
    BOOST_TEST(runs::method_names_text(s).find(runs::rotor_values_text()) != std::string::npos);
  }
  // binary lists its own families, md does not
  BOOST_TEST(listed_in(refusal_of("VERLET", method_system::binary), method_system::binary).count("KEPLER4") == 1u);
  BOOST_TEST(listed_in(refusal_of("VERLET", method_system::md), method_system::md).count("KEPLER4") == 0u);
  BOOST_TEST(listed_in(refusal_of("VERLET", method_system::md), method_system::md).count("odeint-rkf78[:TOL]") == 0u);
}

BOOST_AUTO_TEST_CASE(malformed_names_are_refused_in_one_line) {
  for (auto s : runs::method_systems())
    for (const char* bad : {"SIER3", "sier2", "", "SIER2/", "SIER4/a b", "MRDL/ABCBA2", "MRDL-lammps", "MRDL-Reversed", "MRDL-", "RK4/exact",
                            "odeint-rkf78x", "odeint-rkf78:", "odeint-rkf78:0", "odeint-dopri5:1", "odeint-rkf78:1e-30"}) {
      const auto why = refusal_of(bad, s);
      BOOST_TEST(!why.empty(), bad);
      BOOST_TEST(why.find('\n') == std::string::npos, why);
    }
  BOOST_TEST(refusal_of("SIER2/", method_system::md).find("needs a scheme table name") != std::string::npos);
  BOOST_TEST(refusal_of("SIER2\x01", method_system::md).find("\\x01") != std::string::npos);
  // the tolerance's floor is that of the widest scalar the system runs Odeint in
  BOOST_TEST(refusal_of("odeint-rkf78:1e-17", method_system::spin).empty());
  BOOST_TEST(!refusal_of("odeint-rkf78:1e-17", method_system::binary).empty());
}

BOOST_AUTO_TEST_CASE(the_numeric_tests_splittings_are_the_registrys) {
  for (const auto& spec : test::md_splittings()) {
    const auto m = runs::method_named(spec.name, method_system::md);
    BOOST_TEST(m.splitting.tv_table == spec.tv_table, spec.name);
    BOOST_TEST(m.splitting.rotor == spec.rotor, spec.name);
    BOOST_TEST(m.splitting.rotor_table == spec.rotor_table, spec.name);
    BOOST_TEST(m.splitting.f == spec.f, spec.name);
  }
  // MRDL is DLM's order 1-2-3-2-1 (LAMMPS's NO_SQUISH map); SIER2/sej4 is SEJ4's pair
  BOOST_TEST(runs::method_named("MRDL", method_system::md).splitting.rotor_table == "ABCBA2:ABC");
  BOOST_TEST(runs::method_named("SIER2/sej4", method_system::md).splitting.rotor == "sej4");
  BOOST_TEST(runs::method_named("SIER4/P1:BAC:5", method_system::md).splitting.rotor_table == "P1:BAC:5");  // no body: left to the caller
}

BOOST_AUTO_TEST_CASE(lammps_styles_come_from_the_registry) {
  BOOST_TEST(runs::lammps_style_family("rigid/sier2/small")->tv_table == "Strang-TV");
  BOOST_TEST(runs::lammps_style_family("rigid/sier4/small")->tv_table == "PEFRL-TV");
  BOOST_TEST(runs::lammps_style_family("rigid/kepler4/small") == nullptr);
  BOOST_TEST(runs::lammps_style_family("rigid/small") == nullptr);
}

BOOST_AUTO_TEST_CASE(moments_reach_a_table_rotor_as_numbers_not_text) {
  // 0.4 and 0.7 in double: "%.17g" rounds each to a decimal that is not the double's value
  const models::vec3<double> I = {0.4, 0.7, 1.0};
  char text[96];
  std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g", I[0], I[1], I[2]);
  const auto from_text = runs::numeric_body(text);
  const auto exact = runs::exact_moments(I);
  BOOST_TEST(lie::inertia_text(exact) != lie::inertia_text(from_text));
  BOOST_TEST((runs::to_double(exact) == I));  // the same doubles, different numbers behind them
  const auto by_number = runs::method_named("SIER2/N2:BAC:2", method_system::binary, std::vector<models::vec3<double>>{I, I});
  const auto by_text = runs::method_named("SIER2/N2:BAC:2", method_system::binary, std::vector<lie::moments_of_inertia>{from_text, from_text});
  BOOST_REQUIRE((by_number.rotor_table(0) && by_text.rotor_table(0)));
  BOOST_TEST(by_number.rotor_table(0)->inertia != by_text.rotor_table(0)->inertia);
}

BOOST_AUTO_TEST_SUITE_END()
