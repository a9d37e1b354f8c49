#pragma once
// One run at a time in a folder: `rotlie map --out`, `rotlie sixth --out` and the folder of
// `rotlie md --state` are locked (flock on the folder itself, released by the kernel when the
// process ends, so a killed run leaves nothing behind) for as long as the object lives. A second
// run is refused at once, in one line naming the folder, before it reads or writes anything there;
// the refusal is a failed run (exit 1, as `rotlie report`'s into a busy folder), not a bad argument:
// the same command succeeds once the other run has ended.
#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace rotlie::runs {

/// Another process holds the folder.
struct folder_in_use : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class exclusive_use {
 public:
  /// Locks `folder` (which must exist); throws folder_in_use naming `option` when another process holds
  /// it, bad_input when it cannot be opened or locked at all.
  exclusive_use(const std::filesystem::path& folder, std::string_view option);
  ~exclusive_use();
  exclusive_use(const exclusive_use&) = delete;
  exclusive_use& operator=(const exclusive_use&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace rotlie::runs
