#include "scheme_lookup.hpp"

#include <cln/integer.h>
#include <cln/rational_io.h>
#include <cln/real.h>

#include <cerrno>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "rotlie/bch/scheme_word.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/schemes/reference_schemes.hpp"
#include "rotlie/schemes/same_body.hpp"
#include "rotlie/solver/dedicated_schemes.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::app {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t max_table_bytes = 1 << 20;  // the largest solver table is a few kB

const std::string range_text = "1e-" + std::to_string(max_decimal_exponent) + " … 1e" + std::to_string(max_decimal_exponent);

// |x| compared exactly with 10^±150, before any conversion to double can overflow.
bool magnitude_in_range(const cln::cl_RA& x) {
  static const cln::cl_RA big = cln::expt_pos(cln::cl_I(10), static_cast<unsigned>(max_decimal_exponent));
  const cln::cl_RA a = cln::abs(x);
  return a <= big && a * big >= 1;
}

std::string shown(const cln::cl_RA& x) { return lie::to_decimal(x, 6); }

std::string shown(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

std::string body_text(const lie::moments_of_inertia& m) {
  return "(" + shown(m.I[0]) + ", " + shown(m.I[1]) + ", " + shown(m.I[2]) + ")";
}

void check_body_of(const schemes::scheme_table& t, const std::string& file, const lie::moments_of_inertia& body,
                   foreign_table policy) {
  std::array<std::string, 3> exact;  // p/q text, compared as rationals by the table's own rule
  for (std::size_t i = 0; i < 3; ++i) {
    std::ostringstream text;
    text << body.I[i];
    exact[i] = text.str();
  }
  std::string why;
  try {
    if (schemes::same_body(t, {exact[0], exact[1], exact[2]}) != schemes::body_match::different) return;
    why = file + " was solved for the body (" + t.inertia + "), not for --inertia " + body_text(body) +
          ": its order holds only for the body it was solved for (bodies are compared up to a common factor)";
  } catch (const std::invalid_argument& e) {
    why = file + ": its inertia line '" + t.inertia + "' is not three positive exact numbers";
  }
  if (policy == foreign_table::refuse) throw usage_error(why);
  if (policy == foreign_table::refuse_unless_forced) throw usage_error(why + " (pass --force to use it anyway)");
  std::cerr << "rotlie: warning: " << one_line(why) << " (used anyway: --force)\n";
}

// The whole text of a scheme-table file, with every problem of the file itself named.
std::string table_file_text(const std::string& name) {
  std::error_code ec;
  const auto status = fs::status(name, ec);
  if (fs::is_directory(status)) throw usage_error("--scheme: '" + name + "' is a folder, not a scheme-table file");
  if (!fs::is_regular_file(status)) throw usage_error("--scheme: '" + name + "' is not a regular file");
  const auto size = fs::file_size(name, ec);
  if (!ec && size > max_table_bytes)
    throw usage_error("--scheme: '" + name + "' is " + std::to_string(size) + " bytes, too large for a scheme table");
  std::ifstream in(name, std::ios::binary);
  if (!in) throw usage_error("--scheme: cannot read '" + name + "': " + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  if (in.bad()) throw usage_error("--scheme: cannot read '" + name + "'");
  if (text.empty()) throw usage_error("--scheme: '" + name + "' is empty, not a scheme table");
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a byte-order mark from some editors
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\n' && c != '\r' && c != '\t') || u == 0x7f)
      throw usage_error("--scheme: '" + name + "' is not a text scheme table (it holds binary data)");
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

}  // namespace

std::vector<std::string> permutations_option(const std::string& perm) {
  if (perm == "all") return bch::permutation_names();
  if (!bch::is_permutation_name(perm))
    throw usage_error("--perm must be all or one of ABC, BCA, CAB, ACB, CBA, BAC, got '" + perm + "'");
  return {perm};
}

lie::moments_of_inertia required_moments_option(const std::string& text) {
  if (text.empty()) throw usage_error("--inertia is required (I1,I2,I3, water or sphere)");
  try {
    return lie::parse_moments(text);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what());
  }
}

lie::moments_of_inertia parse_moments_option(const std::string& text) {
  if (text.empty()) throw usage_error("--inertia must not be empty (I1,I2,I3, water or sphere)");
  // A value written as a number but beyond the exact parser's limits is out of range, not "not a number".
  std::size_t start = 0;
  for (int i = 1; i <= 3 && start <= text.size(); ++i) {
    const auto comma = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, comma - start);
    if (!lie::parse_exact_number(part) && why_not_a_number(part).rfind("is out of range", 0) == 0)
      throw usage_error("--inertia: I" + std::to_string(i) + " = '" + part + "' is out of range");
    start = comma + 1;
  }
  try {
    return lie::parse_moments(text);
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--inertia: ") + e.what());
  }
}

lie::moments_of_inertia parse_inertia_option(const std::string& text) {
  const auto m = parse_moments_option(text);
  for (std::size_t i = 0; i < 3; ++i)
    if (!magnitude_in_range(m.I[i]))
      throw usage_error("--inertia: I" + std::to_string(i + 1) + " = " + shown(m.I[i]) + " is outside the range " +
                        range_text + " of the numeric subcommands");
  return m;
}

models::vec3<double> to_double(const lie::moments_of_inertia& body) {
  return {cln::double_approx(body.I[0]), cln::double_approx(body.I[1]), cln::double_approx(body.I[2])};
}

double parse_positive(const std::string& text, const std::string& what) {
  const auto x = lie::parse_exact_number(text);
  if (!x) {
    const auto why = why_not_a_number(text);
    if (why == "is not a number") throw usage_error(what + " must be a number such as 0.01 or 1/64, got '" + text + "'");
    throw usage_error(what + " '" + text + "' " + why);
  }
  if (!cln::plusp(*x)) throw usage_error(what + " must be positive, got '" + text + "'");
  if (!magnitude_in_range(*x)) throw usage_error(what + " '" + text + "' is outside the range " + range_text);
  return cln::double_approx(*x);
}

models::vec3<double> parse_momentum(const std::string& text) {
  models::vec3<double> g{};
  std::size_t start = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto comma = text.find(',', start);
    if ((i < 2) == (comma == std::string::npos)) throw usage_error("--G0 takes three components g1,g2,g3, got '" + text + "'");
    const std::string part = text.substr(start, i < 2 ? comma - start : std::string::npos);
    const auto x = lie::parse_exact_number(part);
    if (!x) throw usage_error("--G0: g" + std::to_string(i + 1) + " = '" + part + "' " + why_not_a_number(part));
    if (!magnitude_in_range(*x) && cln::abs(*x) > 1)
      throw usage_error("--G0: g" + std::to_string(i + 1) + " = '" + part + "' is outside the range " + range_text);
    g[i] = cln::double_approx(*x);  // a component below the range may round to 0: only |G0| matters
    start = comma + 1;
  }
  if (g[0] == 0 && g[1] == 0 && g[2] == 0) throw usage_error("--G0 must not be zero, got '" + text + "'");
  const double length = std::hypot(g[0], g[1], g[2]), range = std::pow(10.0, max_decimal_exponent);
  if (length * range < 1) throw usage_error("--G0: |G0| = " + shown(length) + " is outside the range " + range_text);
  // Squares of smaller components underflow in double: the computation could not see them.
  for (std::size_t i = 0; i < 3; ++i)
    if (g[i] != 0 && std::abs(g[i]) * range < length)
      throw usage_error("--G0: g" + std::to_string(i + 1) + " = " + shown(g[i]) + " is below 1e-" +
                        std::to_string(max_decimal_exponent) + " |G0|; give 0 or a larger value");
  return g;
}

void check_numeric_scales(const std::string& inertia, const std::string& g0, const std::string& total) {
  const auto I = to_double(parse_inertia_option(inertia));
  const auto g = parse_momentum(g0);
  const double T = parse_positive(total, "--T");
  const double smallest = std::min({I[0], I[1], I[2]});
  const double rate = std::hypot(g[0], g[1], g[2]) / smallest;  // ≤ 1e300: finite
  const double limit = std::pow(10.0, max_decimal_exponent);
  if (rate > limit || rate < 1 / limit)
    throw usage_error("the angular rate |G0|/I_min = " + shown(rate) +
                      " of --G0 and --inertia is outside the range " + range_text);
  if (rate * T > limit)
    throw usage_error("--T: the body turns by |G0| T / I_min = " + shown(rate * T) +
                      " radians, outside the range " + range_text);
}

schemes::scheme_table lookup_scheme(const std::string& name, const lie::moments_of_inertia& body, foreign_table policy) {
  if (name.empty()) throw usage_error("--scheme must not be empty");
  try {
    if (auto t = schemes::reference_scheme(name)) return *t;
  } catch (const std::invalid_argument& e) {
    throw usage_error(std::string("--scheme: ") + e.what());
  }
  if (looks_like_path(name)) {
    std::error_code ec;
    if (!fs::exists(name, ec)) throw usage_error("--scheme: no scheme-table file '" + name + "'");
    schemes::scheme_table t;
    try {
      t = schemes::parse_scheme_table(table_file_text(name));
    } catch (const std::invalid_argument& e) {
      throw usage_error(name + ": " + e.what());
    }
    check_body_of(t, name, body, policy);
    return t;
  }
  // SCHEME:PERM:LABEL
  const auto first = name.find(':'), second = name.find(':', first == std::string::npos ? first : first + 1);
  if (first != std::string::npos && second != std::string::npos) {
    const std::string scheme = name.substr(0, first), perm = name.substr(first + 1, second - first - 1);
    const std::string label_text = name.substr(second + 1);
    const auto named = bch::find_named_scheme(scheme);
    if (!named) throw usage_error("--scheme: unknown dedicated scheme '" + scheme + "' in '" + name + "'");
    if (!bch::is_permutation_name(perm)) throw usage_error("--scheme: unknown permutation '" + perm + "' in '" + name + "'");
    const long label = parse_integer_in_range(label_text, "--scheme label", 1, 1000);
    const auto r = solver::solve_dedicated(body, {scheme}, {perm}, 40);
    for (const auto& s : r.solutions)
      if (s.label == label) return solver::scheme_table_of(s, body);
    std::string why = r.systems.empty() || r.systems[0].note.empty() ? "" : " (" + r.systems[0].note + ")";
    throw usage_error("--scheme: " + scheme + " " + perm + " has " + std::to_string(r.solutions.size()) +
                      " real solutions for this body, no label " + label_text + why);
  }
  throw usage_error("--scheme: unknown scheme '" + name +
                    "' (a reference name such as RS4-S5-McLachlan:CBA, SCHEME:PERM:LABEL such as N2:BAC:2, or a scheme-table file)");
}

}  // namespace rotlie::app
