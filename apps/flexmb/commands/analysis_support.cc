#include "apps/flexmb/commands/analysis_support.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "flexmb/common/json_text.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/linearization.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/statics.h"

namespace flexmb::cli {

AnalysisWarnings::AnalysisWarnings(std::vector<std::string>& into)
    : old_(SetWarningSink([&into](const std::string& m) { into.push_back(m); })) {}

AnalysisWarnings::~AnalysisWarnings() { SetWarningSink(std::move(old_)); }

namespace {

// a warning when the state `what` moves (accelerations a or velocities)
void AnalysisWarnIfMoving(const Model& m, const AnalysisModel& am, const VecX& a, const std::string& what,
                          std::vector<std::string>& warnings) {
  Eigen::Index k = 0;
  const double amax = a.size() ? a.cwiseAbs().maxCoeff(&k) : 0.0;
  const double vmax = am.state.v.size() ? am.state.v.cwiseAbs().maxCoeff() : 0.0;
  if (amax > 1e-6 || vmax > 1e-9)
    warnings.push_back(what + " is not an equilibrium (largest acceleration " + std::to_string(amax) + " at " +
                       VelocityCoordinateName(m, static_cast<int>(k)) + ", largest velocity " +
                       std::to_string(vmax) + "): the modes are those of the tangent system at that state");
}

}  // namespace

std::unique_ptr<Model> LoadAnalysisModelFile(const std::string& path, const std::string& text,
                                             const std::string& manoeuvre) {
  SolverOverrides o;
  o.manoeuvre = manoeuvre;
  return text.empty() ? LoadModelFile(path, o) : LoadModelString(text, path, o);
}

void AnalysisLinearizationState(const std::string& path, const std::string& text, const std::string& at,
                                double time, AnalysisModel& am, VecX& a, std::vector<std::string>& warnings) {
  if (at == "time") {
    if (!(time >= 0.0) || !std::isfinite(time)) throw InputError("--time must be a number of seconds >= 0");
    am.model = LoadAnalysisModelFile(path, text);
    Simulator sim(*am.model);
    {
      AnalysisWarnings collect(warnings);
      sim.Initialize();
    }
    if (time > sim.state().t) sim.Run(time, 0.0, nullptr);
    am.state = sim.state();
    am.ws = sim.workspace();
    am.report = sim.constraints();
    a = am.ws.vdot;
    AnalysisWarnIfMoving(*am.model, am, a, "the state at --time", warnings);
    return;
  }
  if (at != "statics" && at != "initial") throw InputError("--at must be statics, initial or time, got '" + at + "'");
  LoadAnalysisModel(path, time, am, warnings, text);
  if (at == "initial") {
    a = am.ws.vdot;
    AnalysisWarnIfMoving(*am.model, am, a, "the initial state", warnings);
    return;
  }
  try {
    SolveStatics(*am.model, am.state, am.ws, StaticsSettingsOf(am.model->solver));
  } catch (const NumericalError& e) {
    throw NumericalError("--at statics: no static equilibrium to linearize about: " + e.message(), e.context());
  }
  a = VecX::Zero(am.model->nv);
}

const Model& AnalysisLinearizationModel(const std::string& path, const std::string& text, const std::string& at,
                                        double time, const AnalysisSource* source, AnalysisModel& am, VecX& a,
                                        std::vector<std::string>& warnings) {
  if (!source) {
    if (at == "current")
      throw InputError("at 'current' needs a model in simulation (Python: a flexmb.Simulation as the model)");
    AnalysisLinearizationState(path, text, at, time, am, a, warnings);
    return *am.model;
  }
  if (at != "current")
    throw InputError("a model in simulation is linearized about its current state: at must be 'current', got '" +
                     at + "'");
  am.state = *source->state;
  am.ws = *source->ws;
  am.report = source->report;
  a = am.ws.vdot;
  AnalysisWarnIfMoving(*source->model, am, a, "the current state", warnings);
  return *source->model;
}

void LoadAnalysisModel(const std::string& path, double t, AnalysisModel& out, std::vector<std::string>& warnings,
                       const std::string& text, const std::string& manoeuvre) {
  out.model = LoadAnalysisModelFile(path, text, manoeuvre);
  out.state = out.model->InitialState();
  out.state.t = t;
  AnalysisWarnings collect(warnings);
  out.report = MakeConsistent(*out.model, out.state, out.ws);
}

std::string AnalysisErrorText(const Error& e, const std::string& model_path) {
  if (!e.context().file.empty()) return e.what();
  return FormatWithContext(e.message(), {model_path, 0, e.context().entity});
}

void JsonObjectText::Raw(const std::string& key, const std::string& value) { items_.emplace_back(key, value); }

void JsonObjectText::Text(const std::string& key, const std::string& value) {
  items_.emplace_back(key, io::JsonString(value));
}

void JsonObjectText::Number(const std::string& key, double value) { items_.emplace_back(key, io::JsonNumber(value)); }

void JsonObjectText::Texts(const std::string& key, const std::vector<std::string>& values) {
  std::string w = "[";
  for (size_t i = 0; i < values.size(); ++i) w += (i ? ", " : "") + io::JsonString(values[i]);
  items_.emplace_back(key, w + "]");
}

std::string JsonObjectText::str() const {
  std::string j = "{\n";
  for (size_t i = 0; i < items_.size(); ++i)
    j += "  " + io::JsonString(items_[i].first) + ": " + items_[i].second + (i + 1 < items_.size() ? ",\n" : "\n");
  return j + "}\n";
}

void WriteAnalysisFile(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << text;
    if (!out) throw InputError("cannot write the file", {path, 0, ""});
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw InputError("cannot write the file: " + ec.message(), {path, 0, ""});
}

bool CreateAnalysisDir(const std::string& dir, std::FILE* err) {
  if (dir.empty()) return true;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!ec) return true;
  if (err) std::fprintf(err, "error: %s: cannot create the output directory: %s\n", dir.c_str(), ec.message().c_str());
  return false;
}

int FinishAnalysisSummary(JsonObjectText& sum, const std::string& dir,
                          std::chrono::steady_clock::time_point start,
                          const std::vector<std::string>& warnings, std::FILE* err, int code,
                          std::string* text) {
  sum.Number("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  sum.Texts("warnings", warnings);
  if (text) *text = sum.str();
  if (dir.empty()) return code;
  try {
    WriteAnalysisFile((std::filesystem::path(dir) / "summary.json").string(), sum.str());
  } catch (const InputError& e) {
    if (err) std::fprintf(err, "error: %s\n", e.what());
    if (code == 0) code = 2;
  }
  return code;
}

}  // namespace flexmb::cli
