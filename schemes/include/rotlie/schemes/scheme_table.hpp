#pragma once
// A splitting scheme as plain data (docs/scheme_table_format.md): the part letter and the
// coefficient of every stage, in time order, with the decimal text kept so that any scalar type
// (double, long double, float128) can read it at full precision.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/schemes/printable_text.hpp"

namespace rotlie::schemes {

/// abc, rs: the free rigid body (LV sections 2–3); tv: a body under forces and torques, T = free
/// flight (translation and free rotation), V = kick by the forces and torques (vZS eqs. 5–6).
enum class split { abc, rs, tv };

/// The split's name in the table text: ABC, RS or TV.
std::string split_name(split s);

struct stage {
  char part = 'A';        ///< A, B, C (ABC splitting, letters already permuted), R, S, or T, V
  std::string name;       ///< a1, b1, … (informative)
  std::string value;      ///< decimal text, ≥ 40 digits for solver tables
  friend bool operator==(const stage&, const stage&) = default;
};

struct scheme_table {
  std::string name;                  ///< e.g. N2:BAC:2 or RS4-S5-McLachlan:CBA
  split splitting = split::abc;
  std::string word;                  ///< stage letters in time order
  std::string permutation = "ABC";   ///< RS: which body axes play 1 (R), 2 (subtracted), 3 (S); TV: always ABC
  int order = 2;                     ///< declared order
  bool symmetric = true;
  std::string inertia;               ///< the body a dedicated scheme was solved for ("" for reference schemes)
  std::string source;
  std::vector<stage> stages;
  friend bool operator==(const scheme_table&, const scheme_table&) = default;
};

/// Parses format version 1 (LF or CRLF line endings, an optional UTF-8 byte-order mark), then
/// checks it (check_scheme_table); throws std::invalid_argument naming the line and the problem.
scheme_table parse_scheme_table(std::string_view text);

/// The table as format version 1 text: parse_scheme_table gives it back (provenance lines that the
/// parser skips, such as digits or residual, are not written).
std::string format_scheme_table(const scheme_table& t);

/// The loader's contract: a known split (a TV table keeps the permutation ABC), letters of that split, every part acting, stage values
/// finite decimals, Σ of each part's n coefficients c = 1 to n·ε·Σ|c| (ε = DBL_EPSILON, in long
/// double: what a double integrator resolves), and the palindrome to ε·(|c_i| + |c_j|) when the
/// table says symmetric. Throws std::invalid_argument with a one-line reason.
void check_scheme_table(const scheme_table& t);

/// Body axis (0, 1, 2) of a permutation letter: the permutation XYZ sends A → X, B → Y, C → Z.
int axis_of_letter(char letter);

/// For an RS table: the body axes playing roles 1 (R), 2 (the moment subtracted) and 3 (S).
std::array<int, 3> rs_axes(const scheme_table& t);

/// Force evaluations f per step of a TV table: its V stages, less one when the first and the last
/// stage are both V (the last kick's forces are the next step's first: first-same-as-last); a thermostat's
/// stages (O, N) move nothing, so the kicks on either side of one count once.
int force_evaluations(const scheme_table& t);

/// The cost of one step in the split's unit. ABC, RS: rotations about principal axes (LV section
/// 4.1): ABC N stages cost N·C0; RS N stages cost (N + 1)·C0, the rotations about the angular
/// momentum being gathered into one. TV: the force evaluations f (force_evaluations).
int cost_in_rotations(const scheme_table& t);

}  // namespace rotlie::schemes
