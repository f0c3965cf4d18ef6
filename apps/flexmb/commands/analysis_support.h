#pragma once
/// \file analysis_support.h
/// Pieces shared by the analysis commands `flexmb statics` and `flexmb
/// modes`: the model with its consistent state, warnings collected into a
/// list, error messages naming the model file, and the key-value JSON of
/// their summary.json.

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/initial_conditions.h"

namespace flexmb::cli {

/// Collects the warnings issued while alive (restores the previous sink).
class AnalysisWarnings {
 public:
  explicit AnalysisWarnings(std::vector<std::string>& into);
  ~AnalysisWarnings();
  AnalysisWarnings(const AnalysisWarnings&) = delete;
  AnalysisWarnings& operator=(const AnalysisWarnings&) = delete;

 private:
  LogSink old_;
};

/// A loaded model with a consistent state at time t and its workspace.
struct AnalysisModel {
  std::unique_ptr<Model> model;
  State state;
  Workspace ws;
  ConstraintReport report;
};

/// Loads the model file and makes its initial state, at time `t` [s],
/// consistent (MakeConsistent); the warnings go to `warnings`. A non-empty
/// `text` is the model-file text itself, `path` then names it in messages.
void LoadAnalysisModel(const std::string& path, double t, AnalysisModel& out, std::vector<std::string>& warnings,
                       const std::string& text = "", const std::string& manoeuvre = "");

/// The model file at `path`, or the model-file text `text` if non-empty
/// (`path` then names it in messages), with the file's `manoeuvres` entry
/// `manoeuvre` applied (empty: the file's own choice).
std::unique_ptr<Model> LoadAnalysisModelFile(const std::string& path, const std::string& text,
                                             const std::string& manoeuvre = "");

/// The state to linearize about (`flexmb modes` and `flexmb linearize`),
/// into `am`, with its accelerations into `a` (nv): `at` "statics" (the
/// static equilibrium under the loads at time `time` [s]; a = 0),
/// "initial" (the consistent initial state at `time`) or "time" (the state
/// of a dynamic run to `time`). A state that moves adds a warning. Throws
/// InputError for a bad `at` or `time`, NumericalError when there is no
/// static equilibrium.
void AnalysisLinearizationState(const std::string& path, const std::string& text, const std::string& at,
                                double time, AnalysisModel& am, VecX& a, std::vector<std::string>& warnings);

/// A model in simulation to linearize about its current state (`at`
/// "current"; Python's flexmb.modes(simulation)): the model, its state and
/// workspace (accelerations in ws.vdot), not owned; they must outlive the
/// analysis.
struct AnalysisSource {
  const Model* model = nullptr;
  const State* state = nullptr;
  const Workspace* ws = nullptr;
  ConstraintReport report;  ///< the source's constraint report
};

/// The model and state to linearize about (`flexmb modes`, `flexmb
/// linearize`, and the same from Python): with `source` (then `at` must be
/// "current"), the source's state, workspace and accelerations copied into
/// `am` and `a` (am.model stays empty) and the source's model returned;
/// without, AnalysisLinearizationState and *am.model. A state that moves
/// adds a warning. Throws InputError for "current" without a source, or a
/// source with another `at`.
const Model& AnalysisLinearizationModel(const std::string& path, const std::string& text, const std::string& at,
                                        double time, const AnalysisSource* source, AnalysisModel& am, VecX& a,
                                        std::vector<std::string>& warnings);

/// The message of `e`, naming `model_path` if the error names no file.
std::string AnalysisErrorText(const Error& e, const std::string& model_path);

/// Builder of a flat JSON object with one key per line.
class JsonObjectText {
 public:
  /// Adds "key": value, value already JSON text.
  void Raw(const std::string& key, const std::string& value);
  /// Adds a string.
  void Text(const std::string& key, const std::string& value);
  /// Adds a number (null if not finite).
  void Number(const std::string& key, double value);
  /// Adds an array of strings.
  void Texts(const std::string& key, const std::vector<std::string>& values);
  /// The object, "{\n ... }\n".
  std::string str() const;

 private:
  std::vector<std::pair<std::string, std::string>> items_;
};

/// Writes `text` to `path` through a temporary file and a rename.
void WriteAnalysisFile(const std::string& path, const std::string& text);

/// Creates the output folder `dir` (nothing for an empty `dir`: no files
/// wanted); false (after printing the error on `err`, if given) when it
/// cannot be created.
bool CreateAnalysisDir(const std::string& dir, std::FILE* err);

/// Adds `wall_time_s` (since `start`) and `warnings` to `sum`, writes it as
/// DIR/summary.json (not for an empty `dir`) and returns `code`, or 2 if the
/// file cannot be written and `code` was 0 (the error printed on `err`);
/// `text`, if given, receives the JSON text.
int FinishAnalysisSummary(JsonObjectText& sum, const std::string& dir,
                          std::chrono::steady_clock::time_point start,
                          const std::vector<std::string>& warnings, std::FILE* err, int code,
                          std::string* text = nullptr);

/// How an analysis command ended, for its callers (CLI and Python).
struct AnalysisOutcome {
  int code = 0;                       ///< exit code: 0 ok, 2 input error, 1 numerical or other error
  std::string error_kind;             ///< "InputError", "NumericalError" or "Error" (empty when ok)
  std::string message;                ///< the error message (empty when ok)
  std::string summary_json;           ///< the summary.json text
  std::vector<std::string> warnings;  ///< warnings of the analysis
};

}  // namespace flexmb::cli
