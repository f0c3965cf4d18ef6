#include "flexmb/bodies/deformation_stiffening.h"

#include <string>

#include "flexmb/common/error.h"

namespace flexmb {

DeformationStiffeningForce::DeformationStiffeningForce(const std::vector<MatX>& g, int n) : g_(g), n_(n) {
  if (static_cast<int>(g.size()) != n)
    throw InputError("deformation stiffness has " + std::to_string(g.size()) + " matrices, expected " +
                         std::to_string(n) + " (one per mode)",
                     {"", 0, "deformation stiffening"});
  for (const MatX& m : g) {
    if (m.rows() != n || m.cols() != n)
      throw InputError("deformation stiffness matrix is " + std::to_string(m.rows()) + " x " +
                           std::to_string(m.cols()) + ", expected " + std::to_string(n) + " x " + std::to_string(n),
                       {"", 0, "deformation stiffening"});
  }
  y_.setZero(n, n);
  gw_.setZero(n, n);
}

void DeformationStiffeningForce::Add(const double* w_ptr, Eigen::Ref<VecX> Qw) const {
  const Eigen::Map<const VecX> w(w_ptr, n_);
  for (int m = 0; m < n_; ++m) y_.col(m).noalias() = g_[m] * w;
  // G(w) w = sum_j w_j (G_j w) = Y w
  Qw.noalias() -= y_ * w;
}

void DeformationStiffeningForce::Add(const double* w_ptr, Eigen::Ref<VecX> Qw, Eigen::Ref<MatX> dQw_dw) const {
  Add(w_ptr, Qw);  // fills y_
  const Eigen::Map<const VecX> w(w_ptr, n_);
  gw_.setZero();
  for (int j = 0; j < n_; ++j) {
    if (w(j) != 0.0) gw_.noalias() += w(j) * g_[j];
  }
  // d(G(w) w)/dw_n = G(w) e_n + G_n w
  dQw_dw -= gw_;
  dQw_dw -= y_;
}

std::unique_ptr<DeformationStiffeningForce> MakeDeformationStiffening(const std::string& body,
                                                                      const reduction::ReducedBody& reduced,
                                                                      GeometricStiffening mode) {
  return MakeStiffening<DeformationStiffeningForce>(body, reduced.deformation_stiffness, reduced.invariants.n, mode,
                                                    "deformation stiffness", "--deformation-stiffening");
}

}  // namespace flexmb
