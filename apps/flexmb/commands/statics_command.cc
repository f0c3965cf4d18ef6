#include "apps/flexmb/commands/statics_command.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>

#include "apps/flexmb/commands/analysis_support.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/results/vtk_animation.h"
#include "flexmb/solver/statics.h"

namespace flexmb::cli {
namespace {

// the results table of the load steps: load factor, Newton iterations,
// residual and every sensor component; kept in `columns` and `rows`, and
// written to `path` unless it is empty
class StaticsTable {
 public:
  StaticsTable(const std::string& path, const Model& m, std::vector<std::string>& columns,
               std::vector<std::vector<double>>& rows)
      : m_(m), rows_(rows) {
    columns = {"load_factor", "iterations", "residual"};
    for (const auto& s : m.sensors) {
      const std::vector<std::string> comps = s->Components();
      counts_.push_back(static_cast<int>(comps.size()));
      for (const std::string& c : comps) columns.push_back(s->name() + "." + c);
    }
    if (path.empty()) return;
    file_ = std::fopen(path.c_str(), "w");
    if (!file_) throw InputError("cannot open the results file for writing", {path, 0, ""});
    for (size_t k = 0; k < columns.size(); ++k) std::fprintf(file_, "%s%s", k ? "," : "", columns[k].c_str());
    std::fputc('\n', file_);
    std::fflush(file_);
  }
  ~StaticsTable() {
    if (file_) std::fclose(file_);
  }
  StaticsTable(const StaticsTable&) = delete;
  StaticsTable& operator=(const StaticsTable&) = delete;

  void Write(double mu, int iterations, double residual, const State& s, const Workspace& ws) {
    std::vector<double> row = {mu, static_cast<double>(iterations), residual};
    for (size_t i = 0; i < m_.sensors.size(); ++i) {
      values_.assign(counts_[i], 0.0);
      m_.sensors[i]->Evaluate(m_, s, ws, values_.data());
      row.insert(row.end(), values_.begin(), values_.end());
    }
    rows_.push_back(row);
    if (!file_) return;
    std::fprintf(file_, "%.15g,%d,%.6g", mu, iterations, residual);
    for (size_t k = 3; k < row.size(); ++k) std::fprintf(file_, ",%.15g", row[k]);
    std::fputc('\n', file_);
    std::fflush(file_);
  }
  long rows() const { return static_cast<long>(rows_.size()); }

 private:
  const Model& m_;
  std::vector<std::vector<double>>& rows_;
  std::FILE* file_ = nullptr;
  std::vector<int> counts_;
  std::vector<double> values_;
};

}  // namespace

bool ModelAsksForStatics(const std::string& model_path, const std::string& manoeuvre) {
  try {
    SolverOverrides o;
    o.manoeuvre = manoeuvre;
    return LoadModelFile(model_path, o)->solver.analysis == Analysis::kStatics;
  } catch (const std::exception&) {
    return false;
  }
}

int StaticsCommand(const StaticsCommandOptions& opt) { return StaticsAnalysis(opt).code; }

StaticsOutcome StaticsAnalysis(const StaticsCommandOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  StaticsOutcome out;
  JsonObjectText sum;
  std::vector<std::string>& warnings = out.warnings;
  std::string status = "ok", message;
  int code = 0;
  double& load_factor = out.load_factor;
  StaticsResult& res = out.solve;
  long rows = 0;
  int frames = 0;
  AnalysisModel am;
  if (!CreateAnalysisDir(opt.out_dir, opt.err)) {
    out.code = 2, out.error_kind = "InputError", out.message = opt.out_dir + ": cannot create the output directory";
    return out;
  }
  const std::filesystem::path dir(opt.out_dir);
  const bool files = !opt.out_dir.empty();
  try {
    if (!std::isfinite(opt.time)) throw InputError("--time must be a finite number of seconds");
    LoadAnalysisModel(opt.model_path, opt.time, am, warnings, opt.model_text, opt.manoeuvre);
    if (opt.err)
      for (const std::string& w : warnings) std::fprintf(opt.err, "warning: %s\n", w.c_str());
    StaticsTable table(files ? (dir / "results.csv").string() : "", *am.model, out.columns, out.rows);
    std::unique_ptr<VtkAnimationWriter> anim;
    if (files && (opt.animation || am.model->output.animation))
      anim = std::make_unique<VtkAnimationWriter>(dir.string(), *am.model);
    am.ws.vdot.setZero();
    StaticsSettings set = StaticsSettingsOf(am.model->solver);
    State frame;
    set.on_increment = [&](double mu, int iterations, const StaticsResult& r) {
      load_factor = mu;
      table.Write(mu, iterations, r.residual, am.state, am.ws);
      rows = table.rows();
      if (!anim) return;
      frame = am.state;
      frame.t = mu;
      anim->WriteFrame(frame);
      frames = anim->frames();
    };
    res = SolveStatics(*am.model, am.state, am.ws, set);
    if (opt.info)
      std::fprintf(opt.info,
                   "static equilibrium of '%s' at t = %g s: %d load steps (%d cut), %d Newton iterations, "
                   "residual %.3g; results in %s\n",
                   am.model->name.c_str(), am.state.t, res.increments, res.cuts, res.iterations, res.residual,
                   opt.out_dir.c_str());
  } catch (const InputError& e) {
    status = "failed", message = AnalysisErrorText(e, opt.model_path), code = 2, out.error_kind = "InputError";
  } catch (const NumericalError& e) {
    status = "failed", message = AnalysisErrorText(e, opt.model_path), code = 1, out.error_kind = "NumericalError";
    if (message.find("load factor") == std::string::npos)
    {
      char lf[32];
      std::snprintf(lf, sizeof lf, "%.4g", load_factor);
      message += std::string(" (load factor reached: ") + lf + " of 1)";
    }
  } catch (const std::exception& e) {
    status = "failed", message = e.what(), code = 1, out.error_kind = "Error";
  }
  if (am.model) {
    out.model_name = am.model->name;
    out.q = am.state.q, out.lambda = am.state.lambda;
    for (const auto& b : am.model->bodies) {
      out.bodies.push_back(b->name());
      out.body_q_offset.push_back(b->q_offset);
      out.body_nq.push_back(b->nq());
    }
    out.dof = am.report.dof, out.constraint_equations = am.report.equations;
  }
  if (code != 0 && opt.err) std::fprintf(opt.err, "error: %s\n", message.c_str());
  sum.Text("status", status);
  sum.Text("message", message);
  sum.Text("analysis", "statics");
  sum.Text("model", opt.model_path);
  sum.Text("model_name", am.model ? am.model->name : "");
  sum.Text("manoeuvre", am.model ? am.model->manoeuvre : opt.manoeuvre);
  sum.Number("time", opt.time);
  sum.Number("load_factor", load_factor);
  sum.Raw("load_steps", std::to_string(res.increments));
  sum.Raw("cuts", std::to_string(res.cuts));
  sum.Raw("newton_iterations", std::to_string(res.iterations));
  sum.Number("residual", res.residual);
  sum.Raw("dof", std::to_string(am.report.dof));
  sum.Raw("constraint_equations", std::to_string(am.report.equations));
  sum.Raw("redundant_constraints", std::to_string(am.report.redundant.size()));
  sum.Raw("rows", std::to_string(rows));
  sum.Raw("frames", std::to_string(frames));
  out.code = FinishAnalysisSummary(sum, opt.out_dir, start, warnings, opt.err, code, &out.summary_json);
  out.message = message;
  if (out.code != 0 && out.error_kind.empty()) out.error_kind = "InputError", out.message = "cannot write summary.json";
  return out;
}

}  // namespace flexmb::cli
