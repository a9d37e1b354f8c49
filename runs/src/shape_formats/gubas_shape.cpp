#include "gubas_shape.hpp"

#include <algorithm>
#include <charconv>
#include <climits>
#include <sstream>
#include <vector>

#include "orientation.hpp"
#include "rotlie/runs/user_input.hpp"
#include "vertex_text.hpp"

namespace rotlie::runs::shape_formats {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(trimmed(f));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

models::polyhedron parse_gubas_shape(const std::string& vertices_text, const std::string& facets_text, const std::string& vertices_name,
                                     const std::string& facets_name) {
  models::polyhedron p;
  std::istringstream vertices(vertices_text);
  long n = 0;
  for (std::string line; std::getline(vertices, line);) {
    ++n;
    if (trimmed(line).empty()) continue;
    const auto refuse = [&](const std::string& why) { throw bad_input(vertices_name + ", line " + std::to_string(n) + ": " + why); };
    const auto fields = fields_of(line);
    if (fields.size() != 4) refuse("a GUBAS vertex row is 'id, x, y, z' (four fields), not " + std::to_string(fields.size()));
    std::istringstream xyz(fields[1] + " " + fields[2] + " " + fields[3]);
    auto v = vertex_of(xyz, refuse);
    for (auto& x : v) x /= 1000;  // metres to km
    p.vertices.push_back(v);
  }
  std::istringstream facets(facets_text);
  n = 0;
  for (std::string line; std::getline(facets, line);) {
    ++n;
    if (trimmed(line).empty()) continue;
    const auto refuse = [&](const std::string& why) { throw bad_input(facets_name + ", line " + std::to_string(n) + ": " + why); };
    const auto fields = fields_of(line);
    if (fields.size() < 3 || std::any_of(fields.begin() + 3, fields.end(), [](const std::string& f) { return !f.empty(); }))
      refuse("a GUBAS facet row is three vertex numbers");
    std::array<int, 3> f{};
    for (std::size_t k = 0; k < 3; ++k) {
      long id = 0;
      const auto [end, error] = std::from_chars(fields[k].data(), fields[k].data() + fields[k].size(), id);
      if (error != std::errc() || end != fields[k].data() + fields[k].size()) refuse("'" + one_line(fields[k]) + "' is not a vertex number");
      f[k] = static_cast<int>(std::clamp<long>(id - 1, -1, INT_MAX));  // out of range: polyhedron_body names it
    }
    p.facets.push_back(f);
  }
  if (!turn_outward(p)) throw bad_input(vertices_name + " and " + facets_name + ": the GUBAS model encloses no volume");
  return p;
}

}  // namespace rotlie::runs::shape_formats
