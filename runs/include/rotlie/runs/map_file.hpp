#pragma once
// The body-set maps as JSON lines (one per body, written as computed): a header line that names
// the map (family, grid), then one line per body in the grid's order. A file is resumable: its
// header says which map it belongs to, and every body line says which body it is.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"

namespace rotlie::runs {

inline constexpr int map_format_version = 1;

/// {"rotlie_map":1,"family":"N","grid":200,"bodies":39800,"reference":"RS4-S5-McLachlan","method":"fast"}
/// method: "fast" (continuation confirmed by the exact solver) or "exact" (a header without it: exact).
nlohmann::ordered_json map_header(const std::string& family, int K, std::size_t bodies, const std::string& method);

/// One body: s, t and I as exact fractions, the best integrator as SCHEME:PERM:LABEL, its ‖H_R5‖,
/// the reference at its best permutation, the equal-cost ratio, the singular systems (SCHEME:PERM),
/// and the best per permutation.
nlohmann::ordered_json map_line(const solver::grid_body& g, const solver::map_point& p);

/// A body whose exact solve failed (the map goes on; the line says why).
nlohmann::ordered_json map_failure_line(const solver::grid_body& g, const std::string& family, const std::string& why);

/// The grid indices (i, j) a body line stands for, checked against the grid K: nullopt when the
/// line is not a body line of that grid.
std::optional<std::pair<int, int>> map_line_indices(const nlohmann::json& line, int K);

/// "14/25": an exact rational as text.
std::string fraction_text(const cln::cl_RA& x);

/// The file of a family's map in a folder: FOLDER/map-N.jsonl.
std::filesystem::path map_file_path(const std::filesystem::path& folder, const std::string& family);

/// A map file as written: its whole lines (a torn last line, from a killed write, is left out).
struct map_file_text {
  std::vector<std::string> lines;  ///< header first, then body lines, in file order
  std::size_t whole_length = 0;    ///< bytes up to the end of the last whole line
  std::string torn_tail;           ///< the bytes after it (a write a kill cut, or something else)
};

/// Reads the file's whole lines. Throws std::runtime_error when it cannot be read.
map_file_text read_map_file(const std::filesystem::path& path);

/// The file a --resume continues (a map or a sweep): its whole lines. Throws bad_input (--resume: …),
/// leaving the file as it is, when it cannot be read or when the bytes after its last whole line are
/// not the start of a `line_kind` line that a kill cut (one write of printable JSON).
map_file_text resumable_text(const std::filesystem::path& path, const std::string& line_kind);

/// A map file's header and body lines parsed, for drawing and auditing: lines that do not parse,
/// and bodies whose solve failed, are left out. nullopt when the file is absent or empty; throws
/// std::runtime_error when its first line is not a map header.
struct map_contents {
  nlohmann::json header;
  std::string family, method;  ///< method: "exact" when the header does not say
  int K = 0;
  std::vector<nlohmann::json> bodies;
};
std::optional<map_contents> read_map_contents(const std::filesystem::path& path);

/// What a resume finds in an existing map file of (family, K, method) over `bodies` (the
/// asymmetric grid): the bodies done and their lines. Throws bad_input (--resume: …), leaving the
/// file as it is, when the file holds another map, a line that is not a body of it, or a repeat.
struct resumed_map {
  std::vector<char> done;          ///< per body of the grid
  std::vector<std::string> lines;  ///< body lines, in file order
  std::size_t whole_length = 0;    ///< bytes up to the last complete line
  bool has_header = false;
};
resumed_map resume_map_file(const std::filesystem::path& path, const std::string& family, int K, const std::string& method,
                            const std::vector<solver::grid_body>& bodies);

/// The one file of a map, appended a whole line per write (O_APPEND), so that a line is whole or
/// absent after any kill. Opening cuts a torn last line of a resumed file, or starts a new file
/// with `header`. Throws std::runtime_error on any failure of the file system.
class map_file_writer {
 public:
  map_file_writer(const std::filesystem::path& path, const resumed_map& existing, const std::string& header);
  ~map_file_writer();
  map_file_writer(const map_file_writer&) = delete;
  map_file_writer& operator=(const map_file_writer&) = delete;
  void append(const std::string& line);
  void finish();  ///< flushes to disk

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace rotlie::runs
