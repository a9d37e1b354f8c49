// rotlie map: the body-set maps of LV section 5 (Figs. 7–10), one JSON line per body, resumable,
// distributed over MPI ranks when started by mpirun.
//
// Every rank computes the bodies of a fixed schedule (the rows of the grid, s fixed, dealt out in
// turn) and sends each line to rank 0, which writes the lines in the grid's order: the file of a run
// on any number of processes, killed and resumed or not, is the file of one uninterrupted process.
// A line is appended with one write and is whole or absent; a resume drops a torn last line.
// By default (--fast) a row is computed as a whole, by continuation (N: solver/continued_map.hpp;
// P: the screened path, solver/screened_map.hpp), so a resume recomputes a row it finds incomplete
// and writes only its missing lines: the result of a body never depends on where a run stopped or
// on the number of processes.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "map_distribution.hpp"
#include "progress.hpp"
#include "rotlie/reports/map_io.hpp"
#include "rotlie/reports/output_file.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continued_map.hpp"
#include "rotlie/solver/screened_map.hpp"

namespace rotlie::app {
namespace {

namespace fs = std::filesystem;

constexpr const char* default_folder = "rotlie-map";

// The asymmetric grid is K rows (1 ≤ i ≤ K − 1) of K bodies (0 ≤ j ≤ K − 1): row r holds the
// indices r K … r K + K − 1. Rows are dealt out to the ranks in turn.
int owner_of_row(std::size_t row, int ranks) { return static_cast<int>(row % static_cast<std::size_t>(ranks)); }

// The fast path is the default where it has been checked against the exact solver at random
// bodies with no disagreement: N (complete continuation) and P (the screened path, which confirms
// each body's best by the exact solver). R is not checked: its map is exact (0.2 s per body).
bool exact_method(const map_options& o) {
  if (o.fast && o.family == "R")
    throw usage_error("--fast: the fast path is checked against the exact solver for the N and P families only; the R "
                      "map uses the exact solver (drop --fast)");
  return o.exact || o.family == "R";
}

// The header's method: a resume continues a map of the same method only.
std::string method_name(bool exact, const std::string& family) { return exact ? "exact" : family == "P" ? "screened" : "fast"; }

std::string checked_family(const std::string& family) {
  if (family != "N" && family != "R" && family != "P") throw usage_error("--family must be N, R or P, got '" + family + "'");
  return family;
}

int checked_grid(const std::string& text) {
  return static_cast<int>(parse_integer_in_range(text, "--grid", 1, solver::max_grid_divisions));
}

fs::path map_file(const std::string& folder, const std::string& family) { return fs::path(folder) / ("map-" + family + ".jsonl"); }

// What a resume finds in an existing file: the bodies done, their lines, and where the whole lines end.
struct existing_map {
  std::vector<char> done;
  std::vector<std::string> lines;  ///< body lines, in file order
  std::size_t whole_length = 0;    ///< bytes up to the last complete line
  bool has_header = false;
};

existing_map read_existing(const fs::path& path, const std::string& family, int K, const std::string& method,
                           const std::vector<solver::grid_body>& bodies) {
  existing_map out;
  out.done.assign(bodies.size(), 0);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw usage_error("--resume: cannot read '" + path.string() + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::map<long, std::size_t> index_of;
  for (std::size_t k = 0; k < bodies.size(); ++k) index_of[static_cast<long>(bodies[k].i) * (K + 1) + bodies[k].j] = k;
  const std::string refusal = "--resume: " + reports::printable_path(path) + " ";
  std::size_t at = 0;
  for (std::size_t line_number = 1;; ++line_number) {
    const auto end = text.find('\n', at);
    if (end == std::string::npos) break;  // a torn last line (a killed write): dropped
    const std::string line = text.substr(at, end - at);
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (line_number == 1) {
      if (j.is_discarded() || !j.is_object() || !j.contains("rotlie_map"))
        throw usage_error(refusal + "is not a rotlie map file; it is left as it is");
      if (j.value("rotlie_map", 0) != reports::map_format_version || j.value("family", "") != family ||
          j.value("grid", 0) != K)
        throw usage_error(refusal + "holds the map of family " + j.value("family", "?") + " at --grid " +
                          std::to_string(j.value("grid", 0)) + ", not " + family + " at --grid " + std::to_string(K) +
                          "; it is left as it is");
      if (j.value("method", "exact") != method) {
        const auto flag = [](const std::string& m) { return m == "exact" ? std::string("--exact") : std::string("--fast"); };
        throw usage_error(refusal + "was computed with " + flag(j.value("method", "exact")) + ", not " + flag(method) +
                          "; it is left as it is");
      }
      out.has_header = true;
    } else {
      const auto ij = j.is_discarded() ? std::nullopt : reports::map_line_indices(j, K);
      const auto found = ij ? index_of.find(static_cast<long>(ij->first) * (K + 1) + ij->second) : index_of.end();
      if (found == index_of.end() || j.value("family", "") != family)
        throw usage_error(refusal + "line " + std::to_string(line_number) + " is not a body of this map; it is left as it is");
      if (out.done[found->second] != 0)
        throw usage_error(refusal + "line " + std::to_string(line_number) + " repeats a body; it is left as it is");
      out.done[found->second] = 1;
      out.lines.push_back(line);
    }
    at = end + 1;
    out.whole_length = at;
  }
  return out;
}

void write_all(int fd, const std::string& text, const fs::path& path) {
  std::size_t written = 0;
  while (written < text.size()) {
    const auto n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write to '" + reports::printable_path(path) + "': " + std::strerror(errno));
    written += static_cast<std::size_t>(n);
  }
}

// The one file of the map, appended a whole line per write.
class map_output {
 public:
  map_output(const fs::path& path, const existing_map& existing, const std::string& header) : path_(path) {
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot open '" + reports::printable_path(path) + "': " + std::strerror(errno));
    if (::ftruncate(fd_, static_cast<off_t>(existing.has_header ? existing.whole_length : 0)) != 0)
      throw std::runtime_error("cannot truncate '" + reports::printable_path(path) + "': " + std::strerror(errno));
    if (!existing.has_header) write_all(fd_, header + "\n", path_);
  }
  ~map_output() {
    if (fd_ >= 0) ::close(fd_);
  }
  map_output(const map_output&) = delete;
  map_output& operator=(const map_output&) = delete;
  void append(const std::string& line) { write_all(fd_, line + "\n", path_); }
  void finish() {
    if (::fsync(fd_) != 0 && errno != EINVAL)
      throw std::runtime_error("cannot flush '" + reports::printable_path(path_) + "': " + std::strerror(errno));
  }

 private:
  fs::path path_;
  int fd_ = -1;
};

std::string body_line(const solver::grid_body& g, const std::string& family) {
  try {
    return reports::map_line(g, solver::compute_map_point(g.body, family, solver::map_digits)).dump();
  } catch (const std::exception& e) {
    return reports::map_failure_line(g, family, one_line(e.what())).dump();
  }
}

// The lines of the bodies [first, first + count) of one row that are still to do (done[k] == 0).
// --fast continues along the whole row whatever is done, so that every line is the same in any run;
// if the row fails as a whole, each body is solved on its own and a failure stays on its line.
std::vector<std::pair<std::size_t, std::string>> row_lines(const std::vector<solver::grid_body>& bodies, std::size_t first,
                                                           std::size_t count, const std::vector<char>& done,
                                                           const std::string& family, bool exact) {
  std::vector<std::pair<std::size_t, std::string>> out;
  bool any = false;
  for (std::size_t k = first; k < first + count; ++k) any = any || done[k] == 0;
  if (!any) return out;
  if (!exact) {
    try {
      const std::vector<solver::grid_body> row(bodies.begin() + static_cast<std::ptrdiff_t>(first),
                                               bodies.begin() + static_cast<std::ptrdiff_t>(first + count));
      const auto points = family == "P" ? solver::screened_map_points(row, family) : solver::continued_map_points(row, family);
      for (std::size_t k = 0; k < count; ++k)
        if (done[first + k] == 0) out.emplace_back(first + k, reports::map_line(row[k], points[k]).dump());
      return out;
    } catch (const std::exception&) {
      // falls through: body by body, each failure on its own line
    }
  }
  for (std::size_t k = first; k < first + count; ++k)
    if (done[k] == 0) out.emplace_back(k, body_line(bodies[k], family));
  return out;
}

// Rank 0's writer: lines arrive in any order and leave in the grid's order.
class ordered_writer {
 public:
  ordered_writer(std::vector<std::size_t> todo, map_output* file, bool echo) : todo_(std::move(todo)), file_(file), echo_(echo) {}
  void add(std::size_t index, std::string line) {
    pending_.emplace(index, std::move(line));
    while (next_ < todo_.size()) {
      const auto found = pending_.find(todo_[next_]);
      if (found == pending_.end()) break;
      if (file_) file_->append(found->second);
      if (echo_) std::cout << found->second << "\n" << std::flush;
      pending_.erase(found);
      ++next_;
    }
  }
  std::size_t written() const { return next_; }
  bool complete() const { return next_ == todo_.size(); }

 private:
  std::vector<std::size_t> todo_;
  map_output* file_;
  bool echo_;
  std::map<std::size_t, std::string> pending_;
  std::size_t next_ = 0;
};

std::string duration_text(double seconds) {
  std::ostringstream s;
  s.precision(seconds < 10 ? 2 : 3);
  if (seconds < 120) s << seconds << " s";
  else if (seconds < 7200) s << seconds / 60 << " min";
  else s << seconds / 3600 << " h";
  return s.str();
}

struct prepared_map {
  std::string family;
  int K = 0;
  std::vector<solver::grid_body> bodies;
  existing_map existing;
  fs::path path;  ///< empty: no file (--json alone)
};

prepared_map prepare(const map_options& o) {
  prepared_map p;
  p.family = checked_family(o.family);
  exact_method(o);  // refuses --fast for R before anything is written
  p.K = checked_grid(o.grid);
  std::string folder = o.out;
  if (folder.empty() && !o.json) folder = default_folder;
  if (o.resume && folder.empty()) throw usage_error("--resume needs --out (the folder of the map to continue)");
  p.bodies = solver::asymmetric_grid(p.K);
  p.existing.done.assign(p.bodies.size(), 0);
  if (folder.empty()) return p;
  check_output_folder(folder, "--out");
  p.path = map_file(folder, p.family);
  const bool exists = fs::exists(p.path);
  if (exists && !o.resume)
    throw usage_error("--out: " + reports::printable_path(p.path) +
                      " exists: continue it with --resume, or choose another folder; it is left as it is");
  if (exists) p.existing = read_existing(p.path, p.family, p.K, method_name(exact_method(o), p.family), p.bodies);
  fs::create_directories(folder);
  return p;
}

std::string summary(const prepared_map& p, double seconds, std::size_t computed, int processes) {
  std::size_t bodies = 0, failed = 0, better = 0, with_ratio = 0, singular = 0;
  std::ifstream in(p.path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) continue;
    ++bodies;
    if (j.contains("failed")) ++failed;
    if (j.contains("ratio") && j["ratio"].is_number()) {
      ++with_ratio;
      if (j["ratio"].get<double>() > 1) ++better;
    }
    if (j.contains("singular") && !j["singular"].empty()) ++singular;
  }
  std::ostringstream s;
  s << "map of family " << p.family << " at --grid " << p.K << ": " << bodies << " of " << p.bodies.size()
    << " asymmetric bodies (" << computed << " computed now in " << duration_text(seconds) << " by " << processes
    << (processes == 1 ? " process" : " processes") << ") in "
    << p.path.string() << "\n";
  if (with_ratio > 0)
    s << p.family << " better than " << solver::map_reference_scheme << " at equal cost (ratio > 1) at " << better << " of "
      << with_ratio << " bodies (" << 100.0 * static_cast<double>(better) / static_cast<double>(with_ratio) << " %)\n";
  s << "bodies with a singular system: " << singular << "; bodies whose solve failed: " << failed << "\n";
  return s.str();
}

int run_rank0(const map_options& o, process_group& group) {
  prepared_map p;
  try {
    p = prepare(o);
  } catch (const usage_error&) {
    group.broadcast(std::to_string(exit_usage));
    throw;
  } catch (...) {
    group.broadcast(std::to_string(exit_failure));
    throw;
  }
  group.broadcast("0" + std::string(p.existing.done.begin(), p.existing.done.end()));

  std::optional<map_output> file;
  if (!p.path.empty())
    file.emplace(p.path, p.existing, reports::map_header(p.family, p.K, p.bodies.size(), method_name(exact_method(o), p.family)).dump());
  if (o.json)
    for (const auto& line : p.existing.lines) std::cout << line << "\n";
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < p.bodies.size(); ++k)
    if (p.existing.done[k] == 0) todo.push_back(k);
  ordered_writer writer(todo, file ? &*file : nullptr, o.json);

  progress_line progress;
  const auto start = std::chrono::steady_clock::now();
  const auto show = [&] {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t done = writer.written();
    std::ostringstream s;
    s << "map " << p.family << " --grid " << p.K << ": " << done << "/" << todo.size() << " bodies on " << group.size()
      << " process(es)";
    if (done > 0) s << ", about " << duration_text(elapsed / static_cast<double>(done) * static_cast<double>(todo.size() - done)) << " left";
    progress.show(s.str());
  };
  const auto drain = [&](bool wait, int& workers_left) {
    while (auto m = group.receive(wait)) {
      if (m->index < 0) {
        --workers_left;
        if (workers_left == 0) return;
      } else {
        writer.add(static_cast<std::size_t>(m->index), std::move(m->payload));
      }
      if (wait) return;
    }
  };
  int workers_left = group.size() - 1;
  const std::size_t K = static_cast<std::size_t>(p.K);
  for (std::size_t row = 0; row * K < p.bodies.size(); ++row) {
    if (owner_of_row(row, group.size()) != 0) continue;
    for (auto& [k, line] : row_lines(p.bodies, row * K, K, p.existing.done, p.family, exact_method(o))) writer.add(k, std::move(line));
    drain(false, workers_left);
    show();
  }
  while (workers_left > 0) {
    drain(true, workers_left);
    show();
  }
  if (!writer.complete()) throw std::runtime_error("a process of the MPI job did not deliver all its bodies");
  if (file) file->finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.json) std::cout << summary(p, seconds, todo.size(), group.size());
  return 0;
}

int run_worker(const map_options& o, process_group& group) {
  const std::string verdict = group.broadcast("");
  if (verdict.empty() || verdict[0] != '0') return verdict.empty() ? exit_failure : verdict[0] - '0';  // rank 0 says why
  const std::string family = checked_family(o.family);
  const int K = checked_grid(o.grid);
  const auto bodies = solver::asymmetric_grid(K);
  const std::vector<char> done(verdict.begin() + 1, verdict.end());
  const std::size_t n = static_cast<std::size_t>(K);
  for (std::size_t row = 0; row * n < bodies.size(); ++row)
    if (owner_of_row(row, group.size()) == group.rank())
      for (auto& [k, line] : row_lines(bodies, row * n, n, done, family, exact_method(o)))
        group.send_result(static_cast<int>(k), line);
  group.send_done();
  return 0;
}

}  // namespace

int run_map(const map_options& options) {
  process_group group;
  if (group.rank() == 0) {
    if (group.size() == 1) return run_rank0(options, group);
    try {
      return run_rank0(options, group);
    } catch (const usage_error&) {
      throw;  // before any work was handed out: the other ranks were told and have ended
    } catch (const std::exception& e) {
      // After the work was handed out the other ranks would wait for ever: end the whole job.
      std::cerr << "rotlie: error: " << one_line(e.what()) << "\n";
      group.abort(exit_failure);
    }
  }
  try {
    return run_worker(options, group);
  } catch (const std::exception& e) {
    std::cerr << "rotlie: error: rank " << group.rank() << ": " << one_line(e.what()) << "\n";
    group.abort(exit_failure);
  }
}

}  // namespace rotlie::app
