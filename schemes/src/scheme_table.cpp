#include "rotlie/schemes/scheme_table.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "rotlie/schemes/same_body.hpp"

namespace rotlie::schemes {
namespace {

[[noreturn]] void fail(int line, const std::string& why) {
  throw std::invalid_argument("scheme table line " + std::to_string(line) + ": " + why);
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// The value of a decimal text, or NaN when it is not [+-]digits[.digits][(e|E)[+-]digits] with a
// finite long double value (strtold alone would also take hexadecimal, inf and nan).
long double decimal_value(const std::string& s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  bool point = false;
  for (; i < s.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(s[i]))) ++digits;
    else if (s[i] == '.' && !point) point = true;
    else break;
  }
  if (digits == 0) return std::numeric_limits<long double>::quiet_NaN();
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t start = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == start) return std::numeric_limits<long double>::quiet_NaN();
  }
  if (i != s.size()) return std::numeric_limits<long double>::quiet_NaN();
  const long double v = std::strtold(s.c_str(), nullptr);
  return std::isfinite(v) ? v : std::numeric_limits<long double>::quiet_NaN();
}

bool is_decimal(const std::string& s) { return !std::isnan(decimal_value(s)); }

}  // namespace

int axis_of_letter(char letter) {
  if (letter < 'A' || letter > 'C') throw std::invalid_argument("not an axis letter: " + printable_text(std::string_view(&letter, 1)));
  return letter - 'A';
}

std::array<int, 3> rs_axes(const scheme_table& t) {
  return {axis_of_letter(t.permutation.at(0)), axis_of_letter(t.permutation.at(1)), axis_of_letter(t.permutation.at(2))};
}

std::string split_name(split s) {
  switch (s) {
    case split::abc: return "ABC";
    case split::rs: return "RS";
    case split::tv: return "TV";
  }
  return "?";
}

int force_evaluations(const scheme_table& t) {
  // a thermostat's letters (O, N) move no body: the forces stay those of the configuration, and the two
  // halves of a kick split around one (V O V) are one evaluation
  std::string moving;
  for (const auto& s : t.stages)
    if ((s.part == 'V' || s.part == 'T') && (moving.empty() || moving.back() != s.part || s.part != 'V')) moving += s.part;
  const int kicks = static_cast<int>(std::count(moving.begin(), moving.end(), 'V'));
  const bool shared = moving.size() > 1 && moving.front() == 'V' && moving.back() == 'V';
  return shared ? kicks - 1 : kicks;
}

int cost_in_rotations(const scheme_table& t) {
  const int n = static_cast<int>(t.stages.size());
  switch (t.splitting) {
    case split::abc: return n;
    case split::rs: return n + 1;
    case split::tv: return force_evaluations(t);
  }
  return n;
}

scheme_table parse_scheme_table(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte-order mark
  scheme_table t;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0, declared_stages = -1;
  std::set<std::string> seen;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();  // CRLF line endings
    line = trimmed(line);
    if (line.empty() || line[0] == '#') continue;
    const auto blank = line.find_first_of(" \t");
    const std::string key = line.substr(0, blank);
    const std::string rest = blank == std::string::npos ? "" : trimmed(line.substr(blank));
    if (key != "stage" && !seen.insert(key).second) fail(number, "'" + printable_text(key) + "' is given twice");
    if (key == "format_version") {
      if (rest != "1") fail(number, "format_version " + printable_text(rest) + " is not supported (only 1)");
    } else if (key == "name") {
      t.name = rest;
    } else if (key == "scheme" || key == "label" || key == "digits" || key == "residual" || key == "analytic_remainder") {
      // provenance, not needed to integrate
    } else if (key == "split") {
      if (rest == "ABC") t.splitting = split::abc;
      else if (rest == "RS") t.splitting = split::rs;
      else if (rest == "TV") t.splitting = split::tv;
      else fail(number, "split must be ABC, RS or TV, got '" + printable_text(rest) + "'");
    } else if (key == "word") {
      t.word = rest;
    } else if (key == "permutation") {
      t.permutation = rest;
    } else if (key == "order") {
      if (rest != "2" && rest != "4" && rest != "6") fail(number, "order must be 2, 4 or 6, got '" + printable_text(rest) + "'");
      t.order = rest[0] - '0';
    } else if (key == "symmetric") {
      if (rest != "true" && rest != "false") fail(number, "symmetric must be true or false");
      t.symmetric = rest == "true";
    } else if (key == "inertia") {
      if (!is_body_text(rest)) fail(number, "inertia must be three positive numbers I1 I2 I3, got '" + printable_text(rest) + "'");
      t.inertia = rest;
    } else if (key == "source") {
      t.source = rest;
    } else if (key == "stages") {
      if (rest.empty() || rest.find_first_not_of("0123456789") != std::string::npos || rest.size() > 4)
        fail(number, "stages must be a count, got '" + printable_text(rest) + "'");
      declared_stages = std::stoi(rest);
    } else if (key == "stage") {
      std::istringstream s(rest);
      std::string letter, name, value;
      s >> letter >> name >> value;
      if (letter.size() != 1) fail(number, "a stage needs a one-letter part, got '" + printable_text(letter) + "'");
      if (!is_decimal(value)) fail(number, "stage value '" + printable_text(value) + "' is not a finite decimal number");
      t.stages.push_back({letter[0], name, value});
    } else {
      fail(number, "unknown key '" + printable_text(key) + "'");
    }
  }
  for (const char* required : {"format_version", "split", "word"})
    if (!seen.count(required)) throw std::invalid_argument(std::string("scheme table: no ") + required + " line");
  if (declared_stages >= 0 && declared_stages != static_cast<int>(t.stages.size()))
    throw std::invalid_argument("scheme table: " + std::to_string(declared_stages) + " stages declared, " +
                                std::to_string(t.stages.size()) + " given");
  check_scheme_table(t);
  return t;
}

std::string format_scheme_table(const scheme_table& t) {
  std::ostringstream out;
  out << "format_version 1\n";
  if (!t.name.empty()) out << "name " << t.name << "\n";
  out << "split " << split_name(t.splitting) << "\n"
      << "word " << t.word << "\n"
      << "permutation " << t.permutation << "\n"
      << "order " << t.order << "\n"
      << "symmetric " << (t.symmetric ? "true" : "false") << "\n";
  if (!t.inertia.empty()) out << "inertia " << t.inertia << "\n";
  if (!t.source.empty()) out << "source " << t.source << "\n";
  out << "stages " << t.stages.size() << "\n";
  for (const auto& s : t.stages) out << "stage " << s.part << " " << (s.name.empty() ? "-" : s.name) << " " << s.value << "\n";
  return out.str();
}

void check_scheme_table(const scheme_table& t) {
  const std::string letters = t.splitting == split::abc ? "ABC" : t.splitting == split::rs ? "RS" : "TV";
  // a TV table may hold a thermostat (thermostat_tables.hpp): O, the Ornstein-Uhlenbeck step; N, a Nose-Hoover chain
  const std::string optional = t.splitting == split::tv ? "ON" : "";
  const std::string name = printable_text(t.name);
  if (t.stages.empty()) throw std::invalid_argument("scheme table " + name + ": no stages");
  if (t.word.size() != t.stages.size())
    throw std::invalid_argument("scheme table " + name + ": the word has " + std::to_string(t.word.size()) +
                                " letters but there are " + std::to_string(t.stages.size()) + " stages");
  static const std::vector<std::string> perms = {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"};
  if (std::find(perms.begin(), perms.end(), t.permutation) == perms.end())
    throw std::invalid_argument("scheme table " + name + ": unknown permutation '" + printable_text(t.permutation) + "'");
  if (t.splitting == split::tv && t.permutation != "ABC")
    throw std::invalid_argument("scheme table " + name + ": a TV table (free flight and kick) has no body axes to permute, got '" +
                                printable_text(t.permutation) + "'");
  std::map<char, long double> sum, size;
  std::map<char, int> count;
  std::vector<long double> value(t.stages.size());
  for (std::size_t i = 0; i < t.stages.size(); ++i) {
    const char p = t.stages[i].part;
    if ((letters + optional).find(p) == std::string::npos)
      throw std::invalid_argument("scheme table " + name + ": part '" + printable_text(std::string(1, p)) + "' is not in the " +
                                  letters + " splitting" + (optional.empty() ? "" : " (nor a thermostat's " + optional + ")"));
    if (t.word[i] != p)
      throw std::invalid_argument("scheme table " + name + ": stage " + std::to_string(i + 1) + " is " +
                                  std::string(1, p) + " but the word says " + printable_text(std::string(1, t.word[i])));
    value[i] = decimal_value(t.stages[i].value);
    if (std::isnan(value[i]))
      throw std::invalid_argument("scheme table " + name + ": stage " + std::to_string(i + 1) + " value '" +
                                  printable_text(t.stages[i].value) + "' is not a finite decimal number");
    sum[p] += value[i];
    size[p] += std::fabs(value[i]);
    ++count[p];
  }
  // Σ = 1 to what the integrator's double arithmetic resolves: the sum of n rounded terms is off
  // by at most n·ε·Σ|c| (ε = DBL_EPSILON), so the tolerance grows with the stages and their sizes.
  for (const char p : letters + optional) {
    if (!count.count(p)) {
      if (optional.find(p) != std::string::npos) continue;  // a thermostat's letter need not act
      throw std::invalid_argument("scheme table " + name + ": part " + std::string(1, p) + " never acts");
    }
    const long double tolerance = count[p] * static_cast<long double>(DBL_EPSILON) * size[p];
    if (!(std::fabs(sum[p] - 1.0L) <= tolerance))
      throw std::invalid_argument("scheme table " + name + ": the coefficients of part " + std::string(1, p) +
                                  " sum to " + std::to_string(static_cast<double>(sum[p])) + ", not 1 (first-order condition)");
  }
  if (t.symmetric)
    for (std::size_t i = 0, j = t.stages.size() - 1; i < j; ++i, --j)
      if (t.stages[i].part != t.stages[j].part ||
          !(std::fabs(value[i] - value[j]) <= static_cast<long double>(DBL_EPSILON) * (std::fabs(value[i]) + std::fabs(value[j]))))
        throw std::invalid_argument("scheme table " + name + ": declared symmetric but stages " + std::to_string(i + 1) +
                                    " and " + std::to_string(j + 1) + " differ");
}

}  // namespace rotlie::schemes
