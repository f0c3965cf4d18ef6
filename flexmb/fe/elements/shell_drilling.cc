#include "flexmb/fe/elements/shell_drilling.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace flexmb::fe::shell {
namespace {

// largest eigenvalue of (k, m) on the local components `comps` of every node
double ShellDrillingBlockMax(const Eigen::MatrixXd& k, const Eigen::MatrixXd& m, int n_nodes,
                             const int* comps, int n_comps) {
  const int n = n_nodes * n_comps;
  Eigen::MatrixXd kb(n, n), mb(n, n);
  for (int i = 0; i < n_nodes; ++i)
    for (int a = 0; a < n_comps; ++a)
      for (int j = 0; j < n_nodes; ++j)
        for (int b = 0; b < n_comps; ++b) {
          kb(n_comps * i + a, n_comps * j + b) = k(6 * i + comps[a], 6 * j + comps[b]);
          mb(n_comps * i + a, n_comps * j + b) = m(6 * i + comps[a], 6 * j + comps[b]);
        }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(kb, mb,
                                                                     Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success) return 0.0;
  return es.eigenvalues().maxCoeff();
}

}  // namespace

double MaxPhysicalEigenvalue(const Eigen::MatrixXd& k, const Eigen::MatrixXd& m, int n_nodes) {
  return std::max(ShellDrillingBlockMax(k, m, n_nodes, kMembraneDofs, 2),
                  ShellDrillingBlockMax(k, m, n_nodes, kPlateDofs, 3));
}

double LumpedDrillingRatio(const Eigen::MatrixXd& nn, const Eigen::VectorXd& share) {
  const Eigen::MatrixXd lumped = share.asDiagonal();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(nn, lumped,
                                                                     Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success) return 1.0;
  return std::clamp(es.eigenvalues().minCoeff(), 0.0, 1.0);
}

double DrillingInertia(const SectionConstants& sc, double k, double lambda_max, double mu) {
  if (!(sc.m2 > 0.0) || !(lambda_max > 0.0) || !std::isfinite(lambda_max)) return sc.m2;
  const double target = kDrillingFrequencyRatio * kDrillingFrequencyRatio * lambda_max;
  return std::min(sc.m2, mu * k / target);
}

}  // namespace flexmb::fe::shell
