#pragma once
/// \file core_simulation.h
/// The simulation object of the Python module (flexmb._core.Simulation): a
/// loaded model, its simulator, the inputs a script sets between steps and
/// the result rows recorded in memory (and optionally written to
/// results.csv with the command line's writer and output grid).

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/results/results_writer.h"
#include "flexmb/math/input_function.h"
#include "flexmb/model/model.h"
#include "flexmb/solver/simulator.h"

namespace flexmb::python {

/// Output times t0 + k dt (as the run command's grid): Due(t) is true at the
/// first call at or after each grid time, always when dt is 0.
class PyOutputGrid {
 public:
  PyOutputGrid(double t0, double dt, double eps) : t0_(t0), dt_(dt), eps_(eps) {}
  /// See the class comment.
  bool Due(double t);

 private:
  double t0_, dt_, eps_;
  long k_ = 0;
};

/// One model in simulation; see the file comment.
class PySimulation {
 public:
  /// Loads a model file (errors as the command line reports them).
  static std::unique_ptr<PySimulation> FromFile(const std::string& path, const std::string& manoeuvre = "");
  /// Loads model-file text; `name` stands for the file in messages.
  static std::unique_ptr<PySimulation> FromString(const std::string& yaml, const std::string& name);

  /// Consistent initial state (once); rethrows errors naming the model.
  void Initialize();
  /// Initialize, then (once, before the first step) the static equilibrium
  /// of a model with `solver: analysis: statics_then_dynamics`, as
  /// `flexmb run` starts it.
  void StartDynamics();
  /// Integrates to t_end [s]; rows every output.interval; `callback` (may be
  /// None) is called as callback(argument) with the GIL at every
  /// `callback_interval` [s] (0: every step); `out_dir` non-empty:
  /// results.csv written there too, as the run command writes it.
  void Run(double t_end, pybind11::object callback, pybind11::object argument, double callback_interval,
           const std::string& out_dir);
  /// Advances by `n` steps of `dt` [s] (each one call of the integrator to t + dt).
  void Step(double dt, int n);
  /// Evaluates the sensors at the current state into `out` (columns - 1 values, unwrapped not).
  void SensorValues(double* out);

  std::string path;                      ///< model file or name for messages
  std::unique_ptr<Model> model;          ///< the model (outlives sim)
  InputTable inputs;                     ///< inputs of the model by name
  std::unique_ptr<Simulator> sim;        ///< its simulator
  std::vector<std::string> warnings;     ///< warnings of the initialization
  bool initialized = false;
  bool started = false;                  ///< StartDynamics done
  std::vector<std::string> columns;      ///< "time" and sensor.component
  std::vector<std::vector<double>> data; ///< per column: recorded values
  double seconds_integrating = 0.0;      ///< wall time inside the integrator [s]

 private:
  void SetUp();
  void Record(const State& st, const Workspace& ws);
  void RethrowWithModel(const Error& e) const;
  std::vector<char> is_angle_;
  std::vector<int> counts_;
  std::vector<double> scratch_;
  std::unique_ptr<ResultsWriter> writer_;
};


}  // namespace flexmb::python
