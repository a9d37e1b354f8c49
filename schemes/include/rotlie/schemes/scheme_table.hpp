#pragma once
// A splitting scheme as plain data (docs/scheme_table_format.md): the part letter and the
// coefficient of every stage, in time order, with the decimal text kept so that any scalar type
// (double, long double, float128) can read it at full precision.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace rotlie::schemes {

enum class split { abc, rs };

struct stage {
  char part = 'A';        ///< A, B, C (ABC splitting, letters already permuted) or R, S
  std::string name;       ///< a1, b1, … (informative)
  std::string value;      ///< decimal text, ≥ 40 digits for solver tables
};

struct scheme_table {
  std::string name;                  ///< e.g. N2:BAC:2 or RS4-S5-McLachlan:CBA
  split splitting = split::abc;
  std::string word;                  ///< stage letters in time order
  std::string permutation = "ABC";   ///< RS: which body axes play 1 (R), 2 (subtracted), 3 (S)
  int order = 2;                     ///< declared order
  bool symmetric = true;
  std::string inertia;               ///< the body a dedicated scheme was solved for ("" for reference schemes)
  std::string source;
  std::vector<stage> stages;
};

/// Parses format version 1; throws std::invalid_argument naming the line and the problem.
scheme_table parse_scheme_table(std::string_view text);

/// The loader's contract: a known split, letters of that split, Σ of each part's coefficients = 1
/// (to 1e-15, in long double), and the palindrome when the table says symmetric. Throws
/// std::invalid_argument with a one-line reason.
void check_scheme_table(const scheme_table& t);

/// Body axis (0, 1, 2) of a permutation letter: the permutation XYZ sends A → X, B → Y, C → Z.
int axis_of_letter(char letter);

/// For an RS table: the body axes playing roles 1 (R), 2 (the moment subtracted) and 3 (S).
std::array<int, 3> rs_axes(const scheme_table& t);

/// Rotations about principal axes per step (section 4.1): ABC N stages cost N·C0; RS N stages
/// cost (N + 1)·C0, the rotations about the angular momentum being gathered into one.
int cost_in_rotations(const scheme_table& t);

}  // namespace rotlie::schemes
