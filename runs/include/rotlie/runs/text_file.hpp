#pragma once
// A text file read whole, plain or xz-compressed (the full-resolution maps shipped under data/ are
// .jsonl.xz): the format is told by the xz magic bytes, not by the name.
#include <filesystem>
#include <string>

namespace rotlie::runs {

/// The bytes of a regular file of at most `limit` bytes: the one reader of a user's file. A FIFO,
/// device, socket or folder is refused without waiting on it; so is a larger file. Throws
/// std::runtime_error naming the file.
std::string read_bounded_file(const std::filesystem::path& path, std::size_t limit);

/// The file's text, decompressed when it is an xz stream. Throws std::runtime_error naming the file
/// when it cannot be read or its xz stream is damaged (truncated, corrupt, or more than `limit` bytes).
std::string read_text_file(const std::filesystem::path& path, std::size_t limit = std::size_t(1) << 31);

}  // namespace rotlie::runs
