// The neighbour check through the binary, on the shipped P map at --grid 200 (data/maps-K200): a map
// whose header records the check is not checked again, and a run killed during the check leaves the
// file as it was (the check rewrites it whole, atomically, only at its end).
#include <boost/test/unit_test.hpp>

#include "skip.hpp"

#include "cli_support.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>

BOOST_AUTO_TEST_SUITE(map_neighbour_cli_test)

using namespace rotlie::test_cli;

namespace {

// The shipped map decompressed into a folder of its own; nullopt when rotlie ships none.
std::optional<fs::path> shipped_map_in(const std::string& folder) {
  if (!fs::exists(SHIPPED_P_MAP)) return std::nullopt;
  const fs::path dir = scratch() / folder;
  fs::create_directories(dir);
  const fs::path file = dir / "map-P.jsonl";
  const auto r = run_command(std::string("(xz -dc ") + SHIPPED_P_MAP + " > " + file.string() + ")");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  return file;
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_checked_map_is_not_checked_again) {
  const auto file = shipped_map_in("checked");
  if (!file) {
    rotlie::test::skip("no shipped P map (data/maps-K200)");
    return;
  }
  const auto before = slurp(*file);
  const auto r = run("map --family P --grid 200 --out " + file->parent_path().string() + " --resume");
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  BOOST_TEST(r.out.find("0 computed now") != std::string::npos);
  BOOST_TEST(r.out.find("neighbour check: ") != std::string::npos);  // the counts its header records
  BOOST_TEST(slurp(*file) == before);
}

BOOST_AUTO_TEST_CASE(a_kill_during_the_check_leaves_the_map_as_it_was) {
  const auto file = shipped_map_in("unchecked");
  if (!file) {
    rotlie::test::skip("no shipped P map (data/maps-K200)");
    return;
  }
  // The same map as an earlier rotlie wrote it: no "neighbour_check" in its header, so a resume checks it
  std::string text = slurp(*file);
  const auto end_of_header = text.find('\n');
  auto header = nlohmann::ordered_json::parse(text.substr(0, end_of_header));
  BOOST_REQUIRE(header.erase("neighbour_check") == 1u);
  text = header.dump() + text.substr(end_of_header);
  {
    std::ofstream out(*file, std::ios::binary);
    out << text;
  }
  // Reading and resuming the file takes what a run on the checked map takes (about 2 s here), then the
  // check some 15 minutes on 2 cores: killed well after the first, well inside the second
  const auto checked = shipped_map_in("timing");
  const auto start = std::chrono::steady_clock::now();
  BOOST_REQUIRE(run("map --family P --grid 200 --out " + checked->parent_path().string() + " --resume").status == 0);
  const double reading = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int after = std::max(8, static_cast<int>(4 * reading) + 2);
  const auto r = run_command("timeout -s KILL " + std::to_string(after) + " " + ROTLIE_BINARY + " map --family P --grid 200 --out " +
                             file->parent_path().string() + " --resume");
  BOOST_TEST(r.status == 137, "not killed: it ended by itself with status " << r.status << ": " << r.err);
  BOOST_TEST(slurp(*file) == text);
  BOOST_TEST(entries(file->parent_path()) == 1u);  // no temporary left beside it
}

BOOST_AUTO_TEST_SUITE_END()  // map_neighbour_cli_test
