#pragma once
// Output files are written whole or not at all. The content goes to an unnamed file in the
// target's folder (O_TMPFILE; a hidden `.rotlie-tmp-<pid>-<n>` file where the file system has no
// unnamed files), is flushed to disk, then renamed over the target (atomic on POSIX file
// systems), and the folder itself is flushed. A run killed even by SIGKILL therefore leaves at
// most a hidden `.rotlie-tmp-` file, which the next report into that folder removes.
//
// Only regular files are written. A path that is a FIFO, a device, a socket or a folder is refused
// (renaming over it would replace it). A symbolic link is written through: its final target, which
// must be an existing regular file, gets the content and the link stays a link.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace rotlie::runs {

/// The name prefix of every temporary file.
inline constexpr std::string_view temporary_prefix = ".rotlie-tmp-";

/// Throws std::runtime_error with the path and the system's reason when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

/// A file written piece by piece and put in place whole, by the rule above: the pieces go to a
/// temporary in the target's folder (unnamed where the file system allows it), and commit() flushes it
/// to disk and renames it over the target. Until commit() the target is as it was; an object destroyed
/// without commit() (an exception, a refused run) removes its temporary and leaves the target alone.
/// For output too large to hold in memory (a long trajectory).
class output_file_stream {
 public:
  /// Refuses the target at once (as writable_target) and opens the temporary. Throws std::runtime_error.
  explicit output_file_stream(const std::filesystem::path& path);
  ~output_file_stream();
  output_file_stream(const output_file_stream&) = delete;
  output_file_stream& operator=(const output_file_stream&) = delete;
  /// Appends text (buffered). Throws std::runtime_error naming the file on a write error.
  void write(std::string_view text);
  /// Puts the file in place. Throws std::runtime_error naming the file, and then the target is as it was.
  void commit();

 private:
  struct state;
  std::unique_ptr<state> state_;
};

/// The file write_file_atomically(path, …) would replace: `path` itself when it is absent or a regular
/// file, a link's final regular target. Throws std::runtime_error for anything else.
std::filesystem::path writable_target(const std::filesystem::path& path);

/// Removes the temporaries left in `dir` by processes that no longer run (a killed earlier run).
/// Returns how many were removed; errors are ignored (the files are hidden and harmless).
std::size_t remove_stale_temporaries(const std::filesystem::path& dir);

/// Unlinks the named temporaries this process is writing right now. Async-signal-safe: meant
/// for a SIGINT/SIGTERM handler that then ends the process.
void remove_pending_temporaries() noexcept;

/// A path for a one-line message: quoted, with control characters and bytes that are not
/// printable ASCII written as \n, \t, \xNN, so that no folder name can break a message in two.
std::string printable_path(const std::filesystem::path& path);

}  // namespace rotlie::runs
