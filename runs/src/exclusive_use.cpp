#include "rotlie/runs/exclusive_use.hpp"

#include <fcntl.h>
#include <sys/file.h>
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

}  // namespace rotlie::runs
