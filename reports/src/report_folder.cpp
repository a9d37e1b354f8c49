#include "rotlie/reports/report_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "rotlie/reports/output_file.hpp"

namespace rotlie::reports {
namespace {

[[noreturn]] void unusable(const std::filesystem::path& path, const std::string& why) {
  throw unusable_output_folder("cannot write the report into " + printable_path(path) + ": " + why);
}

// A file created and removed at once: proves that the folder takes new files (a writable mode
// bit says nothing on a read-only mount, nor for root).
void check_writable(int dirfd, const std::filesystem::path& path) {
  int fd = ::openat(dirfd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) {  // no unnamed files here, or not writable: a named file tells which
    const std::string probe = std::string(temporary_prefix) + std::to_string(::getpid()) + "-probe";
    fd = ::openat(dirfd, probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) ::unlinkat(dirfd, probe.c_str(), 0);
  }
  if (fd < 0) unusable(path, std::string("cannot create a file in it: ") + std::strerror(errno));
  ::close(fd);
}

}  // namespace

report_folder::report_folder(const std::filesystem::path& path) : path_(path) {
  if (path.empty()) throw unusable_output_folder("the output folder (--out) is empty");
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec))
    unusable(path, "it exists and is not a folder");
  std::filesystem::create_directories(path, ec);
  if (ec) throw unusable_output_folder("cannot create the output folder " + printable_path(path) + ": " + ec.message());
  fd_ = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) unusable(path, std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd_);
    if (e == EWOULDBLOCK)
      throw output_folder_busy("another rotlie report is writing into " + printable_path(path) +
                               "; wait for it to finish or choose another --out");
    unusable(path, std::string("cannot lock it: ") + std::strerror(e));
  }
  try {
    check_writable(fd_, path);
  } catch (...) {
    ::close(fd_);
    throw;
  }
  remove_stale_temporaries(path);
}

report_folder::~report_folder() { ::close(fd_); }

}  // namespace rotlie::reports
