#include "flexmb/solver/statics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/sparse_lu.h"

namespace flexmb {
namespace {

// outcome of the Newton iterations of one load increment
enum class StaticsNewton { kConverged, kFailed, kSingular };

// "body 'b' (velocity coordinate k)" or the joint equation of column c of [v; active lambda]
std::string StaticsColumnName(const Model& m, const Workspace& ws, int c) {
  if (c >= 0 && c < m.nv)
    for (const auto& b : m.bodies)
      if (c >= b->v_offset && c < b->v_offset + b->nv())
        return "body '" + b->name() + "' (velocity coordinate " + std::to_string(c - b->v_offset) + ")";
  for (int e = 0; e < m.nc; ++e)
    if (c >= m.nv && ws.row_of_eq[e] == c - m.nv) return DescribeEquation(m, e);
  return "an unknown coordinate";
}

std::string StaticsNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

// the solver's state: continuation residual, iterate and bookkeeping
class StaticsSolver {
 public:
  StaticsSolver(const Model& m, State& s, Workspace& ws, const StaticsSettings& set)
      : m_(m), s_(s), ws_(ws), set_(set), nv_(m.nv), na_(ws.n_active) {
    lam_ = VecX::Zero(na_);
    for (int e = 0; e < m_.nc; ++e)
      if (ws_.row_of_eq[e] >= 0) lam_(ws_.row_of_eq[e]) = s_.lambda(e);
    r_.resize(nv_ + na_);
    r0_ = VecX::Zero(nv_ + na_);
    d_.resize(nv_ + na_);
    dx_.resize(nv_);
    q_it_.resize(m_.nq);
    lam_it_.resize(na_);
  }

  StaticsResult Solve() {
    s_.v.setZero();
    // residual of the true problem at the start: the continuation's r_0
    const double n0 = Residual(1.0, false);
    if (!std::isfinite(n0))
      throw NumericalError("static equilibrium: the forces at the start are not finite at " +
                           StaticsColumnName(m_, ws_, worst_));
    r0_ = r_;
    VecX q_conv = s_.q, lam_conv = lam_;
    double mu = 0.0, dmu = std::min(1.0, std::max(set_.initial_increment, set_.min_increment));
    while (mu < 1.0) {
      const double target = std::min(1.0, mu + dmu);
      int used = 0;
      std::string why;
      StaticsNewton out = StaticsNewton::kFailed;
      try {
        out = Newton(target, used);
      } catch (const NumericalError& e) {
        why = e.what();
      }
      if (out == StaticsNewton::kSingular)
        throw NumericalError("static equilibrium: singular tangent stiffness at " +
                             StaticsColumnName(m_, ws_, singular_) +
                             "; the mechanism has a free motion without stiffness or load path");
      if (out == StaticsNewton::kConverged) {
        mu = target;
        q_conv = s_.q;
        lam_conv = lam_;
        ++res_.increments;
        if (set_.on_increment) {
          StoreLambda();
          set_.on_increment(mu, used, res_);
        }
        if (used <= 5) dmu *= 2.0;
        continue;
      }
      // failed: back to the last equilibrium, half the increment
      ++res_.cuts;
      const std::string worst = StaticsColumnName(m_, ws_, worst_);
      const double worst_value = worst_value_;
      s_.q = q_conv;
      lam_ = lam_conv;
      dmu *= 0.5;
      const bool budget = res_.iterations >= set_.max_total_iterations;
      if (dmu < set_.min_increment || budget) {
        StoreLambda();
        throw NumericalError(
            "static equilibrium: Newton did not converge beyond load factor " + StaticsNumber(mu) + " of 1 (" +
            (budget ? "iteration budget of " + std::to_string(set_.max_total_iterations) + " spent"
                    : "load increment below " + StaticsNumber(set_.min_increment)) +
            "); largest residual " + StaticsNumber(worst_value) + " at " + worst +
            (why.empty() ? std::string() : "; " + why));
      }
    }
    StoreLambda();
    CheckJointLimits(m_, ws_, s_.t, true);
    return res_;
  }

 private:
  // continuation residual at load factor mu: [B^T lam - Q; phi] - (1 - mu) r0;
  // its largest entry (infinity if not finite), worst_ its column
  double Residual(double mu, bool tangents) {
    EvaluateMarkers(m_, s_, ws_);
    EvaluateConstraints(m_, s_, ws_);
    EvaluateForces(m_, s_, ws_, tangents);
    r_.head(nv_) = -ws_.Q;
    r_.head(nv_).noalias() += ws_.B.transpose() * lam_;
    r_.tail(na_) = ws_.phi;
    r_ -= (1.0 - mu) * r0_;
    worst_ = -1;
    worst_value_ = 0.0;
    for (int k = 0; k < nv_ + na_; ++k) {
      if (!std::isfinite(r_(k))) {
        worst_ = k;
        worst_value_ = INFINITY;
        return INFINITY;
      }
      if (std::abs(r_(k)) > worst_value_) worst_value_ = std::abs(r_(k)), worst_ = k;
    }
    return worst_value_;
  }

  // iterate at q_it_ + a d, lam_it_ + a d; returns s(a) = d . r (NaN if not finite)
  double Directional(double a, double mu) {
    dx_ = a * d_.head(nv_);
    RetractAll(m_, q_it_, dx_, s_.q);
    lam_ = lam_it_ + a * d_.tail(na_);
    double n = INFINITY;
    try {
      n = Residual(mu, false);
    } catch (const NumericalError&) {
      n = INFINITY;
    }
    return std::isfinite(n) ? d_.dot(r_) : NAN;
  }

  // step length along d: a root of s(a) if s changes sign on [0, 1]
  // (regula falsi, Illinois variant), else 1; halved while not finite
  double LineSearch(double s0, double mu) {
    double a = 1.0;
    double s1 = Directional(a, mu);
    for (int k = 0; k < 12 && !std::isfinite(s1); ++k) s1 = Directional(a *= 0.5, mu);
    if (!std::isfinite(s1) || !set_.line_search || s0 == 0.0) return a;
    if (std::abs(s1) <= 0.8 * std::abs(s0) || (s1 > 0.0) == (s0 > 0.0)) return a;
    // bracket [lo, hi] with s(lo), s(hi) of opposite signs
    double lo = 0.0, slo = s0, hi = a, shi = s1, best = a, sbest = std::abs(s1);
    for (int k = 0; k < 8; ++k) {
      const double t = std::clamp(hi - shi * (hi - lo) / (shi - slo), lo + 0.05 * (hi - lo), hi - 0.05 * (hi - lo));
      const double st = Directional(t, mu);
      if (!std::isfinite(st)) break;
      if (std::abs(st) < sbest) best = t, sbest = std::abs(st);
      if (std::abs(st) <= 0.5 * std::abs(s0)) break;
      if ((st > 0.0) == (shi > 0.0)) {
        hi = t, shi = st;
        slo *= 0.5;
      } else {
        lo = t, slo = st;
        shi *= 0.5;
      }
    }
    best = std::max(best, 0.05);
    Directional(best, mu);
    return best;
  }

  // Newton iterations at load factor mu from the current iterate
  StaticsNewton Newton(double mu, int& used) {
    SparseLu& lu = lu_;
    double last_step = INFINITY;
    bool inertia_held = false, small_before = false;
    for (int it = 0;; ++it) {
      const double norm = Residual(mu, true);
      if (!std::isfinite(norm)) return StaticsNewton::kFailed;
      fscale_ = std::max(fscale_, ws_.Q.lpNorm<Eigen::Infinity>());
      res_.residual = r_.head(nv_).lpNorm<Eigen::Infinity>();
      const double phi_norm = na_ > 0 ? r_.tail(na_).lpNorm<Eigen::Infinity>() : 0.0;
      // the residual cannot fall below the round-off of the internal forces,
      // eps |K| |q| (a stiff ANCF boom under a small load: 2e-6 N of 2e-2 N)
      const double floor = 100.0 * std::numeric_limits<double>::epsilon() * kscale_ *
                           std::max(1.0, s_.q.lpNorm<Eigen::Infinity>());
      // held throughout (hold_always): the held directions move by
      // residual / damping per iteration, slowly and for ever where a
      // residual no displacement removes (a creep), so the residual decides:
      // converged at the second iteration in a row below the tolerance (the
      // one Newton step between polishes the stiff directions)
      const bool small =
          res_.residual <= std::max(set_.residual_tol * fscale_, floor) && phi_norm <= m_.solver.assembly_tol;
      const bool settled = set_.hold_always && small && small_before;
      small_before = small;
      if ((last_step <= set_.tolerance || settled) && small) {
        if (last_step > set_.tolerance) {
          Eigen::Index k = 0;
          r_.head(nv_).cwiseAbs().maxCoeff(&k);
          res_.creep = StaticsColumnName(m_, ws_, static_cast<int>(k));
        } else {
          res_.creep.clear();
        }
        return StaticsNewton::kConverged;
      }
      // a direction held by its inertia alone that does not settle is a
      // free motion under load (a free body under gravity): say so
      if (it >= set_.max_iterations || res_.iterations >= set_.max_total_iterations)
        return inertia_held ? StaticsNewton::kSingular : StaticsNewton::kFailed;
      ++res_.iterations;
      ++used;
      StoreLambda();
      // hold_always: the pseudo-transient matrix of the fallback below from the start
      const double tau = set_.damping_hold_time, tm = 10.0 * tau;
      const bool hold = set_.hold_always && tau > 0.0;
      AssembleIterationMatrix(m_, s_, ws_,
                              MatrixCoefficients{hold ? 1.0 / (tm * tm) : 0.0, hold ? 1.0 / tau : 0.0, 1.0,
                                                 m_.solver.geometric_stiffness});
      for (int k = 0; k < nv_; ++k) kscale_ = std::max(kscale_, std::abs(ws_.S.coeff(k, k)));
      if (!FactorizeScaled()) {
        singular_ = lu.singular_column();
        // directions without stiffness: held by the damping, if any (file comment)
        const bool held = set_.damping_hold_time > 0.0 && [&] {
          AssembleIterationMatrix(m_, s_, ws_, MatrixCoefficients{0.0, 1.0 / set_.damping_hold_time, 1.0,
                                                                   m_.solver.geometric_stiffness});
          if (FactorizeScaled()) return true;
          // neither stiffness nor damping (a load on one hook turns freely
          // about the rope): held by the inertia too, as a pseudo-time step
          // of 10 tau; the residual stays the true one (file comment)
          const double tm = 10.0 * set_.damping_hold_time;
          AssembleIterationMatrix(m_, s_, ws_, MatrixCoefficients{1.0 / (tm * tm), 1.0 / set_.damping_hold_time, 1.0,
                                                                   m_.solver.geometric_stiffness});
          inertia_held = true;
          return FactorizeScaled();
        }();
        // at a converged equilibrium (first iteration of an increment): a mechanism
        if (!held) return it == 0 ? StaticsNewton::kSingular : StaticsNewton::kFailed;
      }
      // the scaled system: (R S C) (C^-1 d) = R (-r)
      ws_.rhs = -r_.cwiseProduct(row_scale_);
      lu.Solve(ws_.rhs);
      d_ = ws_.rhs.cwiseProduct(col_scale_);
      if (!d_.allFinite()) return StaticsNewton::kFailed;
      const double s0 = d_.dot(r_);
      q_it_ = s_.q;
      lam_it_ = lam_;
      const double a = LineSearch(s0, mu);
      last_step = a * d_.head(nv_).lpNorm<Eigen::Infinity>();
    }
  }

  // Factorizes R S C, ws_.S equilibrated in place: rows and columns scaled
  // to a largest entry of about 1 (Ruiz's iteration, a few sweeps). The
  // matrix [K, B^T; B, 0] mixes stiffnesses up to 1e9 and more (a boom's
  // stiff static modes) with constraint rows of order 1: its pivots then
  // span more than SparseLu's singularity bound of 1e-16 (the constraint
  // pivots are about 1 / K) although the system is well posed, and a crane
  // on outriggers, whose horizontal motion only the pads' friction holds,
  // was reported singular. Scaled, the pivots measure true dependence.
  bool FactorizeScaled() {
    SparseMat& S = ws_.S;
    const int n = static_cast<int>(S.rows());
    row_scale_.setOnes(n);
    col_scale_.setOnes(n);
    row_max_.resize(n);
    col_max_.resize(n);
    for (int sweep = 0; sweep < 4; ++sweep) {
      row_max_.setZero();
      col_max_.setZero();
      for (int j = 0; j < S.outerSize(); ++j)
        for (SparseMat::InnerIterator it(S, j); it; ++it) {
          const double a = std::abs(it.value());
          row_max_(it.row()) = std::max(row_max_(it.row()), a);
          col_max_(it.col()) = std::max(col_max_(it.col()), a);
        }
      for (int i = 0; i < n; ++i) {
        row_max_(i) = row_max_(i) > 0.0 && std::isfinite(row_max_(i)) ? 1.0 / std::sqrt(row_max_(i)) : 1.0;
        col_max_(i) = col_max_(i) > 0.0 && std::isfinite(col_max_(i)) ? 1.0 / std::sqrt(col_max_(i)) : 1.0;
      }
      for (int j = 0; j < S.outerSize(); ++j)
        for (SparseMat::InnerIterator it(S, j); it; ++it) it.valueRef() *= row_max_(it.row()) * col_max_(it.col());
      row_scale_ = row_scale_.cwiseProduct(row_max_);
      col_scale_ = col_scale_.cwiseProduct(col_max_);
    }
    return lu_.Factorize(S);
  }

  // lam_ into s.lambda (inactive equations 0)
  void StoreLambda() {
    s_.lambda.setZero();
    for (int e = 0; e < m_.nc; ++e)
      if (ws_.row_of_eq[e] >= 0) s_.lambda(e) = lam_(ws_.row_of_eq[e]);
  }

  const Model& m_;
  State& s_;
  Workspace& ws_;
  const StaticsSettings& set_;
  const int nv_, na_;
  VecX lam_, r_, r0_, d_, dx_, q_it_, lam_it_;
  VecX row_scale_, col_scale_, row_max_, col_max_;  // FactorizeScaled's R, C and sweeps
  SparseLu lu_;
  StaticsResult res_;
  double fscale_ = 1.0;
  double kscale_ = 0.0;  // largest diagonal entry of the tangent stiffness seen [N/m, N m/rad]
  int worst_ = -1;
  double worst_value_ = 0.0;
  int singular_ = -1;
};

}  // namespace

void CheckJointLimits(const Model& m, const Workspace& ws, double t, bool statics) {
  for (const auto& jp : m.joints) {
    const Joint& j = *jp;
    if (j.NumCoordinates() == 0 || (!std::isfinite(j.coordinate_min) && !std::isfinite(j.coordinate_max))) continue;
    const double c = j.Coordinate(0, ws.markers[j.marker_i], ws.markers[j.marker_j], nullptr);
    if (c >= j.coordinate_min && c <= j.coordinate_max) continue;
    const char* unit = j.CoordinateIsAngle(0) ? "rad" : "m";
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s %.6g %s outside the joint's limits [%.6g, %.6g] %s %s%g s%s",
                  j.CoordinateName(0), c, unit, j.coordinate_min, j.coordinate_max, unit,
                  statics ? "at the static equilibrium (t = " : "at t = ", t, statics ? ")" : "");
    throw NumericalError(buf, {"", 0, "joint '" + j.name() + "'"});
  }
}

StaticsSettings StaticsSettingsOf(const SolverSettings& solver) {
  StaticsSettings s;
  s.hold_always = solver.statics_hold_always;
  s.residual_tol = solver.statics_residual_tol;
  return s;
}

StaticsResult SolveStatics(const Model& m, State& s, Workspace& ws, const StaticsSettings& set) {
  StaticsSolver solver(m, s, ws, set);
  return solver.Solve();
}

}  // namespace flexmb
