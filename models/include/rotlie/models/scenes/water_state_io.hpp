#pragma once
// The liquid-water state as a text file: a header naming the system, then one line per molecule
// with q (Å), p (g/mol·Å/fs), Q row by row (body → lab) and G (g/mol·Å²/fs), every number with
// enough digits to read back the same bits.
//
//   rotlie-state 1
//   system liquid-water
//   model TIP3P
//   molecules 512
//   box 24.86...
//   time_fs 0
//   columns qx qy qz px py pz Q00 Q01 Q02 Q10 Q11 Q12 Q20 Q21 Q22 Gx Gy Gz
//   …
//
// Reading checks the header against the system the caller expects (model, molecule count, box)
// and refuses another system's file with one line saying what differs. Writing goes to a
// temporary file renamed into place, so a failed write leaves no half-written state.
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rotlie/models/composition.hpp"
#include "rotlie/models/rigid_bodies.hpp"

namespace rotlie::models {

/// What a state file says about its system.
template <class T>
struct water_state_header {
  std::string system = "liquid-water";
  std::string model;
  long molecules = 0;
  T box{};
  T time_fs{};
};

/// The text of a state file (full precision: a state read back is the state written).
template <class T>
std::string water_state_text(const water_state_header<T>& header, const rigid_bodies_state<T>& s) {
  std::ostringstream out;
  out.precision(std::numeric_limits<T>::max_digits10);
  out << "rotlie-state 1\nsystem " << header.system << "\nmodel " << header.model << "\nmolecules " << s.bodies.size() << "\nbox "
      << header.box << "\ntime_fs " << header.time_fs << "\ncolumns qx qy qz px py pz Q00 Q01 Q02 Q10 Q11 Q12 Q20 Q21 Q22 Gx Gy Gz\n";
  for (const auto& b : s.bodies) {
    for (const auto& x : b.q) out << x << ' ';
    for (const auto& x : b.p) out << x << ' ';
    for (const auto& x : b.rot.Q.a) out << x << ' ';
    out << b.rot.G[0] << ' ' << b.rot.G[1] << ' ' << b.rot.G[2] << '\n';
  }
  return out.str();
}

/// Writes the state through a temporary of this process's own, renamed over `path` (the numeric
/// core's own writer; the command line writes water_state_text through its one file writer).
template <class T>
void write_water_state(const std::filesystem::path& path, const water_state_header<T>& header, const rigid_bodies_state<T>& s) {
  const std::filesystem::path tmp = path.string() + ".partial-" + std::to_string(::getpid());  // this process's own
  {
    std::ofstream out(tmp);
    if (!out) throw std::runtime_error("cannot write " + path.string());
    out << water_state_text(header, s);
    out.flush();
    if (!out) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + path.string());
    }
  }
  std::filesystem::rename(tmp, path);
}

/// Reads a state written by write_water_state for the expected system (model, molecule count and
/// box; the time is returned in `header`). Throws std::invalid_argument with one line otherwise.
template <class T>
rigid_bodies_state<T> read_water_state(const std::filesystem::path& path, const water_state_header<T>& expected, water_state_header<T>& header) {
  using std::abs;
  using std::isfinite;
  const std::string where = "state file " + path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw std::invalid_argument(where + " is not a regular file");
  constexpr std::uintmax_t largest = std::uintmax_t(1) << 32;  // 4 GiB: about 500 bytes a molecule, 8 million molecules
  if (std::filesystem::file_size(path, ec) > largest) throw std::invalid_argument(where + " is larger than any state file (4 GiB)");
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read state file " + path.string());
  auto field = [&](const std::string& key) {
    std::string line;
    if (!std::getline(in, line)) throw std::invalid_argument(where + ": ends before its '" + key + "' line");
    if (line.rfind(key + " ", 0) != 0) throw std::invalid_argument(where + ": expected a '" + key + "' line, found '" + line.substr(0, 40) + "'");
    return line.substr(key.size() + 1);
  };
  if (field("rotlie-state") != "1") throw std::invalid_argument(where + ": not a rotlie state file of version 1");
  header.system = field("system");
  header.model = field("model");
  const std::string count = field("molecules");
  const std::string box = field("box");
  const std::string time = field("time_fs");
  field("columns");
  char* end = nullptr;
  errno = 0;
  header.molecules = std::strtol(count.c_str(), &end, 10);
  if (count.empty() || end == count.c_str() || *end != '\0' || errno != 0 || header.molecules < 1)
    throw std::invalid_argument(where + ": 'molecules " + count.substr(0, 20) + "' is not a count");
  (void)std::strtod(time.c_str(), &end);
  if (time.empty() || *end != '\0') throw std::invalid_argument(where + ": 'time_fs " + time.substr(0, 20) + "' is not a number");
  header.time_fs = parse_scalar<T>(time);
  if (!isfinite(static_cast<double>(header.time_fs))) throw std::invalid_argument(where + ": its time_fs is not finite");
  header.box = parse_scalar<T>(box);
  if (header.system != expected.system)
    throw std::invalid_argument(where + " is for the system '" + header.system + "', not '" + expected.system + "'");
  if (header.model != expected.model) throw std::invalid_argument(where + " is for the model " + header.model + ", not " + expected.model);
  if (header.molecules != expected.molecules)
    throw std::invalid_argument(where + " holds " + count + " molecules, not " + std::to_string(expected.molecules));
  if (!isfinite(static_cast<double>(header.box)) || abs(header.box - expected.box) > T(1e-9) * expected.box)
    throw std::invalid_argument(where + " has a box of " + box + " Å, not the " + std::to_string(static_cast<double>(expected.box)) + " Å of this system");
  rigid_bodies_state<T> s;
  s.bodies.resize(static_cast<std::size_t>(header.molecules));
  for (long k = 0; k < header.molecules; ++k) {
    std::string line;
    if (!std::getline(in, line)) throw std::invalid_argument(where + ": ends after " + std::to_string(k) + " of its molecules");
    std::istringstream row(line);
    T v[18];
    for (auto& x : v) {
      std::string word;
      if (!(row >> word)) throw std::invalid_argument(where + ": molecule " + std::to_string(k + 1) + " has fewer than 18 numbers");
      char* stop = nullptr;
      (void)std::strtod(word.c_str(), &stop);
      if (stop == word.c_str() || *stop != '\0')
        throw std::invalid_argument(where + ": molecule " + std::to_string(k + 1) + " has '" + word.substr(0, 20) + "', not a number");
      x = parse_scalar<T>(word);
      if (!isfinite(static_cast<double>(x))) throw std::invalid_argument(where + ": molecule " + std::to_string(k + 1) + " has a number that is not finite");
    }
    if (std::string more; row >> more)
      throw std::invalid_argument(where + ": molecule " + std::to_string(k + 1) + " has more than 18 numbers");
    auto& b = s.bodies[static_cast<std::size_t>(k)];
    for (int d = 0; d < 3; ++d) {
      b.q[d] = v[d];
      b.p[d] = v[3 + d];
      b.rot.G[d] = v[15 + d];
    }
    for (int e = 0; e < 9; ++e) b.rot.Q.a[static_cast<std::size_t>(e)] = v[6 + e];
    const mat3<T> should_be_one = transpose(b.rot.Q) * b.rot.Q;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (abs(should_be_one(i, j) - T(i == j ? 1 : 0)) > T(1e-9))
          throw std::invalid_argument(where + ": molecule " + std::to_string(k + 1) + "'s attitude is not a rotation");
  }
  std::string extra;
  while (std::getline(in, extra))
    if (extra.find_first_not_of(" \t\r") != std::string::npos) throw std::invalid_argument(where + ": has more lines than its molecules");
  return s;
}

}  // namespace rotlie::models
