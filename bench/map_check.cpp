// The check of a map file against the exact solver: at M grid bodies drawn at random (fixed seed)
// from the file, the exact solver's best integrator, best per permutation (scheme, permutation,
// label), best reference permutation and number of real solutions against the file's line. A
// screened map (screened_map.hpp) leaves the count and the labels of unconfirmed per-permutation
// bests out: those are compared by scheme and permutation and reported apart.
//   map_check FILE M [SEED]
// Prints every disagreement and a summary; exits 1 when there is one.
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rotlie/runs/map_check.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: map_check FILE M [SEED]\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::string line;
  std::getline(in, line);
  const auto header = nlohmann::json::parse(line);
  const std::string family = header.at("family");
  const int K = header.at("grid");
  std::vector<nlohmann::json> bodies;
  while (std::getline(in, line)) bodies.push_back(nlohmann::json::parse(line));
  const auto r = rotlie::runs::check_map_lines(family, K, bodies, std::stoul(argv[2]), argc > 3 ? std::stoull(argv[3]) : 14);
  for (const auto& d : r.differences) std::cout << d << "\n";
  std::cout << "family " << family << " at --grid " << K << ": " << r.checked << " bodies checked against the exact solver, "
            << r.disagreements << " disagreement(s)\n";
  if (r.unconfirmed > 0)
    std::cout << "unconfirmed per-permutation bests (scheme and permutation only): " << r.unconfirmed_differ << " of "
              << r.unconfirmed << " differ\n";
  return r.disagreements == 0 ? 0 : 1;
}
