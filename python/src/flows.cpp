// The free rigid body from Python, vectorised over N states: exact_flow (the closed form as SIER's
// free flights take it, models/exact_free_rotation.hpp, in double many rows at once through
// exact_free_rotation_batch.hpp) and integrate (a scheme table on models/composition_stepper.hpp),
// each in the scalar asked (double, long double, float128) and rounded once to float64 at the end;
// order (runs::order_run, LV section 4.1) as the JSON of `rotlie order`. The loops run with the GIL
// released and poll for Ctrl-C; a row's result does not depend on the other rows.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>

#include "bindings.hpp"
#include "interruption.hpp"
#include "rotlie/lie/rigid_body.hpp"
#include "rotlie/models/composition_stepper.hpp"
#include "rotlie/models/exact_free_body.hpp"
#include "rotlie/models/exact_free_rotation_batch.hpp"
#include "rotlie/models/moments_from_text.hpp"
#include "rotlie/runs/free_body_io.hpp"
#include "rotlie/runs/body_names.hpp"
#include "rotlie/runs/rotation_check.hpp"
#include "rotlie/schemes/message_number.hpp"
#include "rotlie/runs/free_body_runs.hpp"
#include "rotlie/runs/numeric_inputs.hpp"
#include "rotlie/runs/rotation_check.hpp"
#include "rotlie/runs/user_input.hpp"
#include "rotlie/schemes/quad.hpp"
#include "rotlie/schemes/same_body.hpp"

namespace rotlie::python {
namespace {

namespace py = pybind11;
using rows = py::array_t<double, py::array::c_style | py::array::forcecast>;

constexpr long max_steps = 100'000'000;  // per body, as `rotlie integrate` (T/h)
constexpr long poll_every = 4096;
constexpr double max_momentum = 1e150, max_momentum_inverse = 1e-150;  // runs::max_decimal_exponent        // steps or evaluations between looks at the cancellation flag

/// Calls f with a value of the scalar named.
template <class F>
void with_scalar(const std::string& name, F&& f) {
  if (name == "double")
    f(double{});
  else if (name == "long-double")
    f(static_cast<long double>(0));
  else if (name == "float128")
    f(quad{});
  else
    throw runs::bad_input("--scalar must be double, long-double or float128, got '" + name + "'");
}

/// A positive decimal or rational (1/64) read in T with one rounding of p and of q.
template <class T>
T number_in(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return models::parse_scalar<T>(text);
  return models::parse_scalar<T>(text.substr(0, slash)) / models::parse_scalar<T>(text.substr(slash + 1));
}

/// How far an attitude may be from a rotation: float64 entries written out to about 10 digits.
constexpr double max_rotation_defect = 1e-9;

/// The states of N bodies: G0 of shape (N, 3), Q0 of shape (N, 3, 3) a rotation each, both finite.
struct state_rows {
  const double* G = nullptr;
  const double* Q = nullptr;
  py::ssize_t n = 0;
};

state_rows checked_rows(const rows& G0, const rows& Q0) {
  if (G0.ndim() != 2 || G0.shape(1) != 3) throw runs::bad_input("G0 must have shape (3,) or (N, 3)");
  if (Q0.ndim() != 3 || Q0.shape(0) != G0.shape(0) || Q0.shape(1) != 3 || Q0.shape(2) != 3)
    throw runs::bad_input("Q0 must have shape (3, 3) or (N, 3, 3), one attitude per row of G0");
  state_rows r{G0.data(), Q0.data(), G0.shape(0)};
  for (py::ssize_t i = 0; i < 3 * r.n; ++i)
    if (!std::isfinite(r.G[i])) throw runs::bad_input("G0 must be finite");
  // as --G0 (a body at rest allowed): no energy or rate of the run leaves double's range
  for (py::ssize_t row = 0; row < r.n; ++row) {
    const double* g = r.G + 3 * row;
    const double length = std::hypot(g[0], g[1], g[2]);
    if (length != 0 && !(length >= max_momentum_inverse && length <= max_momentum))
      throw runs::bad_input("G0: |G0| = " + schemes::message_number(length) + " (row " + std::to_string(row) +
                            ") is outside the range 1e-150 … 1e150");
  }
  for (py::ssize_t i = 0; i < 9 * r.n; ++i)
    if (!std::isfinite(r.Q[i])) throw runs::bad_input("Q0 must be finite");
  for (py::ssize_t row = 0; row < r.n; ++row) {
    const auto why = runs::rotation_problem(r.Q + 9 * row, max_rotation_defect);
    if (!why.empty())
      throw runs::bad_input("Q0 (row " + std::to_string(row) + ") is not a rotation (" + why + "; at most " + schemes::message_number(max_rotation_defect) +
                            " and det 1 are needed): orthonormalise it, e.g. by its polar decomposition");
  }
  return r;
}

template <class T>
models::body_state<T> state_of(const state_rows& in, py::ssize_t row) {
  models::body_state<T> s;
  for (std::size_t j = 0; j < 3; ++j) s.G[j] = T(in.G[3 * row + static_cast<py::ssize_t>(j)]);
  for (std::size_t j = 0; j < 9; ++j) s.Q.a[j] = T(in.Q[9 * row + static_cast<py::ssize_t>(j)]);
  return s;
}

template <class T>
void store(const models::body_state<T>& s, py::ssize_t row, double* G, double* Q) {
  for (std::size_t j = 0; j < 3; ++j) G[3 * row + static_cast<py::ssize_t>(j)] = static_cast<double>(s.G[j]);
  for (std::size_t j = 0; j < 9; ++j) Q[9 * row + static_cast<py::ssize_t>(j)] = static_cast<double>(s.Q.a[j]);
}

/// The body's exact moments as a scheme table's inertia line, each within 1e-150 … 1e150.
std::string inertia_line(const std::string& body) {
  auto out = std::make_shared<std::string>();
  run_symbolic([body, out] { *out = lie::inertia_text(runs::numeric_body(body)); });
  return *out;
}

/// A table solved for another body is refused unless forced (then used with a warning).
void check_body_of(const scheme_object& s, const std::string& inertia, bool force) {
  const auto first = inertia.find(' '), second = inertia.rfind(' ');
  const std::string I1 = inertia.substr(0, first), I2 = inertia.substr(first + 1, second - first - 1),
                    I3 = inertia.substr(second + 1);
  if (schemes::same_body(s.table, {I1, I2, I3}) != schemes::body_match::different) return;
  const std::string why = s.table.name + " was solved for the body (" + s.table.inertia + "), not for (" + inertia +
                          "): its order holds only for the body it was solved for (bodies are compared up to a common factor)";
  if (!force) throw runs::bad_input(why + " (pass force=True to use it anyway)");
  if (PyErr_WarnEx(PyExc_UserWarning, (why + " (used anyway: force=True)").c_str(), 2) != 0) throw py::error_already_set();
}

py::tuple exact_flow(const std::string& body, const rows& G0, const rows& Q0, const rows& t, const std::string& scalar) {
  const auto in = checked_rows(G0, Q0);
  if (t.ndim() != 1 || t.shape(0) != in.n) throw runs::bad_input("t must be a number or have shape (N,)");
  for (py::ssize_t i = 0; i < in.n; ++i)
    if (!std::isfinite(t.data()[i])) throw runs::bad_input("t must be finite");
  const std::string inertia = inertia_line(body);
  rows G({in.n, py::ssize_t{3}}), Q({in.n, py::ssize_t{3}, py::ssize_t{3}}), err(in.n);
  double *g = G.mutable_data(), *q = Q.mutable_data(), *e = err.mutable_data();
  const double* times = t.data();
  run_cancellable([&](const cancellation& cancel) {
    with_scalar(scalar, [&](auto zero) {
      using T = decltype(zero);
      // the step of SIER's free flights (exact_free_body where it declines); in double, blocks of rows
      // vectorised across them (exact_free_rotation_batch.hpp)
      const models::exact_free_rotation<T> rotor(models::moments_from_text<T>(inertia));
      if constexpr (std::is_same_v<T, double>) {
        models::free_body_block block;
        for (py::ssize_t first = 0; first < in.n; first += static_cast<py::ssize_t>(block.capacity)) {
          if (cancel.requested()) return;
          block.n = static_cast<std::size_t>(std::min<py::ssize_t>(static_cast<py::ssize_t>(block.capacity), in.n - first));
          for (std::size_t i = 0; i < block.n; ++i) {
            const py::ssize_t row = first + static_cast<py::ssize_t>(i);
            for (std::size_t k = 0; k < 3; ++k) block.G[k][i] = in.G[3 * row + static_cast<py::ssize_t>(k)];
            for (std::size_t j = 0; j < 9; ++j) block.Q[j][i] = in.Q[9 * row + static_cast<py::ssize_t>(j)];
            block.t[i] = times[row];
          }
          models::advance_block(rotor, block);
          for (std::size_t i = 0; i < block.n; ++i) {
            const py::ssize_t row = first + static_cast<py::ssize_t>(i);
            for (std::size_t k = 0; k < 3; ++k) g[3 * row + static_cast<py::ssize_t>(k)] = block.G[k][i];
            for (std::size_t j = 0; j < 9; ++j) q[9 * row + static_cast<py::ssize_t>(j)] = block.Q[j][i];
            e[row] = block.estimate[i];
          }
        }
      } else {
        for (py::ssize_t row = 0; row < in.n; ++row) {
          if (cancel.requested()) return;  // every row: one costs up to 0.2 ms in float128 (4096 of them 0.8 s)
          auto s = state_of<T>(in, row);
          e[row] = static_cast<double>(rotor.advance(s, T(times[row])));
          store(s, row, g, q);
        }
      }
    });
  });
  return py::make_tuple(G, Q, err);
}

py::tuple integrate(const scheme_object& scheme, const std::string& body, const rows& G0, const rows& Q0,
                    const std::string& h, long steps, const std::string& scalar, bool force) {
  const auto in = checked_rows(G0, Q0);
  runs::positive_number(h, "--h");
  if (steps < 0 || steps > max_steps)
    throw runs::bad_input("steps = " + std::to_string(steps) + " must be within 0 … " + std::to_string(max_steps));
  const std::string inertia = inertia_line(body);
  check_body_of(scheme, inertia, force);
  rows G({in.n, py::ssize_t{3}}), Q({in.n, py::ssize_t{3}, py::ssize_t{3}});
  double *g = G.mutable_data(), *q = Q.mutable_data();
  bool finite = true;
  run_cancellable([&](const cancellation& cancel) {
    with_scalar(scalar, [&](auto zero) {
      using T = decltype(zero);
      const auto method = models::free_body_method(scheme.table, models::moments_from_text<T>(inertia));
      const T step = number_in<T>(h);
      long since_poll = 0;
      for (py::ssize_t row = 0; row < in.n; ++row) {
        auto x = state_of<T>(in, row);
        for (long k = 0; k < steps; ++k) {
          method.step(x, step);
          if (++since_poll == poll_every) {
            since_poll = 0;
            if (cancel.requested()) return;
          }
        }
        store(x, row, g, q);
      }
    });
    for (py::ssize_t i = 0; i < 9 * in.n && finite; ++i) finite = std::isfinite(q[i]);
  });
  if (!finite) throw std::runtime_error("the integration diverged (NaN): the step is beyond the scheme's stability limit");
  return py::make_tuple(G, Q);
}

std::string order(const scheme_object& scheme, const std::string& body, const std::string& G0, const std::string& T,
                  long first, long last, const std::string& scalar, bool force) {
  const std::string inertia = inertia_line(body);
  check_body_of(scheme, inertia, force);
  const double total = runs::positive_number(T, "--T");
  const auto g0 = runs::initial_momentum(G0);
  const long lo = runs::integer_in_range(std::to_string(first), "--min-level", 0, 20);
  const long hi = runs::integer_in_range(std::to_string(last), "--max-level", lo, 20);
  with_scalar(scalar, [](auto) {});  // the scalar's name checked before the run
  auto out = std::make_shared<std::string>();
  run_symbolic([table = scheme.table, inertia, total, g0, lo, hi, scalar, out] {
    const auto r = runs::order_run({table, inertia}, g0, total, static_cast<int>(lo), static_cast<int>(hi), scalar);
    *out = runs::order_json(r).dump();
  });
  return *out;
}

}  // namespace

void bind_flows(py::module_& m) {
  m.def("exact_flow", &exact_flow, py::arg("body"), py::arg("G0"), py::arg("Q0"), py::arg("t"), py::arg("scalar"));
  m.def("integrate", &integrate, py::arg("scheme"), py::arg("body"), py::arg("G0"), py::arg("Q0"), py::arg("h"),
        py::arg("steps"), py::arg("scalar"), py::arg("force"));
  m.def("order", &order, py::arg("scheme"), py::arg("body"), py::arg("G0"), py::arg("T"), py::arg("min_level"),
        py::arg("max_level"), py::arg("scalar"), py::arg("force"));
}

}  // namespace rotlie::python
