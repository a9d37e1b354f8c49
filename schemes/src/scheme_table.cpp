#include "rotlie/schemes/scheme_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

namespace rotlie::schemes {
namespace {

[[noreturn]] void fail(int line, const std::string& why) {
  throw std::invalid_argument("scheme table line " + std::to_string(line) + ": " + why);
}

bool is_decimal(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  const long double v = std::strtold(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}

}  // namespace

int axis_of_letter(char letter) {
  if (letter < 'A' || letter > 'C') throw std::invalid_argument(std::string("not an axis letter: ") + letter);
  return letter - 'A';
}

std::array<int, 3> rs_axes(const scheme_table& t) {
  return {axis_of_letter(t.permutation.at(0)), axis_of_letter(t.permutation.at(1)), axis_of_letter(t.permutation.at(2))};
}

int cost_in_rotations(const scheme_table& t) {
  const int n = static_cast<int>(t.stages.size());
  return t.splitting == split::rs ? n + 1 : n;
}

scheme_table parse_scheme_table(std::string_view text) {
  scheme_table t;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0, declared_stages = -1;
  bool have_version = false, have_split = false, have_word = false;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    std::string key;
    f >> key;
    std::string rest;
    std::getline(f, rest);
    if (!rest.empty() && rest[0] == ' ') rest.erase(0, rest.find_first_not_of(' '));
    if (key == "format_version") {
      if (rest != "1") fail(number, "format_version " + rest + " is not supported (only 1)");
      have_version = true;
    } else if (key == "name") {
      t.name = rest;
    } else if (key == "scheme" || key == "label" || key == "digits" || key == "residual" || key == "analytic_remainder") {
      // provenance, not needed to integrate
    } else if (key == "split") {
      if (rest == "ABC") t.splitting = split::abc;
      else if (rest == "RS") t.splitting = split::rs;
      else fail(number, "split must be ABC or RS, got '" + rest + "'");
      have_split = true;
    } else if (key == "word") {
      t.word = rest;
      have_word = true;
    } else if (key == "permutation") {
      t.permutation = rest;
    } else if (key == "order") {
      if (rest != "2" && rest != "4") fail(number, "order must be 2 or 4, got '" + rest + "'");
      t.order = std::stoi(rest);
    } else if (key == "symmetric") {
      if (rest != "true" && rest != "false") fail(number, "symmetric must be true or false");
      t.symmetric = rest == "true";
    } else if (key == "inertia") {
      t.inertia = rest;
    } else if (key == "source") {
      t.source = rest;
    } else if (key == "stages") {
      if (rest.empty() || rest.find_first_not_of("0123456789") != std::string::npos || rest.size() > 4)
        fail(number, "stages must be a count, got '" + rest + "'");
      declared_stages = std::stoi(rest);
    } else if (key == "stage") {
      std::istringstream s(rest);
      std::string letter, name, value;
      s >> letter >> name >> value;
      if (letter.size() != 1) fail(number, "a stage needs a one-letter part, got '" + letter + "'");
      if (!is_decimal(value)) fail(number, "stage value '" + value + "' is not a finite decimal number");
      t.stages.push_back({letter[0], name, value});
    } else {
      fail(number, "unknown key '" + key + "'");
    }
  }
  if (!have_version) throw std::invalid_argument("scheme table: no format_version line");
  if (!have_split) throw std::invalid_argument("scheme table: no split line");
  if (!have_word) throw std::invalid_argument("scheme table: no word line");
  if (declared_stages >= 0 && declared_stages != static_cast<int>(t.stages.size()))
    throw std::invalid_argument("scheme table: " + std::to_string(declared_stages) + " stages declared, " +
                                std::to_string(t.stages.size()) + " given");
  check_scheme_table(t);
  return t;
}

void check_scheme_table(const scheme_table& t) {
  const std::string letters = t.splitting == split::abc ? "ABC" : "RS";
  if (t.stages.empty()) throw std::invalid_argument("scheme table " + t.name + ": no stages");
  if (t.word.size() != t.stages.size())
    throw std::invalid_argument("scheme table " + t.name + ": the word has " + std::to_string(t.word.size()) +
                                " letters but there are " + std::to_string(t.stages.size()) + " stages");
  static const std::vector<std::string> perms = {"ABC", "BCA", "CAB", "ACB", "CBA", "BAC"};
  if (std::find(perms.begin(), perms.end(), t.permutation) == perms.end())
    throw std::invalid_argument("scheme table " + t.name + ": unknown permutation '" + t.permutation + "'");
  std::map<char, long double> sum;
  for (std::size_t i = 0; i < t.stages.size(); ++i) {
    const char p = t.stages[i].part;
    if (letters.find(p) == std::string::npos)
      throw std::invalid_argument("scheme table " + t.name + ": part '" + std::string(1, p) + "' is not in the " +
                                  letters + " splitting");
    if (t.word[i] != p)
      throw std::invalid_argument("scheme table " + t.name + ": stage " + std::to_string(i + 1) + " is " +
                                  std::string(1, p) + " but the word says " + std::string(1, t.word[i]));
    sum[p] += std::strtold(t.stages[i].value.c_str(), nullptr);
  }
  for (const char p : letters) {
    if (!sum.count(p)) throw std::invalid_argument("scheme table " + t.name + ": part " + std::string(1, p) + " never acts");
    if (std::fabs(sum[p] - 1.0L) > 1e-15L)
      throw std::invalid_argument("scheme table " + t.name + ": the coefficients of part " + std::string(1, p) +
                                  " sum to " + std::to_string(static_cast<double>(sum[p])) + ", not 1 (first-order condition)");
  }
  if (t.symmetric)
    for (std::size_t i = 0, j = t.stages.size() - 1; i < j; ++i, --j)
      if (t.stages[i].part != t.stages[j].part ||
          std::fabs(std::strtold(t.stages[i].value.c_str(), nullptr) - std::strtold(t.stages[j].value.c_str(), nullptr)) > 1e-15L)
        throw std::invalid_argument("scheme table " + t.name + ": declared symmetric but stages " + std::to_string(i + 1) +
                                    " and " + std::to_string(j + 1) + " differ");
}

}  // namespace rotlie::schemes
