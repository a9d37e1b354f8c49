#pragma once
// A map file's lines against the exact solver: at bodies drawn at random (a fixed seed) from the
// lines, the exact solver's best integrator (scheme, permutation, label), best reference
// permutation, count of real solutions and best per permutation against the line. A screened map
// (solver/screened_map.hpp) leaves the count and the labels of unconfirmed per-permutation bests
// out: those are compared by scheme and permutation and counted apart.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rotlie::runs {

struct map_check_result {
  int checked = 0;
  int disagreements = 0;                  ///< bodies where anything compared differs
  std::vector<std::string> differences;   ///< one line per such body
  int unconfirmed = 0;                    ///< per-permutation bests the line leaves unlabelled
  int unconfirmed_differ = 0;             ///< of which another scheme or permutation than the exact solver's
};

/// `bodies`: body lines of one map of `family` on grid K. At most `count` of them, shuffled by `seed`.
map_check_result check_map_lines(const std::string& family, int K, std::vector<nlohmann::json> bodies, std::size_t count,
                                 std::uint64_t seed, const std::function<void(int done, int of)>& progress = {});

}  // namespace rotlie::runs
