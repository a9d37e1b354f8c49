#include "rotlie/runs/scheme_names.hpp"

#include <cerrno>
#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "exact_range.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/schemes/same_body.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"
#include "rotlie/runs/text_file.hpp"
#include "rotlie/runs/user_input.hpp"

namespace rotlie::runs {
namespace {

namespace fs = std::filesystem;


std::string body_text(const lie::moments_of_inertia& m) {
  return "(" + shown(m.I[0]) + ", " + shown(m.I[1]) + ", " + shown(m.I[2]) + ")";
}

void check_body_of(const schemes::scheme_table& t, const std::string& file, const lie::moments_of_inertia& body,
                   foreign_table policy, const warning_sink& warn) {
  std::array<std::string, 3> exact;  // p/q text, compared as rationals by the table's own rule
  for (std::size_t i = 0; i < 3; ++i) {
    std::ostringstream text;
    text << body.I[i];
    exact[i] = text.str();
  }
  std::string why;
  try {
    if (schemes::same_body(t, {exact[0], exact[1], exact[2]}) != schemes::body_match::different) return;
    // integrate and order take the body from --inertia; md and spin from their scene (no such option)
    const std::string whose = policy == foreign_table::refuse ? "this run's body " : "--inertia ";
    why = file + " was solved for the body (" + t.inertia + "), not for " + whose + body_text(body) +
          ": its order holds only for the body it was solved for (bodies are compared up to a common factor)";
  } catch (const std::invalid_argument& e) {
    why = file + ": its inertia line '" + t.inertia + "' is not three positive exact numbers";
  }
  if (policy == foreign_table::refuse) throw bad_input(why);
  if (policy == foreign_table::refuse_unless_forced) throw bad_input(why + " (pass --force to use it anyway)");
  const std::string warning = one_line(why) + " (used anyway: --force)";
  if (warn) warn(warning);
  else std::cerr << "rotlie: warning: " << warning << "\n";
}

// The whole text of a scheme-table file, with every problem of the file itself named.
std::string table_file_text(const std::string& name) {
  std::error_code ec;
  const auto status = fs::status(name, ec);
  if (fs::is_directory(status)) throw bad_input("--scheme: '" + name + "' is a folder, not a scheme-table file");
  if (!fs::is_regular_file(status)) throw bad_input("--scheme: '" + name + "' is not a regular file");
  const auto size = fs::file_size(name, ec);
  if (!ec && size > max_table_bytes)
    throw bad_input("--scheme: '" + name + "' is " + std::to_string(size) + " bytes, too large for a scheme table");
  std::string text;
  try {
    text = read_bounded_file(name, max_table_bytes);  // the one bounded reader (it grew since the check: refused)
  } catch (const std::runtime_error& e) {
    throw bad_input(std::string("--scheme: ") + e.what());
  }
  if (text.empty()) throw bad_input("--scheme: '" + name + "' is empty, not a scheme table");
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a byte-order mark from some editors
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\r' && c != '\t') || u == 0x7f)
      throw bad_input("--scheme: '" + name + "' is not a text scheme table (it holds binary data)");
  }
  // Windows line ends (CRLF, or a lone CR at the end) read as plain ones.
  std::string lf;
  lf.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] != '\r' || (i + 1 < text.size() && text[i + 1] != '\n')) lf += text[i];
  return lf;
}

bool looks_like_path(const std::string& name) {
  std::error_code ec;
  return name.find('/') != std::string::npos || fs::exists(name, ec) ||
         (name.size() > 7 && name.compare(name.size() - 7, 7, ".scheme") == 0);
}

schemes::scheme_table table_file(const std::string& name, const lie::moments_of_inertia& body, foreign_table policy,
                                 const warning_sink& warn) {
  std::error_code ec;
  if (!fs::exists(name, ec)) throw bad_input("--scheme: no scheme-table file '" + name + "'");
  schemes::scheme_table t;
  try {
    t = schemes::parse_scheme_table(table_file_text(name));
  } catch (const bad_input&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw bad_input(name + ": " + e.what());
  }
  check_body_of(t, name, body, policy, warn);
  return t;
}

// SCHEME:PERM:LABEL, solved for the body; nullopt when the name is not of that form.
std::optional<schemes::scheme_table> solved_scheme(const std::string& name, const lie::moments_of_inertia& body) {
  const auto first = name.find(':'), second = name.find(':', first == std::string::npos ? first : first + 1);
  if (first == std::string::npos || second == std::string::npos) return std::nullopt;
  const std::string scheme = name.substr(0, first), perm = name.substr(first + 1, second - first - 1);
  const std::string label_text = name.substr(second + 1);
  const auto named = bch::find_named_scheme(scheme);
  if (!named) throw bad_input("--scheme: unknown dedicated scheme '" + scheme + "' in '" + name + "'");
  if (!bch::is_permutation_name(perm)) throw bad_input("--scheme: unknown permutation '" + perm + "' in '" + name + "'");
  const long label = integer_in_range(label_text, "--scheme label", 1, 1000);
  const auto r = solver::solve_dedicated(body, {scheme}, {perm}, 40);
  for (const auto& s : r.solutions)
    if (s.label == label) return solver::scheme_table_of(s, body);
  std::string why = r.systems.empty() || r.systems[0].note.empty() ? "" : " (" + r.systems[0].note + ")";
  throw bad_input("--scheme: " + scheme + " " + perm + " has " + std::to_string(r.solutions.size()) +
                  " real solutions for this body, no label " + label_text + why);
}

}  // namespace

std::vector<std::string> permutations_named(const std::string& perm) {
  if (perm == "all") return bch::permutation_names();
  if (!bch::is_permutation_name(perm))
    throw bad_input("--perm must be all or one of ABC, BCA, CAB, ACB, CBA, BAC, got '" + perm + "'");
  return {perm};
}

schemes::scheme_table scheme_named(const std::string& name, const lie::moments_of_inertia& body, foreign_table policy,
                                   const warning_sink& warn) {
  if (name.empty()) throw bad_input("--scheme must not be empty");
  try {
    if (auto t = schemes::reference_scheme(name)) return *t;
  } catch (const std::invalid_argument& e) {
    throw bad_input(std::string("--scheme: ") + e.what());
  }
  if (looks_like_path(name)) return table_file(name, body, policy, warn);
  if (auto t = solved_scheme(name, body)) return *t;
  throw bad_input("--scheme: unknown scheme '" + name +
                  "' (a reference name such as RS4-S5-McLachlan:CBA, SCHEME:PERM:LABEL such as N2:BAC:2, or a scheme-table file)");
}

}  // namespace rotlie::runs
