#include "arguments.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

namespace rotlie::app {

namespace fs = std::filesystem;

long parse_integer_in_range(std::string_view text, std::string_view option, long lo, long hi) {
  const std::string name(option);
  const std::string shown(text);
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  long value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || (ec != std::errc() && ec != std::errc::result_out_of_range) || end != digits.data() + digits.size())
    throw usage_error(name + ": '" + shown + "' is not an integer");
  const bool too_small = ec == std::errc::result_out_of_range ? digits.front() == '-' : value < lo;
  const bool too_large = ec == std::errc::result_out_of_range ? digits.front() != '-' : value > hi;
  if (too_small) throw usage_error(name + " must be at least " + std::to_string(lo) + ", got " + shown);
  if (too_large) throw usage_error(name + " must be at most " + std::to_string(hi) + ", got " + shown);
  return value;
}

std::string why_not_a_number(std::string_view text) {
  std::string lower;
  for (const char c : text) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  for (const char* word : {"nan", "inf"})
    if (lower.find(word) != std::string::npos) return "is not a finite number";
  // [+-]digits[.digits][e[+-]digits], possibly over the limits of the exact parser
  std::size_t i = 0, mantissa_digits = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  bool point = false;
  for (; i < text.size() && ((text[i] >= '0' && text[i] <= '9') || (text[i] == '.' && !point)); ++i)
    if (text[i] == '.') point = true;
    else ++mantissa_digits;
  if (mantissa_digits == 0) return "is not a number";
  if (i == text.size()) return "is out of range (too many digits)";
  if (text[i] != 'e' && text[i] != 'E') return "is not a number";
  ++i;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t exponent_start = i;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  return i == text.size() && i > exponent_start ? "is out of range" : "is not a number";
}

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

std::string one_line(std::string_view message) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (u < 0x20 || u == 0x7f) out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
    else out += c;
  }
  return out;
}

bool is_library_message(std::string_view message) {
  for (const char* mark : {"boost::", "Error in function", "cln::", "CLN", "GiNaC", "std::", "basic_string", "_M_",
                           "filesystem error", "stoi", "stol", "stod", "bad_alloc", "bad_function_call", "vector::",
                           "map::at", "out_of_range", "invalid_argument"})
    if (message.find(mark) != std::string_view::npos) return true;
  return false;
}

}  // namespace rotlie::app
