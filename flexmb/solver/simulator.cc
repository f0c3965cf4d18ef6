#include "flexmb/solver/simulator.h"

#include <cmath>

#include "flexmb/common/error.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/sparse_lu.h"

namespace flexmb {

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

StaticsResult Simulator::SettleStatics(const StaticsSettings& settings) {
  if (!initialized_) Initialize();
  const StaticsResult r = SolveStatics(model_, state_, ws_, settings);
  SparseLu lu;
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
  long out_index = 0;
  auto next_output = [&]() {
    return output_interval > 0 ? t0 + (out_index + 1) * output_interval : t_end;
  };
  if (observer) {
    RefreshWorkspace();
    observer(state_, ws_);
  }
  while (state_.t < t_end - eps) {
    double h = ss.adaptive ? h_ : ss.dt;
    const double t_out = std::min(next_output(), t_end);
    bool hits_output = false;
    if (state_.t + h >= t_out - eps) {
      h = t_out - state_.t;
      hits_output = true;
    }
    const StepStatus st = integrator_.TryStep(state_, h);
    if (st == StepStatus::kConverged && (!ss.adaptive || integrator_.error_estimate() <= 1.0)) {
      integrator_.Accept(state_);
      if (ss.adaptive) {
        const double err = std::max(integrator_.error_estimate(), 1e-10);
        const double grow = std::clamp(0.9 * std::pow(err, -1.0 / 3.0), 0.2, 2.0);
        if (!hits_output || h >= h_) h_ = std::min(h_max, h * grow);
      }
      if (hits_output && state_.t >= t_out - eps) ++out_index;
      if (observer && (output_interval <= 0 || hits_output || state_.t >= t_end - eps)) {
        RefreshWorkspace();
        observer(state_, ws_);
      }
      continue;
    }
    // rejected: cut the step
    ++integrator_.stats.rejected;
    if (st == StepStatus::kConverged) {
      const double err = integrator_.error_estimate();
      h_ = h * std::clamp(0.9 * std::pow(err, -1.0 / 3.0), 0.1, 0.9);
    } else {
      h_ = 0.25 * h;
      if (!ss.adaptive) {
        // fixed-step runs may still cut a step to get through a hard spot
        double hh = 0.5 * h;
        bool ok = false;
        while (hh >= ss.dt_min) {
          if (integrator_.TryStep(state_, hh) == StepStatus::kConverged) {
            integrator_.Accept(state_);
            ok = true;
            break;
          }
          hh *= 0.5;
        }
        if (ok) continue;
        h_ = hh;
      }
    }
    if (h_ < ss.dt_min)
      throw NumericalError("step size fell below dt_min = " + std::to_string(ss.dt_min) +
                           " s at t = " + std::to_string(state_.t) +
                           " s; " + integrator_.failure_hint());
  }
}

}  // namespace flexmb
