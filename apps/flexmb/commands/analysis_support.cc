#include "apps/flexmb/commands/analysis_support.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "flexmb/common/json_text.h"
#include "flexmb/model_file/model_file.h"

namespace flexmb::cli {

AnalysisWarnings::AnalysisWarnings(std::vector<std::string>& into)
    : old_(SetWarningSink([&into](const std::string& m) { into.push_back(m); })) {}

AnalysisWarnings::~AnalysisWarnings() { SetWarningSink(std::move(old_)); }

void LoadAnalysisModel(const std::string& path, double t, AnalysisModel& out, std::vector<std::string>& warnings) {
  out.model = LoadModelFile(path);
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
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!ec) return true;
  if (err) std::fprintf(err, "error: %s: cannot create the output directory: %s\n", dir.c_str(), ec.message().c_str());
  return false;
}

int FinishAnalysisSummary(JsonObjectText& sum, const std::string& dir,
                          std::chrono::steady_clock::time_point start,
                          const std::vector<std::string>& warnings, std::FILE* err, int code) {
  sum.Number("wall_time_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  sum.Texts("warnings", warnings);
  try {
    WriteAnalysisFile((std::filesystem::path(dir) / "summary.json").string(), sum.str());
  } catch (const InputError& e) {
    if (err) std::fprintf(err, "error: %s\n", e.what());
    if (code == 0) code = 2;
  }
  return code;
}

}  // namespace flexmb::cli
