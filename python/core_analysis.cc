// The analysis commands in the compiled core: statics, modes and linearize
// (apps/flexmb/commands/{statics,modes,linearize}_command.h), each the same
// function the command line calls, returning its result as a dict of numpy
// arrays; the pure-Python wrappers are in python/flexmb/analysis.py.
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <complex>
#include <string>
#include <vector>

#include "apps/flexmb/commands/linearize_command.h"
#include "apps/flexmb/commands/modes_command.h"
#include "apps/flexmb/commands/statics_command.h"
#include "python/core_bindings.h"
#include "python/core_simulation.h"

namespace flexmb::python {
namespace py = pybind11;

namespace {

// a copy of an Eigen matrix (column-major) as a C-ordered numpy array
py::array AnalysisMatrix(const MatX& a) {
  py::array_t<double> out({static_cast<py::ssize_t>(a.rows()), static_cast<py::ssize_t>(a.cols())});
  auto r = out.mutable_unchecked<2>();
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) r(i, j) = a(i, j);
  return out;
}

py::array AnalysisVector(const VecX& v) { return py::array_t<double>(v.size(), v.data()); }

// the fields every analysis returns: code, error kind, message, summary, warnings
py::dict AnalysisOutcomeDict(const cli::AnalysisOutcome& o) {
  py::dict d;
  d["code"] = o.code;
  d["error_kind"] = o.error_kind;
  d["message"] = o.message;
  d["summary_json"] = o.summary_json;
  d["warnings"] = o.warnings;
  return d;
}

py::dict AnalysisStaticsDict(const cli::StaticsOutcome& r) {
  py::dict d = AnalysisOutcomeDict(r);
  d["model_name"] = r.model_name;
  d["load_factor"] = r.load_factor;
  d["iterations"] = r.solve.iterations;
  d["residual"] = r.solve.residual;
  d["load_steps"] = r.solve.increments;
  d["cuts"] = r.solve.cuts;
  d["columns"] = r.columns;
  py::array_t<double> rows({static_cast<py::ssize_t>(r.rows.size()), static_cast<py::ssize_t>(r.columns.size())});
  auto w = rows.mutable_unchecked<2>();
  for (size_t i = 0; i < r.rows.size(); ++i)
    for (size_t j = 0; j < r.columns.size(); ++j) w(i, j) = r.rows[i][j];
  d["rows"] = rows;
  d["q"] = AnalysisVector(r.q);
  d["lambda"] = AnalysisVector(r.lambda);
  py::dict bodies;
  for (size_t b = 0; b < r.bodies.size(); ++b)
    bodies[py::str(r.bodies[b])] = py::make_tuple(r.body_q_offset[b], r.body_nq[b]);
  d["bodies"] = bodies;
  d["dof"] = r.dof;
  d["constraint_equations"] = r.constraint_equations;
  return d;
}

py::dict AnalysisModesDict(const cli::ModesResult& r) {
  py::dict d = AnalysisOutcomeDict(r);
  d["model_name"] = r.model_name;
  d["time"] = r.time;
  d["dof"] = r.dof;
  d["rigid_modes"] = r.rigid;
  d["coordinates"] = r.coordinates;
  const size_t n = r.modes.size(), nv = r.coordinates.size();
  std::vector<std::string> kinds;
  VecX f(n), fd(n), zeta(n);
  std::vector<std::complex<double>> s;
  MatX shapes(nv, n), shapes_imag(nv, n);
  for (size_t k = 0; k < n; ++k) {
    const SystemMode& md = r.modes[k];
    kinds.push_back(ModeKindName(md.kind));
    f(k) = md.frequency_hz, fd(k) = md.damped_frequency_hz, zeta(k) = md.damping_ratio;
    s.push_back(md.eigenvalue);
    shapes.col(k) = md.shape, shapes_imag.col(k) = md.shape_imag;
  }
  d["kinds"] = kinds;
  d["frequencies_hz"] = AnalysisVector(f);
  d["damped_frequencies_hz"] = AnalysisVector(fd);
  d["damping_ratios"] = AnalysisVector(zeta);
  d["eigenvalues"] = py::array_t<std::complex<double>>(s.size(), s.data());
  d["shapes"] = AnalysisMatrix(shapes);
  d["shapes_imag"] = AnalysisMatrix(shapes_imag);
  // lane-change (truck) files: the modes' names by their dominant motion
  std::vector<std::string> names;
  for (const cli::TruckModeName& t : r.names) names.push_back(t.name);
  d["names"] = names;
  return d;
}

py::dict AnalysisLinearizeDict(const cli::LinearizeResult& r) {
  py::dict d = AnalysisOutcomeDict(r);
  d["A"] = AnalysisMatrix(r.A);
  d["B"] = AnalysisMatrix(r.B);
  d["C"] = AnalysisMatrix(r.C);
  d["D"] = AnalysisMatrix(r.D);
  d["states"] = r.states;
  d["inputs"] = r.inputs;
  d["outputs"] = r.outputs;
  d["output_values"] = AnalysisVector(r.output_values);
  d["time"] = r.time;
  return d;
}

// the current state of a Python Simulation (`simulation` not None) as the
// source of an analysis: initialized first, then its model, state and
// workspace (borrowed: the Python object outlives the call, which holds a
// reference to it)
bool AnalysisSourceOf(const py::object& simulation, cli::AnalysisSource& source) {
  if (simulation.is_none()) return false;
  PySimulation& s = simulation.cast<PySimulation&>();
  s.Initialize();
  source.model = s.model.get();
  source.state = &s.sim->state();
  source.ws = &s.sim->workspace();
  source.report = s.sim->constraints();
  return true;
}

}  // namespace

void BindAnalysis(py::module_& m) {
  m.def("statics", [](const std::string& model, const std::string& text, const std::string& out_dir, double time,
                      bool animation, const std::string& manoeuvre) {
    cli::StaticsCommandOptions o;
    o.model_path = model;
    o.model_text = text;
    o.out_dir = out_dir;
    o.time = time;
    o.animation = animation;
    o.manoeuvre = manoeuvre;
    cli::StaticsOutcome r;
    {
      py::gil_scoped_release release;
      r = cli::StaticsAnalysis(o);
    }
    return AnalysisStaticsDict(r);
  }, py::arg("model"), py::arg("text") = "", py::arg("out_dir") = "", py::arg("time") = 0.0,
        py::arg("animation") = false, py::arg("manoeuvre") = "",
        "`flexmb statics`: the static equilibrium as a dict (files in out_dir unless empty); text: the model-file "
        "text (model then names it); manoeuvre: the entry of the file's `manoeuvres` (empty: the file's).");
  m.def("modes", [](const std::string& model, const std::string& text, const std::string& out_dir,
                    const std::string& at, double time, int count, bool animation, int frames, double amplitude,
                    const std::string& frame, const py::object& simulation) {
    cli::ModesCommandOptions o;
    o.frame = frame;
    cli::AnalysisSource source;
    if (AnalysisSourceOf(simulation, source)) o.source = &source;
    o.model_path = model;
    o.model_text = text;
    o.out_dir = out_dir;
    o.at = at;
    o.time = time;
    o.count = count;
    o.animation = animation;
    o.frames = frames;
    o.amplitude = amplitude;
    cli::ModesResult r;
    {
      py::gil_scoped_release release;
      r = cli::ModesAnalysis(o);
    }
    return AnalysisModesDict(r);
  }, py::arg("model"), py::arg("text") = "", py::arg("out_dir") = "", py::arg("at") = "statics",
        py::arg("time") = 0.0, py::arg("count") = 10, py::arg("animation") = true, py::arg("frames") = 24,
        py::arg("amplitude") = 0.1, py::arg("frame") = "", py::arg("simulation") = py::none(),
        "`flexmb modes`: the modes as a dict (files in out_dir unless empty); frame: lane-change files only, "
        "\"rigid\" or \"elastic\" (empty: the file's); simulation: a Simulation linearized about its current "
        "state (at 'current').");
  m.def("linearize", [](const std::string& model, const std::string& text, const std::string& out_dir,
                        const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                        const std::string& at, double time, const py::object& simulation) {
    cli::LinearizeCommandOptions o;
    cli::AnalysisSource source;
    if (AnalysisSourceOf(simulation, source)) o.source = &source;
    o.model_path = model;
    o.model_text = text;
    o.out_dir = out_dir;
    o.inputs = inputs;
    o.outputs = outputs;
    o.at = at;
    o.time = time;
    cli::LinearizeResult r;
    {
      py::gil_scoped_release release;
      r = cli::LinearizeAnalysis(o);
    }
    return AnalysisLinearizeDict(r);
  }, py::arg("model"), py::arg("text") = "", py::arg("out_dir") = "", py::arg("inputs") = std::vector<std::string>{},
        py::arg("outputs") = std::vector<std::string>{}, py::arg("at") = "statics", py::arg("time") = 0.0,
        py::arg("simulation") = py::none(),
        "`flexmb linearize`: A, B, C, D and their names as a dict (files in out_dir unless empty); simulation: a "
        "Simulation linearized about its current state (at 'current').");
}

}  // namespace flexmb::python
