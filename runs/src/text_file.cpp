#include "rotlie/runs/text_file.hpp"

#include <fcntl.h>
#include <lzma.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "rotlie/runs/output_file.hpp"

namespace rotlie::runs {
namespace {

constexpr std::array<unsigned char, 6> xz_magic = {0xFD, '7', 'z', 'X', 'Z', 0x00};

bool is_xz(const std::string& bytes) {
  if (bytes.size() < xz_magic.size()) return false;
  for (std::size_t k = 0; k < xz_magic.size(); ++k)
    if (static_cast<unsigned char>(bytes[k]) != xz_magic[k]) return false;
  return true;
}

std::string xz_decompressed(const std::string& in, std::size_t limit, const std::string& name) {
  lzma_stream s = LZMA_STREAM_INIT;
  if (lzma_stream_decoder(&s, UINT64_MAX, LZMA_CONCATENATED) != LZMA_OK)
    throw std::runtime_error("cannot start the xz decoder for " + name);
  std::string out;
  std::array<char, 1 << 16> buffer{};
  s.next_in = reinterpret_cast<const std::uint8_t*>(in.data());
  s.avail_in = in.size();
  lzma_ret r = LZMA_OK;
  while (r == LZMA_OK) {
    s.next_out = reinterpret_cast<std::uint8_t*>(buffer.data());
    s.avail_out = buffer.size();
    r = lzma_code(&s, LZMA_FINISH);
    out.append(buffer.data(), buffer.size() - s.avail_out);
    if (out.size() > limit) {
      lzma_end(&s);
      throw std::runtime_error(name + " decompresses to more than " + std::to_string(limit) + " bytes");
    }
  }
  lzma_end(&s);
  if (r != LZMA_STREAM_END) throw std::runtime_error(name + " is not a complete xz stream (truncated or damaged)");
  return out;
}

}  // namespace

std::string read_bounded_file(const std::filesystem::path& path, std::size_t limit) {
  const std::string name = printable_path(path);
  // O_NONBLOCK: opening a FIFO must not wait for a writer; the kind is checked before any read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot read " + name + ": " + std::strerror(errno));
  struct closer {
    int fd;
    ~closer() { ::close(fd); }
  } guard{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw std::runtime_error("cannot read " + name + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw std::runtime_error("cannot read " + name + ": it is a folder");
  if (!S_ISREG(st.st_mode)) throw std::runtime_error("cannot read " + name + ": it is not a regular file (a FIFO, device or socket)");
  if (static_cast<std::uintmax_t>(st.st_size) > limit)
    throw std::runtime_error("cannot read " + name + ": it is " + std::to_string(st.st_size) + " bytes, more than the " +
                             std::to_string(limit) + " this file can hold");
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error("cannot read " + name + ": " + std::strerror(errno));
    if (n == 0) break;  // it shrank while being read: what is there
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

std::string read_text_file(const std::filesystem::path& path, std::size_t limit) {
  const std::string bytes = read_bounded_file(path, limit);
  return is_xz(bytes) ? xz_decompressed(bytes, limit, printable_path(path)) : bytes;
}

}  // namespace rotlie::runs
