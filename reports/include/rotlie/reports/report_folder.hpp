#pragma once
// The output folder of one report: checked before any work starts, locked for the whole run
// (flock on the folder itself, so no lock file is left behind), and cleared of the hidden
// temporaries of an earlier killed run. A second report into the same folder fails at once and
// leaves the folder untouched.
#include <filesystem>
#include <stdexcept>

namespace rotlie::reports {

/// The folder cannot hold a report (a file, under a file, empty, not writable): a bad argument.
struct unusable_output_folder : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Another report is writing into the folder.
struct output_folder_busy : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class report_folder {
 public:
  /// Creates the folder if needed, locks it and removes stale temporaries. Throws
  /// unusable_output_folder or output_folder_busy, both naming the path.
  explicit report_folder(const std::filesystem::path& path);
  ~report_folder();  ///< releases the lock
  report_folder(const report_folder&) = delete;
  report_folder& operator=(const report_folder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace rotlie::reports
