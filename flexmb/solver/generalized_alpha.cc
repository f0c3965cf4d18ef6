#include "flexmb/solver/generalized_alpha.h"

#include <algorithm>
#include <cmath>

#include "flexmb/solver/assembler.h"

namespace flexmb {

GeneralizedAlpha::GeneralizedAlpha(const Model& model, Workspace& ws, double rho)
    : model_(model), ws_(ws) {
  rho = std::clamp(rho, 0.0, 1.0);
  am_ = (2.0 * rho - 1.0) / (rho + 1.0);
  af_ = rho / (rho + 1.0);
  gamma_ = 0.5 + af_ - am_;
  beta_ = 0.25 * (gamma_ + 0.5) * (gamma_ + 0.5);
  const int nv = model.nv;
  for (VecX* x : {&a_, &vdot_, &a1_, &vdot1_, &v1_, &dq_, &res_, &dx_}) x->setZero(nv);
  q1_.setZero(model.nq);
}

void GeneralizedAlpha::Start(const State& s) {
  vdot_ = ws_.vdot;
  a_ = vdot_;
  trial_ = s;
  lam1_.setZero(ws_.n_active);
  rhs_probe_.setZero(ws_.rhs.size());
  have_matrix_ = false;
}

StepStatus GeneralizedAlpha::TryStep(const State& s, double h) {
  if (!model_.solver.jacobian_reuse) return Attempt(s, h, false);
  const StepStatus st = Attempt(s, h, true);
  if (st == StepStatus::kConverged || !used_kept_) return st;
  // the kept matrix may be to blame: repeat with full Newton
  have_matrix_ = false;
  return Attempt(s, h, false);
}

StepStatus GeneralizedAlpha::Attempt(const State& s, double h, bool reuse) {
  const Model& m = model_;
  Workspace& ws = ws_;
  const int nv = m.nv, na = ws.n_active;
  const double bp = (1.0 - am_) / (h * h * beta_ * (1.0 - af_));  // d vdot / d dx
  const double gp = gamma_ / (h * beta_);                        // d v / d dx
  const double ap = (1.0 - af_) / (1.0 - am_);                    // d a / d vdot
  last_bp_ = bp;
  last_h_ = h;
  last_failed_ = true;

  // predictor, and the position and velocity that the integration formulas
  // give with it: full Newton starts from the last step's acceleration,
  // vdot_{n+1} = vdot_n (11 to 26 % fewer iterations on the examples, the
  // same solutions within the Newton tolerance); a kept matrix from
  // vdot_{n+1} = 0, with which its error estimate was validated
  // (docs/design.md "Newton predictor")
  if (reuse) {
    vdot1_.setZero();
  } else {
    vdot1_ = vdot_;
  }
  a1_ = ((1.0 - af_) * vdot1_ + af_ * vdot_ - am_ * a_) / (1.0 - am_);
  v1_ = s.v + h * (1.0 - gamma_) * a_ + h * gamma_ * a1_;
  dq_ = h * (s.v + h * (0.5 - beta_) * a_ + h * beta_ * a1_);
  RetractAll(m, s.q, dq_, q1_);
  trial_.t = s.t + h;
  trial_.q = q1_;
  trial_.v = v1_;
  for (int e = 0; e < m.nc; ++e) {
    const int r = ws.row_of_eq[e];
    if (r >= 0) lam1_(r) = s.lambda(e);
  }

  const MatrixCoefficients coef{1.0, gp / bp, 1.0 / bp, m.solver.geometric_stiffness};
  double prev_norm = INFINITY;
  const double max_rate = m.solver.jacobian_reuse_rate;
  int probe_accepted_at = -1, probe_failed_at = -1;  // iterations of this attempt's chord checks
  bool kept_chord = false;  // a chord step above the tolerance was taken with the current factorization
  bool refresh = !reuse || !have_matrix_ || matrix_h_ != h;
  used_kept_ = false;
  for (int it = 0; it < m.solver.max_newton; ++it) {
    ++stats.newton_iterations;
    // fresh: iteration matrix at this iterate; else the kept factorization
    bool fresh = refresh;
    refresh = !reuse;
    // full Newton from the second iteration on: the previous iterate's
    // factorization first gives a chord correction; if that is already within
    // the tolerance it is the last correction of the step, else the matrix is
    // refreshed at this iterate (docs/design.md "Convergence check by a chord step")
    const bool probe = !reuse && it > 0 && it >= probe_from_;
    if (probe) fresh = false;
    trial_.lambda.setZero();
    for (int e = 0; e < m.nc; ++e)
      if (ws.row_of_eq[e] >= 0) trial_.lambda(e) = lam1_(ws.row_of_eq[e]);
    EvaluateMarkers(m, trial_, ws);
    EvaluateConstraints(m, trial_, ws);
    EvaluateForces(m, trial_, ws, fresh);
    if (fresh) AddMassTangents(m, trial_, vdot1_, ws);
    // residual r = M vdot - Q + B^T lambda, scaled by 1/beta'
    MassTimes(m, ws, vdot1_, res_);
    res_ -= ws.Q;
    res_.noalias() += ws.B.transpose() * lam1_;
    ws.rhs.head(nv) = -res_ / bp;
    ws.rhs.tail(na) = -ws.phi;
    if (!ws.rhs.allFinite()) {
      hint_ = "non-finite residual";
      return StepStatus::kNewtonFailed;
    }
    if (fresh) {
      if (!FactorizeIterationMatrix(coef, h)) return StepStatus::kNewtonFailed;
    } else if (reuse) {
      used_kept_ = true;
    }
    bool chord_ok = false;  // this iteration's chord correction ends the step
    if (probe) rhs_probe_ = ws.rhs;
    lu_.Solve(ws.rhs);
    if (probe) {
      const double scale0 = std::max(1.0, dq_.lpNorm<Eigen::Infinity>());
      const double chord = ws.rhs.head(nv).lpNorm<Eigen::Infinity>() / scale0;
      ++stats.chord_checks;
      // within the tolerance and contracting (a matrix that no longer fits
      // the iterate, e.g. after a contact opened, shows in the rate); after
      // a kept chord step the matrix is older than the previous iterate, and
      // the error left, rate / (1 - rate) |chord|, must be as small as a
      // kept matrix's (kChordKeepRate = kKeptMatrixErrorFraction)
      const double max_rate = kept_chord ? kChordKeepRate : kChordMaxRate;
      chord_ok = chord <= kChordAcceptFraction * m.solver.newton_tol && chord <= max_rate * prev_norm;
      // above the tolerance but contracting fast: take it, check again next
      const bool keep = !chord_ok && chord <= kChordKeepRate * prev_norm && it + 1 < m.solver.max_newton;
      if (chord_ok || keep) {
        if (probe_accepted_at < 0) probe_accepted_at = it;
        if (keep) {
          ++stats.chord_steps;
          kept_chord = true;
        }
      } else {
        kept_chord = false;
        probe_failed_at = it;
        // not converged yet: the Newton matrix at this iterate
        EvaluateForces(m, trial_, ws, true);
        AddMassTangents(m, trial_, vdot1_, ws);
        if (!FactorizeIterationMatrix(coef, h)) return StepStatus::kNewtonFailed;
        fresh = true;
        ws.rhs = rhs_probe_;
        lu_.Solve(ws.rhs);
      }
    }
    dx_ = ws.rhs.head(nv);
    // update
    // q_{n+1} = q_n (+) dq with the accumulated increment (composing the
    // corrections one by one is not the same on SO(3) and is unstable)
    dq_ += dx_;
    RetractAll(m, s.q, dq_, trial_.q);
    trial_.v += gp * dx_;
    vdot1_ += bp * dx_;
    a1_ += ap * bp * dx_;
    lam1_ += bp * ws.rhs.tail(na);
    const double scale = std::max(1.0, dq_.lpNorm<Eigen::Infinity>());
    const double norm = dx_.lpNorm<Eigen::Infinity>() / scale;
    if (!std::isfinite(norm) || (it > 2 && norm > prev_norm)) {
      hint_ = "Newton diverged";
      return StepStatus::kNewtonFailed;
    }
    // a kept matrix must contract fast, else it is refreshed; its correction
    // must be far below the tolerance (full Newton's remaining error is
    // quadratic in |dx|, a kept matrix's only linear), with a contraction
    // rate measured in this step. The estimate rate / (1 - rate) |dx| alone
    // is not enough: components that the kept matrix reduces slowly hardly
    // show in |dx| (docs/design.md "Newton predictor")
    bool accept = norm <= m.solver.newton_tol || chord_ok;
    if (reuse && !fresh) {
      if (it > 0) {
        rate_ = norm / prev_norm;
        if (rate_ > max_rate) refresh = true;
      }
      accept = accept && it > 0 && rate_ <= max_rate && norm <= kKeptMatrixErrorFraction * m.solver.newton_tol;
    } else {
      rate_ = 1.0;  // not measured yet for this matrix
    }
    prev_norm = norm;
    if (accept) {
      // converged: error estimate and hand over
      double sum = 0.0;
      const double c = (beta_ - 1.0 / 6.0) * h * h;
      for (int i = 0; i < nv; ++i) {
        const double e = c * (a1_(i) - a_(i));
        const double sc = m.solver.atol + m.solver.rtol * std::abs(dq_(i));
        sum += (e / sc) * (e / sc);
      }
      error_ = nv > 0 ? std::sqrt(sum / nv) : 0.0;
      trial_.lambda.setZero();
      for (int e = 0; e < m.nc; ++e)
        if (ws.row_of_eq[e] >= 0) trial_.lambda(e) = lam1_(ws.row_of_eq[e]);
      // constraint violation at the converged state
      EvaluateMarkers(m, trial_, ws);
      EvaluateConstraints(m, trial_, ws);
      const double viol = na > 0 ? ws.phi.lpNorm<Eigen::Infinity>() : 0.0;
      stats.max_constraint_violation = std::max(stats.max_constraint_violation, viol);
      last_failed_ = false;
      if (!reuse) {
        // where the next step tries its first chord check: where this one's
        // was accepted, or after the last that failed (a check that fails
        // costs a force evaluation and a solve); now and then from the start
        if (probe_accepted_at > 0) probe_from_ = probe_accepted_at;
        else if (probe_failed_at > 0) probe_from_ = probe_failed_at + 1;
        if (++probe_steps_ % kChordRelearnSteps == 0) probe_from_ = 1;
      }
      return StepStatus::kConverged;
    }
  }
  // name the worst constraint or coordinate
  int worst = -1;
  double wv = 0.0;
  for (int e = 0; e < m.nc; ++e) {
    const int r = ws.row_of_eq[e];
    if (r >= 0 && std::abs(ws.phi(r)) > wv) wv = std::abs(ws.phi(r)), worst = e;
  }
  hint_ = worst >= 0 ? "largest constraint residual in " + DescribeEquation(m, worst) : "Newton did not converge";
  return StepStatus::kNewtonFailed;
}

bool GeneralizedAlpha::FactorizeIterationMatrix(const MatrixCoefficients& coef, double h) {
  AssembleIterationMatrix(model_, trial_, ws_, coef);
  ++stats.factorizations;
  have_matrix_ = false;
  if (!lu_.Factorize(ws_.S)) {
    const int c = lu_.singular_column();
    hint_ = c >= 0 && c < model_.nv ? "singular iteration matrix at velocity coordinate " + std::to_string(c)
                                    : "singular iteration matrix";
    return false;
  }
  have_matrix_ = true;
  matrix_h_ = h;
  return true;
}

std::vector<ResidualShare> GeneralizedAlpha::FailureShares(int count) const {
  if (!last_failed_) return {};
  // the multipliers of the last iterate, all equations
  return LargestResidualShares(model_, ws_, res_, trial_.lambda, last_bp_, count);
}

std::vector<ResidualShare> GeneralizedAlpha::ErrorShares(int count) const {
  if (last_failed_) return {};
  // the terms of error_estimate(), summed per body
  const double c = (beta_ - 1.0 / 6.0) * last_h_ * last_h_;
  std::vector<ResidualShare> shares;
  double total = 0.0;
  for (const auto& b : model_.bodies) {
    double sum = 0.0;
    for (int i = b->v_offset; i < b->v_offset + b->nv(); ++i) {
      const double e = c * (a1_(i) - a_(i)) / (model_.solver.atol + model_.solver.rtol * std::abs(dq_(i)));
      sum += e * e;
    }
    total += sum;
    shares.push_back({"body", b->name(), sum});
  }
  for (ResidualShare& s : shares) s.share = total > 0.0 ? s.share / total : 0.0;
  std::stable_sort(shares.begin(), shares.end(),
                   [](const ResidualShare& a, const ResidualShare& b) { return a.share > b.share; });
  std::vector<ResidualShare> top;
  for (const ResidualShare& s : shares)
    if (static_cast<int>(top.size()) < count && s.share >= 0.01) top.push_back(s);
  return top;
}

void GeneralizedAlpha::Accept(State& s) {
  s.t = trial_.t;
  s.q = trial_.q;
  s.v = trial_.v;
  s.lambda = trial_.lambda;
  ws_.vdot = vdot1_;
  a_ = a1_;
  vdot_ = vdot1_;
  ++stats.steps;
}

}  // namespace flexmb
