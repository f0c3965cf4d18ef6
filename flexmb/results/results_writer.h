#pragma once
/// \file results_writer.h
/// Writes sensor results as CSV: a header "time,<sensor>.<component>,..." and
/// one row per output time, flushed after every row so that an interrupted
/// run keeps everything written so far.

#include <cstdio>
#include <string>
#include <vector>

namespace flexmb {

class Model;
struct State;
struct Workspace;

/// CSV writer of all sensor components of a model. Angle components
/// (Sensor::ComponentIsAngle) are unwrapped across +-pi: each written value
/// is shifted by a multiple of 2 pi to lie within pi of the previous row's.
class ResultsWriter {
 public:
  /// Opens (truncates) `path` and writes the header. Throws InputError if the
  /// file cannot be opened. `model` must be finalized and outlive the writer.
  ResultsWriter(const std::string& path, const Model& model);
  ~ResultsWriter();
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  /// Evaluates every sensor at `state` (the workspace must be up to date for
  /// it) and writes one row: time [s] then the components, "%.15g". Flushes.
  void Write(const State& state, const Workspace& ws);

  /// Writes one row from given values: time [s] and one value per column
  /// (column_names().size() - 1 values). Applies unwrapping; flushes.
  void WriteRow(double t, const double* values);

  /// Column names, "time" first.
  const std::vector<std::string>& column_names() const { return names_; }
  /// Number of rows written.
  long rows() const { return rows_; }
  /// Closes the file (also done by the destructor).
  void Close();

 private:
  const Model& model_;
  std::FILE* file_ = nullptr;
  std::string path_;
  std::vector<std::string> names_;
  std::vector<int> counts_;      ///< per sensor: number of components
  std::vector<char> is_angle_;   ///< per value column
  std::vector<double> values_;   ///< scratch: current row
  std::vector<double> previous_; ///< last written value per column (for unwrapping)
  long rows_ = 0;
};

}  // namespace flexmb
