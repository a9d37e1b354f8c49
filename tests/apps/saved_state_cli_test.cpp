// Saved states and output folders through the binary (issue: sweeps that can be trusted): a folder
// in use by another run is refused before anything is read or written; a saved state names what it
// belongs to and is refused, unchanged, for anything else; damaged resume files are refused in one
// line with exit status 2, never read as something they are not.
#include <boost/test/unit_test.hpp>

#include "cli_support.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

BOOST_AUTO_TEST_SUITE(saved_state_cli_test)

namespace fs = std::filesystem;
using namespace rotlie::test_cli;

namespace {

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// Holds the lock another rotlie run would hold on `folder` (flock on the folder itself).
struct held_folder {
  int fd;
  explicit held_folder(const fs::path& folder) : fd(::open(folder.c_str(), O_RDONLY | O_DIRECTORY)) {
    BOOST_REQUIRE(fd >= 0);
    BOOST_REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
  }
  ~held_folder() { ::close(fd); }
};

void refused(const run_result& r, const std::string& mention, int status = 2) {
  BOOST_TEST(r.status == status, r.err);
  BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u, r.err);
  BOOST_TEST(r.err.find(mention) != std::string::npos, "should mention '" << mention << "': " << r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

// Whether some process holds the flock of `folder`, read from /proc/locks (taking the lock to find out
// would make the run being watched find its folder busy).
bool folder_is_locked(const fs::path& folder) {
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) return false;
  std::ifstream locks("/proc/locks");
  const std::string inode = ":" + std::to_string(st.st_ino);
  for (std::string line; std::getline(locks, line);) {
    std::istringstream words(line);
    std::string n, kind, advisory, mode, pid, where;
    words >> n >> kind >> advisory >> mode >> pid >> where;
    if (kind == "FLOCK" && where.size() > inode.size() && where.compare(where.size() - inode.size(), inode.size(), inode) == 0)
      return true;
  }
  return false;
}

// Waits (at most a minute) until the background run holds the folder.
bool locked_by(background_run& other, const fs::path& folder) {
  for (int i = 0; i < 600; ++i) {
    if (folder_is_locked(folder)) return true;
    if (!other.running()) return false;
    ::usleep(100000);
  }
  return false;
}

const std::string sixth_word = "sixth --words ABABABACABCBACABABABA:BCA --starts 200 --best 1 --json ";  // 4 roots for water

}  // namespace

// A busy folder is a failed run (exit 1), as for `rotlie report`: the same command succeeds later.
BOOST_AUTO_TEST_CASE(a_folder_in_use_by_another_run_is_refused_and_left_as_it_is) {
  const fs::path dir = scratch() / "busy";
  fs::create_directories(dir);
  write(dir / "map-N.jsonl", "kept\n");
  {
    held_folder other(dir);
    refused(run("map --family N --grid 4 --resume --out " + dir.string()), "another rotlie run is using the folder", 1);
    refused(run(sixth_word + "--inertia water --out " + dir.string()), "another rotlie run is using the folder", 1);
    refused(run("md --scene liquid-water --integrator SIER2 --h 1 --molecules 400 --state " + (dir / "s.state").string()),
            "another rotlie run is using the folder", 1);
  }
  BOOST_TEST(contents(dir / "map-N.jsonl") == "kept\n");
  BOOST_TEST(!fs::exists(dir / "scan-state.txt"));
  BOOST_TEST(!fs::exists(dir / "s.state"));
}

// The same with two real runs at once (the campaign's two `map --resume` runs once left 661 lines for 380
// bodies): while one run works in the folder, the second is refused in one line and writes nothing there.
BOOST_AUTO_TEST_CASE(a_second_real_run_into_a_working_folder_is_refused) {
  const fs::path maps = scratch() / "working-map", scans = scratch() / "working-sixth", md = scratch() / "working-md";
  for (const auto& d : {maps, scans, md}) fs::create_directories(d);
  {
    background_run first("map --family N --grid 80 --out " + maps.string());  // about a minute of work
    BOOST_REQUIRE(locked_by(first, maps));
    refused(run("map --family N --grid 80 --resume --out " + maps.string()), "another rotlie run is using the folder", 1);
    first.stop();
    // what the first run wrote is one line per body: the second added nothing
    std::set<std::string> places;
    std::size_t lines = 0;
    std::istringstream text(contents(maps / "map-N.jsonl"));
    for (std::string line; std::getline(text, line); ++lines)
      if (line.rfind("{\"s\"", 0) == 0) places.insert(line.substr(0, line.find(",\"I\"")));
    BOOST_TEST(places.size() + 1 == lines);
  }
  {
    background_run first("sixth --inertia water --all --out " + scans.string());  // a scan of every word: long
    BOOST_REQUIRE(locked_by(first, scans));
    refused(run(sixth_word + "--inertia water --out " + scans.string()), "another rotlie run is using the folder", 1);
  }
  {
    // an equilibration of 4,000 molecules: many minutes before its state is written
    background_run first("md --scene liquid-water --integrator MRDL --h 2 --T 0.02 --runs 1 --molecules 4000 --state " +
                         (md / "s.state").string());
    BOOST_REQUIRE(locked_by(first, md));
    refused(run("md --scene liquid-water --integrator MRDL --h 2 --T 0.02 --runs 1 --molecules 4000 --state " +
                (md / "s.state").string()),
            "another rotlie run is using the folder", 1);
    first.stop();
    BOOST_TEST(!fs::exists(md / "s.state"));
  }
}

// Each process writes its own temporary: a leftover of the name every run once shared (a folder here,
// so that writing to it fails) does not stop a scan, and is left alone.
BOOST_AUTO_TEST_CASE(a_leftover_temporary_of_another_run_is_not_this_runs) {
  const fs::path dir = scratch() / "sixth-leftover";
  fs::create_directories(dir / "scan-state.txt.part");
  const auto r = run(sixth_word + "--inertia water --out " + dir.string());
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(fs::exists(dir / "scan-state.txt"));
  BOOST_TEST(fs::is_directory(dir / "scan-state.txt.part"));
}

// A path in a message is quoted once (map file errors once printed ''path'').
BOOST_AUTO_TEST_CASE(a_map_file_that_cannot_be_opened_is_named_once_in_quotes) {
  const fs::path dir = scratch() / "map-is-a-folder";
  fs::create_directories(dir / "map-N.jsonl");
  const auto r = run("map --family N --grid 4 --resume --out " + dir.string());
  refused(r, "cannot open '" + (dir / "map-N.jsonl").string() + "': ", 1);
  BOOST_TEST(r.err.find("''") == std::string::npos, r.err);
}

BOOST_AUTO_TEST_CASE(a_sixth_scan_state_of_another_body_is_refused_unchanged) {
  const fs::path dir = scratch() / "sixth";
  const auto first = run(sixth_word + "--inertia water --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(first.status == 0, first.err);
  const auto state = contents(dir / "scan-state.txt");
  BOOST_TEST(state.rfind("problem inertia ", 0) == 0u, state.substr(0, 80));
  const auto tables = std::distance(fs::directory_iterator(dir), fs::directory_iterator());
  refused(run(sixth_word + "--inertia 1,2,5/2 --out " + dir.string()), "is the scan of inertia");
  BOOST_TEST(contents(dir / "scan-state.txt") == state);
  BOOST_TEST(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == tables);
  // the same body continues it
  const auto again = run(sixth_word + "--inertia water --out " + dir.string());
  BOOST_TEST(again.status == 0, again.err);
}

BOOST_AUTO_TEST_CASE(a_damaged_sixth_state_is_refused_in_one_line) {
  const fs::path dir = scratch() / "sixth-damaged";
  const auto first = run(sixth_word + "--inertia water --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(first.status == 0, first.err);
  const auto good = contents(dir / "scan-state.txt");
  const auto root = good.find("\nroot ");
  BOOST_REQUIRE(root != std::string::npos);
  const auto root_end = good.find('\n', root + 1);
  const std::string before = good.substr(0, root + 1), after = good.substr(root_end);
  for (const auto& [line, mention] : std::vector<std::pair<std::string, std::string>>{
           {"root 1 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9", "is not"},  // 9 values: once a crash
           {"root 1 0.1", "is not"},                                   // too few: once "please report"
           {"root 1 1e300 1e300 1e300 1e300 1e300 1e300 1e300 1e300 1e300 1e300", "is not"},  // once -nan, exit 0
       }) {
    write(dir / "scan-state.txt", before + line + after);
    refused(run(sixth_word + "--inertia water --out " + dir.string()), mention);
  }
  write(dir / "scan-state.txt", good.substr(good.find('\n') + 1));  // the state without its problem line
  refused(run(sixth_word + "--inertia water --out " + dir.string()), "names no problem");
}

BOOST_AUTO_TEST_CASE(a_damaged_map_file_is_refused_in_one_line_and_left_as_it_is) {
  const fs::path dir = scratch() / "map-damaged";
  const auto first = run("map --family N --grid 4 --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(first.status == 0, first.err);
  const auto good = contents(dir / "map-N.jsonl");
  const auto header_end = good.find('\n');
  const std::string header = good.substr(0, header_end + 1), body = good.substr(header_end + 1);
  std::string grid_20_9 = header;
  grid_20_9.replace(grid_20_9.find("\"grid\":4"), 8, "\"grid\":4.9");
  std::string grid_wrapped = header;
  grid_wrapped.replace(grid_wrapped.find("\"grid\":4"), 8, "\"grid\":4294967300");
  std::string family_number = header;
  family_number.replace(family_number.find("\"family\":\"N\""), 12, "\"family\":5");
  const std::string no_result = "{\"s\":\"1/4\",\"t\":\"0\",\"family\":\"N\"}\n";
  for (const auto& [text, mention] : std::vector<std::pair<std::string, std::string>>{
           {grid_20_9 + body, "is not a rotlie map file"},
           {grid_wrapped + body, "at --grid 4294967300"},
           {family_number + body, "is not a rotlie map file"},
           {header + no_result, "holds no result"},
       }) {
    write(dir / "map-N.jsonl", text);
    refused(run("map --family N --grid 4 --resume --out " + dir.string()), mention);
    BOOST_TEST(contents(dir / "map-N.jsonl") == text);
  }
  refused(run("map --family N --grid 1 --json"), "--grid");
}

BOOST_AUTO_TEST_SUITE_END()  // saved_state_cli_test
