#include "rotlie/runs/free_body_io.hpp"

#include <cmath>

namespace rotlie::runs {
namespace {

nlohmann::json point_json(const models::protocol_point& p, double cpu) {
  return {{"h", p.h}, {"h_over_C", p.h_over_cost}, {"error", p.error}, {"cpu_s", cpu}, {"reference_error", p.reference_error}};
}

}  // namespace

nlohmann::json integrate_json(const runs::integrate_result& r) {
  return nlohmann::json{{"scheme", r.scheme}, {"slope", nullptr}, {"points", {point_json(r.point, r.cpu_s)}}};
}

nlohmann::json order_json(const runs::order_result& r) {
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 0; i < r.measurement.points.size(); ++i) points.push_back(point_json(r.measurement.points[i], r.cpu_s[i]));
  nlohmann::json j{{"scheme", r.scheme}, {"scalar", r.scalar}, {"declared_order", r.declared_order}, {"points", points}};
  j["slope"] = std::isfinite(r.measurement.slope) ? nlohmann::json(r.measurement.slope) : nlohmann::json(nullptr);
  return j;
}

nlohmann::json exact_json(const runs::exact_result& r) {
  const auto& s = r.state;
  nlohmann::json Q = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) Q.push_back({s.Q(i, 0), s.Q(i, 1), s.Q(i, 2)});
  return nlohmann::json{{"T", r.T}, {"G", {s.G[0], s.G[1], s.G[2]}}, {"Q", Q}, {"error_estimate", r.error_estimate}};
}

}  // namespace rotlie::runs
