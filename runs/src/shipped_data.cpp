#include "rotlie/runs/shipped_data.hpp"

#include <cstdlib>
#include <vector>

namespace rotlie::runs {
namespace {

std::vector<std::filesystem::path> data_folders() {
  std::vector<std::filesystem::path> out;
  if (const char* given = std::getenv("ROTLIE_DATA"); given && *given) out.emplace_back(given);
  out.emplace_back(ROTLIE_INSTALLED_DATA_DIR);
  out.emplace_back(ROTLIE_SOURCE_DATA_DIR);
  return out;
}

}  // namespace

std::optional<std::filesystem::path> shipped_file(const std::string& relative) {
  for (const auto& folder : data_folders()) {
    const auto file = folder / relative;
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) return file;
  }
  return std::nullopt;
}

std::optional<std::filesystem::path> shipped_map(const std::string& family) {
  return shipped_file("maps-K200/map-" + family + ".jsonl.xz");
}

}  // namespace rotlie::runs
