#pragma once
// Helpers shared by the report tests: scratch folders, the files of a folder, PNG facts read
// from the bytes (independent of the code under test), and fake gnuplot programs.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace report_test {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline fs::path scratch(const std::string& what) {
  const fs::path dir = fs::temp_directory_path() / ("rotlie-" + what + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

/// A leftover of an unfinished write, in any naming this program has used.
inline bool is_temporary(const std::string& name) {
  return name.rfind(".rotlie-tmp-", 0) == 0 || name.find(".tmp.") != std::string::npos ||
         name.find(".partial") != std::string::npos || name.find(".run.gp") != std::string::npos;
}

/// Width and height from the IHDR chunk (PNG spec: bytes 16-23, big-endian), or 0,0.
inline std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& png) {
  if (png.size() < 24 || png.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) != 0 || png.compare(12, 4, "IHDR") != 0)
    return {0, 0};
  auto be = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  return {be(16), be(20)};
}

/// True when the bytes end with the 12-byte IEND chunk (length 0, "IEND", its fixed CRC).
inline bool ends_with_iend(const std::string& png) {
  static const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return png.size() >= iend.size() && png.compare(png.size() - iend.size(), iend.size(), iend) == 0;
}

/// Writes an executable `gnuplot` shell script into dir (put dir first on PATH to use it).
inline void fake_gnuplot(const fs::path& dir, const std::string& body) {
  fs::create_directories(dir);
  std::ofstream(dir / "gnuplot") << "#!/bin/sh\n" << body << "\n";
  ::chmod((dir / "gnuplot").c_str(), 0755);
}

/// A pid that no process has now: a child that has exited and been reaped.
inline pid_t dead_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

}  // namespace report_test
