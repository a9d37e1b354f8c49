#include "rotlie/runs/exclusive_use.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {

exclusive_use::exclusive_use(const std::filesystem::path& folder, std::string_view option) {
  const std::string where = one_line(folder.string());
  fd_ = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw bad_input(std::string(option) + ": cannot open the folder '" + where + "': " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    if (e == EWOULDBLOCK)
      throw folder_in_use(std::string(option) + ": another rotlie run is using the folder '" + where +
                      "'; wait for it to finish or choose another folder");
    throw bad_input(std::string(option) + ": cannot lock the folder '" + where + "': " + std::strerror(e));
  }
}

exclusive_use::~exclusive_use() {
  if (fd_ >= 0) ::close(fd_);
}

exclusive_file::exclusive_file(const std::filesystem::path& file, std::string_view option) {
  const std::string where = one_line(file.string());
  // O_EXCL: of two runs that found no file, one creates it, the other opens the same file;
  // O_NONBLOCK: a FIFO put there meanwhile is not waited on
  for (int attempt = 0; attempt < 2 && fd_ < 0; ++attempt) {
    fd_ = ::open(file.c_str(), O_RDONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, 0644);
    if (fd_ >= 0) {
      created_ = true;
      break;
    }
    if (errno != EEXIST) throw bad_input(std::string(option) + ": cannot create '" + where + "': " + std::strerror(errno));
    struct stat st {};
    if (::stat(file.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return;
    fd_ = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0 && errno != ENOENT) throw bad_input(std::string(option) + ": cannot open '" + where + "': " + std::strerror(errno));
  }
  if (fd_ < 0) throw bad_input(std::string(option) + ": '" + where + "' appears and disappears; it cannot be locked");
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    return;
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int e = errno;
    ::close(fd_);
    fd_ = -1;
    if (e == EWOULDBLOCK)
      throw folder_in_use(std::string(option) + ": another rotlie run is using the file '" + where +
                          "' (by this name or another link to it); wait for it to finish or choose another file");
    throw bad_input(std::string(option) + ": cannot lock the file '" + where + "': " + std::strerror(e));
  }
}

exclusive_file::~exclusive_file() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace rotlie::runs
