#include "rotlie/runs/solve_io.hpp"

#include <cln/rational_io.h>
#include <cln/real.h>

#include <cstdio>
#include <sstream>

#include "rotlie/lie/exact_number.hpp"

namespace rotlie::runs {
namespace {

std::string text(const cln::cl_RA& x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// The relative residual as a number; below a double's normal range (--digits near 300) as its
// decimal text, which a double would round to 0 or not hold at all.
nlohmann::json residual_json(const cln::cl_RA& r) {
  static const cln::cl_RA smallest = cln::recip(cln::expt(cln::cl_RA(10), 300));
  if (!cln::zerop(r) && r < smallest) return lie::to_decimal(r, 3);
  return cln::double_approx(r);
}

}  // namespace

nlohmann::json solve_json(const solver::family_result& r, const lie::moments_of_inertia& body, const std::string& family,
                          int digits) {
  nlohmann::json solutions = nlohmann::json::array();
  for (const auto& s : r.solutions) {
    nlohmann::json coefficients = nlohmann::json::object();
    for (const auto& [name, v] : s.coefficients) coefficients[name] = lie::to_decimal(v, digits);
    solutions.push_back({{"scheme", s.scheme},
                         {"perm", s.permutation},
                         {"label", s.label},
                         {"word", s.layout.permuted},
                         {"coefficients", coefficients},
                         {"analytic_remainder", s.analytic_remainder},
                         {"residual", residual_json(s.residual)}});
  }
  nlohmann::json systems = nlohmann::json::array();
  for (const auto& s : r.systems) {
    nlohmann::json j = {{"scheme", s.scheme}, {"perm", s.permutation}, {"real_solutions", s.real_solutions},
                        {"degenerate", s.degenerate}};
    if (!s.note.empty()) j["note"] = s.note;
    j["eliminant_degree"] = s.eliminant_degree;
    if (!s.eliminated.empty()) {
      j["eliminated"] = s.eliminated;
      j["discarded"] = s.discarded;
    }
    if (s.uncertified > 0) j["uncertified"] = s.uncertified;
    systems.push_back(std::move(j));
  }
  return {{"inertia", {text(body.I[0]), text(body.I[1]), text(body.I[2])}},
          {"family", family},
          {"real_solutions", r.solutions.size()},
          {"solutions", solutions},
          {"systems", systems},
          {"seconds", {{"conditions", r.seconds_conditions},
                       {"elimination", r.seconds_elimination},
                       {"roots", r.seconds_roots},
                       {"analytic_remainder", r.seconds_remainder}}}};
}

std::string solve_text(const solver::family_result& r, const lie::moments_of_inertia& body, int digits, std::size_t rows) {
  std::ostringstream out;
  out << "Body I = (" << text(body.I[0]) << ", " << text(body.I[1]) << ", " << text(body.I[2]) << "): "
      << r.solutions.size() << " real solutions in " << r.systems.size() << " systems, ranked by analytic remainder ‖H_R5‖\n\n";
  char line[256];
  std::snprintf(line, sizeof line, "%4s  %-14s %-12s %-13s %s\n", "rank", "integrator", "word", "‖H_R5‖", "free coefficients");
  out << line;
  std::size_t rank = 0;
  for (const auto& s : r.solutions) {
    if (++rank > rows) break;
    std::string free;
    for (const auto& f : s.free)
      for (const auto& [n, v] : s.coefficients)
        if (n == f) free += (free.empty() ? "" : "  ") + n + " = " + lie::to_decimal(v, std::min(digits, 25));
    std::snprintf(line, sizeof line, "%4zu  %-14s %-12s %-13.4e ", rank, s.name().c_str(), s.layout.permuted.c_str(),
                  s.analytic_remainder);
    out << line << free << "\n";
  }
  if (r.solutions.size() > rows) out << "… " << r.solutions.size() - rows << " more (all of them with --json or --out)\n";
  for (const auto& s : r.systems)
    if (s.degenerate)
      out << "\n" << s.scheme << " " << s.permutation << ": degenerate — " << s.note;
    else if (s.uncertified > 0)
      out << "\n" << s.scheme << " " << s.permutation << ": " << s.note;
  out << "\n";
  return out.str();
}

}  // namespace rotlie::runs
