#include "rotlie/reports/map_io.hpp"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/rational_io.h>

#include <sstream>

#include "rotlie/lie/exact_number.hpp"
#include "rotlie/solver/scheme_table.hpp"

namespace rotlie::reports {

std::string fraction_text(const cln::cl_RA& x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

namespace {

nlohmann::ordered_json body_fields(const solver::grid_body& g, const std::string& family) {
  nlohmann::ordered_json j;
  j["s"] = fraction_text(g.s);
  j["t"] = fraction_text(g.t);
  j["I"] = {fraction_text(g.body.I[0]), fraction_text(g.body.I[1]), fraction_text(g.body.I[2])};
  j["family"] = family;
  return j;
}

}  // namespace

nlohmann::ordered_json map_header(const std::string& family, int K, std::size_t bodies, const std::string& method) {
  nlohmann::ordered_json j;
  j["rotlie_map"] = map_format_version;
  j["family"] = family;
  j["grid"] = K;
  j["bodies"] = bodies;
  j["reference"] = solver::map_reference_scheme;
  j["method"] = method;
  return j;
}

nlohmann::ordered_json map_line(const solver::grid_body& g, const solver::map_point& p) {
  auto j = body_fields(g, p.family);
  const std::string reference = solver::map_reference_scheme;
  j["best"] = p.best ? nlohmann::ordered_json(solver::scheme_table_name(*p.best)) : nlohmann::ordered_json();
  j["remainder"] = p.best ? nlohmann::ordered_json(p.best->analytic_remainder) : nlohmann::ordered_json();
  j["reference"] = reference + ":" + p.reference_permutation;
  j["reference_remainder"] = p.reference_remainder;
  j["ratio"] = p.ratio ? nlohmann::ordered_json(*p.ratio) : nlohmann::ordered_json();
  j["flat"] = g.flat;
  nlohmann::ordered_json singular = nlohmann::ordered_json::array();
  for (const auto& s : p.singular) singular.push_back(s.scheme + ":" + s.permutation);
  j["singular"] = singular;
  // The screened path knows the solutions of the systems it confirmed only (screened_map.hpp).
  j["real_solutions"] = p.complete ? nlohmann::ordered_json(p.real_solutions) : nlohmann::ordered_json();
  nlohmann::ordered_json perms = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < p.per_permutation.size(); ++k) {
    const auto& b = p.per_permutation[k];
    nlohmann::ordered_json e;
    e["perm"] = b.permutation;
    e["best"] = b.best && b.confirmed ? nlohmann::ordered_json(solver::scheme_table_name(*b.best)) : nlohmann::ordered_json();
    if (b.best && !b.confirmed) e["unconfirmed_best"] = b.best->scheme + ":" + b.best->permutation;  // label unknown
    e["remainder"] = b.best ? nlohmann::ordered_json(b.best->analytic_remainder) : nlohmann::ordered_json();
    e["reference_remainder"] = p.reference_remainders[k];
    perms.push_back(std::move(e));
  }
  j["permutations"] = perms;
  return j;
}

nlohmann::ordered_json map_failure_line(const solver::grid_body& g, const std::string& family, const std::string& why) {
  auto j = body_fields(g, family);
  j["failed"] = why;
  return j;
}

std::optional<std::pair<int, int>> map_line_indices(const nlohmann::json& line, int K) {
  if (!line.is_object() || !line.contains("s") || !line.contains("t") || !line["s"].is_string() || !line["t"].is_string())
    return std::nullopt;
  const auto s = lie::parse_exact_number(line["s"].get<std::string>());
  const auto t = lie::parse_exact_number(line["t"].get<std::string>());
  if (!s || !t) return std::nullopt;
  const cln::cl_RA is = *s * K, jt = *t * K;
  if (cln::denominator(is) != 1 || cln::denominator(jt) != 1) return std::nullopt;
  if (is < 0 || is > K || jt < 0 || jt > K) return std::nullopt;
  const long i = cln::cl_I_to_long(cln::the<cln::cl_I>(is)), j = cln::cl_I_to_long(cln::the<cln::cl_I>(jt));
  if (i < 0 || i > K || j < 0 || j > K) return std::nullopt;
  return std::pair<int, int>(static_cast<int>(i), static_cast<int>(j));
}

}  // namespace rotlie::reports
