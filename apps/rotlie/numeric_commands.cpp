// integrate, order and exact: the numeric core on the command line (DESIGN.md CLI table). Every
// run is models::integrate on the composition engine, observed by the free-body observers.
#include <nlohmann/json.hpp>

#include <boost/multiprecision/float128.hpp>

#include <cmath>
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "rotlie/models/error_protocol.hpp"
#include "rotlie/models/moments_from_text.hpp"
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

// One numeric run's table and body: the table looked up for the body (a table solved for another
// body is refused unless --force), and the body's exact moments as text, read into the scalar of
// each run once by models::moments_from_text.
struct free_body_input {
  schemes::scheme_table table;
  std::string inertia;
};

free_body_input free_body_of(const std::string& scheme, const std::string& inertia, bool force) {
  const auto body = parse_inertia_option(inertia);
  return {lookup_scheme(scheme, body, force ? foreign_table::use_with_warning : foreign_table::refuse_unless_forced), lie::inertia_text(body)};
}

template <class T>
models::body_state<T> initial_state(const models::vec3<double>& g0) {
  return {models::mat3<T>::identity(), {T(g0[0]), T(g0[1]), T(g0[2])}};
}

// The protocol in scalar T, fitted over the finest points (at most four) above T's round-off floor
// and well above the exact reference's estimated error.
template <class T>
models::order_measurement order_in(const free_body_input& in, const models::vec3<double>& g0, double total, int first,
                                   int last) {
  const auto initial = initial_state<T>(g0);
  const auto method = models::free_body_method(in.table, models::moments_from_text<T>(in.inertia));
  check_time_limit(models::exact_free_body<T>(method.system().moments(), initial), total);
  models::fit_rule rule;
  rule.at_most = 4;
  rule.floor = models::round_off_floor<T>();
  return models::measure_order(method, initial, T(total), first, last, rule);
}

}  // namespace

int run_integrate(const integrate_options& o) {
  const auto in = free_body_of(o.scheme, o.inertia, o.force);
  const double h = parse_positive(o.h, "--h"), total = parse_positive(o.T, "--T");
  const long steps = step_count(total, h);
  const auto initial = initial_state<double>(parse_momentum(o.G0));
  const auto method = models::free_body_method(in.table, models::moments_from_text<double>(in.inertia));
  const models::exact_free_body<double> exact(method.system().moments(), initial);
  check_time_limit(exact, total);
  progress_line progress;
  auto guard = models::stop_unless_finite<double>();
  models::flow_attitude_error<double> attitude(exact);
  auto show_progress = [&](long k, double, const models::body_state<double>&) {
    if (k % 1000000 == 0) progress.show("step " + std::to_string(k) + " of " + std::to_string(steps));
  };
  auto s = initial;
  models::integrate(method, s, h, steps, guard, attitude, show_progress);
  if (guard.stopped())
    throw std::runtime_error("the integration diverged (NaN): the step is beyond the scheme's stability limit");
  const models::protocol_point point{h, h / method.cost(), attitude.mean(), attitude.reference_mean()};
  if (!point.attributable()) warn_reference(point.error, point.reference_error, "h = " + number(h));
  const double cpu = models::cpu_seconds_per_unit_time(method, initial, h) * total;
  if (o.json) {
    std::cout << nlohmann::json{{"scheme", in.table.name}, {"slope", nullptr},
                                {"points", {point_json(h, point.h_over_cost, point.error, cpu, point.reference_error)}}}
                     .dump(2)
              << "\n";
  } else {
    std::cout << in.table.name << " (" << method.cost() << " C0 per step), h = " << h << ", T = " << total << ", " << steps
              << " steps\nmean attitude error " << point.error << " (exact reference: estimated error "
              << point.reference_error << ")\nCPU " << cpu << " s (stepping only)\n";
  }
  return 0;
}

int run_order(const order_options& o) {
  const auto in = free_body_of(o.scheme, o.inertia, o.force);
  const double total = parse_positive(o.T, "--T");
  const auto g0 = parse_momentum(o.G0);
  const int first = static_cast<int>(parse_integer_in_range(o.min_level, "--min-level", 0, 20));
  const int last = static_cast<int>(parse_integer_in_range(o.max_level, "--max-level", first, 20));
  models::order_measurement m;
  if (o.scalar == "double")
    m = order_in<double>(in, g0, total, first, last);
  else if (o.scalar == "long-double")
    m = order_in<long double>(in, g0, total, first, last);
  else if (o.scalar == "float128")
    m = order_in<boost::multiprecision::float128>(in, g0, total, first, last);
  else
    throw usage_error("--scalar must be double, long-double or float128, got '" + o.scalar + "'");
  // CPU per run in double (the scalar a user integrates with), stepping only
  const auto timing = models::free_body_method(in.table, models::moments_from_text<double>(in.inertia));
  const auto initial = initial_state<double>(g0);
  std::vector<double> cpu;
  for (const auto& p : m.points) {
    cpu.push_back(models::cpu_seconds_per_unit_time(timing, initial, p.h, 0.005) * total);
    if (!p.attributable()) warn_reference(p.error, p.reference_error, "h = " + number(p.h) + " (left out of the fit)");
  }
  if (o.json) {
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t i = 0; i < m.points.size(); ++i)
      points.push_back(point_json(m.points[i].h, m.points[i].h_over_cost, m.points[i].error, cpu[i], m.points[i].reference_error));
    nlohmann::json j{{"scheme", in.table.name}, {"scalar", o.scalar}, {"declared_order", in.table.order}, {"points", points}};
    j["slope"] = std::isfinite(m.slope) ? nlohmann::json(m.slope) : nlohmann::json(nullptr);
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << in.table.name << " in " << o.scalar << ": declared order " << in.table.order << ", fitted slope " << m.slope
              << "\n";
    for (std::size_t i = 0; i < m.points.size(); ++i)
      std::cout << "  h = " << m.points[i].h << "  h/C = " << m.points[i].h_over_cost << "  error = " << m.points[i].error
                << "  reference error = " << m.points[i].reference_error << "  cpu = " << cpu[i] << " s\n";
  }
  return 0;
}

int run_exact(const exact_options& o) {
  const auto I = models::moments_from_text<double>(lie::inertia_text(parse_inertia_option(o.inertia)));
  const double total = parse_positive(o.T, "--T");
  const models::exact_free_body<double> exact(I, initial_state<double>(parse_momentum(o.G0)));
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
