#pragma once
// A scheme as a user names it, turned into a scheme table: a reference scheme
// (RS4-S5-McLachlan:CBA), a dedicated solution SCHEME:PERM:LABEL solved for the body given
// (N2:BAC:2, P1:BAC:5), or the path of a scheme-table file. This is where the symbolic and numeric
// sides meet, through text.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/schemes/scheme_table.hpp"

namespace rotlie::runs {

/// The largest scheme-table file read (the largest solver table is a few kB); larger ones are refused.
inline constexpr std::uintmax_t max_table_bytes = 1 << 20;

/// What to do with a scheme-table file solved for another body (its `inertia` line, compared up
/// to a common factor): refuse it and name --force (integrate, order), refuse it where the command
/// has no such option (md), or use it with a warning (--force given).
enum class foreign_table { refuse_unless_forced, refuse, use_with_warning };

/// Receives the one-line warning of a foreign table used anyway.
using warning_sink = std::function<void(const std::string&)>;

/// Throws bad_input for an unknown name, a bad label or a file that fails its checks; `warn`
/// (default: standard error) receives the warning of foreign_table::use_with_warning.
schemes::scheme_table scheme_named(const std::string& name, const lie::moments_of_inertia& body,
                                   foreign_table policy = foreign_table::refuse_unless_forced,
                                   const warning_sink& warn = {});

/// --perm of the solving commands: all (every permutation, in the paper's order) or one name.
std::vector<std::string> permutations_named(const std::string& perm);

}  // namespace rotlie::runs
