// One shard of the measured-ratio study: maps_truth_study K SHARD SHARDS > part.csv. Bodies
// k ≡ SHARD (mod SHARDS) of runs::truth_bodies(K), one CSV row per family as it is measured.
// Separate processes because the exact solver (GiNaC, CLN) is not thread-safe.
#include <ctime>
#include <iostream>
#include <string>

#include "rotlie/runs/maps_truth.hpp"
#include "rotlie/runs/maps_truth_csv.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: maps_truth_study K SHARD SHARDS\n";
    return 2;
  }
  const int K = std::stoi(argv[1]), shard = std::stoi(argv[2]), shards = std::stoi(argv[3]);
  const auto bodies = rotlie::runs::truth_bodies(K);
  if (shard == 0) std::cout << rotlie::runs::truth_csv_header() << std::flush;
  for (std::size_t k = static_cast<std::size_t>(shard); k < bodies.size(); k += static_cast<std::size_t>(shards)) {
    const std::clock_t start = std::clock();
    const auto b = rotlie::runs::measure_body_truth(bodies[k], {"N", "P"});
    std::cout << rotlie::runs::truth_csv_rows(b) << std::flush;
    std::cerr << "body " << k + 1 << "/" << bodies.size() << ": "
              << static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC << " s CPU\n";
  }
  return 0;
}
