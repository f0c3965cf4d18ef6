#include "flexmb/bodies/flexible_mass_tangent.h"

#include "flexmb/reduction/inertia_invariants.h"

namespace flexmb {
namespace {

Eigen::Matrix3d MassTangentSkew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace

FlexibleMassTangent::FlexibleMassTangent(const reduction::InertiaInvariants& inv, const FlexibleInertia& inertia)
    : inv_(inv), inertia_(inertia), n_(inv.n) {
  mb_.setZero(6 + n_, 6 + n_);
  ab_.setZero(6 + n_);
  y_.setZero(6 + n_);
  col_.setZero(6 + n_);
}

void FlexibleMassTangent::Add(const Eigen::Matrix3d& R, const double* w, const double* a, double scale,
                              Eigen::Ref<Eigen::MatrixXd> K) const {
  const int n = n_, N = 6 + n_;
  const Eigen::Map<const Eigen::VectorXd> av(a, N);
  inertia_.MassMatrix(w, mb_);  // also the contraction MooDerivative reads
  ab_ = av;
  ab_.head<3>() = R.transpose() * av.head<3>();
  y_.noalias() = mb_ * ab_;
  const Eigen::Vector3d av_b = ab_.head<3>(), ao = ab_.segment<3>(3);
  const Eigen::Matrix3d s_av = MassTangentSkew(av_b);

  // rotation columns
  K.block<3, 3>(0, 3) += scale * (R * (mb_.block<3, 3>(0, 0) * s_av - MassTangentSkew(y_.head<3>())));
  K.block(3, 3, N - 3, 3).noalias() += scale * mb_.block(3, 0, N - 3, 3) * s_av;

  // modal columns: T^T (dM_B/dw_i) a_B
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix3d doo = inertia_.MooDerivative(i);
    col_.head<3>() = R * (inv_.mvo1[i] * ao);
    col_.segment<3>(3).noalias() = inv_.mow1[i] * ab_.tail(n);
    col_.segment<3>(3) += inv_.mvo1[i].transpose() * av_b + doo * ao;
    col_.tail(n).noalias() = inv_.mow1[i].transpose() * ao;
    K.col(6 + i) += scale * col_;
  }
}

}  // namespace flexmb
