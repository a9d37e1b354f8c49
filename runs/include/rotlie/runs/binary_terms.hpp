#pragma once
// The force terms a binary run can add beside the mutual gravity, each registered once (one file in
// runs/src/binary_terms/ and one line in binary_term_list.hpp): its name is the request's field (the
// command line's --NAME, Python's NAME=, a sweep line's "NAME"), its parameters are numbers with
// units, and its values at the final state join the JSON under its name. No front end holds code of
// its own for a term.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "rotlie/models/scenes/binary_system.hpp"

namespace rotlie::runs {

/// A term as the floor holds it: the numeric contract (models::binary_term) and what it reports.
class registered_term : public models::binary_term<double> {
 public:
  /// Its values at (x, t), for the JSON (an object).
  virtual nlohmann::json values(const models::binary_state<double>& x, double t) const = 0;
};

struct term_parameter {
  std::string name, unit;
  std::vector<std::pair<std::string, double>> named{};  ///< words accepted in place of the number (any case)
};

struct binary_term_description {
  std::string name;                       ///< the request's field
  std::string summary;                    ///< one line for --help and Python's docstring
  std::vector<term_parameter> parameters;  ///< given in this order, comma-separated
  std::string example;                     ///< values the report runs it with on Didymos (empty: none), and where they come from
  /// The term for these values (as many as parameters, checked here: throws bad_input naming
  /// --NAME), acting on the pair `system`.
  std::shared_ptr<const registered_term> (*make)(const std::vector<double>& values, const models::binary_system<double>& system);
};

/// Every registered term, in the list's order.
const std::vector<binary_term_description>& binary_terms();

/// The term named so, or nullptr.
const binary_term_description* binary_term_named(const std::string& name);

/// The values' text with each parameter's words (e.g. the flyby's `earth`) replaced by their numbers.
std::string with_named_values(const binary_term_description& term, const std::string& text);

/// "NAME a,e,…": the syntax with units, for help texts.
std::string term_syntax(const binary_term_description& term);

}  // namespace rotlie::runs
