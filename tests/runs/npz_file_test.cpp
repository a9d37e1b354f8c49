// The .npz writer (npz_file.hpp): CRC-32 of known strings, an .npy member's header and bytes, and an
// archive read back through its own local headers and central directory.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "rotlie/runs/npz_file.hpp"

BOOST_AUTO_TEST_SUITE(npz_file_test)

using namespace rotlie::runs;

namespace {

std::uint32_t u16(const std::string& s, std::size_t at) { return static_cast<unsigned char>(s[at]) | static_cast<unsigned char>(s[at + 1]) << 8; }
std::uint32_t u32(const std::string& s, std::size_t at) { return u16(s, at) | u16(s, at + 2) << 16; }

struct member {
  std::string name, content;
};

// The archive's members read off its local headers in turn, each checked against its CRC and its
// central directory entry (found through the end record).
std::vector<member> read_back(const std::string& zip) {
  BOOST_TEST_REQUIRE(zip.size() >= 22u);
  const std::size_t end = zip.size() - 22;
  BOOST_TEST_REQUIRE(u32(zip, end) == 0x06054b50u);
  const std::size_t count = u16(zip, end + 10), directory = u32(zip, end + 16);
  BOOST_TEST(u32(zip, end + 12) == end - directory);  // the directory's size
  std::vector<member> members;
  std::size_t at = 0, entry = directory;
  for (std::size_t n = 0; n < count; ++n) {
    BOOST_TEST_REQUIRE(u32(zip, at) == 0x04034b50u);
    BOOST_TEST(u16(zip, at + 8) == 0u);  // stored
    const std::size_t size = u32(zip, at + 18), name_size = u16(zip, at + 26), extra = u16(zip, at + 28);
    BOOST_TEST(u32(zip, at + 22) == size);  // no compression: sizes equal
    member m{zip.substr(at + 30, name_size), zip.substr(at + 30 + name_size + extra, size)};
    BOOST_TEST(u32(zip, at + 14) == crc32(m.content), m.name);
    BOOST_TEST_REQUIRE(u32(zip, entry) == 0x02014b50u);
    BOOST_TEST(u32(zip, entry + 42) == at);  // where the directory says the member starts
    BOOST_TEST(u32(zip, entry + 16) == u32(zip, at + 14));
    BOOST_TEST(zip.substr(entry + 46, u16(zip, entry + 28)) == m.name);
    entry += 46 + u16(zip, entry + 28) + u16(zip, entry + 30) + u16(zip, entry + 32);
    at += 30 + name_size + extra + size;
    members.push_back(m);
  }
  BOOST_TEST(at == directory);
  BOOST_TEST(entry == end);
  return members;
}

}  // namespace

BOOST_AUTO_TEST_CASE(crc32_of_known_strings) {
  BOOST_TEST(crc32("") == 0u);
  BOOST_TEST(crc32("a") == 0xE8B7BE43u);
  BOOST_TEST(crc32("123456789") == 0xCBF43926u);  // the check value of CRC-32/ISO-HDLC
  BOOST_TEST(crc32("The quick brown fox jumps over the lazy dog") == 0x414FA339u);
  BOOST_TEST(crc32(std::string(1, '\0')) == 0xD202EF8Du);
}

BOOST_AUTO_TEST_CASE(an_npy_member_holds_its_header_and_the_values_bit_for_bit) {
  const std::vector<double> values = {0.1, -0.0, std::numeric_limits<double>::infinity(), std::nan(""), 4.9e-324, -1e300};
  const auto npy = npy_float64(values);
  BOOST_TEST(npy.substr(0, 8) == std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header = u16(npy, 8);
  BOOST_TEST((10 + header) % 64 == 0u);
  const std::string dictionary = "{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }";
  BOOST_TEST(npy.compare(10, dictionary.size(), dictionary) == 0);
  BOOST_TEST(npy.find_first_not_of(' ', 10 + dictionary.size()) == 10 + header - 1);  // spaces, then the newline
  BOOST_TEST(npy[10 + header - 1] == '\n');
  BOOST_TEST_REQUIRE(npy.size() == 10 + header + 8 * values.size());
  for (std::size_t k = 0; k < values.size(); ++k) BOOST_TEST(std::memcmp(npy.data() + 10 + header + 8 * k, &values[k], 8) == 0, "value " << k);
  // little-endian: 0.1 = 0x3FB999999999999A, its low byte first
  BOOST_TEST(static_cast<unsigned char>(npy[10 + header]) == 0x9Au);
  BOOST_TEST(static_cast<unsigned char>(npy[10 + header + 7]) == 0x3Fu);
  // an empty column and a long one keep the alignment
  BOOST_TEST((10 + u16(npy_float64({}), 8)) % 64 == 0u);
  BOOST_TEST((10 + u16(npy_float64(std::vector<double>(100000)), 8)) % 64 == 0u);
}

BOOST_AUTO_TEST_CASE(an_archive_reads_back_through_its_own_headers) {
  const std::vector<std::pair<std::string, std::vector<double>>> columns = {{"t", {0, 300, 600}}, {"r_x", {1.2, 1.19, 1.18}}, {"energy", {}}};
  const auto zip = npz_of_columns(columns);
  const auto members = read_back(zip);
  BOOST_TEST_REQUIRE(members.size() == 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    BOOST_TEST(members[k].name == columns[k].first + ".npy");
    BOOST_TEST(members[k].content == npy_float64(columns[k].second));
  }
  BOOST_TEST(npz_of_columns(columns) == zip);  // fixed dates: the same bytes again
  BOOST_TEST(read_back(stored_zip({})).empty());
}

BOOST_AUTO_TEST_SUITE_END()
