#include "rotlie/runs/map_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/rational_io.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::runs {

std::string fraction_text(const cln::cl_RA& x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

namespace {

nlohmann::ordered_json body_fields(const solver::grid_body& g, const std::string& family) {
  nlohmann::ordered_json j;
  j["s"] = fraction_text(g.s);
  j["t"] = fraction_text(g.t);
  j["I"] = {fraction_text(g.body.I[0]), fraction_text(g.body.I[1]), fraction_text(g.body.I[2])};
  j["family"] = family;
  return j;
}

}  // namespace

nlohmann::ordered_json map_header(const std::string& family, int K, std::size_t bodies, const std::string& method) {
  nlohmann::ordered_json j;
  j["rotlie_map"] = map_format_version;
  j["family"] = family;
  j["grid"] = K;
  j["bodies"] = bodies;
  j["reference"] = solver::map_reference_scheme;
  j["method"] = method;
  return j;
}

nlohmann::ordered_json map_line(const solver::grid_body& g, const solver::map_point& p) {
  auto j = body_fields(g, p.family);
  const std::string reference = solver::map_reference_scheme;
  j["best"] = p.best ? nlohmann::ordered_json(solver::scheme_table_name(*p.best)) : nlohmann::ordered_json();
  j["remainder"] = p.best ? nlohmann::ordered_json(p.best->analytic_remainder) : nlohmann::ordered_json();
  j["reference"] = reference + ":" + p.reference_permutation;
  j["reference_remainder"] = p.reference_remainder;
  j["ratio"] = p.ratio ? nlohmann::ordered_json(*p.ratio) : nlohmann::ordered_json();
  j["flat"] = g.flat;
  nlohmann::ordered_json singular = nlohmann::ordered_json::array();
  for (const auto& s : p.singular) singular.push_back(s.scheme + ":" + s.permutation);
  j["singular"] = singular;
  // The screened path knows the solutions of the systems it confirmed only (screened_map.hpp).
  j["real_solutions"] = p.complete ? nlohmann::ordered_json(p.real_solutions) : nlohmann::ordered_json();
  nlohmann::ordered_json perms = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < p.per_permutation.size(); ++k) {
    const auto& b = p.per_permutation[k];
    nlohmann::ordered_json e;
    e["perm"] = b.permutation;
    e["best"] = b.best && b.confirmed ? nlohmann::ordered_json(solver::scheme_table_name(*b.best)) : nlohmann::ordered_json();
    if (b.best && !b.confirmed) e["unconfirmed_best"] = b.best->scheme + ":" + b.best->permutation;  // label unknown
    e["remainder"] = b.best ? nlohmann::ordered_json(b.best->analytic_remainder) : nlohmann::ordered_json();
    e["reference_remainder"] = p.reference_remainders[k];
    perms.push_back(std::move(e));
  }
  j["permutations"] = perms;
  return j;
}

nlohmann::ordered_json map_failure_line(const solver::grid_body& g, const std::string& family, const std::string& why) {
  auto j = body_fields(g, family);
  j["failed"] = why;
  return j;
}

std::optional<std::pair<int, int>> map_line_indices(const nlohmann::json& line, int K) {
  if (!line.is_object() || !line.contains("s") || !line.contains("t") || !line["s"].is_string() || !line["t"].is_string())
    return std::nullopt;
  const auto s = lie::parse_exact_number(line["s"].get<std::string>());
  const auto t = lie::parse_exact_number(line["t"].get<std::string>());
  if (!s || !t) return std::nullopt;
  const cln::cl_RA is = *s * K, jt = *t * K;
  if (cln::denominator(is) != 1 || cln::denominator(jt) != 1) return std::nullopt;
  if (is < 0 || is > K || jt < 0 || jt > K) return std::nullopt;
  const long i = cln::cl_I_to_long(cln::the<cln::cl_I>(is)), j = cln::cl_I_to_long(cln::the<cln::cl_I>(jt));
  if (i < 0 || i > K || j < 0 || j > K) return std::nullopt;
  return std::pair<int, int>(static_cast<int>(i), static_cast<int>(j));
}


std::filesystem::path map_file_path(const std::filesystem::path& folder, const std::string& family) {
  return folder / ("map-" + family + ".jsonl");
}

namespace {

constexpr std::size_t largest_map_bytes = std::size_t(1) << 31;  // a map at --grid 200 is 43 MB

map_file_text lines_of(const std::string& text) {
  map_file_text out;
  for (std::size_t at = 0;;) {
    const auto end = text.find('\n', at);
    if (end == std::string::npos) break;  // a torn last line (a killed write): dropped
    out.lines.push_back(text.substr(at, end - at));
    at = end + 1;
    out.whole_length = at;
  }
  out.torn_tail = text.substr(out.whole_length);
  return out;
}

}  // namespace

map_file_text read_map_file(const std::filesystem::path& path) {
  return lines_of(read_bounded_file(path, largest_map_bytes));  // a FIFO or device is refused, not waited on
}

std::optional<map_contents> read_map_contents(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  const auto text = lines_of(read_text_file(path));  // a map file, or one shipped xz-compressed
  if (text.lines.empty()) return std::nullopt;
  map_contents m;
  m.header = nlohmann::json::parse(text.lines.front(), nullptr, false);
  if (m.header.is_discarded() || !m.header.is_object() || !m.header.contains("grid") || !m.header["grid"].is_number_integer() ||
      !m.header.contains("family") || !m.header["family"].is_string())
    throw std::runtime_error(printable_path(path) + " has no map header");
  m.family = m.header["family"].get<std::string>();
  m.K = m.header["grid"].get<int>();
  m.method = m.header.value("method", std::string("exact"));
  for (std::size_t k = 1; k < text.lines.size(); ++k) {
    auto j = nlohmann::json::parse(text.lines[k], nullptr, false);
    if (!j.is_discarded() && j.is_object() && !j.contains("failed")) m.bodies.push_back(std::move(j));
  }
  return m;
}

namespace {

// A body line holds a result: a failure with its reason, or the best (a name, or null where every
// system is singular) with its remainder, the reference's remainder and the per-permutation list.
bool has_result(const nlohmann::json& j) {
  if (j.contains("failed")) return j["failed"].is_string();
  const auto string_or_null = [&](const char* k) { return j.contains(k) && (j[k].is_string() || j[k].is_null()); };
  const auto number_or_null = [&](const char* k) { return j.contains(k) && (j[k].is_number() || j[k].is_null()); };
  return string_or_null("best") && number_or_null("remainder") && j.contains("reference_remainder") &&
         j["reference_remainder"].is_number() && number_or_null("ratio") && j.contains("permutations") && j["permutations"].is_array();
}

}  // namespace

map_file_text resumable_text(const std::filesystem::path& path, const std::string& line_kind) {
  map_file_text text;
  try {
    text = read_map_file(path);
  } catch (const std::runtime_error& e) {
    throw bad_input(std::string("--resume: ") + e.what());
  }
  // A line is appended by one write of printable JSON: a kill can leave only a prefix of one. Other
  // bytes after the last whole line (binary data, another program's text) are not ours to drop.
  const auto& tail = text.torn_tail;
  const bool a_cut_line = tail.empty() || (tail.front() == '{' && std::none_of(tail.begin(), tail.end(), [](char c) {
                                             return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
                                           }));
  if (!a_cut_line)
    throw bad_input("--resume: " + printable_path(path) + " ends with " + std::to_string(tail.size()) + " bytes that are not the start of a " +
                    line_kind + " line (not a write cut by a kill); it is left as it is");
  return text;
}

resumed_map resume_map_file(const std::filesystem::path& path, const std::string& family, int K, const std::string& method,
                            const std::vector<solver::grid_body>& bodies) {
  resumed_map out;
  out.done.assign(bodies.size(), 0);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))  // as the writer says it when the map is not resumed: a failed run
    throw std::runtime_error("cannot open " + printable_path(path) + ": " + std::strerror(EISDIR));
  const map_file_text text = resumable_text(path, "map");
  out.whole_length = text.whole_length;
  const std::string refusal = "--resume: " + printable_path(path) + " ";
  bool claims_check = false;
  std::map<long, std::size_t> index_of;
  for (std::size_t k = 0; k < bodies.size(); ++k) index_of[static_cast<long>(bodies[k].i) * (K + 1) + bodies[k].j] = k;
  for (std::size_t n = 0; n < text.lines.size(); ++n) {
    const std::size_t line_number = n + 1;
    const auto j = nlohmann::json::parse(text.lines[n], nullptr, false);
    if (line_number == 1) {
      // each field of the type the writer gives it: a grid of 20.9 or 2^32 + 20 is not 20
      const bool typed = !j.is_discarded() && j.is_object() && j.contains("rotlie_map") && j["rotlie_map"].is_number_integer() &&
                         j.contains("family") && j["family"].is_string() && j.contains("grid") && j["grid"].is_number_integer() &&
                         (!j.contains("method") || j["method"].is_string());
      if (!typed) throw bad_input(refusal + "is not a rotlie map file (its header line is not one); it is left as it is");
      const auto grid = j["grid"].get<long long>();
      if (j["rotlie_map"].get<long long>() != map_format_version || j["family"].get<std::string>() != family || grid != K)
        throw bad_input(refusal + "holds the map of family " + one_line(j["family"].get<std::string>()) + " at --grid " +
                        std::to_string(grid) + ", not " + family + " at --grid " + std::to_string(K) + "; it is left as it is");
      const std::string made_by = j.contains("method") ? j["method"].get<std::string>() : "exact";
      if (made_by != method) {
        const auto flag = [](const std::string& m) { return m == "exact" ? std::string("--exact") : std::string("--fast"); };
        throw bad_input(refusal + "was computed with " + flag(made_by) + " (" + one_line(made_by) + "), not " + flag(method) + " (" +
                        method + "); it is left as it is");
      }
      // the rest of the header must describe this map too: a resume keeps the header as it is
      if (j.contains("bodies") && !(j["bodies"].is_number_unsigned() && j["bodies"].get<unsigned long long>() == bodies.size()))
        throw bad_input(refusal + "says its map has " + one_line(j["bodies"].dump()) + " bodies, where family " + family + " at --grid " +
                        std::to_string(K) + " has " + std::to_string(bodies.size()) + "; it is left as it is");
      if (j.contains("reference") && !(j["reference"].is_string() && j["reference"].get<std::string>() == solver::map_reference_scheme))
        throw bad_input(refusal + "names the reference scheme " + one_line(j["reference"].dump()) + ", not " +
                        solver::map_reference_scheme + "; it is left as it is");
      claims_check = j.contains("neighbour_check");
      out.has_header = true;
      continue;
    }
    const auto ij = j.is_discarded() ? std::nullopt : map_line_indices(j, K);
    const auto found = ij ? index_of.find(static_cast<long>(ij->first) * (K + 1) + ij->second) : index_of.end();
    if (found == index_of.end() || !j.contains("family") || !j["family"].is_string() || j["family"].get<std::string>() != family)
      throw bad_input(refusal + "line " + std::to_string(line_number) + " is not a body of this map; it is left as it is");
    if (!has_result(j))
      throw bad_input(refusal + "line " + std::to_string(line_number) +
                      " holds no result (neither a best with its remainders nor a failure); it is left as it is");
    if (out.done[found->second] != 0)
      throw bad_input(refusal + "line " + std::to_string(line_number) + " repeats a body; it is left as it is");
    out.done[found->second] = 1;
    out.lines.push_back(text.lines[n]);
  }
  if (claims_check && out.lines.size() < bodies.size())
    throw bad_input(refusal + "records a neighbour check in its header, but " + std::to_string(bodies.size() - out.lines.size()) + " of " +
                    std::to_string(bodies.size()) + " bodies are missing (the check runs on a whole map only); it is left as it is");
  return out;
}

namespace {

void write_all(int fd, const std::string& text, const std::filesystem::path& path) {
  std::size_t written = 0;
  while (written < text.size()) {
    const auto n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write to " + printable_path(path) + ": " + std::strerror(errno));
    written += static_cast<std::size_t>(n);
  }
}

}  // namespace

map_file_writer::map_file_writer(const std::filesystem::path& path, const resumed_map& existing, const std::string& header)
    : path_(path) {
  // O_NONBLOCK: a FIFO under the map's name must be refused, not waited on (a link to a regular file is written through;
  // a link to nothing is refused, which O_CREAT would follow and create)
  if (std::error_code ec; std::filesystem::is_symlink(path, ec)) writable_target(path);
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NONBLOCK, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open " + printable_path(path) + ": " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error("cannot write " + printable_path(path) + ": it is not a regular file; rotlie writes regular files only");
  }
  ::fcntl(fd_, F_SETFL, O_WRONLY | O_APPEND);  // blocking writes again
  if (::ftruncate(fd_, static_cast<off_t>(existing.has_header ? existing.whole_length : 0)) != 0)
    throw std::runtime_error("cannot truncate " + printable_path(path) + ": " + std::strerror(errno));
  if (!existing.has_header) write_all(fd_, header + "\n", path_);
}

map_file_writer::~map_file_writer() {
  if (fd_ >= 0) ::close(fd_);
}

void map_file_writer::append(const std::string& line) { write_all(fd_, line + "\n", path_); }

void map_file_writer::finish() {
  if (::fsync(fd_) != 0 && errno != EINVAL)
    throw std::runtime_error("cannot flush " + printable_path(path_) + ": " + std::strerror(errno));
}

}  // namespace rotlie::runs
