#include "rotlie/runs/npz_file.hpp"

#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace rotlie::runs {

namespace {

static_assert(std::endian::native == std::endian::little, "the .npy columns are written as the machine holds them: little-endian");

constexpr std::uint16_t dos_time = 0, dos_date = (0 << 9) | (1 << 5) | 1;  // 1980-01-01 00:00, ZIP's first day
constexpr std::uint16_t zip_version = 20;                                  // 2.0: what every reader accepts

void put16(std::string& out, std::uint16_t x) {
  out += static_cast<char>(x & 0xff), out += static_cast<char>(x >> 8);
}
void put32(std::string& out, std::uint32_t x) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((x >> (8 * k)) & 0xff);
}

const std::array<std::uint32_t, 256>& crc_table() {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  return table;
}

}  // namespace

std::uint32_t crc32(std::string_view bytes) {
  const auto& table = crc_table();
  std::uint32_t c = 0xFFFFFFFFu;
  for (const unsigned char b : bytes) c = table[(c ^ b) & 0xff] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string npy_float64(const std::vector<double>& values) {
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(values.size()) + ",), }";
  const std::size_t preamble = 10;  // magic (6), version (2), header length (2)
  header.append((64 - (preamble + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01', out += '\x00';
  put16(out, static_cast<std::uint16_t>(header.size()));
  out += header;
  const std::size_t at = out.size();
  out.resize(at + 8 * values.size());
  if (!values.empty()) std::memcpy(out.data() + at, values.data(), 8 * values.size());
  return out;
}

std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& members) {
  constexpr std::size_t limit = std::numeric_limits<std::uint32_t>::max();
  if (members.size() > std::numeric_limits<std::uint16_t>::max()) throw std::length_error("more members than a ZIP archive holds without ZIP64");
  std::string out, directory;
  for (const auto& [name, content] : members) {
    if (out.size() > limit || content.size() > limit || name.size() > std::numeric_limits<std::uint16_t>::max())
      throw std::length_error("the archive would exceed the 4 GiB a ZIP archive holds without ZIP64");
    const auto crc = crc32(content);
    const auto offset = static_cast<std::uint32_t>(out.size());
    const auto size = static_cast<std::uint32_t>(content.size());
    const auto name_size = static_cast<std::uint16_t>(name.size());
    // the local header, then the member
    put32(out, 0x04034b50), put16(out, zip_version), put16(out, 0), put16(out, 0), put16(out, dos_time), put16(out, dos_date);
    put32(out, crc), put32(out, size), put32(out, size), put16(out, name_size), put16(out, 0);
    out += name;
    out += content;
    // its entry in the central directory
    put32(directory, 0x02014b50), put16(directory, zip_version), put16(directory, zip_version), put16(directory, 0), put16(directory, 0);
    put16(directory, dos_time), put16(directory, dos_date), put32(directory, crc), put32(directory, size), put32(directory, size);
    put16(directory, name_size), put16(directory, 0), put16(directory, 0), put16(directory, 0), put16(directory, 0), put32(directory, 0), put32(directory, offset);
    directory += name;
  }
  if (out.size() + directory.size() > limit) throw std::length_error("the archive would exceed the 4 GiB a ZIP archive holds without ZIP64");
  const auto directory_offset = static_cast<std::uint32_t>(out.size());
  out += directory;
  const auto count = static_cast<std::uint16_t>(members.size());
  put32(out, 0x06054b50), put16(out, 0), put16(out, 0), put16(out, count), put16(out, count);
  put32(out, static_cast<std::uint32_t>(directory.size())), put32(out, directory_offset), put16(out, 0);
  return out;
}

std::string npz_of_columns(const std::vector<std::pair<std::string, std::vector<double>>>& columns) {
  std::vector<std::pair<std::string, std::string>> members;
  members.reserve(columns.size());
  for (const auto& [name, values] : columns) members.emplace_back(name + ".npy", npy_float64(values));
  return stored_zip(members);
}

}  // namespace rotlie::runs
