#include "rotlie/runs/output_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <utility>

namespace rotlie::runs {
namespace output_file_detail {  // named: output_file_stream::state holds its types

// The named temporaries being written now, for the signal handler: a folder descriptor and a
// program-chosen name per slot (dirfd < 0: free). The process writes one file at a time.
struct pending_temporary {
  std::atomic<int> dirfd{-1};
  std::array<char, 64> name{};
};
std::array<pending_temporary, 4> pending;
std::atomic<unsigned long> temporary_counter{0};

// Claims a slot so that a signal arriving from now on removes `name` in `dirfd`.
class pending_guard {
 public:
  pending_guard(int dirfd, const std::string& name) {
    for (auto& p : pending) {
      int free = -1;
      if (!p.dirfd.compare_exchange_strong(free, -2)) continue;
      std::snprintf(p.name.data(), p.name.size(), "%s", name.c_str());
      p.dirfd.store(dirfd);
      slot_ = &p;
      return;
    }
  }
  ~pending_guard() {
    if (slot_) slot_->dirfd.store(-1);
  }
  pending_guard(const pending_guard&) = delete;
  pending_guard& operator=(const pending_guard&) = delete;

 private:
  pending_temporary* slot_ = nullptr;
};

class file_descriptor {
 public:
  explicit file_descriptor(int fd) : fd_(fd) {}
  ~file_descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  file_descriptor(const file_descriptor&) = delete;
  file_descriptor& operator=(const file_descriptor&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }
  void reset(int fd) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_;
};

[[noreturn]] void fail(const std::filesystem::path& path, int error) {
  throw std::runtime_error("cannot write " + printable_path(path) + ": " + std::strerror(error));
}

// fsync where the file system supports it (EINVAL: it does not, nothing to flush).
bool flushed(int fd) { return ::fsync(fd) == 0 || errno == EINVAL || errno == ENOTSUP; }

// Writes everything; returns 0 or the errno of the failure.
int write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t n = ::write(fd, content.data(), content.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    content.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

// Writes everything and flushes it to disk; returns 0 or the errno of the failure.
int write_and_flush(int fd, std::string_view content) {
  if (const int e = write_all(fd, content)) return e;
  return flushed(fd) ? 0 : errno;
}

std::string next_temporary_name() {
  return std::string(temporary_prefix) + std::to_string(::getpid()) + "-" + std::to_string(++temporary_counter);
}

// Gives the unnamed file `fd` the name `temporary` in `dirfd`; returns 0 or the errno of the failure.
int link_unnamed(int fd, int dirfd, const std::string& temporary) {
  if (::linkat(fd, "", dirfd, temporary.c_str(), AT_EMPTY_PATH) == 0) return 0;
  const std::string proc = "/proc/self/fd/" + std::to_string(fd);  // without CAP_DAC_READ_SEARCH
  if (::linkat(AT_FDCWD, proc.c_str(), dirfd, temporary.c_str(), AT_SYMLINK_FOLLOW) == 0) return 0;
  return errno;
}

// An unnamed file (O_TMPFILE) holding the content, then linked under a temporary name: a kill
// before the link leaves nothing. False when the file system cannot do it (the caller falls back).
bool write_unnamed(int dirfd, const std::string& temporary, std::string_view content, const std::filesystem::path& path) {
  file_descriptor fd(::openat(dirfd, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666));
  if (fd.get() < 0) {
    if (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL) return false;
    fail(path, errno);
  }
  if (const int e = write_and_flush(fd.get(), content)) fail(path, e);
  const int e = link_unnamed(fd.get(), dirfd, temporary);
  if (e == 0) return true;
  if (e == ENOSPC || e == EDQUOT || e == EROFS || e == EIO) fail(path, e);
  return false;
}

void write_named(int dirfd, const std::string& temporary, std::string_view content, const std::filesystem::path& path) {
  file_descriptor fd(::openat(dirfd, temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
  if (fd.get() < 0) fail(path, errno);
  int e = write_and_flush(fd.get(), content);
  if (::close(fd.release()) != 0 && e == 0) e = errno;
  if (e != 0) {
    ::unlinkat(dirfd, temporary.c_str(), 0);
    fail(path, e);
  }
}

// What a non-regular file is, for the refusal.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void refuse_kind(const std::filesystem::path& path, mode_t mode) {
  throw std::runtime_error("cannot write " + printable_path(path) + ": it is " + kind_of(mode) +
                           "; rotlie writes regular files only (and never replaces anything else)");
}

// The name `name` in `dirfd` may be replaced: absent, or a regular file (not a link, FIFO, device).
void check_replaceable(int dirfd, const std::string& name, const std::filesystem::path& path) {
  struct stat st {};
  if (::fstatat(dirfd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) {
    if (errno == ENOENT) return;
    fail(path, errno);
  }
  if (S_ISLNK(st.st_mode)) throw std::runtime_error("cannot write " + printable_path(path) + ": it became a symbolic link while rotlie wrote it");
  if (!S_ISREG(st.st_mode)) refuse_kind(path, st.st_mode);
}

bool valid_utf8_at(const std::string& s, std::size_t i, std::size_t& length) {
  const auto c = static_cast<unsigned char>(s[i]);
  length = c >= 0xf0 && c <= 0xf4 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c <= 0xdf ? 2 : 0;
  if (c >= 0xf5) length = 0;
  if (length == 0 || i + length > s.size()) return false;
  for (std::size_t k = 1; k < length; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
  return true;
}

// The folder and name of a file to be replaced, the target checked (writable_target, check_replaceable).
struct replaced_file {
  std::filesystem::path path;  ///< the regular file replaced (a link's target)
  std::string name;            ///< its name in its folder
  file_descriptor dir;
  explicit replaced_file(const std::filesystem::path& typed);
  // Renames `temporary` over the target after checking it again (it may have been replaced
  // meanwhile), then flushes the folder; removes the temporary on failure.
  void replace_with(const std::string& temporary) const;
};

}  // namespace output_file_detail

using namespace output_file_detail;

std::filesystem::path writable_target(const std::filesystem::path& path) {
  std::filesystem::path target = path;
  for (int links = 0;; ++links) {
    struct stat st {};
    if (::lstat(target.c_str(), &st) != 0) {
      if (errno != ENOENT) fail(path, errno);
      if (links > 0)
        throw std::runtime_error("cannot write " + printable_path(path) + ": it is a symbolic link to " + printable_path(target) +
                                 ", which does not exist (rotlie writes through a link only to an existing regular file)");
      return target;
    }
    if (S_ISREG(st.st_mode)) return target;
    if (!S_ISLNK(st.st_mode)) refuse_kind(path, st.st_mode);
    if (links == 40) fail(path, ELOOP);
    std::error_code ec;
    const auto next = std::filesystem::read_symlink(target, ec);
    if (ec) fail(path, ec.value());
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
}

replaced_file::replaced_file(const std::filesystem::path& typed) : path(writable_target(typed)), dir(-1) {
  const auto parent = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  name = path.filename().string();
  if (name.empty() || name == "." || name == "..") fail(path, EISDIR);
  dir.reset(::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.get() < 0) fail(path, errno);
  check_replaceable(dir.get(), name, path);
}

void replaced_file::replace_with(const std::string& temporary) const {
  try {
    check_replaceable(dir.get(), name, path);  // again: it may have been replaced while the content was written
  } catch (...) {
    ::unlinkat(dir.get(), temporary.c_str(), 0);
    throw;
  }
  if (::renameat(dir.get(), temporary.c_str(), dir.get(), name.c_str()) != 0) {
    const int e = errno;
    ::unlinkat(dir.get(), temporary.c_str(), 0);
    fail(path, e);
  }
  if (!flushed(dir.get())) fail(path, errno);  // the rename itself reaches the disk
}

void write_file_atomically(const std::filesystem::path& typed, std::string_view content) {
  const replaced_file target(typed);
  const std::string temporary = next_temporary_name();
  pending_guard guard(target.dir.get(), temporary);
  if (!write_unnamed(target.dir.get(), temporary, content, target.path)) write_named(target.dir.get(), temporary, content, target.path);
  target.replace_with(temporary);
}

// The temporary of an output_file_stream: unnamed until commit() where the file system allows it,
// else named (and then removed by a signal handler calling remove_pending_temporaries, or here).
struct output_file_stream::state {
  replaced_file target;
  std::string temporary = next_temporary_name();
  std::optional<pending_guard> guard;  ///< while a named temporary exists
  file_descriptor fd{-1};
  bool unnamed = true, committed = false;
  std::string buffer;

  explicit state(const std::filesystem::path& typed) : target(typed) {
    fd.reset(::openat(target.dir.get(), ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666));
    if (fd.get() >= 0) return;
    if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) fail(target.path, errno);
    unnamed = false;
    guard.emplace(target.dir.get(), temporary);
    fd.reset(::openat(target.dir.get(), temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
    if (fd.get() < 0) fail(target.path, errno);
  }
  void drain() {
    if (const int e = write_all(fd.get(), buffer)) fail(target.path, e);
    buffer.clear();
  }
};

output_file_stream::output_file_stream(const std::filesystem::path& path) : state_(std::make_unique<state>(path)) {}

output_file_stream::~output_file_stream() {
  if (!state_->committed && !state_->unnamed) ::unlinkat(state_->target.dir.get(), state_->temporary.c_str(), 0);
}

void output_file_stream::write(std::string_view text) {
  if (state_->committed) throw std::logic_error("output_file_stream: write after commit");
  state_->buffer += text;
  if (state_->buffer.size() >= (std::size_t(1) << 20)) state_->drain();
}

void output_file_stream::commit() {
  auto& s = *state_;
  if (s.committed) return;
  s.drain();
  if (!flushed(s.fd.get())) fail(s.target.path, errno);
  if (s.unnamed) {
    s.guard.emplace(s.target.dir.get(), s.temporary);
    if (const int e = link_unnamed(s.fd.get(), s.target.dir.get(), s.temporary)) fail(s.target.path, e);
    s.unnamed = false;  // named from here: removed by the destructor if the rename fails
  }
  if (::close(s.fd.release()) != 0) fail(s.target.path, errno);
  s.target.replace_with(s.temporary);
  s.committed = true;
}

std::size_t remove_stale_temporaries(const std::filesystem::path& dir) {
  std::size_t removed = 0;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(dir, ec); !ec && it != std::filesystem::directory_iterator();
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(temporary_prefix, 0) != 0) continue;
    // .rotlie-tmp-<pid>-<n>: keep the files of a process that still runs (another writer).
    const long pid = std::strtol(name.c_str() + temporary_prefix.size(), nullptr, 10);
    const bool alive = pid > 0 && pid != ::getpid() && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    std::error_code ignored;
    if (!alive && std::filesystem::remove(it->path(), ignored)) ++removed;
  }
  return removed;
}

void remove_pending_temporaries() noexcept {
  for (auto& p : pending) {
    const int dirfd = p.dirfd.load();
    if (dirfd >= 0) ::unlinkat(dirfd, p.name.data(), 0);
  }
}

std::string printable_path(const std::filesystem::path& path) {
  const std::string s = path.string();
  std::string out = "'";
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t length = 0;
    if (c >= 0x80 && valid_utf8_at(s, i, length)) {
      out.append(s, i, length);
      i += length - 1;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\\' || c == '\'') {
      out += '\\', out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7f) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "'";
}

}  // namespace rotlie::runs
