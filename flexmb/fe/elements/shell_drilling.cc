#include "flexmb/fe/elements/shell_drilling.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace flexmb::fe::shell {
namespace {

// largest eigenvalue of (k, m) on the C local components `comps` of every node
template <int N, int C>
double ShellDrillingBlockMax(const Eigen::Matrix<double, 6 * N, 6 * N>& k,
                             const Eigen::Matrix<double, 6 * N, 6 * N>& m, const int (&comps)[C]) {
  using Block = Eigen::Matrix<double, C * N, C * N>;
  Block kb, mb;
  for (int i = 0; i < N; ++i)
    for (int a = 0; a < C; ++a)
      for (int j = 0; j < N; ++j)
        for (int b = 0; b < C; ++b) {
          kb(C * i + a, C * j + b) = k(6 * i + comps[a], 6 * j + comps[b]);
          mb(C * i + a, C * j + b) = m(6 * i + comps[a], 6 * j + comps[b]);
        }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Block> es(kb, mb, Eigen::EigenvaluesOnly);
  if (es.info() != Eigen::Success) return 0.0;
  return es.eigenvalues().maxCoeff();
}

}  // namespace

template <int N>
double MaxPhysicalEigenvalue(const Eigen::Matrix<double, 6 * N, 6 * N>& k,
                             const Eigen::Matrix<double, 6 * N, 6 * N>& m) {
  return std::max(ShellDrillingBlockMax<N, 2>(k, m, kMembraneDofs),
                  ShellDrillingBlockMax<N, 3>(k, m, kPlateDofs));
}

template double MaxPhysicalEigenvalue<3>(const Eigen::Matrix<double, 18, 18>&,
                                         const Eigen::Matrix<double, 18, 18>&);
template double MaxPhysicalEigenvalue<4>(const Eigen::Matrix<double, 24, 24>&,
                                         const Eigen::Matrix<double, 24, 24>&);

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
