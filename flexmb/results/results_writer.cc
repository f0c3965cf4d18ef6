#include "flexmb/results/results_writer.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <numbers>

#include "flexmb/common/error.h"
#include "flexmb/model/model.h"

namespace flexmb {

ResultsWriter::ResultsWriter(const std::string& path, const Model& model)
    : model_(model), path_(path) {
  names_.push_back("time");
  for (const auto& s : model.sensors) {
    const std::vector<std::string> comps = s->Components();
    counts_.push_back(static_cast<int>(comps.size()));
    for (int k = 0; k < static_cast<int>(comps.size()); ++k) {
      names_.push_back(s->name() + "." + comps[k]);
      is_angle_.push_back(s->ComponentIsAngle(k) ? 1 : 0);
    }
  }
  values_.assign(is_angle_.size(), 0.0);
  previous_.assign(is_angle_.size(), 0.0);

  file_ = std::fopen(path.c_str(), "w");
  if (!file_)
    throw InputError("cannot open results file for writing: " + std::string(std::strerror(errno)),
                     {path, 0, ""});
  for (size_t c = 0; c < names_.size(); ++c)
    std::fprintf(file_, "%s%s", c ? "," : "", names_[c].c_str());
  std::fputc('\n', file_);
  std::fflush(file_);
}

ResultsWriter::~ResultsWriter() { Close(); }

void ResultsWriter::Close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

void ResultsWriter::Write(const State& state, const Workspace& ws) {
  double* out = values_.data();
  for (size_t i = 0; i < model_.sensors.size(); ++i) {
    model_.sensors[i]->Evaluate(model_, state, ws, out);
    out += counts_[i];
  }
  WriteRow(state.t, values_.data());
}

void ResultsWriter::WriteRow(double t, const double* values) {
  if (!file_) throw Error("results file is closed", {path_, 0, ""});
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  std::fprintf(file_, "%.15g", t);
  for (size_t c = 0; c < previous_.size(); ++c) {
    double x = values[c];
    // shift angles by whole turns to stay within pi of the previous row
    if (is_angle_[c] && rows_ > 0 && std::isfinite(x))
      x += kTwoPi * std::round((previous_[c] - x) / kTwoPi);
    previous_[c] = x;
    std::fprintf(file_, ",%.15g", x);
  }
  std::fputc('\n', file_);
  std::fflush(file_);
  ++rows_;
}

}  // namespace flexmb
