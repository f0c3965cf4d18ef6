#include "flexmb/common/json_text.h"
#include "apps/flexmb/commands/run.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/durability/modal_history.h"
#include "flexmb/forces/reeved_rope.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/results/progress.h"
#include "flexmb/results/results_writer.h"
#include "flexmb/results/vtk_animation.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

using Clock = std::chrono::steady_clock;
using io::JsonNumber;
using io::JsonString;

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// Thrown by the observer when the user interrupts a run.
struct Interrupted {};

/// Collects the warnings issued while alive (restores the previous sink).
class WarningCollector {
 public:
  explicit WarningCollector(std::vector<std::string>& into)
      : old_(SetWarningSink([&into](const std::string& m) { into.push_back(m); })) {}
  ~WarningCollector() { SetWarningSink(std::move(old_)); }

 private:
  LogSink old_;
};

/// Counts output times on a grid t0 + k dt: Due(t) is true at the first call
/// at or after each grid time (always when dt is 0).
class OutputGrid {
 public:
  OutputGrid(double t0, double dt, double eps) : t0_(t0), dt_(dt), eps_(eps) {}
  bool Due(double t) {
    if (dt_ <= 0) return true;
    if (t < t0_ + k_ * dt_ - eps_) return false;
    k_ = static_cast<long>(std::floor((t - t0_ + eps_) / dt_)) + 1;
    return true;
  }

 private:
  double t0_, dt_, eps_;
  long k_ = 0;
};

// the message of e, naming the model file if the error does not name a file
std::string Describe(const Error& e, const std::string& model_path) {
  if (!e.context().file.empty()) return e.what();
  return FormatWithContext(e.message(), {model_path, 0, e.context().entity});
}

void WriteSummaryFile(const std::string& path, const RunSummary& s) {
  // temporary file and rename: summary.json is never half written
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << SummaryJson(s);
    if (!out) return;
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
}

// the simulation itself; throws on any fault, statistics go to s as it runs
void Simulate(const RunOptions& opt, RunSummary& s, std::unique_ptr<Model>& model,
              std::unique_ptr<Simulator>& sim, Clock::time_point& t_start) {
  model = LoadModelFile(opt.model_path, SolverOverrides{opt.t_end, opt.dt, opt.manoeuvre});
  s.model_name = model->name;
  s.manoeuvre = model->manoeuvre;
  if (model->solver.analysis == Analysis::kStatics)
    throw InputError("solver.analysis is 'statics': a static solve, not a time integration (flexmb statics)");
  const double t_end = model->solver.t_end;
  s.t_end_requested = t_end;

  const std::filesystem::path dir(opt.out_dir);
  ResultsWriter results((dir / "results.csv").string(), *model);
  durability::ModelModalHistory modal(dir.string(), *model);
  const OutputSettings& out = model->output;
  std::unique_ptr<VtkAnimationWriter> anim;
  if (out.animation || opt.animation) {
    anim = std::make_unique<VtkAnimationWriter>(dir.string(), *model);
    // ropes as lines along their path (the falls of a hook block as one)
    for (const auto& f : model->forces) {
      if (std::string(f->type()) != "rope") continue;
      const auto* reeved = dynamic_cast<const ReevedRope*>(f.get());
      const int path = reeved ? reeved->path_markers() : 2;
      for (int a = 0; a + 1 < path; ++a) anim->AddLink(f->MarkerAt(a), f->MarkerAt(a + 1));
    }
  }

  // consistent initial state; warnings are collected, then printed
  t_start = Clock::now();
  sim = std::make_unique<Simulator>(*model);
  {
    WarningCollector collect(s.warnings);
    const ConstraintReport& rep = sim->Initialize();
    s.dof = rep.dof;
    s.constraint_equations = rep.equations;
    s.redundant_constraints = static_cast<int>(rep.redundant.size());
  }
  if (model->solver.analysis == Analysis::kStaticsThenDynamics) {
    // start from the static equilibrium at t0 (drivers at their t0 values)
    const StaticsResult st = sim->SettleStatics(StaticsSettingsOf(model->solver));
    if (opt.info)
      std::fprintf(opt.info, "static equilibrium at t = %g s: %d load increments, %d Newton iterations\n",
                   sim->state().t, st.increments, st.iterations);
  }
  s.t_end = sim->state().t;
  if (opt.err)
    for (const std::string& w : s.warnings) std::fprintf(opt.err, "warning: %s\n", w.c_str());
  if (opt.info) {
    std::fprintf(opt.info, "model '%s': %d degrees of freedom, %d constraint equations (%d redundant)\n",
                 model->name.c_str(), s.dof, s.constraint_equations, s.redundant_constraints);
    std::fflush(opt.info);
  }

  // the observer runs on the finer of the two grids and decimates
  const double t0 = sim->state().t;
  const double eps = 1e-9 * std::max(1.0, std::abs(t_end));
  double interval = out.interval;
  if (anim && interval > 0) interval = std::min(interval, out.animation_interval);
  OutputGrid rows(t0, out.interval, eps), frames(t0, out.animation_interval, eps);
  ProgressBar progress(opt.err, opt.progress, t0, t_end);
  const Simulator& simr = *sim;
  const size_t init_warnings = s.warnings.size();
  WarningCollector collect_run(s.warnings);
  sim->Run(t_end, interval, [&](const State& st, const Workspace& ws) {
    if (opt.interrupt && *opt.interrupt) throw Interrupted{};
    const bool last = st.t >= t_end - eps;
    if (rows.Due(st.t) || last) {
      results.Write(st, ws);
      modal.Write(st);
    }
    if (anim && (frames.Due(st.t) || last)) anim->WriteFrame(st);
    s.t_end = st.t;
    s.rows = results.rows();
    s.frames = anim ? anim->frames() : 0;
    progress.Update(st.t, simr.stats().steps);
  });
  progress.Finish(sim->state().t, sim->stats().steps);
  if (opt.err)
    for (size_t k = init_warnings; k < s.warnings.size(); ++k)
      std::fprintf(opt.err, "warning: %s\n", s.warnings[k].c_str());
}

}  // namespace

const char* StatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kOk: return "ok";
    case RunStatus::kInterrupted: return "interrupted";
    case RunStatus::kTerminated: return "terminated";
    default: return "failed";
  }
}

int ExitCode(RunStatus status) {
  switch (status) {
    case RunStatus::kOk: return 0;
    case RunStatus::kInputError: return 2;
    case RunStatus::kInterrupted: return 130;
    case RunStatus::kTerminated: return 143;
    default: return 1;
  }
}

RunSummary RunModel(const RunOptions& opt) {
  RunSummary s;
  s.model = opt.model_path;
  const Clock::time_point start = Clock::now();
  Clock::time_point t_start = start;
  std::unique_ptr<Model> model;
  std::unique_ptr<Simulator> sim;

  std::error_code ec;
  std::filesystem::create_directories(opt.out_dir, ec);
  if (ec) {
    s.status = RunStatus::kInputError;
    s.message = FormatWithContext("cannot create the output directory: " + ec.message(),
                                  {opt.out_dir, 0, ""});
    return s;
  }
  try {
    Simulate(opt, s, model, sim, t_start);
  } catch (const InputError& e) {
    s.status = RunStatus::kInputError;
    s.message = Describe(e, opt.model_path);
  } catch (const NumericalError& e) {
    s.status = RunStatus::kNumericalError;
    s.message = Describe(e, opt.model_path);
  } catch (const Interrupted&) {
    const bool term = opt.interrupt && *opt.interrupt == SIGTERM;
    s.status = term ? RunStatus::kTerminated : RunStatus::kInterrupted;
    s.message = term ? "terminated by SIGTERM (e.g. a job scheduler or kill)" : "interrupted by the user";
  } catch (const std::exception& e) {
    s.status = RunStatus::kOtherError;
    s.message = e.what();
  }

  // statistics of what was done, also after a failure
  const Clock::time_point end = Clock::now();
  s.wall_time_s = Seconds(start, end);
  if (sim) {
    const IntegratorStats& st = sim->stats();
    s.t_end = sim->state().t;
    s.steps = st.steps;
    s.rejected_steps = st.rejected;
    s.newton_iterations = st.newton_iterations;
    s.factorizations = st.factorizations;
    s.chord_checks = st.chord_checks;
    s.chord_steps = st.chord_steps;
    s.max_constraint_violation = st.max_constraint_violation;
    s.integration_time_s = Seconds(t_start, end);
    s.steps_per_second = s.integration_time_s > 0 ? s.steps / s.integration_time_s : 0.0;
    if (!sim->failure_shares().empty()) {
      s.culprit = sim->failure_shares().front().Entity();
      s.culprit_share = sim->failure_shares().front().share;
    }
    s.max_error_estimate = sim->accuracy().max_error;
    s.dt_needed = sim->accuracy().dt_needed;
  }
  WriteSummaryFile((std::filesystem::path(opt.out_dir) / "summary.json").string(), s);
  return s;
}

std::string SummaryJson(const RunSummary& s) {
  std::string j = "{\n";
  auto add = [&](const char* key, const std::string& value, bool last = false) {
    j += "  " + JsonString(key) + ": " + value + (last ? "\n" : ",\n");
  };
  add("status", JsonString(StatusName(s.status)));
  add("message", JsonString(s.message));
  add("model", JsonString(s.model));
  add("model_name", JsonString(s.model_name));
  add("manoeuvre", JsonString(s.manoeuvre));
  add("t_end_requested", JsonNumber(s.t_end_requested));
  add("t_end", JsonNumber(s.t_end));
  add("steps", std::to_string(s.steps));
  add("rejected_steps", std::to_string(s.rejected_steps));
  add("newton_iterations", std::to_string(s.newton_iterations));
  add("factorizations", std::to_string(s.factorizations));
  add("chord_checks", std::to_string(s.chord_checks));
  add("chord_steps", std::to_string(s.chord_steps));
  add("wall_time_s", JsonNumber(s.wall_time_s));
  add("integration_time_s", JsonNumber(s.integration_time_s));
  add("max_constraint_violation", JsonNumber(s.max_constraint_violation));
  add("dof", std::to_string(s.dof));
  add("constraint_equations", std::to_string(s.constraint_equations));
  add("redundant_constraints", std::to_string(s.redundant_constraints));
  add("steps_per_second", JsonNumber(s.steps_per_second));
  add("rows", std::to_string(s.rows));
  add("frames", std::to_string(s.frames));
  add("culprit", JsonString(s.culprit));
  add("culprit_share", JsonNumber(s.culprit_share));
  add("max_error_estimate", JsonNumber(s.max_error_estimate));
  add("dt_needed", JsonNumber(s.dt_needed));
  std::string w = "[";
  for (size_t i = 0; i < s.warnings.size(); ++i) w += (i ? ", " : "") + JsonString(s.warnings[i]);
  add("warnings", w + "]", true);
  return j + "}\n";
}

void CheckModel(const std::string& model_path, std::FILE* out, const std::string& manoeuvre) {
  std::unique_ptr<Model> model = LoadModelFile(model_path, SolverOverrides{std::nullopt, std::nullopt, manoeuvre});
  ReportModel(*model, model_path, out);
}

void ReportModel(const Model& m, const std::string& model_path, std::FILE* out) {
  std::fprintf(out, "model '%s' (%s)\n", m.name.c_str(), model_path.c_str());
  std::fprintf(out, "bodies: %d (plus ground)\n", static_cast<int>(m.bodies.size()) - 1);
  for (size_t b = 1; b < m.bodies.size(); ++b) std::fprintf(out, "  '%s'\n", m.bodies[b]->name().c_str());
  int equations = 0;
  for (const auto& j : m.joints) equations += j->NumEquations();
  std::fprintf(out, "joints: %d (%d equations)\n", static_cast<int>(m.joints.size()), equations);
  for (const auto& j : m.joints)
    std::fprintf(out, "  %s '%s': %d equations\n", j->type(), j->name().c_str(), j->NumEquations());
  std::fprintf(out, "forces: %d\n", static_cast<int>(m.forces.size()));
  int components = 0;
  for (const auto& s : m.sensors) components += static_cast<int>(s->Components().size());
  std::fprintf(out, "sensors: %d (%d output columns)\n", static_cast<int>(m.sensors.size()), components);

  Simulator sim(m);
  std::vector<std::string> warnings;
  ConstraintReport rep;
  try {
    WarningCollector collect(warnings);
    rep = sim.Initialize();
  } catch (const InputError& e) {
    if (!e.context().file.empty()) throw;
    throw InputError(e.message(), {model_path, 0, e.context().entity});
  } catch (const NumericalError& e) {
    if (!e.context().file.empty()) throw;
    throw NumericalError(e.message(), {model_path, 0, e.context().entity});
  }
  std::fprintf(out, "degrees of freedom: %d\n", rep.dof);
  std::fprintf(out, "constraint equations: %d (%d redundant)\n", rep.equations,
               static_cast<int>(rep.redundant.size()));
  for (const std::string& w : warnings) std::fprintf(out, "warning: %s\n", w.c_str());
  std::fflush(out);
}

}  // namespace flexmb
