#pragma once
// The results shipped with rotlie (data/): the papers' full-resolution sweeps, computed once with the
// command recorded beside each file (data/README.md). Looked up in $ROTLIE_DATA, then the installed
// share/rotlie/data, then the source tree's data/ folder.
#include <filesystem>
#include <optional>
#include <string>

namespace rotlie::runs {

/// A shipped file by its path inside data/ (vzs-fig1/liquid_water_points.csv), when present.
std::optional<std::filesystem::path> shipped_file(const std::string& relative);

/// The shipped map of a family at the paper's grid (maps-K200/map-F.jsonl.xz), when present.
std::optional<std::filesystem::path> shipped_map(const std::string& family);

}  // namespace rotlie::runs
