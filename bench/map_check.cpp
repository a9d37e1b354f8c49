// The check of a map file against the exact solver: at M grid bodies drawn at random (fixed seed)
// from the file, the exact solver's best integrator, best per permutation (scheme, permutation,
// label), best reference permutation and number of real solutions against the file's line.
//   map_check FILE M [SEED]
// Prints every disagreement and a summary; exits 1 when there is one.
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "rotlie/reports/map_io.hpp"
#include "rotlie/solver/body_grid.hpp"
#include "rotlie/solver/body_map.hpp"
#include "rotlie/solver/continued_map.hpp"
#include "rotlie/solver/scheme_table.hpp"

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
  const std::size_t M = std::min<std::size_t>(std::stoul(argv[2]), bodies.size());
  std::mt19937_64 random(argc > 3 ? std::stoull(argv[3]) : 14);
  std::shuffle(bodies.begin(), bodies.end(), random);
  int disagreements = 0;
  const auto name = [](const std::optional<rotlie::solver::dedicated_solution>& s) {
    return s ? rotlie::solver::scheme_table_name(*s) : std::string();
  };
  for (std::size_t k = 0; k < M; ++k) {
    const auto& b = bodies[k];
    const auto ij = rotlie::reports::map_line_indices(b, K);
    const auto g = rotlie::solver::grid_point(K, ij->first, ij->second);
    const auto exact = rotlie::solver::compute_map_point(g.body, family, rotlie::solver::map_digits);
    std::vector<std::string> differ;
    if (b.value("best", std::string()) != name(exact.best)) differ.push_back("best " + b.value("best", std::string()) + " vs " + name(exact.best));
    if (b.at("reference").get<std::string>() != std::string(rotlie::solver::map_reference_scheme) + ":" + exact.reference_permutation)
      differ.push_back("reference");
    if (b.at("real_solutions").get<int>() != exact.real_solutions) differ.push_back("real solutions");
    for (std::size_t p = 0; p < exact.per_permutation.size(); ++p) {
      const auto& e = b.at("permutations")[p];
      const std::string file = e.at("best").is_null() ? std::string() : e.at("best").get<std::string>();
      if (file != name(exact.per_permutation[p].best)) differ.push_back("best at " + exact.per_permutation[p].permutation);
    }
    if (!differ.empty()) {
      ++disagreements;
      std::cout << "s = " << b.at("s").get<std::string>() << ", t = " << b.at("t").get<std::string>() << ":";
      for (const auto& d : differ) std::cout << " " << d << ";";
      std::cout << "\n";
    }
  }
  std::cout << "family " << family << " at --grid " << K << ": " << M << " bodies checked against the exact solver, "
            << disagreements << " disagreement(s)\n";
  return disagreements == 0 ? 0 : 1;
}
