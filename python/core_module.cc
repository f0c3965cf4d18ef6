// The compiled core of the Python module, flexmb._core: the exceptions, the
// command workflows (run, check, fe, reduce, body info, lane change) and the
// parts of core_bindings.h. The pure-Python package python/flexmb/ wraps it.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <optional>
#include <sstream>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/common/process_tuning.h"
#include "apps/flexmb/commands/fe_commands.h"
#include "apps/flexmb/commands/reduce_commands.h"
#include "apps/flexmb/commands/run.h"
#include "apps/flexmb/commands/handling.h"
#include "apps/flexmb/commands/driver_sensitivity.h"
#include "apps/flexmb/commands/lane_change.h"
#include "python/core_bindings.h"

namespace py = pybind11;

namespace {

// text that `print(FILE*)` writes, captured in memory
template <class F>
std::string ModuleCapture(F&& print) {
  char* buf = nullptr;
  size_t len = 0;
  std::FILE* f = open_memstream(&buf, &len);
  if (!f) throw std::runtime_error("cannot open a memory stream");
  try {
    print(f);
  } catch (...) {
    std::fclose(f);
    std::free(buf);
    throw;
  }
  std::fclose(f);
  std::string out(buf, len);
  std::free(buf);
  return out;
}

// a command of fe_commands.h / reduce_commands.h with its JSON output
template <class F>
std::string ModuleJson(F&& command) {
  std::ostringstream out;
  {
    py::gil_scoped_release release;
    command(out);
  }
  return out.str();
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "flexmb compiled core (use the package flexmb; docs/python.md)";
  static py::exception<flexmb::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<flexmb::InputError> input_error(m, "InputError", error.ptr());
  static py::exception<flexmb::NumericalError> numerical_error(m, "NumericalError", error.ptr());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const flexmb::InputError& e) {
      input_error(e.what());
    } catch (const flexmb::NumericalError& e) {
      numerical_error(e.what());
    } catch (const flexmb::Error& e) {
      error(e.what());
    }
  });

  m.def("run_file", [](const std::string& model, const std::string& out_dir, std::optional<double> t_end,
                       std::optional<double> dt, bool animation, const std::string& manoeuvre) {
    flexmb::RunOptions o;
    o.model_path = model;
    o.manoeuvre = manoeuvre;
    o.out_dir = out_dir;
    o.t_end = t_end;
    o.dt = dt;
    o.animation = animation;
    flexmb::RunSummary s;
    {
      py::gil_scoped_release release;
      s = flexmb::RunModel(o);
    }
    return py::make_tuple(flexmb::SummaryJson(s), static_cast<int>(s.status));
  }, py::arg("model"), py::arg("out_dir"), py::arg("t_end") = py::none(), py::arg("dt") = py::none(),
        py::arg("animation") = false, py::arg("manoeuvre") = "",
        "`flexmb run`: runs a model file, writes results.csv and summary.json to out_dir; returns the "
        "summary as JSON text and the status (0 ok, 1 input error, 2 numerical error, 3 interrupted, 4 other).");
  m.def("check_report", [](const std::string& model) {
    return ModuleCapture([&](std::FILE* f) {
      if (flexmb::vehicle::IsLaneChangeFile(model)) {
        flexmb::vehicle::LaneChangeOptions o;
        o.file = model;
        flexmb::vehicle::CheckLaneChange(o, f);
      } else {
        flexmb::CheckModel(model, f);
      }
    });
  }, py::arg("model"), "`flexmb check`: the report text.");

  m.def("fe_modes", [](const std::string& model, int count, const std::string& fix, bool lumped, double shift) {
    flexmb::io::FeModesOptions o;
    o.model_path = model;
    o.count = count;
    o.fix = fix;
    o.lumped = lumped;
    o.shift = shift;
    o.json = true;
    return ModuleJson([&](std::ostream& out) { flexmb::io::FeModes(o, out); });
  }, py::arg("model"), py::arg("count") = 10, py::arg("fix") = "", py::arg("lumped") = false,
        py::arg("shift") = 0.0, "`flexmb fe modes --json`.");
  m.def("fe_info", [](const std::string& model) {
    flexmb::io::FeInfoOptions o;
    o.model_path = model;
    o.json = true;
    return ModuleJson([&](std::ostream& out) { flexmb::io::FeInfo(o, out); });
  }, py::arg("model"), "`flexmb fe info --json`.");
  m.def("fe_export", [](const std::string& model, const std::string& hb_dir, const std::string& fix,
                        const std::string& interface, int modes) {
    flexmb::io::FeExportOptions o{model, hb_dir, fix, interface, modes};
    return ModuleJson([&](std::ostream& out) { flexmb::io::FeExport(o, out); });
  }, py::arg("model"), py::arg("hb_dir"), py::arg("fix") = "", py::arg("interface") = "",
        py::arg("modes") = 10, "`flexmb fe export`: the report text.");
  m.def("reduce", [](const std::string& model, const std::string& output, const std::string& interface,
                     int modes, double cutoff_hz, int keep, const std::string& fix, const std::string& rayleigh,
                     const std::string& damping_ratio, const std::string& modes_file, bool geometric_stiffening,
                     const std::string& units, bool solid_corner_stress, bool deformation_stiffening,
                     const std::string& frame, bool acceleration_modes) {
    flexmb::io::ReduceOptions o;
    o.model_path = model;
    o.output = output;
    o.interface = interface;
    o.modes = modes;
    o.cutoff_hz = cutoff_hz;
    o.keep = keep;
    o.fix = fix;
    o.rayleigh = rayleigh;
    o.damping_ratio = damping_ratio;
    o.modes_file = modes_file;
    o.geometric_stiffening = geometric_stiffening;
    o.units = units;
    o.solid_corner_stress = solid_corner_stress;
    o.deformation_stiffening = deformation_stiffening;
    o.frame = frame;
    o.acceleration_modes = acceleration_modes;
    o.json = true;
    return ModuleJson([&](std::ostream& out) { flexmb::io::Reduce(o, out); });
  }, py::arg("model"), py::arg("output"), py::arg("interface") = "", py::arg("modes") = -1,
        py::arg("cutoff_hz") = 0.0, py::arg("keep") = -1, py::arg("fix") = "", py::arg("rayleigh") = "",
        py::arg("damping_ratio") = "", py::arg("modes_file") = "", py::arg("geometric_stiffening") = false,
        py::arg("units") = "SI", py::arg("solid_corner_stress") = false,
        py::arg("deformation_stiffening") = false, py::arg("frame") = "", py::arg("acceleration_modes") = false,
        "`flexmb reduce --json`.");
  m.def("body_info", [](const std::string& body) {
    flexmb::io::BodyInfoOptions o{body, true};
    return ModuleJson([&](std::ostream& out) { flexmb::io::BodyInfo(o, out); });
  }, py::arg("body"), "`flexmb body info --json`.");

  // a driver dict {key: value} as LaneChangeOptions::driver_settings, in its order
  auto driver_settings = [](const py::dict& driver) {
    std::vector<std::pair<std::string, double>> out;
    for (const auto& [key, value] : driver) out.emplace_back(py::str(key), value.cast<double>());
    return out;
  };
  m.def("lane_change", [driver_settings](const std::string& file, std::optional<double> speed_kmh,
                          std::optional<std::string> frame, std::optional<double> dt, const std::string& out_dir,
                          bool stop_on_failure, std::optional<double> stop_distance,
                          std::optional<double> run_up_time, const py::dict& driver) {
    flexmb::vehicle::LaneChangeOptions o;
    o.driver_settings = driver_settings(driver);
    o.file = file;
    o.out_dir = out_dir;
    o.speed_kmh = speed_kmh;
    o.frame = frame;
    o.dt = dt;
    o.stop_on_failure = stop_on_failure;
    o.stop_distance = stop_distance;
    o.run_up_time = run_up_time;
    flexmb::vehicle::LaneChangeResult r;
    {
      py::gil_scoped_release release;
      r = flexmb::vehicle::RunLaneChange(o);
    }
    return flexmb::vehicle::LaneChangeJson(r);
  }, py::arg("file"), py::arg("speed_kmh") = py::none(), py::arg("frame") = py::none(),
        py::arg("dt") = py::none(), py::arg("out_dir") = "", py::arg("stop_on_failure") = false,
        py::arg("stop_distance") = py::none(), py::arg("run_up_time") = py::none(), py::arg("driver") = py::dict(),
        "`flexmb run` of a lane-change file: the result as JSON text.");
  m.def("truck_handling", [](const std::string& file, const std::string& test, const std::string& out_dir,
                             std::optional<double> speed_kmh, std::optional<double> steer_deg,
                             std::optional<std::string> frame, std::optional<double> dt, const py::dict& options) {
    flexmb::vehicle::HandlingOptions o;
    o.file = file;
    o.test = test;
    o.out_dir = out_dir;
    o.speed_kmh = speed_kmh;
    o.steer_deg = steer_deg;
    o.frame = frame;
    o.dt = dt;
    // the numeric settings by their names in HandlingOptions
    const std::pair<const char*, double*> numbers[] = {
        {"target_ay", &o.target_ay},           {"radius", &o.radius},
        {"step_time", &o.step_time},           {"rise_time", &o.rise_time},
        {"hold_time", &o.hold_time},           {"speed_rate_kmh_s", &o.speed_rate_kmh_s},
        {"max_ay", &o.max_ay},                 {"max_speed_kmh", &o.max_speed_kmh},
        {"decel", &o.decel},                   {"brake_rise_time", &o.brake_rise_time},
        {"frequency", &o.frequency}};
    for (const auto& [key, value] : options) {
      const std::string name = py::str(key);
      if (name == "brake_torque") {
        o.brake_torque = value.cast<double>();
        continue;
      }
      if (name == "periods") {
        o.periods = value.cast<int>();
        continue;
      }
      bool known = false;
      for (const auto& [n, p] : numbers)
        if (name == n) *p = value.cast<double>(), known = true;
      if (!known) throw flexmb::InputError("unknown handling option '" + name + "'", {file, 0, "truck_handling"});
    }
    flexmb::vehicle::HandlingResult r;
    {
      py::gil_scoped_release release;
      r = flexmb::vehicle::RunHandlingTest(o);
    }
    return flexmb::vehicle::HandlingJson(r);
  }, py::arg("file"), py::arg("test"), py::arg("out_dir") = "", py::arg("speed_kmh") = py::none(),
        py::arg("steer_deg") = py::none(), py::arg("frame") = py::none(), py::arg("dt") = py::none(),
        py::arg("options") = py::dict(), "`flexmb truck handling`: summary.json as JSON text.");
  m.def("max_pass_speed", [driver_settings](const std::string& file, double low, double high, double tol,
                             std::optional<std::string> frame, const py::dict& driver) {
    flexmb::vehicle::LaneChangeOptions o;
    o.file = file;
    o.driver_settings = driver_settings(driver);
    o.frame = frame;
    o.stop_on_failure = true;
    bool low_ok = false;
    double v = 0.0;
    {
      py::gil_scoped_release release;
      v = flexmb::vehicle::MaxPassSpeed(o, low, high, tol, nullptr, &low_ok);
    }
    return py::make_tuple(v, low_ok);
  }, py::arg("file"), py::arg("low"), py::arg("high"), py::arg("tol") = 0.5, py::arg("frame") = py::none(),
        py::arg("driver") = py::dict(), "Highest passed entry speed [km/h] by bisection, and whether `low` passed.");
  m.def("driver_sensitivity", [](const std::string& file, const py::dict& vary, double low, double high, double tol,
                                 std::optional<std::string> frame, const std::string& out_dir) {
    flexmb::vehicle::DriverSensitivityOptions o;
    o.base.file = file;
    o.base.frame = frame;
    o.low = low;
    o.high = high;
    o.tol = tol;
    o.out_dir = out_dir;
    for (const auto& [key, values] : vary)
      o.vary.push_back({py::str(key), values.cast<std::vector<double>>()});
    flexmb::vehicle::DriverSensitivityResult r;
    {
      py::gil_scoped_release release;
      r = flexmb::vehicle::RunDriverSensitivity(o);
    }
    return flexmb::vehicle::DriverSensitivityJson(o, r);
  }, py::arg("file"), py::arg("vary"), py::arg("low") = 20.0, py::arg("high") = 90.0, py::arg("tol") = 1.0,
        py::arg("frame") = py::none(), py::arg("out_dir") = "",
        "`flexmb truck driver-sensitivity`: summary.json as JSON text.");

  m.def("process_tuning", [] {
    const flexmb::ProcessTuning t = flexmb::PlanProcessTuning();
    py::dict d;
    if (*t.openblas_coretype) d["OPENBLAS_CORETYPE"] = t.openblas_coretype;
    if (*t.glibc_tunables) d["GLIBC_TUNABLES"] = t.glibc_tunables;
    return d;
  }, "The environment the flexmb program sets at start-up (OpenBLAS kernels, malloc; docs/design.md) "
     "that this Python process lacks: set it before starting Python for the CLI's FE speed.");

  flexmb::python::BindSimulation(m);
  flexmb::python::BindBodies(m);
  flexmb::python::BindAnalysis(m);
}
