// Bad input at the command line, subcommand by subcommand: each case is run on the built binary
// and must give exactly the status the interface promises (2 for bad arguments, 1 for a failed
// run such as a write error), one line on stderr that starts with "rotlie: error: " and names
// what was wrong, nothing on stdout, and no crash or library text.
#include <boost/test/unit_test.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

// Named, not anonymous: the folder's test files share one unity source.
namespace bad_input_support {

constexpr int usage = 2;    // bad arguments
constexpr int failure = 1;  // the run failed

struct bad_input {
  std::vector<std::string> args;  ///< "@DIR@" stands for the scratch folder
  int status;
  std::string mention;  ///< the message must contain this, so that it says what was wrong
};

fs::path scratch() {
  static const fs::path dir = fs::temp_directory_path() / ("rotlie-bad-input-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string with_dir(std::string s) {
  for (auto at = s.find("@DIR@"); at != std::string::npos; at = s.find("@DIR@"))
    s.replace(at, 5, scratch().string());
  return s;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct run_result {
  int status = -1;  ///< exit status, or 128 + signal
  std::string out, err;
};

constexpr int closed_stdout = -2;

// fork and exec without a shell, so that every byte of an argument reaches rotlie as written;
// `stdout_fd` replaces standard output when not negative, or closes it (closed_stdout).
run_result run(const std::vector<std::string>& args, int stdout_fd = -1) {
  const fs::path out = scratch() / "stdout", err = scratch() / "stderr";
  std::vector<std::string> argv_text{ROTLIE_BINARY};
  for (const auto& a : args) argv_text.push_back(with_dir(a));
  std::vector<char*> argv;
  for (auto& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open("/dev/null", O_RDONLY);
    const int o = stdout_fd >= 0 ? stdout_fd : ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);  // fd 3 or above
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(in, 0);
    ::dup2(o, 1);
    ::dup2(e, 2);
    if (stdout_fd == closed_stdout) ::close(1);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  run_result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  r.out = stdout_fd == -1 ? slurp(out) : "";
  r.err = slurp(err);
  return r;
}

std::string shown(const std::vector<std::string>& args) {
  std::string s = "rotlie";
  for (const auto& a : args) s += " '" + with_dir(a) + "'";
  return s;
}

// The promise every bad input gets, whatever the subcommand.
void check_one_line_error(const run_result& r, int status, const std::string& mention) {
  BOOST_TEST(r.status == status);
  BOOST_TEST(r.out.empty());
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(r.err.back() == '\n');
  BOOST_TEST(r.err.rfind("rotlie: error: ", 0) == 0u);
  BOOST_TEST(r.err.find(with_dir(mention)) != std::string::npos, "should mention '" << with_dir(mention) << "'");
  for (const char* banned : {"terminate called", "Assertion", "boost::", "cln", "CLN", "GiNaC", "basic_string", "std::",
                             "filesystem error", "what():", "At Most", "required TEXT", "The following argument"})
    BOOST_TEST(r.err.find(banned) == std::string::npos, "library or crash text '" << banned << "'");
}

// A hand-written ABC leapfrog table (Σ per part = 1, a palindrome) with an `inertia` line, the
// body a dedicated table would name; `line_end` lets a case write CRLF.
std::string table_text(const std::string& inertia, const std::string& line_end = "\n") {
  const std::vector<std::string> lines = {
      "format_version 1", "name test:ABCBA", "split ABC", "word ABCBA", "permutation ABC", "order 2",
      "symmetric true", inertia.empty() ? "# no body" : "inertia " + inertia, "stages 5", "stage A a1 0.5",
      "stage B b1 0.5", "stage C c1 1", "stage B b1 0.5", "stage A a1 0.5"};
  std::string s;
  for (const auto& l : lines) s += l + line_end;
  return s;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Files the table below refers to, made once.
void make_files() {
  static bool made = false;
  if (made) return;
  made = true;
  const auto d = scratch();
  write(d / "a-file", "x");
  write(d / "empty.scheme", "");
  write(d / "binary.scheme", std::string("format_version 1\n\x01\x02\0\xff", 21));
  const auto good = table_text("1/4 1/2 1/2");
  write(d / "truncated.scheme", good.substr(0, good.find("stage B")));
  write(d / "unsummed.scheme", table_text("1/4 1/2 1/2").replace(good.find("C c1 1"), 6, "C c1 2"));
  write(d / "other-body.scheme", table_text("1 2 2"));
  write(d / "garbled-body.scheme", table_text("one two three"));
  write(d / "version-2.scheme", "format_version 2\n");
  fs::create_directories(d / "folder.scheme");
  std::string big(2 << 20, '#');
  write(d / "huge.scheme", big);
  // shape models: an open one, a tetrahedron turned inside out, one naming vertex 9 of 4, one of quadrilaterals
  const std::string tetra_vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  write(d / "open.obj", "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                        "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\n");  // an octahedron less a facet
  write(d / "inverted.obj", tetra_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  write(d / "out-of-range.obj", tetra_vertices + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 9\n");
  write(d / "quads.obj", tetra_vertices + "f 1 3 2 4\n");
  // a state falling almost straight at the primary (its pericentre inside both bodies)
  const std::string aligned = R"("Q1": [[1,0,0],[0,1,0],[0,0,1]], "Q2": [[1,0,0],[0,1,0],[0,0,1]], "omega1": [0,0,0], "omega2": [0,0,0])";
  write(d / "falling.json", R"({"r": [1.2, 0, 0], "v": [-1e-4, 1e-6, 0], )" + aligned + "}");
  write(d / "not-rotation.json", R"({"r": [1.2, 0, 0], "v": [0, 1e-4, 0], "Q1": [[1,0,0],[0,1,0],[0,0,2]], "Q2": [[1,0,0],[0,1,0],[0,0,1]], "omega1": [0,0,0], "omega2": [0,0,0]})");
  write(d / "nan.json", R"({"r": [1.2, 0, 0], "v": [0, NaN, 0], )" + aligned + "}");
  // a sweep's results file that is a link to nothing
  write(d / "runs.jsonl", R"({"system": "didymos", "integrator": "SIER2", "h": 10, "T": 100})" "\n");
  fs::create_symlink(d / "nowhere.jsonl", d / "dangling.jsonl");
  // a map folder whose map file is a link to nothing
  fs::create_directories(d / "dangling-maps");
  fs::create_symlink(d / "nowhere-map.jsonl", d / "dangling-maps" / "map-N.jsonl");
}

// clang-format off
const std::vector<bad_input> cases = {
  // no or unknown subcommand
  {{}, usage, "subcommand"},
  {{"frobnicate"}, usage, "unknown subcommand 'frobnicate'"},
  {{"--bogus"}, usage, "unknown option --bogus before the subcommand"},
  {{"--json", "dims", "--max-order", "3"}, usage, "unknown option --json before the subcommand"},
  {{"DIMS", "--max-order", "3"}, usage, "unknown subcommand 'DIMS'"},

  // dims
  {{"dims"}, usage, "--max-order is required"},
  {{"dims", "--max-order"}, usage, "--max-order needs a value"},
  {{"dims", "--max-order", ""}, usage, "--max-order must not be empty"},
  {{"dims", "--max-order", "0"}, usage, "--max-order must be at least 1"},
  {{"dims", "--max-order", "201"}, usage, "--max-order must be at most 200"},
  {{"dims", "--max-order", "99999999999999999999"}, usage, "--max-order must be at most"},
  {{"dims", "--max-order", "-99999999999999999999"}, usage, "--max-order must be at least"},
  {{"dims", "--max-order", "1e3"}, usage, "not an integer"},
  {{"dims", "--max-order", "0x10"}, usage, "not an integer"},
  {{"dims", "--max-order", "nan"}, usage, "not an integer"},
  {{"dims", "--max-order", "5", "--max-order", "6"}, usage, "--max-order is given more than once"},
  {{"bch", "--series", "XY", "--degree", "0"}, usage, "--degree must be at least 1"},
  {{"bch", "--series", "XY", "--degree", "-3"}, usage, "--degree must be at least 1"},
  {{"bch", "--series", "XY", "--degree", "21"}, usage, "--degree must be at most 20"},
  {{"bch", "--series", "XYZ", "--degree", "15"}, usage, "--degree must be at most 14"},
  {{"bch", "--series", "SYM", "--degree", "99999999999999999999"}, usage, "--degree must be at most"},
  {{"bch", "--series", "XY", "--degree", "1e3"}, usage, "not an integer"},
  {{"bch", "--series", "XYW", "--degree", "3"}, usage, "unknown series 'XYW'"},
  {{"bch", "--series", "XY"}, usage, "--degree is required"},
  {{"bch", "--series", "XY", "--degree", "3", "--threads", "0"}, usage, "--threads must be at least 1"},
  {{"dims", "--max-order", "5", "--json", "--json"}, usage, "--json is given more than once"},
  {{"dims", "--max-order", "5", "--bogus"}, usage, "unknown option --bogus"},
  {{"dims", "--max-order", "5", "--json=maybe"}, usage, "--json takes no value, got 'maybe'"},
  {{"dims", "--max-order", "\xd9\xa5"}, usage, "not an integer"},  // an Arabic-Indic five
  {{"dims", "--max-order", "5", "extra"}, usage, "unexpected argument extra"},

  // stages
  {{"stages"}, usage, "--max-order is required"},
  {{"stages", "--max-order", "41"}, usage, "--max-order must be at most 40"},
  {{"stages", "--max-order", "-1"}, usage, "--max-order must be at least 1"},
  {{"stages", "--max-order", "2.5"}, usage, "not an integer"},
  {{"stages", "--max-order", " "}, usage, "not an integer"},
  {{"stages", "--max-order", "5", "--exact"}, usage, "unknown option --exact"},
  {{"stages", "--max-order", "5", "--json", "--json"}, usage, "--json is given more than once"},

  // remainder: words (the limits are enforced here, before any algebra)
  {{"remainder"}, usage, "--scheme is required"},
  {{"remainder", "--scheme", ""}, usage, "--scheme must not be empty"},
  {{"remainder", "--scheme", "ABA"}, usage, "part C never acts"},
  {{"remainder", "--scheme", "ABA", "--split", "ABC"}, usage, "part C never acts"},
  {{"remainder", "--scheme", "RRR"}, usage, "part S never acts"},
  {{"remainder", "--scheme", std::string(100, 'A') + "B" + std::string(98, 'A') + "C"}, usage, "200 letters, at most 40"},
  {{"remainder", "--scheme", "ABC" + std::string(38, 'A')}, usage, "41 letters, at most 40"},
  {{"remainder", "--scheme", "ABCABCABCABCABCA"}, usage, "leaves 13 free coefficients at --order 5, at most 10"},
  {{"remainder", "--scheme", "ABCABCA", "--order", "9"}, usage, "leaves 4 free coefficients at --order 9, at most 3"},
  {{"remainder", "--scheme", "RSRSRSRSR", "--order", "9"}, usage, "leaves 3 free coefficients at --order 9, at most 1"},
  {{"remainder", "--scheme", "ABD"}, usage, "'D'"},
  {{"remainder", "--scheme", "AB\nC"}, usage, "\\x0A"},
  {{"remainder", "--scheme", "N9"}, usage, "unknown scheme name 'N9'"},
  {{"remainder", "--scheme", "P16"}, usage, "unknown scheme name 'P16'"},
  {{"remainder", "--scheme", "N4", "--scheme", "N3"}, usage, "--scheme is given more than once"},
  {{"remainder", "--scheme", "N4", "--order", "50"}, usage, "--order must be at most 9"},
  {{"remainder", "--scheme", "N4", "--order", "0"}, usage, "--order must be at least 1"},
  {{"remainder", "--scheme", "N4", "--order", "99999999999999999999"}, usage, "--order must be at most"},
  {{"remainder", "--scheme", "N4", "--split", ""}, usage, "--split must not be empty"},
  {{"remainder", "--scheme", "N4", "--split", "AB"}, usage, "--split must be ABC or RS"},
  {{"remainder", "--scheme", "N4", "--split", "RS"}, usage, "ABC scheme"},
  {{"remainder", "--scheme", "N4", "--perm", ""}, usage, "--perm must not be empty"},
  {{"remainder", "--scheme", "N4", "--perm", "abc"}, usage, "unknown permutation"},
  {{"remainder", "--scheme", "N4", "--coeffs", ""}, usage, "--coeffs must not be empty"},
  {{"remainder", "--scheme", "N4", "--coeffs", "a1=1e999"}, usage, "out of range"},
  {{"remainder", "--scheme", "N4", "--coeffs", "a1=1/0"}, usage, "a1"},
  {{"remainder", "--scheme", "N4", "--coeffs", "a1=inf"}, usage, "not a finite number"},
  {{"remainder", "--scheme", "N4", "--coeffs", "a1=1,"}, usage, "name=value"},
  {{"remainder", "--scheme", "N4", "--coeffs", "c9=1"}, usage, "c9"},
  {{"remainder", "--scheme", "N4", "--inertia", ""}, usage, "--inertia must not be empty"},
  {{"remainder", "--scheme", "N4", "--inertia", "1e500,1,1"}, usage, "I1 = '1e500' is out of range"},
  {{"remainder", "--scheme", "N4", "--inertia", "1,1,1,1"}, usage, "--inertia"},
  {{"remainder", "--scheme", "N4", "--inertia", "1,,1"}, usage, "I2"},
  {{"remainder", "--scheme", "N4", "--inertia", "1,2,4"}, usage, "triangle inequality"},
  {{"remainder", "--scheme", "N4", "--inertia", "1,0,1"}, usage, "not positive"},
  {{"remainder", "--scheme", "N4", "--latex", "--json"}, usage, "exclude"},

  // solve (every case fails before any solving)
  {{"solve"}, usage, "--family is required"},
  {{"solve", "--family", ""}, usage, "--family must not be empty"},
  {{"solve", "--family", "X", "--inertia", "water"}, usage, "--family must be N, R, P, Q or QRS"},
  {{"solve", "--family", "Q", "--inertia", "water", "--starts", "0"}, usage, "--starts"},
  {{"solve", "--family", "QRS", "--inertia", "water", "--starts", "1e9"}, usage, "--starts"},
  {{"solve", "--family", "Q", "--inertia", "water", "--seed", "-1"}, usage, "--seed"},
  {{"solve", "--family", "Q", "--scheme", "ABABACABABA", "--inertia", "water"}, usage, "not a word of the Q family"},
  {{"solve", "--family", "QRS", "--perm", "ABCD", "--inertia", "water"}, usage, "--perm"},
  {{"solve", "--family", "Q", "--scheme", "ABACBABABCABA"}, usage, "--inertia is required"},
  {{"solve", "--family", "Q", "--inertia", "1,1,3"}, usage, "--inertia"},
  {{"solve", "--family", "N", "--scheme", "", "--inertia", "water"}, usage, "--scheme must not be empty"},
  {{"solve", "--family", "N", "--scheme", "N8", "--inertia", "water"}, usage, "not in the N family"},
  {{"solve", "--family", "N", "--perm", "", "--inertia", "water"}, usage, "--perm must not be empty"},
  {{"solve", "--family", "N", "--perm", "ABCD", "--inertia", "water"}, usage, "--perm"},
  {{"solve", "--family", "N", "--inertia", "1e999,1,1"}, usage, "--inertia"},
  {{"solve", "--family", "N", "--inertia", "inf,1,1"}, usage, "not a finite number"},
  {{"solve", "--family", "N", "--inertia", "-1,1,1"}, usage, "not positive"},
  {{"solve", "--family", "N", "--inertia", "1,2,4"}, usage, "triangle inequality"},
  {{"solve", "--family", "N", "--inertia", "water", "--digits", "1e3"}, usage, "--digits"},
  {{"solve", "--family", "N", "--inertia", "water", "--digits", "9"}, usage, "--digits must be at least 10"},
  {{"solve", "--family", "N", "--inertia", "water", "--digits", "99999999999999999999"}, usage, "--digits must be at most"},
  {{"solve", "--family", "N", "--inertia", "water", "--out", ""}, usage, "--out must not be empty"},
  {{"solve", "--family", "N", "--inertia", "water", "--out", "@DIR@/a-file"}, usage, "'@DIR@/a-file' exists and is not a folder"},
  {{"solve", "--family", "N", "--inertia", "water", "--out", "@DIR@/a-file/sub"}, usage, "'@DIR@/a-file' is a file"},
  {{"solve", "--family", "N", "--inertia", "water", "--out", "/proc/rotlie-no-such-folder"}, usage, "cannot create '/proc/rotlie-no-such-folder'"},
  {{"solve", "--family", "N", "--inertia", "water", "--json", "--json"}, usage, "--json is given more than once"},
  {{"solve", "--family", "N", "--inertia", "water", "--out", "/dev/null/x"}, usage, "'/dev/null' is a file"},
  {{"solve", "--family", "n", "--inertia", "water"}, usage, "--family must be N, R, P, Q or QRS"},
  {{"solve", "--family", "R", "--perm", "ABC", "--inertia", "1/2,1/2,1"}, usage, "undefined for this body"},

  // integrate: numbers
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water"}, usage, "--h is required"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", ""}, usage, "--h must not be empty"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "0"}, usage, "--h must be positive"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "-1/64"}, usage, "--h must be positive"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "nan"}, usage, "--h 'nan' is not a finite number"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1e999"}, usage, "--h '1e999' is out of range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1e-400"}, usage, "--h '1e-400' is outside the range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--h", "1/32"}, usage, "--h is given more than once"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--T", "1e400"}, usage, "--T '1e400' is outside the range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--T", "0.3"}, usage, "whole number of steps"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1e-9", "--T", "1000"}, usage, "over the limit"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "1e999,1,1"}, usage, "g1 = '1e999' is out of range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "1e300,1,1"}, usage, "g1 = '1e300' is outside the range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "1,1e-200,0"}, usage, "g2 = 1e-200 is below"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "0,0,0"}, usage, "--G0 must not be zero"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "1,1"}, usage, "three components"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "1,1,1,"}, usage, "three components"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--G0", "1,x,1"}, usage, "g2 = 'x' is not a number"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "1e500,1,1", "--h", "1/64"}, usage, "I1 = '1e500' is out of range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "1e300,1e300,1e300", "--h", "1/64"}, usage, "is outside the range"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "1e-150,1e-150,1e-150", "--h", "1/64", "--G0", "1e150,0,1"}, usage, "angular rate"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "nan,1,1", "--h", "1/64"}, usage, "not a finite number"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "", "--h", "1/64"}, usage, "--inertia must not be empty"},
  // integrate: schemes and scheme-table files
  {{"integrate", "--scheme", "", "--inertia", "water", "--h", "1/64"}, usage, "--scheme must not be empty"},
  {{"integrate", "--scheme", "FOO", "--inertia", "water", "--h", "1/64"}, usage, "unknown scheme 'FOO'"},
  {{"integrate", "--scheme", "ABCBA2:XYZ", "--inertia", "water", "--h", "1/64"}, usage, "unknown permutation 'XYZ'"},
  {{"integrate", "--scheme", "N2:XYZ:2", "--inertia", "water", "--h", "1/64"}, usage, "unknown permutation 'XYZ'"},
  {{"integrate", "--scheme", "N9:BAC:1", "--inertia", "water", "--h", "1/64"}, usage, "unknown dedicated scheme 'N9'"},
  {{"integrate", "--scheme", "N2:BAC:", "--inertia", "water", "--h", "1/64"}, usage, "--scheme label"},
  {{"integrate", "--scheme", "N2::2", "--inertia", "water", "--h", "1/64"}, usage, "unknown permutation ''"},
  {{"integrate", "--scheme", "N2:BAC:2:extra", "--inertia", "water", "--h", "1/64"}, usage, "--scheme label"},
  {{"integrate", "--scheme", "ABCBA2:ABC:1", "--inertia", "water", "--h", "1/64"}, usage, "unknown permutation"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/-64"}, usage, "--h must be positive"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "0x1p-6"}, usage, "--h must be a number"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64/2"}, usage, "--h must be a number"},
  {{"integrate", "--scheme", "N2:BAC:0", "--inertia", "water", "--h", "1/64"}, usage, "--scheme label must be at least 1"},
  {{"integrate", "--scheme", "N2:BAC:9", "--inertia", "water", "--h", "1/64"}, usage, "no label 9"},
  {{"integrate", "--scheme", "R:ABC:1", "--inertia", "1/2,1/2,1", "--h", "1/64"}, usage, "0 real solutions"},
  {{"integrate", "--scheme", "@DIR@", "--inertia", "water", "--h", "1/64"}, usage, "is a folder"},
  {{"integrate", "--scheme", "@DIR@/folder.scheme", "--inertia", "water", "--h", "1/64"}, usage, "is a folder"},
  {{"integrate", "--scheme", "/dev/null", "--inertia", "water", "--h", "1/64"}, usage, "'/dev/null' is not a regular file"},
  {{"integrate", "--scheme", "@DIR@/missing.scheme", "--inertia", "water", "--h", "1/64"}, usage, "no scheme-table file"},
  {{"integrate", "--scheme", "@DIR@/empty.scheme", "--inertia", "water", "--h", "1/64"}, usage, "is empty"},
  {{"integrate", "--scheme", "@DIR@/binary.scheme", "--inertia", "water", "--h", "1/64"}, usage, "binary data"},
  {{"integrate", "--scheme", "@DIR@/huge.scheme", "--inertia", "water", "--h", "1/64"}, usage, "too large"},
  {{"integrate", "--scheme", "@DIR@/truncated.scheme", "--inertia", "1,2,2", "--h", "1/64"}, usage, "truncated.scheme"},
  {{"integrate", "--scheme", "@DIR@/unsummed.scheme", "--inertia", "1,2,2", "--h", "1/64"}, usage, "not 1"},
  {{"integrate", "--scheme", "@DIR@/version-2.scheme", "--inertia", "water", "--h", "1/64"}, usage, "format_version"},
  {{"integrate", "--scheme", "@DIR@/other-body.scheme", "--inertia", "water", "--h", "1/64"}, usage, "pass --force"},
  {{"integrate", "--scheme", "@DIR@/garbled-body.scheme", "--inertia", "water", "--h", "1/64"}, usage, "inertia must be three positive numbers"},
  {{"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/64", "--force", "--force"}, usage, "--force is given more than once"},

  // map and best (every case fails before any solving; a refused map file is left as it was: map_cli_test)
  {{"map", "--grid", "4"}, usage, "--family is required"},
  {{"map", "--family", "N"}, usage, "--grid is required"},
  {{"map", "--family", "Q", "--grid", "4", "--json"}, usage, "--family must be N, R or P"},
  {{"map", "--family", "N", "--grid", "0", "--json"}, usage, "--grid must be at least 2"},
  {{"map", "--family", "N", "--grid", "-5", "--json"}, usage, "--grid must be at least 2"},
  {{"map", "--family", "N", "--grid", "1", "--json"}, usage, "--grid must be at least 2"},  // no asymmetric body: once an empty map with exit 0
  {{"map", "--family", "N", "--grid", "100000", "--json"}, usage, "--grid must be at most 2000"},
  {{"map", "--family", "N", "--grid", "99999999999999999999", "--json"}, usage, "--grid must be at most"},
  {{"map", "--family", "N", "--grid", "1e3", "--json"}, usage, "--grid"},
  {{"map", "--family", "N", "--grid", "4", "--json", "--resume"}, usage, "--resume needs --out"},
  {{"map", "--family", "N", "--grid", "4", "--out", "@DIR@/a-file"}, usage, "'@DIR@/a-file' exists and is not a folder"},
  {{"map", "--family", "N", "--grid", "4", "--out", "/proc/rotlie-no-such-folder"}, usage, "cannot create '/proc/rotlie-no-such-folder'"},
  {{"map", "--family", "N", "--grid", "4", "--out", "/dev/null/x"}, usage, "'/dev/null' is a file"},
  // the screened P path is checked at --grid 200 only: coarser grids take the exact solver
  {{"map", "--family", "P", "--grid", "5", "--fast", "--json"}, usage, "--fast: the P map's fast path is checked against the exact solver at --grid 200 and finer only"},
  // the screened path below --grid 200 (the report's default grid 8 among them) is refused at every grid
  {{"map", "--family", "P", "--grid", "3", "--fast"}, usage, "--fast: the P map's fast path is checked against the exact solver at --grid 200 and finer only"},
  {{"map", "--family", "P", "--grid", "8", "--fast"}, usage, "--fast: the P map's fast path is checked against the exact solver at --grid 200 and finer only"},
  {{"map", "--family", "P", "--grid", "10", "--fast"}, usage, "--fast: the P map's fast path is checked against the exact solver at --grid 200 and finer only"},
  {{"map", "--family", "P", "--grid", "199", "--fast"}, usage, "--fast: the P map's fast path is checked against the exact solver at --grid 200 and finer only"},
  {{"best"}, usage, "--inertia is required"},
  {{"best", "--inertia", "1,2,4"}, usage, "triangle inequality"},
  {{"best", "--inertia", "-1,1,1"}, usage, "not positive"},
  {{"best", "--inertia", "sphere"}, usage, "symmetric top"},
  {{"best", "--inertia", "1/2,3/4,3/4"}, usage, "symmetric top"},
  {{"best", "--inertia", "nan,1,1"}, usage, "--inertia"},

  // order
  {{"order", "--scheme", "ABCBA2"}, usage, "--inertia is required"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--scalar", "quad"}, usage, "--scalar must be double"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--scalar", ""}, usage, "--scalar must not be empty"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--min-level", "21"}, usage, "--min-level must be at most 20"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--min-level", "-1"}, usage, "--min-level must be at least 0"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--max-level", "99999999999999999999"}, usage, "--max-level must be at most"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--min-level", "5", "--max-level", "2"}, usage, "--max-level must be at least 5"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--T", "1e400"}, usage, "--T '1e400' is outside the range"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--T", "inf"}, usage, "--T 'inf' is not a finite number"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--G0", "1e999,1,1"}, usage, "out of range"},
  {{"order", "--scheme", "@DIR@/other-body.scheme", "--inertia", "sphere"}, usage, "pass --force"},
  {{"order", "--scheme", "ABCBA2", "--inertia", "water", "--bogus", "1"}, usage, "unknown option --bogus"},

  // exact
  {{"exact", "--inertia", "water"}, usage, "--T is required"},
  {{"exact", "--T", "1"}, usage, "--inertia is required"},
  {{"exact", "--inertia", "water", "--T", ""}, usage, "--T must not be empty"},
  {{"exact", "--inertia", "water", "--T", "-1"}, usage, "--T must be positive"},
  {{"exact", "--inertia", "water", "--T", "1e400"}, usage, "--T '1e400' is outside the range"},
  {{"exact", "--inertia", "water", "--T", "1e999"}, usage, "--T '1e999' is out of range"},
  {{"exact", "--inertia", "water", "--T", "NaN"}, usage, "not a finite number"},
  {{"exact", "--inertia", "water", "--T", "1", "--G0", "1e400,1,1"}, usage, "outside the range"},
  {{"exact", "--inertia", "water", "--T", "1", "--G0", "1e-160,0,0"}, usage, "|G0| = 1e-160 is outside the range"},
  {{"exact", "--inertia", "water", "--T", "1", "--G0", "nan,1,1"}, usage, "g1 = 'nan' is not a finite number"},
  // a limit far below 1e-6 in six significant digits (the command's own check; the library's exact-flow
  // message, once "|t| ≤ 0.000000", is checked from Python in test_errors.py)
  {{"exact", "--inertia", "water", "--T", "1", "--G0", "1e140,1e140,1e140"}, usage, "limit of 2.31578e-123 for this body"},
  {{"exact", "--inertia", "1e-100,1e-100,1e-100", "--T", "1e50", "--G0", "1,0,1"}, usage, "turns by"},
  {{"exact", "--inertia", "0.345,0.653,1", "--T", "1"}, usage, "eq. (77)"},
  {{"exact", "--inertia", "water", "--T", "1e150"}, usage, "turns by"},
  {{"exact", "--inertia", "water,1,1", "--T", "1"}, usage, "--inertia"},
  {{"exact", "--inertia", "1e400,1e400,1e400", "--T", "1"}, usage, "outside the range"},
  {{"exact", "--inertia", "water", "--T", "1", "--T", "2"}, usage, "--T is given more than once"},

  // binary
  {{"binary", "--integrator", "SIER2", "--T", "0"}, usage, "--primary and --secondary are required"},
  {{"binary", "--system", "ganymede", "--integrator", "SIER2", "--T", "0"}, usage, "no binary system is called 'ganymede'"},
  {{"binary", "--system", "didymos", "--separation", "0.4", "--integrator", "SIER2", "--T", "0"}, usage, "the bodies overlap"},
  {{"binary", "--system", "didymos", "--primary", "ellipsoid:-0.4,0.3,0.2", "--integrator", "SIER2", "--T", "0"}, usage, "--primary ellipsoid: a semi-axis must be positive"},
  {{"binary", "--system", "didymos", "--primary", "ellipsoid:0.4,0,0", "--integrator", "SIER2", "--T", "0"}, usage, "must be positive"},
  {{"binary", "--system", "didymos", "--primary", "ellipsoid:0.3,0.4,0.2", "--integrator", "SIER2", "--T", "0"}, usage, "a >= b >= c"},
  {{"binary", "--system", "didymos", "--secondary", "sphere:0.1", "--integrator", "SIER2", "--T", "0"}, usage, "neither ellipsoid:a,b,c (km), polyhedron:FILE nor gubas:VERTICES,FACETS"},
  {{"binary", "--system", "didymos", "--primary", "polyhedron:@DIR@/open.obj", "--integrator", "SIER2", "--T", "0"}, usage, "not a closed, consistently oriented surface"},
  {{"binary", "--system", "didymos", "--primary", "polyhedron:@DIR@/inverted.obj", "--integrator", "SIER2", "--T", "0"}, usage, "the facets face inward"},
  {{"binary", "--system", "didymos", "--primary", "polyhedron:@DIR@/out-of-range.obj", "--integrator", "SIER2", "--T", "0"}, usage, "names vertex 9 of 4"},
  {{"binary", "--system", "didymos", "--primary", "polyhedron:@DIR@/quads.obj", "--integrator", "SIER2", "--T", "0"}, usage, "facets must be triangles"},
  {{"binary", "--system", "didymos", "--primary", "polyhedron:@DIR@/missing.obj", "--integrator", "SIER2", "--T", "0"}, usage, "missing.obj"},
  // (--T 0 evaluates any pose, issue 46: only a run into the collision is refused)
  {{"binary", "--system", "didymos", "--state", "@DIR@/falling.json", "--integrator", "SIER2", "--h", "10", "--T", "100"}, usage, "they collide"},
  {{"binary", "--system", "didymos", "--state", "@DIR@/not-rotation.json", "--integrator", "SIER2", "--T", "0"}, usage, "\"Q1\" is not a rotation"},
  {{"binary", "--system", "didymos", "--state", "@DIR@/nan.json", "--integrator", "SIER2", "--T", "0"}, usage, "not JSON"},
  {{"binary", "--system", "didymos", "--density", "nan", "--integrator", "SIER2", "--T", "0"}, usage, "--density 'nan' is not a finite number"},
  {{"binary", "--system", "didymos", "--density", "0", "--integrator", "SIER2", "--T", "0"}, usage, "--density must be positive"},
  {{"binary", "--system", "didymos", "--mass", "5e11", "--integrator", "SIER2", "--T", "0"}, usage, "--mass takes two values"},
  {{"binary", "--system", "didymos", "--order", "17", "--integrator", "SIER2", "--T", "0"}, usage, "--order must be at most 16, got 17"},
  {{"binary", "--system", "didymos", "--integrator", "SIER3", "--T", "0"}, usage, "unknown integrator 'SIER3'"},
  {{"binary", "--system", "didymos", "--integrator", "KEPLER3", "--T", "0"}, usage, "unknown integrator 'KEPLER3' (binary: SIER2, SIER4, SIER6"},
  {{"binary", "--system", "didymos", "--integrator", "odeint-rkf78:1e-20", "--T", "0"}, usage, "the tolerance must be within"},
  {{"binary", "--system", "didymos", "--integrator", "SIER2", "--h", "0", "--T", "100"}, usage, "--h must be positive"},
  {{"binary", "--system", "didymos", "--integrator", "SIER2", "--h", "7", "--T", "100"}, usage, "is not a whole number of steps"},
  {{"binary", "--system", "didymos", "--integrator", "SIER2", "--T", "100"}, usage, "--h is required"},
  {{"binary", "--system", "didymos", "--integrator", "SIER4/NOPE", "--h", "10", "--T", "100"}, usage, "--integrator SIER4/NOPE"},

  {{"sweep", "--in", "@DIR@/runs.jsonl", "--out", "@DIR@/dangling.jsonl"}, usage, "which does not exist"},
  {{"map", "--family", "N", "--grid", "3", "--out", "@DIR@/dangling-maps"}, usage, "which does not exist"},

  // md
  {{"md", "--integrator", "SIER2", "--h", "1"}, usage, "--scene is required"},
  {{"md", "--scene", "liquid", "--integrator", "SIER2", "--h", "1"}, usage, "--scene must be free-water, dipole-field, liquid-water or spin-orbit, got 'liquid'"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--molecules", "256"}, usage, "smaller than twice the 11 Å cutoff"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "0"}, usage, "--h must be positive"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "nan"}, usage, "--h 'nan' is not a finite number"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--threads", "0"}, usage, "--threads must be at least 1"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--runs", "0"}, usage, "--runs must be at least 1"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--T", "-1"}, usage, "--T must be positive"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--equilibrate", "0"}, usage, "--equilibrate must be positive"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--equilibrate", "inf"}, usage, "--equilibrate 'inf' is not a finite number"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--equilibrate", "1e9"}, usage, "--equilibrate must span 1 to 10⁹ steps of 1 fs, from 0.001 to 1e+06 ps"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--equilibrate", "1e-6"}, usage, "--equilibrate must span 1 to 10⁹ steps"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "1", "--equilibrate", "1"}, usage, "--equilibrate applies to the liquid-water scene only"},
  // --seed is liquid-water's since it runs at a temperature (the lattice start and the noise); the thermostat's options:
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--temperature", "300"}, usage, "--temperature does not apply to the dipole-field scene"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2", "--h", "1", "--temperature", "300"}, usage, "--temperature needs an integrator at a temperature"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2-NHC", "--h", "1", "--friction", "3"}, usage, "SIER2-NHC takes --tau"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2-BAOAB", "--h", "1", "--temperature", "0"}, usage, "--temperature must be positive"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2-BAOAB", "--h", "1", "--tau", "0.1"}, usage, "SIER2-BAOAB takes --friction"},
  {{"md", "--scene", "liquid-water", "--integrator", "VERLET", "--h", "1"}, usage, "unknown integrator 'VERLET'"},
  {{"md", "--scene", "liquid-water", "--integrator", "SIER2/N9:BAC:1", "--h", "1"}, usage, "unknown dedicated scheme 'N9'"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "1", "--molecules", "512"}, usage, "--molecules applies to the liquid-water scene only"},
  {{"md", "--scene", "free-water", "--integrator", "VERLET", "--h", "1"}, usage, "unknown integrator 'VERLET'"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2/", "--h", "1"}, usage, "needs a scheme table name"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2/N9:BAC:1", "--h", "1"}, usage, "--integrator SIER2/N9:BAC:1"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2/ABCBA2:XYZ", "--h", "1"}, usage, "--integrator SIER2/ABCBA2:XYZ"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2/Strang-TV", "--h", "1", "--T", "0.01", "--runs", "1"}, usage, "the free rotation needs an ABC or RS table"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "0"}, usage, "--h must be positive"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "-1"}, usage, "--h must be positive"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "nan"}, usage, "--h 'nan' is not a finite number"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--T", "0"}, usage, "--T must be positive"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--T", "-inf"}, usage, "--T '-inf' is not a finite number"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "10", "--T", "0.001"}, usage, "--T must be at least one step"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--runs", "0"}, usage, "--runs must be at least 1"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--runs", "1.5"}, usage, "--runs: '1.5' is not an integer"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--seed", "-1"}, usage, "--seed must be at least 0"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--scalar", "half"}, usage, "--scalar must be double"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--field", "nan"}, usage, "--field 'nan' is not a finite number"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--dipole", "NaN"}, usage, "--dipole 'NaN' is not a finite number"},
  {{"md", "--scene", "dipole-field", "--integrator", "SIER2", "--h", "1", "--dipole", "0"}, usage, "--dipole must be positive"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "1", "--field", "3"}, usage, "dipole-field scene only"},
  {{"md", "--scene", "free-water", "--integrator", "SIER2", "--h", "1e-6", "--T", "1e6"}, usage, "over the limit"},

  // report (every case fails before the report starts)
  {{"report", "--out", ""}, usage, "--out must not be empty"},
  {{"report", "--out", "@DIR@/a-file"}, usage, "exists and is not a folder"},
  {{"report", "--out", "@DIR@/a-file/sub"}, usage, "cannot create"},
  {{"report", "--out", "/proc/rotlie-no-such-folder"}, usage, "cannot create"},
  {{"report", "--bogus"}, usage, "unknown option --bogus"},
  {{"report", "--out", "/dev/null"}, usage, "'/dev/null': it exists and is not a folder"},
  {{"report", "--quick=maybe"}, usage, "--quick takes no value"},
  {{"report", "--out", "a", "--out", "b"}, usage, "--out is given more than once"},
  {{"report", "--quick", "--quick"}, usage, "--quick is given more than once"},
  {{"report", "extra"}, usage, "unexpected argument extra"},
};
// clang-format on

// Run inside the scratch folder, so that a case that wrongly succeeded (a report with its
// default folder) leaves nothing outside it; removed at the end.
struct cleanup {
  cleanup() { fs::current_path(scratch()); }
  ~cleanup() {
    fs::current_path(fs::temp_directory_path());
    std::error_code ec;
    fs::remove_all(scratch(), ec);
  }
};

}  // namespace bad_input_support

// The folder's other suites share this executable: the fixture is this suite's, not global.
BOOST_AUTO_TEST_SUITE(bad_input_test, *boost::unit_test::fixture<bad_input_support::cleanup>())

using namespace bad_input_support;

BOOST_AUTO_TEST_CASE(every_bad_input_gets_one_line_and_its_status) {
  make_files();
  std::map<std::string, int> per_subcommand;
  std::set<std::vector<std::string>> distinct;
  for (const auto& c : cases) {
    const auto r = run(c.args);
    BOOST_TEST_CONTEXT(shown(c.args) << " → status " << r.status << ", stderr: " << r.err) {
      check_one_line_error(r, c.status, c.mention);
    }
    ++per_subcommand[c.args.empty() ? "(none)" : c.args[0]];
    distinct.insert(c.args);
  }
  BOOST_TEST(distinct.size() == cases.size(), "every case is distinct");
  BOOST_TEST(cases.size() >= 100u);
  for (const auto* sub : {"dims", "stages", "remainder", "solve", "integrate", "order", "exact", "report", "map", "best"})
    BOOST_TEST(per_subcommand[sub] >= 5, sub << " has " << per_subcommand[sub] << " cases");
  for (const auto& [sub, n] : per_subcommand) BOOST_TEST_MESSAGE(sub << ": " << n << " bad inputs");
}

BOOST_AUTO_TEST_CASE(probing_an_output_folder_leaves_nothing_behind) {
  // --out is checked by creating the missing folders and removing them again; the bad --digits
  // then stops the run, and the file system is as before.
  const fs::path fresh = scratch() / "fresh";
  const auto r = run({"solve", "--family", "N", "--inertia", "water", "--digits", "5", "--out", (fresh / "deeper").string()});
  check_one_line_error(r, usage, "--digits");
  BOOST_TEST(!fs::exists(fresh));
  std::size_t probes = 0;
  for (const auto& e : fs::directory_iterator(scratch())) probes += e.path().filename().string().find(".rotlie-probe") == 0;
  BOOST_TEST(probes == 0u);
}

// Root writes anywhere: /proc stands in for an unwritable place in the table above.
boost::test_tools::assertion_result not_root(boost::unit_test::test_unit_id) { return ::geteuid() != 0; }

BOOST_AUTO_TEST_CASE(a_folder_without_write_permission_is_refused, *boost::unit_test::precondition(not_root)) {
  const fs::path locked = scratch() / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  check_one_line_error(run({"report", "--out", locked.string()}), usage, "Permission denied");
  check_one_line_error(run({"solve", "--family", "N", "--inertia", "water", "--out", (locked / "sub").string()}), usage,
                       "cannot create");
  fs::permissions(locked, fs::perms::owner_all);
  const fs::path unreadable = scratch() / "unreadable.scheme";
  write(unreadable, table_text(""));
  fs::permissions(unreadable, fs::perms::none);
  check_one_line_error(run({"integrate", "--scheme", unreadable.string(), "--inertia", "water", "--h", "1/64"}), usage,
                       "cannot read '" + unreadable.string() + "': Permission denied");
}

BOOST_AUTO_TEST_CASE(a_full_disk_is_a_failure) {
  // /dev/full accepts the open and fails every write with ENOSPC.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"dims", "--max-order", "5"}, {"stages", "--max-order", "5", "--json"},
        {"remainder", "--scheme", "N4", "--order", "3"}, {"exact", "--inertia", "water", "--T", "1"},
        {"integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "1/8"}, {"--help"}}) {
    const int full = ::open("/dev/full", O_WRONLY);
    BOOST_REQUIRE(full >= 0);
    const auto r = run(args, full);
    ::close(full);
    BOOST_TEST_CONTEXT(shown(args) << " > /dev/full → status " << r.status << ", stderr: " << r.err) {
      check_one_line_error(r, failure, "cannot write to standard output: No space left on device");
    }
  }
}

BOOST_AUTO_TEST_CASE(a_closed_standard_output_is_a_failure) {
  check_one_line_error(run({"dims", "--max-order", "3"}, closed_stdout), failure,
                       "cannot write to standard output: Bad file descriptor");
  // The tables solve writes must not take the free descriptor 1: the listing, written after
  // them, would land in the last table opened if its descriptor were still in use.
  const fs::path out = scratch() / "closed-stdout-tables";
  const auto r = run({"solve", "--family", "N", "--scheme", "N4", "--perm", "BCA", "--inertia", "water", "--out", out.string()},
                     closed_stdout);
  check_one_line_error(r, failure, "cannot write to standard output");
  const auto table = slurp(out / "N4_BCA_1.scheme");
  BOOST_TEST(table.rfind("# rotlie scheme table", 0) == 0u, table.substr(0, 80));
  BOOST_TEST(table.find("rank") == std::string::npos);  // no line of the listing
}

BOOST_AUTO_TEST_CASE(a_closed_pipe_ends_the_writer_by_sigpipe) {
  // The reader has gone before anything is written: the first write raises SIGPIPE, which rotlie
  // keeps at its default even when the parent ignores it (status 128 + 13, nothing on stderr).
  for (const bool parent_ignores : {false, true}) {
    const auto previous = std::signal(SIGPIPE, parent_ignores ? SIG_IGN : SIG_DFL);
    int fds[2];
    BOOST_REQUIRE(::pipe(fds) == 0);
    ::close(fds[0]);
    const auto r = run({"dims", "--max-order", "12", "--json"}, fds[1]);
    ::close(fds[1]);
    std::signal(SIGPIPE, previous);
    BOOST_TEST(r.status == 128 + SIGPIPE, "parent ignores SIGPIPE: " << parent_ignores);
    BOOST_TEST(r.err.empty(), r.err);
  }
}

BOOST_AUTO_TEST_CASE(scheme_tables_with_crlf_or_a_scaled_body_are_accepted) {
  // The same table with LF and with CRLF line ends gives the same error figure; the body of the
  // table scaled by 7/3 is the same body (the schemes depend on moment ratios only).
  write(scratch() / "lf.scheme", table_text("1/4 1/2 1/2"));
  write(scratch() / "crlf.scheme", table_text("1/4 1/2 1/2", "\r\n"));
  const auto error_of = [](const run_result& r) {
    const auto at = r.out.find("\"error\":");
    return at == std::string::npos ? std::string("none") : r.out.substr(at, r.out.find_first_of(",\n}", at) - at);
  };
  const auto lf = run({"integrate", "--scheme", (scratch() / "lf.scheme").string(), "--inertia", "1,2,2", "--h", "1/16", "--json"});
  const auto crlf = run({"integrate", "--scheme", (scratch() / "crlf.scheme").string(), "--inertia", "1,2,2", "--h", "1/16", "--json"});
  BOOST_TEST(lf.status == 0, lf.err);
  BOOST_TEST(crlf.status == 0, crlf.err);
  BOOST_TEST(error_of(lf) != "none");
  BOOST_TEST(error_of(crlf) == error_of(lf));
  const auto scaled = run({"integrate", "--scheme", (scratch() / "lf.scheme").string(), "--inertia", "7/12,7/6,7/6", "--h", "1/16"});
  BOOST_TEST(scaled.status == 0, scaled.err);
  BOOST_TEST(scaled.err.empty(), scaled.err);
  // A reference scheme names no body and never warns.
  const auto reference = run({"integrate", "--scheme", "ABCBA2", "--inertia", "1,2,2", "--h", "1/16"});
  BOOST_TEST(reference.status == 0);
  BOOST_TEST(reference.err.empty(), reference.err);
}

BOOST_AUTO_TEST_CASE(force_uses_a_table_of_another_body_with_a_warning) {
  write(scratch() / "other.scheme", table_text("1 2 2"));
  const auto r = run({"integrate", "--scheme", (scratch() / "other.scheme").string(), "--inertia", "water", "--h", "1/16", "--force"});
  BOOST_TEST(r.status == 0, r.err);
  BOOST_TEST(!r.out.empty());
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  BOOST_TEST(r.err.rfind("rotlie: warning: ", 0) == 0u, r.err);
  BOOST_TEST(r.err.find("(1 2 2)") != std::string::npos, r.err);  // the table's body, as its inertia line gives it
}

BOOST_AUTO_TEST_SUITE_END()  // bad_input_test
