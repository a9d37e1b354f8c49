// SPDX-License-Identifier: GPL-2.0-or-later
// The adapter's classes have the layout of the headers it was compiled with, so it refuses a LAMMPS
// library of another version with one ERROR: line and a non-zero exit. Exercised through
// lammps_version_probe: the installed library with its version string replaced (no second LAMMPS
// build is needed), against the same library with its own string as the control.
#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "version.h"  // LAMMPS_VERSION of the headers the adapter was compiled with

BOOST_AUTO_TEST_SUITE(version_test)

namespace {

struct probe_result {
  int status;
  std::string output;
};

probe_result probe(const std::string& version) {
  const std::string cmd = std::string("OMP_NUM_THREADS=1 '") + ROTLIE_VERSION_PROBE + "' " + (version.empty() ? "" : "'" + version + "'") + " 2>&1";
  probe_result r{-1, {}};
  FILE* pipe = ::popen(cmd.c_str(), "r");
  BOOST_REQUIRE(pipe);
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  r.status = ::pclose(pipe);
  return r;
}

std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> found;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.find(prefix) != std::string::npos) found.push_back(line);
  return found;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_headers_version_is_accepted) {
  const auto r = probe("");
  BOOST_TEST(r.status == 0, r.output);
  BOOST_TEST(lines_starting(r.output, "ERROR").empty(), r.output);
  BOOST_TEST(r.output.find("registered into LAMMPS") != std::string::npos, r.output);
}

BOOST_AUTO_TEST_CASE(another_version_is_refused_in_one_line) {
  const auto r = probe("1 Jan 2000");
  const auto errors = lines_starting(r.output, "ERROR");
  BOOST_TEST_MESSAGE("a library claiming LAMMPS 1 Jan 2000 → " << (errors.empty() ? "(no error)" : errors.front()));
  BOOST_TEST(r.status != 0);
  BOOST_TEST(r.output.find("registered into LAMMPS") == std::string::npos, r.output);
  BOOST_REQUIRE_MESSAGE(errors.size() == 1u, r.output);
  BOOST_TEST(errors.front().rfind("ERROR:", 0) == 0u, errors.front());
  BOOST_TEST(errors.front().find("this is LAMMPS 1 Jan 2000") != std::string::npos, errors.front());
  BOOST_TEST(errors.front().find("built against LAMMPS " LAMMPS_VERSION) != std::string::npos, errors.front());
}

BOOST_AUTO_TEST_SUITE_END()
