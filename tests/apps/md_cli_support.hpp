#pragma once
// `rotlie md ARGS --json` run and its JSON parsed; the run must succeed (the md CLI tests share it).
#include <nlohmann/json.hpp>

#include <string>

#include "cli_support.hpp"

namespace rotlie::test_cli {

inline nlohmann::json md_json(const std::string& args) {
  const auto r = run("md " + args + " --json");
  BOOST_TEST_REQUIRE(r.status == 0, "rotlie md " << args << ": " << r.err);
  return nlohmann::json::parse(r.out);
}

}  // namespace rotlie::test_cli
