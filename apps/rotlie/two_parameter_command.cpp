// `rotlie solve --family Q|QRS`: the dedicated 4th-order family with two free parameters (13-stage ABC
// palindromes, 11-stage RS palindromes), each (word, permutation) searched for the local minima of
// ‖H_R5‖ (LV eq. (64)) on its surface H_R3 = 0, the best polished and certified; ranked.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "rotlie/lie/exact_number.hpp"
#include "rotlie/runs/output_file.hpp"
#include "rotlie/runs/two_parameter_io.hpp"
#include "rotlie/runs/family_names.hpp"
#include "rotlie/runs/two_parameter_solve.hpp"

namespace rotlie::app {
namespace {

std::string decimal(const cln::cl_RA& x) { return lie::to_decimal(x, 2); }

}  // namespace

int run_solve_two_parameter(const solve_options& options) {
  const auto solved = runs::solve_two_parameter(
      {options.family, options.scheme, options.perm, options.inertia, options.digits, options.starts, options.seed});
  const auto& result = solved.result;
  if (!options.out.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.out, ec);
    if (ec) throw std::runtime_error("cannot create the output folder " + options.out + ": " + ec.message());
    for (const auto& e : result.entries) {
      if (!e.polished) continue;
      std::string file = runs::two_parameter_name(e);
      std::replace(file.begin(), file.end(), ':', '_');
      runs::write_file_atomically(std::filesystem::path(options.out) / (file + ".scheme"),
                                     solved.table_text(e, "rotlie solve --family " + options.family));
    }
  }
  if (options.json) {
    std::cout << runs::two_parameter_json(result, options.family, solved.body, solved.digits, solved.search.starts).dump(2)
              << "\n";
    return 0;
  }
  std::cout << "Two free parameters at order 4 (" << options.family << ", " << result.entries.size() << " systems, "
            << solved.search.starts << " starts each, " << std::fixed << std::setprecision(1) << result.seconds << " s CPU)\n"
            << std::defaultfloat;
  std::cout << "rank  scheme  ||H_R5||  minima(hits of converged/starts)  projected-gradient  order-residual\n";
  int rank = 0;
  for (const auto& e : result.entries) {
    ++rank;
    std::cout << std::setw(4) << rank << "  " << runs::two_parameter_name(e) << "  ";
    if (!e.polished) {
      std::cout << "-  (" << e.note << ")\n";
      continue;
    }
    std::cout << std::setprecision(6) << e.best.remainder << "  " << e.search.minima.size() << " ("
              << e.search.minima.front().hits << " of " << e.search.converged << "/" << e.search.starts << ")  "
              << decimal(e.best.projected_gradient) << "  " << decimal(e.best.order_residual) << "\n";
  }
  if (result.entries.size() == 1) {  // one system: every distinct local minimum the search reached
    std::cout << "local minima of " << runs::two_parameter_name(result.entries.front()) << " (||H_R5||, hits, free coefficients):\n";
    for (const auto& m : result.entries.front().search.minima) {
      std::cout << "  " << std::setprecision(10) << m.remainder << "  " << m.hits << " ";
      for (long double v : m.x) std::cout << " " << std::setprecision(12) << static_cast<double>(v);
      std::cout << "\n";
    }
  }
  return 0;
}

}  // namespace rotlie::app
