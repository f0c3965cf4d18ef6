#include "flexmb/solver/simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/sparse_lu.h"

namespace flexmb {

namespace {

// printf-style text ("%g" for numbers that mean something at any scale)
[[gnu::format(printf, 1, 2)]] std::string SimulatorFormat(const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof(buf), format, args);
  va_end(args);
  return buf;
}

}  // namespace

Simulator::Simulator(const Model& model)
    : model_(model),
      state_(model.InitialState()),
      integrator_(model, ws_, model.solver.rho_inf),
      h_(model.solver.dt) {
  if (!model.finalized()) throw Error("Simulator needs a finalized model");
}

const ConstraintReport& Simulator::Initialize() {
  report_ = MakeConsistent(model_, state_, ws_);
  integrator_.Start(state_);
  initialized_ = true;
  return report_;
}

StaticsResult Simulator::SettleStatics(const StaticsSettings& settings, bool keep_velocities) {
  if (!initialized_) Initialize();
  const VecX v0 = state_.v;
  const StaticsResult r = SolveStatics(model_, state_, ws_, settings);
  SparseLu lu;
  if (keep_velocities) {
    state_.v = v0;
    ProjectVelocities(model_, state_, ws_, lu);
  }
  InitialAccelerations(model_, state_, ws_, lu);
  integrator_.Start(state_);
  return r;
}

void Simulator::RefreshWorkspace() {
  EvaluateMarkers(model_, state_, ws_);
  EvaluateConstraints(model_, state_, ws_);
  EvaluateForces(model_, state_, ws_, false);
}

void Simulator::Run(double t_end, double output_interval, const Observer& observer) {
  if (!initialized_) Initialize();
  const SolverSettings& ss = model_.solver;
  const double h_max = ss.dt_max > 0 ? ss.dt_max : 100.0 * ss.dt;
  const double t0 = state_.t;
  const double eps = 1e-12 * std::max(1.0, std::abs(t_end));
  const long steps0 = integrator_.stats.steps, rejected0 = integrator_.stats.rejected;
  long out_index = 0;
  auto next_output = [&]() {
    return output_interval > 0 ? t0 + (out_index + 1) * output_interval : t_end;
  };
  // a runaway stops with its own message instead of grinding on
  auto check_runaway = [&]() {
    const long rejected = integrator_.stats.rejected - rejected0, accepted = integrator_.stats.steps - steps0;
    if (IsRunaway(rejected, accepted)) {
      Fail(SimulatorFormat("runaway: %ld step attempts rejected for %ld accepted (more than %g times as many) at "
                           "t = %g s; ",
                           rejected, accepted, kRunawayRatio, state_.t));
    }
  };
  // steps end exactly at the joints' release times (Joint::release_time)
  std::vector<double> releases;
  for (const auto& j : model_.joints)
    if (std::isfinite(j->release_time) && j->release_time > t0 + eps) releases.push_back(j->release_time);
  std::sort(releases.begin(), releases.end());
  size_t next_release = 0;
  ReleaseJoints(eps);
  // any joint with limits on its coordinate (a cylinder's stroke)?
  const bool limited = std::any_of(model_.joints.begin(), model_.joints.end(), [](const auto& j) {
    return j->NumCoordinates() > 0 && (std::isfinite(j->coordinate_min) || std::isfinite(j->coordinate_max));
  });
  if (limited) {
    RefreshWorkspace();
    CheckJointLimits(model_, ws_, state_.t);
  }
  if (observer) {
    RefreshWorkspace();
    observer(state_, ws_);
  }
  while (state_.t < t_end - eps) {
    while (next_release < releases.size() && releases[next_release] <= state_.t + eps) ++next_release;
    double h = ss.adaptive ? h_ : ss.dt;
    const double t_out = std::min(next_output(), t_end);
    const double t_stop = next_release < releases.size() ? std::min(t_out, releases[next_release]) : t_out;
    bool hits_output = false, hits_stop = false;
    if (state_.t + h >= t_stop - eps) {
      h = t_stop - state_.t;
      hits_stop = true;
      hits_output = t_stop >= t_out - eps;
    }
    const StepStatus st = integrator_.TryStep(state_, h);
    if (st == StepStatus::kConverged && (!ss.adaptive || integrator_.error_estimate() <= 1.0)) {
      if (!ss.adaptive) NoteAccuracy(h);
      integrator_.Accept(state_);
      if (ss.adaptive) {
        const double err = std::max(integrator_.error_estimate(), 1e-10);
        const double grow = std::clamp(0.9 * std::pow(err, -1.0 / 3.0), 0.2, 2.0);
        if (!hits_stop || h >= h_) h_ = std::min(h_max, h * grow);
      }
    } else {
      // rejected: cut the step
      ++integrator_.stats.rejected;
      check_runaway();
      if (ss.adaptive) {
        if (st == StepStatus::kConverged) {
          const double err = integrator_.error_estimate();
          h_ = h * std::clamp(0.9 * std::pow(err, -1.0 / 3.0), 0.1, 0.9);
        } else {
          h_ = 0.25 * h;
        }
        if (h_ < ss.dt_min)
          Fail(SimulatorFormat("step size fell below dt_min = %g s at t = %g s; ", ss.dt_min, state_.t));
        continue;
      }
      // fixed-step runs cut a step into pieces to get through a hard spot;
      // the pieces end on the step's own time, so that outputs are kept
      CutStep(state_.t + h, h, eps, check_runaway);
    }
    if (next_release < releases.size() && state_.t >= releases[next_release] - eps) ReleaseJoints(eps);
    if (limited) CheckJointLimits(model_, ws_, state_.t);
    if (hits_output && state_.t >= t_out - eps) ++out_index;
    if (observer && (output_interval <= 0 || hits_output || state_.t >= t_end - eps)) {
      RefreshWorkspace();
      observer(state_, ws_);
    }
  }
  if (!ss.adaptive && accuracy_.max_error > kFarAboveTolerance && accuracy_.warning.empty()) {
    accuracy_.warning = SimulatorFormat(
        "fixed step dt = %g s is too large for the tolerance: the local error estimate reached %.3g times it "
        "(rtol = %g, atol = %g) at t = %g s; a step of about %.2g s would be needed (solver.dt), or let the "
        "error control choose it (solver.adaptive: true)",
        ss.dt, accuracy_.max_error, ss.rtol, ss.atol, accuracy_.t, accuracy_.dt_needed);
    LogWarning(accuracy_.warning);
  }
}

void Simulator::NoteAccuracy(double h) {
  const double err = integrator_.error_estimate();
  if (!(err <= 1.0)) {
    const double needed = std::isfinite(err) ? 0.5 * h * std::pow(err, -1.0 / 3.0) : 0.0;
    if (accuracy_.dt_needed == 0.0 || needed < accuracy_.dt_needed) accuracy_.dt_needed = needed;
  }
  if (err > accuracy_.max_error || !std::isfinite(err)) {
    accuracy_.max_error = err;
    accuracy_.t = state_.t + h;
  }
}

void Simulator::ReleaseJoints(double eps) {
  bool any = false;
  for (size_t k = 0; k < model_.joints.size(); ++k) {
    const Joint& j = *model_.joints[k];
    if (ws_.joint_released[k] || !(j.release_time <= state_.t + eps)) continue;
    ws_.joint_released[k] = 1;
    any = true;
  }
  if (!any) return;
  SparseLu lu;
  InitialAccelerations(model_, state_, ws_, lu);
  integrator_.Start(state_);
}

void Simulator::CutStep(double t_target, double h, double eps, const std::function<void()>& check_runaway) {
  const double dt_min = model_.solver.dt_min;
  double piece = 0.5 * h;
  while (state_.t < t_target - eps) {
    if (piece < dt_min) {
      h_ = piece;
      Fail(SimulatorFormat("step size fell below dt_min = %g s at t = %g s (fixed step %g s cut into pieces); ",
                           dt_min, state_.t, h));
    }
    double step = piece;
    if (state_.t + step >= t_target - eps) step = t_target - state_.t;
    if (integrator_.TryStep(state_, step) == StepStatus::kConverged) {
      NoteAccuracy(step);
      integrator_.Accept(state_);
      piece = std::min(2.0 * piece, h);
    } else {
      ++integrator_.stats.rejected;
      check_runaway();
      piece *= 0.5;
    }
  }
}

bool IsRunaway(long rejected, long accepted) {
  return rejected >= kRunawayMinRejected &&
         static_cast<double>(rejected) > kRunawayRatio * static_cast<double>(accepted);
}

void Simulator::Fail(const std::string& what) {
  failure_shares_ = integrator_.FailureShares(3);
  if (!integrator_.last_failed()) {
    // the error control cut the step: name the bodies with the largest error
    failure_shares_ = integrator_.ErrorShares(3);
    std::string text = what + SimulatorFormat("the local error estimate stays above the tolerance (rtol = %g, "
                                              "atol = %g)",
                                              model_.solver.rtol, model_.solver.atol);
    if (!failure_shares_.empty()) {
      std::string named = DescribeResidualShares(failure_shares_);
      named.replace(0, named.find(':'), "largest share of the local error estimate");
      text += "; " + named;
    }
    throw NumericalError(text, {"", 0, failure_shares_.empty() ? "" : failure_shares_.front().Entity()});
  }
  std::string text = what + integrator_.failure_hint();
  if (!failure_shares_.empty()) text += "; " + DescribeResidualShares(failure_shares_);
  throw NumericalError(text, {"", 0, failure_shares_.empty() ? "" : failure_shares_.front().Entity()});
}

}  // namespace flexmb
