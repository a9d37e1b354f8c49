#pragma once
// Output files are written whole or not at all: content goes to a temporary file in the
// same folder, which is then renamed over the target (atomic on POSIX file systems).
#include <filesystem>
#include <string_view>

namespace rotlie::reports {

/// Throws std::runtime_error with the path and the reason when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace rotlie::reports
