#pragma once
/// \file core_bindings.h
/// The parts of the compiled core flexmb._core (python/core_*.cc), each
/// adding its classes and functions to the module.

#include <pybind11/pybind11.h>

namespace flexmb::python {

/// Simulation and Input (core_simulation.cc).
void BindSimulation(pybind11::module_& m);
/// read_body (core_bodies.cc).
void BindBodies(pybind11::module_& m);
/// statics, modes, linearize (core_analysis.cc).
void BindAnalysis(pybind11::module_& m);

}  // namespace flexmb::python
