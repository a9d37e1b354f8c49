#pragma once
// The binary scene's request, each field described once: the command line's options, Python's
// keywords (and the signature help() shows), a sweep line's keys and the docs come from this table.
// The defaults are binary_request's own (binary_run.hpp); the registered force terms
// (binary_terms.hpp) join every front end beside these fields.
#include <string>
#include <string_view>
#include <vector>

#include "rotlie/runs/binary_run.hpp"

namespace rotlie::runs {

struct binary_field {
  enum class kind { text, number, numbers, integer, flag, state };
  std::string name;     ///< Python's keyword, a sweep line's key
  std::string option;   ///< the command line's option
  kind type = kind::text;
  std::string python_type;     ///< the annotation help() shows
  std::string python_default;  ///< as Python writes it; empty: required
  std::string help;
  std::string cli_type;        ///< the value's form in the command line's --help (KM, SECONDS, REL[,RAD]); none for a flag
  std::string binary_request::*text = nullptr;  ///< where a text, number, integer or state (its file) goes
  bool binary_request::*flag = nullptr;         ///< where a flag goes
  bool cli_required = false;
  bool run_only = false;  ///< a run's, not a held simulation's (T, every)
  bool sweep = true;      ///< a sweep line may give it
};

/// Every field, in the order the help lists them.
const std::vector<binary_field>& binary_fields();

/// The field of this name (or the command line's spelling without dashes: primary-period), or nullptr.
const binary_field* binary_field_named(std::string_view name);

}  // namespace rotlie::runs
