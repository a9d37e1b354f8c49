// integrate, order and exact: the numeric core on the command line (DESIGN.md CLI table).
#include <nlohmann/json.hpp>

#include <boost/multiprecision/float128.hpp>

#include <cmath>
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "scheme_lookup.hpp"

namespace rotlie::app {
namespace {

constexpr long max_steps = 100'000'000;

long step_count(double total, double h) {
  const double n = total / h;
  if (n > static_cast<double>(max_steps))
    throw usage_error("T/h = " + std::to_string(n) + " steps is over the limit of " + std::to_string(max_steps));
  const long steps = std::lround(n);
  if (steps < 1 || std::abs(static_cast<double>(steps) * h - total) > 1e-9 * total)
    throw usage_error("--T must be a whole number of steps --h (T/h = " + std::to_string(n) + ")");
  return steps;
}

nlohmann::json point_json(double h, double h_over_c, double error, double cpu, double reference_error) {
  return {{"h", h}, {"h_over_C", h_over_c}, {"error", error}, {"cpu_s", cpu}, {"reference_error", reference_error}};
}

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

// The exact flow's time limit is a property of the arguments: a usage error, not a failure.
template <class T>
void check_time_limit(const models::exact_free_body<T>& exact, double total) {
  if (total > static_cast<double>(exact.max_time()))
    throw usage_error("--T = " + number(total) + " is beyond the exact flow's limit of " +
                      number(static_cast<double>(exact.max_time())) + " for this body and G0 (|ω| T ≤ 2^60 rad)");
}

void warn_reference(double error, double reference_error, const std::string& where) {
  std::cerr << "rotlie: warning: " << where << ": the exact reference's estimated error " << reference_error
            << " is not well below the measured error " << error
            << " (within a factor " << models::reference_margin << "): the figure may measure the reference rather than the scheme\n";
}

template <class T>
models::vec3<T> cast(const models::vec3<double>& v) {
  return {T(v[0]), T(v[1]), T(v[2])};
}

}  // namespace

int run_integrate(const integrate_options& o) {
  const auto body = parse_inertia_option(o.inertia);
  const auto table = lookup_scheme(o.scheme, body, o.force);
  const double h = parse_positive(o.h, "--h"), total = parse_positive(o.T, "--T");
  const long steps = step_count(total, h);
  const auto I = to_double(body);
  const auto initial = models::body_state<double>{models::mat3<double>::identity(), parse_momentum(o.G0)};
  const models::composition_stepper<double> stepper(table, I);
  const models::exact_free_body<double> exact(I, initial);
  check_time_limit(exact, total);
  progress_line progress;
  auto s = initial;
  double sum = 0, reference_sum = 0;
  for (long k = 1; k <= steps; ++k) {
    stepper.step(s, h);
    const auto r = exact.evaluate(static_cast<double>(k) * h);
    sum += models::distance(s.Q, r.state.Q);
    reference_sum += 3 * r.error_estimate;  // max abs entry → R^9 distance
    if (k % 1000000 == 0) progress.show("step " + std::to_string(k) + " of " + std::to_string(steps));
  }
  const double error = sum / static_cast<double>(steps), reference_error = reference_sum / static_cast<double>(steps);
  if (!std::isfinite(error)) throw std::runtime_error("the integration diverged (NaN): the step is beyond the scheme's stability limit");
  const models::protocol_point point{h, h / stepper.cost(), error, reference_error};
  if (!point.attributable()) warn_reference(error, reference_error, "h = " + number(h));
  const double cpu = models::cpu_seconds_per_unit_time(stepper, initial, h) * total;
  if (o.json) {
    std::cout << nlohmann::json{{"scheme", table.name}, {"slope", nullptr},
                                {"points", {point_json(h, h / stepper.cost(), error, cpu, reference_error)}}}.dump(2) << "\n";
  } else {
    std::cout << table.name << " (" << stepper.cost() << " C0 per step), h = " << h << ", T = " << total << ", "
              << steps << " steps\nmean attitude error " << error << " (exact reference: estimated error " << reference_error
              << ")\nCPU " << cpu << " s (stepping only)\n";
  }
  return 0;
}

namespace {
template <class T>
models::order_measurement order_in(const schemes::scheme_table& table, const lie::moments_of_inertia& body,
                                   const models::vec3<double>& g0, double total, int first, int last, double floor) {
  const models::body_state<T> initial{models::mat3<T>::identity(), cast<T>(g0)};
  check_time_limit(models::exact_free_body<T>(cast<T>(to_double(body)), initial), total);
  auto m = models::measure_order<T>(table, cast<T>(to_double(body)), initial, T(total), first, last, last - first + 1);
  // Fit over the finest points still above the round-off floor of T and well above the exact
  // reference's estimated error (at most four).
  std::vector<double> hs, es;
  for (auto it = m.points.rbegin(); it != m.points.rend() && hs.size() < 4; ++it)
    if (it->error > floor && it->attributable()) hs.push_back(it->h), es.push_back(it->error);
  m.slope = hs.size() >= 2 ? models::fitted_slope(hs, es) : std::nan("");
  return m;
}
}  // namespace

int run_order(const order_options& o) {
  const auto body = parse_inertia_option(o.inertia);
  const auto table = lookup_scheme(o.scheme, body, o.force);
  const double total = parse_positive(o.T, "--T");
  const auto g0 = parse_momentum(o.G0);
  const int first = static_cast<int>(parse_integer_in_range(o.min_level, "--min-level", 0, 20));
  const int last = static_cast<int>(parse_integer_in_range(o.max_level, "--max-level", first, 20));
  models::order_measurement m;
  if (o.scalar == "double")
    m = order_in<double>(table, body, g0, total, first, last, 1e-13);
  else if (o.scalar == "long-double")
    m = order_in<long double>(table, body, g0, total, first, last, 1e-16);
  else if (o.scalar == "float128")
    m = order_in<boost::multiprecision::float128>(table, body, g0, total, first, last, 1e-28);
  else
    throw usage_error("--scalar must be double, long-double or float128, got '" + o.scalar + "'");
  // CPU per run in double (the scalar a user integrates with), stepping only
  const models::composition_stepper<double> timing(table, to_double(body));
  const models::body_state<double> initial{models::mat3<double>::identity(), g0};
  std::vector<double> cpu;
  for (const auto& p : m.points) {
    cpu.push_back(models::cpu_seconds_per_unit_time(timing, initial, p.h, 0.005) * total);
    if (!p.attributable()) warn_reference(p.error, p.reference_error, "h = " + number(p.h) + " (left out of the fit)");
  }
  if (o.json) {
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t i = 0; i < m.points.size(); ++i)
      points.push_back(point_json(m.points[i].h, m.points[i].h_over_cost, m.points[i].error, cpu[i], m.points[i].reference_error));
    nlohmann::json j{{"scheme", table.name}, {"scalar", o.scalar}, {"declared_order", table.order}, {"points", points}};
    j["slope"] = std::isfinite(m.slope) ? nlohmann::json(m.slope) : nlohmann::json(nullptr);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << table.name << " in " << o.scalar << ": declared order " << table.order << ", fitted slope " << m.slope << "\n";
    for (std::size_t i = 0; i < m.points.size(); ++i)
      std::cout << "  h = " << m.points[i].h << "  h/C = " << m.points[i].h_over_cost << "  error = " << m.points[i].error
                << "  reference error = " << m.points[i].reference_error << "  cpu = " << cpu[i] << " s\n";
  }
  return 0;
}

int run_exact(const exact_options& o) {
  const auto body = parse_inertia_option(o.inertia);
  const auto I = to_double(body);
  const double total = parse_positive(o.T, "--T");
  const models::exact_free_body<double> exact(I, {models::mat3<double>::identity(), parse_momentum(o.G0)});
  check_time_limit(exact, total);
  const auto r = exact.evaluate(total);
  const auto& s = r.state;
  if (o.json) {
    nlohmann::json Q = nlohmann::json::array();
    for (int i = 0; i < 3; ++i) Q.push_back({s.Q(i, 0), s.Q(i, 1), s.Q(i, 2)});
    std::cout << nlohmann::json{{"T", total}, {"G", {s.G[0], s.G[1], s.G[2]}}, {"Q", Q}, {"error_estimate", r.error_estimate}}.dump(2)
              << "\n";
  } else {
    std::ostringstream out;
    out.precision(17);
    out << "T = " << total << "\nG = (" << s.G[0] << ", " << s.G[1] << ", " << s.G[2] << ")\nQ =\n";
    for (int i = 0; i < 3; ++i) out << "  " << s.Q(i, 0) << "  " << s.Q(i, 1) << "  " << s.Q(i, 2) << "\n";
    out.precision(2);
    out << "estimated error (max abs entry of Q and of G/|G|) " << r.error_estimate << "\n";
    std::cout << out.str();
  }
  return 0;
}

}  // namespace rotlie::app
