// Output files are written whole or not at all, flushed, and named only when complete; write
// errors are exceptions that name the path; stale temporaries of dead writers are removed.
#include <boost/test/unit_test.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <fstream>

#include "folder_support.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/runs/text_file.hpp"

BOOST_AUTO_TEST_SUITE(output_file_test)

namespace fs = std::filesystem;
using namespace report_test;
using rotlie::reports::write_file_atomically;

namespace {

// The exception's message, or "" when none was thrown.
std::string failure_of(const fs::path& target, const std::string& content) {
  try {
    write_file_atomically(target, content);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(writes_and_replaces_whole_files) {
  const fs::path dir = scratch("output-replace");
  write_file_atomically(dir / "a.txt", "first");
  BOOST_TEST(slurp(dir / "a.txt") == "first");
  const std::string big(3'000'000, 'x');  // several write() calls
  write_file_atomically(dir / "a.txt", big);
  BOOST_TEST(slurp(dir / "a.txt") == big);
  write_file_atomically(dir / "a.txt", "");
  BOOST_TEST(fs::file_size(dir / "a.txt") == 0u);
  BOOST_TEST(entries(dir) == std::set<std::string>{"a.txt"});  // no temporary left behind
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_missing_folder_is_an_error_not_a_partial_file) {
  const fs::path target = fs::temp_directory_path() / "rotlie-no-such-folder" / "x" / "a.txt";
  const std::string message = failure_of(target, "content");
  BOOST_TEST(message.find("cannot write '" + target.string() + "'") == 0u, message);
  BOOST_TEST(message.find("No such file or directory") != std::string::npos, message);
  BOOST_TEST(!fs::exists(target));
}

BOOST_AUTO_TEST_CASE(a_parent_that_is_a_file_is_an_error) {
  const fs::path dir = scratch("output-parent-file");
  std::ofstream(dir / "plain") << "x";
  const std::string message = failure_of(dir / "plain" / "a.txt", "content");
  BOOST_TEST(message.find("Not a directory") != std::string::npos, message);
  BOOST_TEST(entries(dir) == std::set<std::string>{"plain"});
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_folder_that_takes_no_files_is_an_error) {
  // /proc refuses new files even to root; a mode-0555 folder refuses them to everyone else.
  BOOST_TEST(!failure_of("/proc/rotlie-test.txt", "content").empty());
  BOOST_TEST(!fs::exists("/proc/rotlie-test.txt"));
  if (::geteuid() == 0) {
    BOOST_TEST_MESSAGE("running as root: the read-only-mode case is covered by /proc only");
    return;
  }
  const fs::path dir = scratch("output-read-only");
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string message = failure_of(dir / "a.txt", "content");
  fs::permissions(dir, fs::perms::owner_all);
  BOOST_TEST(message.find("Permission denied") != std::string::npos, message);
  BOOST_TEST(entries(dir).empty());
  fs::remove_all(dir);
}

// A full disk, as a non-root user can make one: a file-size limit turns the write past the
// limit into EFBIG (SIGXFSZ ignored). The old file must survive intact and no temporary remain.
BOOST_AUTO_TEST_CASE(a_write_past_the_file_size_limit_fails_and_keeps_the_old_file) {
  const fs::path dir = scratch("output-full");
  write_file_atomically(dir / "a.txt", "old content");
  const fs::path message_file = dir.parent_path() / (dir.filename().string() + ".message");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const std::string message = failure_of(dir / "a.txt", std::string(1'000'000, 'y'));
    { std::ofstream(message_file) << message; }
    ::_exit(message.empty() ? 1 : 0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  BOOST_TEST(WIFEXITED(status));
  BOOST_TEST(WEXITSTATUS(status) == 0, "the write past the limit did not throw");
  const std::string message = slurp(message_file);
  BOOST_TEST(message.find("cannot write '" + (dir / "a.txt").string() + "': File too large") == 0u, message);
  BOOST_TEST(slurp(dir / "a.txt") == "old content");
  BOOST_TEST(entries(dir) == std::set<std::string>{"a.txt"});
  fs::remove_all(dir);
  fs::remove(message_file);
}

BOOST_AUTO_TEST_CASE(stale_temporaries_of_dead_writers_are_removed_live_ones_kept) {
  const fs::path dir = scratch("output-stale");
  const std::string dead = ".rotlie-tmp-" + std::to_string(dead_pid()) + "-3";
  const std::string live = ".rotlie-tmp-" + std::to_string(::getppid()) + "-1";  // our parent runs
  const std::string mine = ".rotlie-tmp-" + std::to_string(::getpid()) + "-9";   // none can be pending now
  for (const auto& n : {dead, live, mine, std::string("keep.txt"), std::string(".rotlie-tmpX")})
    std::ofstream(dir / n) << "x";
  BOOST_TEST(rotlie::reports::remove_stale_temporaries(dir) == 2u);
  BOOST_TEST((entries(dir) == std::set<std::string>{live, "keep.txt", ".rotlie-tmpX"}));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_link_is_written_through_and_stays_a_link) {
  const fs::path dir = scratch("output-link");
  std::ofstream(dir / "target.txt") << "old";
  fs::create_symlink("target.txt", dir / "link.txt");
  write_file_atomically(dir / "link.txt", "new");
  BOOST_TEST(fs::is_symlink(dir / "link.txt"));
  BOOST_TEST(slurp(dir / "target.txt") == "new");
  // a link to a link to a regular file: the final target
  fs::create_symlink("link.txt", dir / "link2.txt");
  write_file_atomically(dir / "link2.txt", "newer");
  BOOST_TEST((fs::is_symlink(dir / "link2.txt") && fs::is_symlink(dir / "link.txt")));
  BOOST_TEST(slurp(dir / "target.txt") == "newer");
  // a link to nothing is refused and stays
  fs::create_symlink("missing.txt", dir / "dangling.txt");
  const std::string message = failure_of(dir / "dangling.txt", "x");
  BOOST_TEST(message.find("does not exist") != std::string::npos, message);
  BOOST_TEST(fs::is_symlink(dir / "dangling.txt"));
  BOOST_TEST(!fs::exists(dir / "missing.txt"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_fifo_a_device_or_a_folder_is_refused_and_kept) {
  const fs::path dir = scratch("output-special");
  BOOST_TEST_REQUIRE(::mkfifo((dir / "fifo").c_str(), 0644) == 0);
  fs::create_directory(dir / "folder");
  fs::create_symlink("fifo", dir / "link-to-fifo");
  for (const char* name : {"fifo", "folder", "link-to-fifo"}) {
    const std::string message = failure_of(dir / name, "content");
    BOOST_TEST(message.find("regular files only") != std::string::npos, name << ": " << message);
  }
  BOOST_TEST(fs::is_fifo(dir / "fifo"));
  BOOST_TEST(fs::is_directory(dir / "folder"));
  BOOST_TEST(fs::is_symlink(dir / "link-to-fifo"));
  // a character device of the test's own (root only: a faulty writer must not replace the machine's /dev/null)
  std::set<std::string> kept{"fifo", "folder", "link-to-fifo"};
  if (::geteuid() == 0 && ::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
    const std::string message = failure_of(dir / "null", "content");
    BOOST_TEST(message.find("it is a device") != std::string::npos, message);
    BOOST_TEST(fs::is_character_file(dir / "null"));
    kept.insert("null");
  }
  BOOST_TEST(entries(dir) == kept);  // no temporary left
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_stream_is_in_place_only_after_commit) {
  const fs::path dir = scratch("output-stream");
  std::ofstream(dir / "a.txt") << "old";
  {
    rotlie::runs::output_file_stream out(dir / "a.txt");
    const std::string piece(700'000, 'y');  // past the buffer: written to the temporary before commit
    out.write(piece);
    out.write(piece);
    BOOST_TEST(slurp(dir / "a.txt") == "old");
    out.commit();
  }
  BOOST_TEST(fs::file_size(dir / "a.txt") == 1'400'000u);
  {
    rotlie::runs::output_file_stream abandoned(dir / "a.txt");  // destroyed without commit: nothing changes
    abandoned.write(std::string(2'000'000, 'z'));
  }
  BOOST_TEST(fs::file_size(dir / "a.txt") == 1'400'000u);
  {
    rotlie::runs::output_file_stream fresh(dir / "b.txt");
    fresh.write("new\n");
    fresh.commit();
  }
  BOOST_TEST(slurp(dir / "b.txt") == "new\n");
  BOOST_TEST(entries(dir) == (std::set<std::string>{"a.txt", "b.txt"}));  // no temporary left
  fs::create_directory(dir / "folder");
  BOOST_CHECK_THROW(rotlie::runs::output_file_stream(dir / "folder"), std::runtime_error);
  BOOST_CHECK_THROW(rotlie::runs::output_file_stream(dir / "missing" / "c.txt"), std::runtime_error);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(the_bounded_reader_refuses_what_it_cannot_read_without_waiting) {
  const fs::path dir = scratch("reader-special");
  BOOST_TEST_REQUIRE(::mkfifo((dir / "fifo").c_str(), 0644) == 0);
  const auto refusal = [](const fs::path& p, std::size_t limit) {
    try {
      rotlie::runs::read_bounded_file(p, limit);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(refusal(dir / "fifo", 100).find("not a regular file") != std::string::npos);  // returns: no writer waited for
  BOOST_TEST(refusal("/dev/zero", 100).find("not a regular file") != std::string::npos);
  BOOST_TEST(refusal(dir, 100).find("folder") != std::string::npos);
  std::ofstream(dir / "big") << std::string(101, 'x');
  BOOST_TEST(refusal(dir / "big", 100).find("101 bytes") != std::string::npos);
  BOOST_TEST(rotlie::runs::read_bounded_file(dir / "big", 101) == std::string(101, 'x'));
  BOOST_TEST(rotlie::runs::read_text_file(dir / "big") == std::string(101, 'x'));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(printable_paths_stay_on_one_line) {
  using rotlie::reports::printable_path;
  BOOST_TEST(printable_path("a\nb") == "'a\\nb'");
  BOOST_TEST(printable_path("q'x") == "'q\\'x'");
  BOOST_TEST(printable_path("bad\xff\x01") == "'bad\\xff\\x01'");
  BOOST_TEST(printable_path("r\xc3\xa9sultats") == "'r\xc3\xa9sultats'");  // valid UTF-8 kept
  BOOST_TEST(printable_path("cut\xc3") == "'cut\\xc3'");                    // a truncated sequence is not
}

BOOST_AUTO_TEST_SUITE_END()  // output_file_test
