#include "arguments.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

#include "rotlie/runs/output_file.hpp"

namespace rotlie::app {

namespace fs = std::filesystem;

namespace {

// Creates and removes a probe file: the only test that also holds for root and read-only mounts.
std::string probe_writable(const fs::path& folder) {
  const fs::path probe = folder / (".rotlie-probe." + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) return std::strerror(errno);
  ::close(fd);
  ::unlink(probe.c_str());
  return "";
}

}  // namespace

void check_output_file(const std::string& path, std::string_view option) {
  std::error_code ec;
  if (!fs::is_symlink(path, ec)) return;
  try {
    runs::writable_target(path);
  } catch (const std::runtime_error& e) {
    throw usage_error(std::string(option) + ": " + e.what());
  }
}

void check_output_folder(const std::string& folder, std::string_view option) {
  const std::string name(option);
  if (folder.empty()) throw usage_error(name + " must not be empty");
  std::error_code ec;
  const fs::path target(folder);
  const auto status = fs::status(target, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status)) throw usage_error(name + ": '" + folder + "' exists and is not a folder");
    if (const auto why = probe_writable(target); !why.empty())
      throw usage_error(name + ": cannot write into '" + folder + "': " + why);
    return;
  }
  // Make the missing folders as the command would, probe, and remove what was made.
  std::vector<fs::path> made;
  fs::path walk;
  for (const auto& part : target.lexically_normal()) {
    walk /= part;
    if (part.empty()) continue;
    const auto s = fs::status(walk, ec);
    if (fs::exists(s)) {
      if (!fs::is_directory(s))
        throw usage_error(name + ": cannot create '" + folder + "': '" + walk.string() + "' is a file, not a folder");
      continue;
    }
    if (::mkdir(walk.c_str(), 0777) != 0) {
      const std::string why = std::strerror(errno);
      for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
      throw usage_error(name + ": cannot create '" + folder + "': " + why);
    }
    made.push_back(walk);
  }
  const auto why = made.empty() ? std::string() : probe_writable(made.back());
  for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
  if (!why.empty()) throw usage_error(name + ": cannot create '" + folder + "': " + why);
}

namespace {

// std::cout's buffer, writing to file descriptor 1 itself so that the reason of the first failed
// write (ENOSPC, EPIPE, EIO) is kept until the end of the run instead of being lost in errno.
class checked_output_buffer : public std::streambuf {
 public:
  checked_output_buffer() { setp(buffer_, buffer_ + sizeof buffer_); }
  int first_error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    for (const char* p = pbase(); p < pptr();) {
      const auto n = ::write(1, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        if (error_ == 0) error_ = errno;
        break;
      }
      p += n;
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return error_ == 0;
  }

  char buffer_[1 << 16];
  int error_ = 0;
};

// Never destroyed: std::cout is flushed once more at exit, after function-local statics are gone.
checked_output_buffer& output_buffer() {
  static auto* const buffer = new checked_output_buffer;
  return *buffer;
}

}  // namespace

void route_standard_output() {
  // A closed descriptor 0, 1 or 2 would be reused by the next file opened (a scheme table
  // written by solve --out would receive the output). /dev/null opened read-only holds the
  // place: a closed standard output still fails every write, and is reported.
  for (const int fd : {0, 1, 2})
    if (::fcntl(fd, F_GETFD) < 0 && errno == EBADF) {
      const int placeholder = ::open("/dev/null", fd == 2 ? O_WRONLY : O_RDONLY);
      if (placeholder >= 0 && placeholder != fd) {
        ::dup2(placeholder, fd);
        ::close(placeholder);
      }
    }
  std::cout.rdbuf(&output_buffer());
}

std::string flush_standard_output() {
  std::cout.flush();
  const int err = output_buffer().first_error();
  if (err == 0 && std::cout) return "";
  return err != 0 ? std::strerror(err) : "write error";
}

bool is_library_message(std::string_view message) {
  for (const char* mark : {"boost::", "Error in function", "cln::", "CLN", "GiNaC", "std::", "basic_string", "_M_",
                           "filesystem error", "stoi", "stol", "stod", "bad_alloc", "bad_function_call", "vector::",
                           "map::at", "out_of_range", "invalid_argument"})
    if (message.find(mark) != std::string_view::npos) return true;
  return false;
}

}  // namespace rotlie::app
