#pragma once
// Replayable randomness for tests: the seed comes from ROTLIE_SEED when set, otherwise from
// the clock, and is always printed so that a failure can be replayed exactly.
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

namespace rotlie::test {

inline std::uint64_t test_seed(const std::string& test_name) {
  std::uint64_t seed;
  if (const char* env = std::getenv("ROTLIE_SEED"))
    seed = std::strtoull(env, nullptr, 10);
  else
    seed = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) % 1000000007ULL;
  std::cout << test_name << ": seed " << seed << " (replay with ROTLIE_SEED=" << seed << ")" << std::endl;
  return seed;
}

}  // namespace rotlie::test
