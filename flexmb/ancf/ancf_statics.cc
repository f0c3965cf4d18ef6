#include "flexmb/ancf/ancf_statics.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"

namespace flexmb::ancf {

AncfStaticsResult SolveAncfStatics(const AncfBeam2dBody& body, const std::vector<int>& held,
                                   const VecX& load, const Vec3& g_W, VecX& q,
                                   const AncfStaticsSettings& settings) {
  return SolveBodyStatics(body, body.element().length() * body.elements(), held, load, g_W, q, settings);
}

AncfStaticsResult SolveAncfStatics(const AncfCable3dBody& body, const std::vector<int>& held,
                                   const VecX& load, const Vec3& g_W, VecX& q,
                                   const AncfStaticsSettings& settings) {
  return SolveBodyStatics(body, body.element().length() * body.elements(), held, load, g_W, q, settings);
}

AncfStaticsResult SolveBodyStatics(const Body& body, double L, const std::vector<int>& held,
                                   const VecX& load, const Vec3& g_W, VecX& q,
                                   const AncfStaticsSettings& settings) {
  const int n = body.nv();
  const ErrorContext ctx{"", 0, "body '" + body.name() + "'"};
  if (q.size() != n || load.size() != n)
    throw InputError("static solve: coordinate or load vector of the wrong size", ctx);
  std::vector<char> is_held(n, 0);
  for (int j : held) {
    if (j < 0 || j >= n) throw InputError("static solve: held coordinate out of range", ctx);
    is_held[j] = 1;
  }
  std::vector<int> free;
  for (int j = 0; j < n; ++j)
    if (!is_held[j]) free.push_back(j);
  const int nf = static_cast<int>(free.size());
  const VecX v = VecX::Zero(n);
  VecX Q(n), Rf(nf), dq(nf), trial(n);
  MatX K(n, n), C(n, n), Kf(nf, nf);
  // free residual at load factor l (and, if wanted, the free tangent); returns its norm
  auto residual = [&](double l, const VecX& qq, bool tangent) {
    Q = l * load;
    K.setZero();
    C.setZero();
    body.AddForces(qq.data(), v.data(), l * g_W, Q, K, C);
    for (int a = 0; a < nf; ++a) {
      Rf(a) = Q(free[a]);
      if (tangent)
        for (int b = 0; b < nf; ++b) Kf(a, b) = -K(free[a], free[b]);
    }
    return Rf.norm();
  };
  AncfStaticsResult res;
  const int steps = std::max(1, settings.load_steps);
  for (int step = 1; step <= steps; ++step) {
    const double l0 = settings.initial_load_factor;
    const double lambda = l0 + (1.0 - l0) * static_cast<double>(step) / steps;
    bool converged = false;
    for (int it = 0; it < settings.max_iterations; ++it) {
      residual(lambda, q, true);
      res.residual = Rf.cwiseAbs().maxCoeff();
      Eigen::PartialPivLU<MatX> lu(Kf);
      dq = lu.solve(Rf);
      if (!dq.allFinite()) throw NumericalError("static solve: singular tangent (is the beam supported?)", ctx);
      ++res.iterations;
      if (dq.cwiseAbs().maxCoeff() <= settings.tolerance * L) {
        for (int a = 0; a < nf; ++a) q(free[a]) += dq(a);
        converged = true;
        break;
      }
      // backtracking on the residual norm, away from the solution (close to
      // it the residual is at round-off level and Newton steps are taken whole)
      const double r0 = Rf.norm();
      const bool close = dq.cwiseAbs().maxCoeff() <= 1e-6 * L;
      double alpha = 1.0;
      const int tries = close || !settings.line_search ? 1 : 12;
      for (int ls = 0; ls < tries; ++ls) {
        trial = q;
        for (int a = 0; a < nf; ++a) trial(free[a]) += alpha * dq(a);
        if (tries == 1 || residual(lambda, trial, false) < r0) break;
        alpha *= 0.5;
      }
      q = trial;
    }
    if (!converged)
      throw NumericalError("static solve: Newton did not converge at load factor " +
                               std::to_string(lambda) + " (take more load steps)",
                           ctx);
  }
  return res;
}

}  // namespace flexmb::ancf
