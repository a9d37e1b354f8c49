#include "rotlie/runs/text_file.hpp"

#include <lzma.h>

#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>

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

std::string read_text_file(const std::filesystem::path& path, std::size_t limit) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string bytes = buffer.str();
  return is_xz(bytes) ? xz_decompressed(bytes, limit, path.string()) : bytes;
}

}  // namespace rotlie::runs
