#pragma once
// The anchor a user would otherwise reach for: Euler's equations with the attitude kinematics
// (12 unknowns) integrated by a general Boost.Odeint Runge-Kutta stepper at a fixed step.
#include <boost/numeric/odeint.hpp>

#include <array>

#include "rotlie/models/rigid_body.hpp"

namespace rotlie::bench {

using ode_state = std::array<double, 12>;  // Q row-major, then G

inline ode_state pack(const models::body_state<double>& s) {
  ode_state x{};
  for (std::size_t i = 0; i < 9; ++i) x[i] = s.Q.a[i];
  for (std::size_t i = 0; i < 3; ++i) x[9 + i] = s.G[i];
  return x;
}

inline models::mat3<double> attitude_of(const ode_state& x) {
  models::mat3<double> Q;
  for (std::size_t i = 0; i < 9; ++i) Q.a[i] = x[i];
  return Q;
}

struct euler_system {
  models::vec3<double> I;
  void operator()(const ode_state& x, ode_state& dxdt, double /*t*/) const {
    models::body_state<double> s, ds;
    for (std::size_t i = 0; i < 9; ++i) s.Q.a[i] = x[i];
    for (std::size_t i = 0; i < 3; ++i) s.G[i] = x[9 + i];
    models::euler_rhs(I, s, ds);
    for (std::size_t i = 0; i < 9; ++i) dxdt[i] = ds.Q.a[i];
    for (std::size_t i = 0; i < 3; ++i) dxdt[9 + i] = ds.G[i];
  }
};

using rkf78 = boost::numeric::odeint::runge_kutta_fehlberg78<ode_state>;
using dopri5 = boost::numeric::odeint::runge_kutta_dopri5<ode_state>;

}  // namespace rotlie::bench
