#pragma once
// One run at a time in a folder: `rotlie map --out`, `rotlie sixth --out` and the folder of
// `rotlie md --state` are locked (flock on the folder itself, released by the kernel when the
// process ends, so a killed run leaves nothing behind) for as long as the object lives. A second
// run is refused at once, in one line naming the folder, before it reads or writes anything there.
#include <filesystem>
#include <string_view>

namespace rotlie::runs {

class exclusive_use {
 public:
  /// Locks `folder` (which must exist); throws bad_input naming `option` when another process holds it.
  exclusive_use(const std::filesystem::path& folder, std::string_view option);
  ~exclusive_use();
  exclusive_use(const exclusive_use&) = delete;
  exclusive_use& operator=(const exclusive_use&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace rotlie::runs
