#pragma once
// What the held simulations (spin_simulation.cpp, md_simulation.cpp) share: integrate(t) with the GIL
// released, Ctrl-C ending it at the step reached, and one call at a time per simulation.
#include <pybind11/pybind11.h>

#include <string>

#include "interruption.hpp"

namespace rotlie::python {

/// A simulation with a flag that refuses a second integrate while one runs (the GIL is released then).
template <class Simulation>
struct held {
  Simulation sim;
  bool busy = false;  // read and written with the GIL held
};

/// sim.integrate(t, stop) on a worker thread, the GIL released; a KeyboardInterrupt leaves the
/// simulation at the last whole step it reached.
template <class Simulation>
void integrate_held(held<Simulation>& h, double t) {
  if (h.busy) {
    PyErr_SetString(PyExc_RuntimeError, "this simulation is integrating in another thread");
    throw pybind11::error_already_set();
  }
  h.busy = true;
  struct release {
    bool& busy;
    ~release() { busy = false; }
  } guard{h.busy};
  run_cancellable([&](const cancellation& cancel) { h.sim.integrate(t, [&cancel] { return cancel.requested(); }); });
}

}  // namespace rotlie::python
