// Charts with gnuplot: hostile folder names and titles run no command and still give the right
// PNG; every way gnuplot can fail is recorded with the chart's name and leaves no PNG.
#include <boost/test/unit_test.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "folder_support.hpp"
#include "rotlie/reports/chart.hpp"
#include "rotlie/reports/child_process.hpp"

BOOST_AUTO_TEST_SUITE(chart_test)

namespace fs = std::filesystem;
using namespace report_test;
using namespace rotlie::reports;

namespace {

chart sample_chart(const std::string& title = "error against h", const std::string& series = "N2 BAC") {
  chart c;
  c.title = title, c.x_label = "h", c.y_label = "error";
  chart_series s{series, {}, {}};
  for (int i = 1; i <= 8; ++i) s.x.push_back(std::ldexp(1.0, -i)), s.y.push_back(1e-3 * std::ldexp(1.0, -4 * i));  // error ∝ h^4
  c.series = {s};
  c.horizontal_line = 1e-10;
  c.horizontal_label = "threshold";
  return c;
}

// Folder names that broke out of the old `set output "<path>"` and `sh -c` quoting; each one's
// injected command would create `marker` (absolute) or MARKER (relative to the working folder).
std::vector<std::string> hostile_names(const fs::path& marker) {
  const std::string m = marker.string();
  return {"bq`touch " + m + "`",
          "dollar$(touch " + m + ")",
          "dq\"; system('touch " + m + "'); \"",
          "sq'; system(\"touch " + m + "\"); '",
          "nl\nsystem('touch " + m + "')\nx",
          "semi;touch " + m + ";",
          "-dash",
          "with spaces\tand tab",
          "out\"\nset output '" + m + "'\nplot x\n",
          "macro@MARKER",
          "bad\xff\xfeutf8",
          "q\\\"`touch MARKER`"};
}

struct path_prefix {
  std::string saved;
  explicit path_prefix(const fs::path& dir) : saved(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", (dir.string() + ":" + saved).c_str(), 1);
  }
  ~path_prefix() { ::setenv("PATH", saved.c_str(), 1); }
};

// Runs gnuplot on a saved script inside `dir`, as a user restyling a chart would.
int run_saved_script(const fs::path& dir, const std::string& script) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execlp("gnuplot", "gnuplot", script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

BOOST_AUTO_TEST_CASE(hostile_folder_names_give_pngs_and_run_nothing) {
  const fs::path root = scratch("chart-hostile");
  BOOST_REQUIRE(::chdir(root.c_str()) == 0);  // relative injections would land here
  const fs::path marker = root / "MARKER";
  const chart_log log;
  for (const auto& name : hostile_names(marker)) {
    BOOST_TEST_CONTEXT("folder " << name) {
      const fs::path dir = root / name;
      fs::create_directories(dir);
      const auto files = write_chart(dir, "fig", sample_chart());
      BOOST_TEST(files.png, files.note);
      const std::string png = slurp(dir / "fig.png");
      BOOST_TEST((png_size(png) == std::pair<std::uint32_t, std::uint32_t>{1000, 700}));  // `size 1000,700`
      BOOST_TEST(ends_with_iend(png));
      BOOST_TEST((entries(dir) == std::set<std::string>{"fig.csv", "fig.gp", "fig.png"}));
      BOOST_TEST(!fs::exists(marker));
      BOOST_TEST(!fs::exists(root / "MARKER"));
    }
  }
  BOOST_TEST(log.charts() == hostile_names(marker).size());
  BOOST_TEST(log.failures().empty());
  BOOST_REQUIRE(::chdir("/") == 0);
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(hostile_titles_and_series_names_are_plain_text) {
  const fs::path root = scratch("chart-titles");
  BOOST_REQUIRE(::chdir(root.c_str()) == 0);
  const std::string m = (root / "MARKER").string();
  const auto c = sample_chart("t`touch " + m + "`'\n" + "system('touch " + m + "')\n'@x\\",
                              "s'; system(\"touch " + m + "\"); '\"`touch MARKER`");
  const auto files = write_chart(root, "titles", c);
  BOOST_TEST(files.png, files.note);
  BOOST_TEST(!fs::exists(root / "MARKER"));
  // The saved script redraws the same picture in the folder (and runs nothing either).
  const std::string drawn = slurp(root / "titles.png");
  fs::remove(root / "titles.png");
  BOOST_TEST(run_saved_script(root, "titles.gp") == 0);
  BOOST_TEST((slurp(root / "titles.png") == drawn));
  BOOST_TEST(!fs::exists(root / "MARKER"));
  // CSV: the series name in one quoted field, quotes doubled (RFC 4180).
  const std::string csv = slurp(root / "titles.csv");
  BOOST_TEST(csv.find("\"s'; system(\"\"touch " + m + "\"\"); '\"\"`touch MARKER`\",0.5,") != std::string::npos, csv);
  BOOST_REQUIRE(::chdir("/") == 0);
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(every_gnuplot_failure_is_recorded_and_leaves_no_png) {
  const fs::path root = scratch("chart-failures");
  struct fake {
    std::string body, reason;
  };
  const std::vector<fake> fakes{
      {"echo 'line 3: undefined function' >&2; exit 3", "gnuplot failed with status 3: line 3: undefined function"},
      {"cat > /dev/null; exit 0", "gnuplot drew an empty PNG"},
      {"cat > /dev/null; printf 'not a png at all'", "gnuplot's output is not a complete PNG"},
      {"cat > /dev/null; printf '\\211PNG\\r\\n\\032\\n\\0\\0\\0\\rIHDR'", "gnuplot's output is not a complete PNG"},
      {"kill -9 $$", "gnuplot was ended by signal 9"},
  };
  for (std::size_t k = 0; k < fakes.size(); ++k) {
    BOOST_TEST_CONTEXT("fake gnuplot: " << fakes[k].body) {
      const fs::path bin = root / ("bin" + std::to_string(k)), dir = root / ("out" + std::to_string(k));
      fake_gnuplot(bin, fakes[k].body);
      fs::create_directories(dir);
      std::ofstream(dir / "fig.png") << "picture of an earlier run";
      const path_prefix use(bin);
      const chart_log log;
      const auto files = write_chart(dir, "fig", sample_chart());
      BOOST_TEST(!files.png);
      BOOST_REQUIRE(log.failures().size() == 1u);
      BOOST_TEST(log.failures()[0].chart == "fig");
      BOOST_TEST(log.failures()[0].reason == fakes[k].reason);
      BOOST_TEST(files.note.find(fakes[k].reason) != std::string::npos);
      BOOST_TEST((entries(dir) == std::set<std::string>{"fig.csv", "fig.gp"}));  // the stale PNG is gone
    }
  }
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(a_missing_gnuplot_is_a_failure) {
  const fs::path root = scratch("chart-missing");
  const char* saved = std::getenv("PATH");
  const std::string path = saved ? saved : "";
  ::setenv("PATH", (root / "empty").c_str(), 1);
  const chart_log log;
  const auto files = write_chart(root, "fig", sample_chart());
  ::setenv("PATH", path.c_str(), 1);
  BOOST_TEST(!files.png);
  BOOST_REQUIRE(log.failures().size() == 1u);
  BOOST_TEST(log.failures()[0].reason == "gnuplot is not installed (not found on PATH)");
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(png_completeness) {
  const fs::path root = scratch("chart-png");
  write_chart(root, "fig", sample_chart());
  const std::string png = slurp(root / "fig.png");
  BOOST_TEST(is_complete_png(png));
  BOOST_TEST(!is_complete_png(png.substr(0, png.size() - 1)));
  BOOST_TEST(!is_complete_png(png.substr(0, png.size() / 2)));
  BOOST_TEST(!is_complete_png(png + "x"));
  BOOST_TEST(!is_complete_png(""));
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(chart_names_are_plain_file_names) {
  const fs::path root = scratch("chart-names");
  for (const auto* bad : {"", "../x", "a/b", "-x", ".hidden", "a b", "a'b"})
    BOOST_CHECK_THROW(write_chart(root, bad, sample_chart()), std::invalid_argument);
  BOOST_TEST(entries(root).empty());
  fs::remove_all(root);
}

BOOST_AUTO_TEST_SUITE_END()  // chart_test
