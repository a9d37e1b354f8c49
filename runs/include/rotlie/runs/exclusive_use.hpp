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

/// Another process holds the folder (or the file, for exclusive_file).
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

/// One run at a time on a results file (`rotlie sweep --out`), whatever name reaches it: the lock is on
/// the file itself (its device and inode), so a hard link in another folder or a symbolic link is the
/// same file, and two files of one folder are two. As the folder's lock: released by the kernel when
/// the process ends, a second run refused at once (folder_in_use, one line naming the file) before it
/// reads or writes the file. An absent file is created empty first (`created()`), so that it is
/// locked before anything is written to it; a path that is not a regular file (a folder, a FIFO) is
/// neither created nor locked (`locked()` false), left to the caller's refusal.
class exclusive_file {
 public:
  exclusive_file(const std::filesystem::path& file, std::string_view option);
  ~exclusive_file();
  exclusive_file(const exclusive_file&) = delete;
  exclusive_file& operator=(const exclusive_file&) = delete;
  bool created() const { return created_; }
  bool locked() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
  bool created_ = false;
};

}  // namespace rotlie::runs
