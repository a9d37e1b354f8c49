#pragma once
// NumPy's .npz without NumPy: a ZIP archive whose members are stored (no compression) .npy files, one
// per named column, each a 1-D little-endian float64 array in NPY format 1.0 (a header padded with
// spaces to a multiple of 64 bytes, ending in a newline). numpy.load reads it as a mapping of name
// to array. The archive's dates are fixed (1980-01-01), so equal columns give equal bytes.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rotlie::runs {

/// CRC-32 as ZIP computes it (the reflected polynomial 0xEDB88320, initial and final inversion).
std::uint32_t crc32(std::string_view bytes);

/// One .npy file holding `values` as a 1-D '<f8' array.
std::string npy_float64(const std::vector<double>& values);

/// A ZIP archive of the (name, content) members in order, stored. Throws std::length_error beyond
/// what ZIP without its 64-bit extension holds (4 GiB, 65,535 members).
std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& members);

/// The .npz of named columns: member NAME.npy for each.
std::string npz_of_columns(const std::vector<std::pair<std::string, std::vector<double>>>& columns);

}  // namespace rotlie::runs
