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
/// consistent (MakeConsistent); the warnings go to `warnings`.
void LoadAnalysisModel(const std::string& path, double t, AnalysisModel& out, std::vector<std::string>& warnings);

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

/// Creates the output folder `dir`; false (after printing the error on
/// `err`, if given) when it cannot be created.
bool CreateAnalysisDir(const std::string& dir, std::FILE* err);

/// Adds `wall_time_s` (since `start`) and `warnings` to `sum`, writes it as
/// DIR/summary.json and returns `code`, or 2 if the file cannot be written
/// and `code` was 0 (the error printed on `err`).
int FinishAnalysisSummary(JsonObjectText& sum, const std::string& dir,
                          std::chrono::steady_clock::time_point start,
                          const std::vector<std::string>& warnings, std::FILE* err, int code);

}  // namespace flexmb::cli
