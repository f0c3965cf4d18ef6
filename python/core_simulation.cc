#include "python/core_simulation.h"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "python/core_bindings.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/sensors/joint_sensors.h"
#include "flexmb/solver/statics.h"

namespace flexmb::python {
namespace py = pybind11;

namespace {

// a 1-D numpy view of n doubles at ptr, keeping `owner` alive
py::array SimulationView(const py::object& owner, double* ptr, py::ssize_t n) {
  return py::array_t<double>({n}, {static_cast<py::ssize_t>(sizeof(double))}, ptr, owner);
}

// the model's entity index by name, or KeyError naming it
int SimulationIndex(int index, const char* what, const std::string& name) {
  if (index < 0) throw py::key_error(std::string("there is no ") + what + " named '" + name + "'");
  return index;
}

py::array SimulationMat3(const Mat3& R) {
  py::array_t<double> a({3, 3});
  auto r = a.mutable_unchecked<2>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = R(i, j);
  return a;
}

py::array SimulationVec3(const Vec3& v) {
  py::array_t<double> a(3);
  for (int i = 0; i < 3; ++i) a.mutable_at(i) = v(i);
  return a;
}

}  // namespace

bool PyOutputGrid::Due(double t) {
  if (dt_ <= 0) return true;
  if (t < t0_ + k_ * dt_ - eps_) return false;
  k_ = static_cast<long>(std::floor((t - t0_ + eps_) / dt_)) + 1;
  return true;
}

std::unique_ptr<PySimulation> PySimulation::FromFile(const std::string& path, const std::string& manoeuvre) {
  auto s = std::make_unique<PySimulation>();
  s->path = path;
  {
    InputScope scope(s->inputs);
    SolverOverrides o;
    o.manoeuvre = manoeuvre;
    s->model = LoadModelFile(path, o);
  }
  s->SetUp();
  return s;
}

std::unique_ptr<PySimulation> PySimulation::FromString(const std::string& yaml, const std::string& name) {
  auto s = std::make_unique<PySimulation>();
  s->path = name;
  {
    InputScope scope(s->inputs);
    s->model = LoadModelString(yaml, name);
  }
  s->SetUp();
  return s;
}

void PySimulation::SetUp() {
  sim = std::make_unique<Simulator>(*model);
  columns.push_back("time");
  for (const auto& sensor : model->sensors) {
    const std::vector<std::string> comps = sensor->Components();
    counts_.push_back(static_cast<int>(comps.size()));
    for (int k = 0; k < static_cast<int>(comps.size()); ++k) {
      columns.push_back(sensor->name() + "." + comps[k]);
      is_angle_.push_back(sensor->ComponentIsAngle(k) ? 1 : 0);
    }
  }
  data.resize(columns.size());
  scratch_.assign(columns.size() - 1, 0.0);
}

void PySimulation::RethrowWithModel(const Error& e) const {
  // the message of the run command: the model file named when the error has no file
  const std::string msg = e.context().file.empty()
                              ? FormatWithContext(e.message(), {path, 0, e.context().entity})
                              : std::string(e.what());
  if (dynamic_cast<const NumericalError*>(&e)) throw NumericalError(msg);
  if (dynamic_cast<const InputError*>(&e)) throw InputError(msg);
  throw Error(msg);
}

void PySimulation::Initialize() {
  if (initialized) return;
  LogSink old = SetWarningSink([this](const std::string& m) { warnings.push_back(m); });
  try {
    sim->Initialize();
  } catch (const Error& e) {
    SetWarningSink(std::move(old));
    RethrowWithModel(e);
  }
  SetWarningSink(std::move(old));
  initialized = true;
}

void PySimulation::StartDynamics() {
  Initialize();
  if (started) return;
  started = true;
  if (model->solver.analysis != Analysis::kStaticsThenDynamics) return;
  try {
    sim->SettleStatics(StaticsSettingsOf(model->solver));
  } catch (const Error& e) {
    RethrowWithModel(e);
  }
}

void PySimulation::SensorValues(double* out) {
  const State& st = sim->state();
  for (size_t i = 0; i < model->sensors.size(); ++i) {
    model->sensors[i]->Evaluate(*model, st, sim->workspace(), out);
    out += counts_[i];
  }
}

void PySimulation::Record(const State& st, const Workspace& ws) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double* out = scratch_.data();
  for (size_t i = 0; i < model->sensors.size(); ++i) {
    model->sensors[i]->Evaluate(*model, st, ws, out);
    out += counts_[i];
  }
  const bool first = data[0].empty();
  data[0].push_back(st.t);
  for (size_t c = 0; c < scratch_.size(); ++c) {
    double x = scratch_[c];
    // angles shifted by whole turns to stay within pi of the previous row (as results.csv)
    if (is_angle_[c] && !first && std::isfinite(x)) x += kTwoPi * std::round((data[c + 1].back() - x) / kTwoPi);
    data[c + 1].push_back(x);
  }
  if (writer_) writer_->Write(st, ws);
}

void PySimulation::Run(double t_end, py::object callback, py::object argument, double callback_interval,
                       const std::string& out_dir) {
  StartDynamics();
  if (!(std::isfinite(t_end))) throw InputError("t_end must be a finite number of seconds");
  const OutputSettings& out = model->output;
  const bool has_callback = !callback.is_none();
  double interval = out.interval;
  if (has_callback) {
    if (callback_interval < 0) throw InputError("the callback interval must be >= 0 s");
    interval = (callback_interval > 0 && out.interval > 0) ? std::min(callback_interval, out.interval)
                                                           : callback_interval > 0 ? callback_interval : 0.0;
  }
  if (!out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(out_dir, ec);
    writer_ = std::make_unique<ResultsWriter>((std::filesystem::path(out_dir) / "results.csv").string(), *model);
  }
  const double t0 = sim->state().t;
  const double eps = 1e-9 * std::max(1.0, std::abs(t_end));
  PyOutputGrid rows(t0, out.interval, eps), calls(t0, has_callback ? callback_interval : 0.0, eps);
  const bool continuing = !data[0].empty();
  const auto start = std::chrono::steady_clock::now();
  try {
    py::gil_scoped_release release;
    sim->Run(t_end, interval, [&](const State& st, const Workspace& ws) {
      if (!has_callback) {
        // Ctrl-C (KeyboardInterrupt) ends a long run at the next output time
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      }
      const bool last = st.t >= t_end - eps;
      // a continued run does not repeat the row of its start
      const bool repeat = continuing && st.t <= data[0].back();
      if ((rows.Due(st.t) || last) && !repeat) Record(st, ws);
      if (has_callback && calls.Due(st.t)) {
        py::gil_scoped_acquire acquire;
        callback(argument);
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      }
    });
  } catch (const Error& e) {
    seconds_integrating += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writer_.reset();
    RethrowWithModel(e);
  } catch (...) {
    writer_.reset();
    throw;
  }
  seconds_integrating += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writer_.reset();
}

void PySimulation::Step(double dt, int n) {
  StartDynamics();
  if (!(dt > 0) || !std::isfinite(dt)) throw InputError("step: dt must be a positive number of seconds");
  const double eps = 1e-9 * std::max(1.0, std::abs(model->solver.t_end));
  const auto start = std::chrono::steady_clock::now();
  try {
    py::gil_scoped_release release;
    for (int k = 0; k < n; ++k) {
      const double t_next = sim->state().t + dt;
      sim->Run(t_next, 0.0, [&](const State& st, const Workspace& ws) {
        if (!data[0].empty() && st.t <= data[0].back()) return;
        // rows on the model's output grid counted from t = 0
        const double iv = model->output.interval;
        if (iv <= 0 || data[0].empty() || st.t >= data[0].back() + iv - eps) Record(st, ws);
      });
    }
  } catch (const Error& e) {
    RethrowWithModel(e);
  }
  seconds_integrating += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BindSimulation(py::module_& m) {
  py::class_<InputSignal, std::shared_ptr<InputSignal>>(m, "Input",
                                                      "A model input ({input: NAME} in the model file): "
                                                      "its value is held until set again.")
      .def_readwrite("value", &InputSignal::value, "current value [unit of the quantity it drives]");

  using S = PySimulation;
  py::class_<S>(m, "Simulation", "A model in simulation (see docs/python.md).")
      .def_static("from_file", &S::FromFile, py::arg("path"), py::arg("manoeuvre") = "",
                  "Loads a YAML model file (with one of its `manoeuvres`, if named).")
      .def_static("from_string", &S::FromString, py::arg("yaml"), py::arg("name") = "<string>",
                  "Loads model-file text; `name` stands for the file in error messages.")
      .def_readonly("path", &S::path)
      .def_property_readonly("name", [](const S& s) { return s.model->name; })
      .def("initialize", &S::Initialize, "Makes the initial state consistent (done by the first run/step).")
      .def("check", [](S& s) {
        s.Initialize();
        const ConstraintReport& rep = s.sim->constraints();
        py::dict d;
        d["dof"] = rep.dof;
        d["constraint_equations"] = rep.equations;
        d["redundant_constraints"] = static_cast<int>(rep.redundant.size());
        d["warnings"] = s.warnings;
        d["bodies"] = static_cast<int>(s.model->bodies.size()) - 1;
        d["joints"] = static_cast<int>(s.model->joints.size());
        d["forces"] = static_cast<int>(s.model->forces.size());
        d["sensors"] = static_cast<int>(s.model->sensors.size());
        return d;
      }, "Degrees of freedom, constraint equations, redundant ones, warnings and counts.")
      .def("run", [](py::object self, std::optional<double> t_end, py::object callback, double interval,
                     const std::string& out_dir) {
        S& s = self.cast<S&>();
        s.Run(t_end ? *t_end : s.model->solver.t_end, callback, self, interval, out_dir);
      }, py::arg("t_end") = py::none(), py::arg("callback") = py::none(), py::arg("interval") = 0.0,
         py::arg("out_dir") = "",
         "Integrates to t_end [s] (default solver.t_end); callback(sim) every `interval` [s] (0: every step); "
         "out_dir: also write results.csv there as `flexmb run` does.")
      .def("step", &S::Step, py::arg("dt"), py::arg("n") = 1, "Advances n times by dt [s].")
      .def_property_readonly("t", [](S& s) { return s.sim->state().t; }, "time [s]")
      .def_property_readonly("q", [](py::object self) {
        S& s = self.cast<S&>();
        return SimulationView(self, s.sim->state().q.data(), s.sim->state().q.size());
      }, "position coordinates (view, nq)")
      .def_property_readonly("v", [](py::object self) {
        S& s = self.cast<S&>();
        return SimulationView(self, s.sim->state().v.data(), s.sim->state().v.size());
      }, "velocity coordinates (view, nv)")
      .def_property_readonly("lam", [](py::object self) {
        S& s = self.cast<S&>();
        return SimulationView(self, s.sim->state().lambda.data(), s.sim->state().lambda.size());
      }, "constraint multipliers (view, nc); reactions are -B^T lambda")
      .def("body_q", [](py::object self, const std::string& name) {
        S& s = self.cast<S&>();
        const Body& b = *s.model->bodies[SimulationIndex(s.model->FindBody(name), "body", name)];
        return SimulationView(self, s.sim->state().q.data() + b.q_offset, b.nq());
      }, py::arg("body"), "the body's position coordinates (view): rigid (p_WC [m], quaternion wxyz), "
                          "flexible also its modal coordinates")
      .def("body_v", [](py::object self, const std::string& name) {
        S& s = self.cast<S&>();
        const Body& b = *s.model->bodies[SimulationIndex(s.model->FindBody(name), "body", name)];
        return SimulationView(self, s.sim->state().v.data() + b.v_offset, b.nv());
      }, py::arg("body"), "the body's velocity coordinates (view): (v_WC [m/s], w body axes [rad/s], ...)")
      .def("modal_coordinates", [](py::object self, const std::string& name) {
        S& s = self.cast<S&>();
        const Body& b = *s.model->bodies[SimulationIndex(s.model->FindBody(name), "body", name)];
        const int n = b.nq() - 7 == b.nv() - 6 && b.nq() > 7 ? b.nq() - 7 : 0;
        return SimulationView(self, s.sim->state().q.data() + b.q_offset + 7, n);
      }, py::arg("body"), "modal coordinates of a flexible body (view; empty for other bodies)")
      .def("body_pose", [](S& s, const std::string& name) {
        const Body& b = *s.model->bodies[SimulationIndex(s.model->FindBody(name), "body", name)];
        Vec3 p;
        Mat3 R;
        b.BodyFramePose(s.sim->state().q.data() + b.q_offset, p, R);
        return py::make_tuple(SimulationVec3(p), SimulationMat3(R));
      }, py::arg("body"), "(p_WB [m], R_WB) of the body frame (copies)")
      .def("marker", [](S& s, const std::string& name) {
        const int i = SimulationIndex(s.model->FindMarker(name), "marker", name);
        s.Initialize();
        const MarkerState& mk = s.sim->workspace().markers[i];
        py::dict d;
        d["p"] = SimulationVec3(mk.p_WM);
        d["R"] = SimulationMat3(mk.R_WM);
        d["v"] = SimulationVec3(mk.v_WM);
        d["w"] = SimulationVec3(mk.w_WM);
        return d;
      }, py::arg("marker"), "position [m], orientation, velocity [m/s], angular velocity [rad/s] in world "
                            "(at the last output time)")
      .def("joint_coordinates", [](S& s, const std::string& name) {
        const Joint& j = *s.model->joints[SimulationIndex(s.model->FindJoint(name), "joint", name)];
        s.Initialize();
        const Workspace& ws = s.sim->workspace();
        py::array_t<double> a(j.NumCoordinates());
        for (int k = 0; k < j.NumCoordinates(); ++k)
          a.mutable_at(k) = j.Coordinate(k, ws.markers[j.marker_i], ws.markers[j.marker_j], nullptr);
        return a;
      }, py::arg("joint"), "the joint's coordinates [rad or m] (copy, at the last output time)")
      .def("joint_lambda", [](py::object self, const std::string& name) {
        S& s = self.cast<S&>();
        const Joint& j = *s.model->joints[SimulationIndex(s.model->FindJoint(name), "joint", name)];
        return SimulationView(self, s.sim->state().lambda.data() + j.lambda_offset, j.NumEquations());
      }, py::arg("joint"), "the joint's constraint multipliers (view) [N or N m per equation]")
      .def("joint_reaction", [](S& s, const std::string& name, bool world) {
        const int j = SimulationIndex(s.model->FindJoint(name), "joint", name);
        s.Initialize();
        const JointReactionSensor sensor(name, j, world);
        py::array_t<double> a(6);
        sensor.Evaluate(*s.model, s.sim->state(), s.sim->workspace(), a.mutable_data());
        return a;
      }, py::arg("joint"), py::arg("world") = false,
         "(fx, fy, fz [N], mx, my, mz [N m]): the wrench the joint applies to marker j about its origin, in "
         "marker i's axes (world=True: world axes), as the joint_reaction sensor (at the last output time)")
      .def("sensor_values", [](S& s) {
        s.Initialize();
        std::vector<double> v(s.columns.size() - 1);
        s.SensorValues(v.data());
        py::dict d;
        d["time"] = s.sim->state().t;
        for (size_t c = 1; c < s.columns.size(); ++c) d[py::str(s.columns[c])] = v[c - 1];
        return d;
      }, "current sensor values by column name (at the last output time)")
      .def("input", [](S& s, const std::string& name) {
        auto it = s.inputs.find(name);
        if (it == s.inputs.end()) throw py::key_error("there is no input named '" + name + "'");
        return it->second;
      }, py::arg("name"), "the named input (set .value between steps)")
      .def("set_input", [](S& s, const std::string& name, double value) {
        auto it = s.inputs.find(name);
        if (it == s.inputs.end()) throw py::key_error("there is no input named '" + name + "'");
        it->second->value = value;
      }, py::arg("name"), py::arg("value"))
      .def_property_readonly("input_names", [](const S& s) {
        std::vector<std::string> n;
        for (const auto& kv : s.inputs) n.push_back(kv.first);
        return n;
      })
      .def_property_readonly("body_names", [](const S& s) {
        std::vector<std::string> n;
        for (size_t b = 1; b < s.model->bodies.size(); ++b) n.push_back(s.model->bodies[b]->name());
        return n;
      })
      .def_property_readonly("joint_names", [](const S& s) {
        std::vector<std::string> n;
        for (const auto& j : s.model->joints) n.push_back(j->name());
        return n;
      })
      .def_readonly("columns", &S::columns, "result columns: time, then sensor.component")
      .def("result_arrays", [](const S& s) {
        py::dict d;
        for (size_t c = 0; c < s.columns.size(); ++c)
          d[py::str(s.columns[c])] = py::array_t<double>(static_cast<py::ssize_t>(s.data[c].size()),
                                                         s.data[c].data());
        return d;
      }, "the recorded rows: column name -> numpy array (copies)")
      .def_property_readonly("stats", [](const S& s) {
        const IntegratorStats& st = s.sim->stats();
        py::dict d;
        d["steps"] = st.steps;
        d["rejected_steps"] = st.rejected;
        d["newton_iterations"] = st.newton_iterations;
        d["factorizations"] = st.factorizations;
        d["chord_checks"] = st.chord_checks;
        d["chord_steps"] = st.chord_steps;
        d["max_constraint_violation"] = st.max_constraint_violation;
        d["integration_time_s"] = s.seconds_integrating;
        return d;
      }, "integrator statistics and the wall time spent integrating [s]")
      .def_property_readonly("t_end", [](const S& s) { return s.model->solver.t_end; }, "solver.t_end [s]")
      .def_property_readonly("dt", [](const S& s) { return s.model->solver.dt; }, "solver.dt [s]");
}

}  // namespace flexmb::python
