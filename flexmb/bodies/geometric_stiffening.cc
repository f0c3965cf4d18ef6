#include "flexmb/bodies/geometric_stiffening.h"

#include <string>

#include "flexmb/common/error.h"
#include "flexmb/reduction/geometric_stiffness.h"

namespace flexmb {

GeometricStiffeningForce::GeometricStiffeningForce(const std::vector<MatX>& kg, int n) : kg_(kg), n_(n) {
  if (static_cast<int>(kg.size()) != reduction::kCentrifugalCases)
    throw InputError("geometric stiffness has " + std::to_string(kg.size()) + " load cases, expected 6");
  for (const MatX& m : kg) {
    if (m.rows() != n || m.cols() != n)
      throw InputError("geometric stiffness is " + std::to_string(m.rows()) + " x " + std::to_string(m.cols()) +
                       ", expected " + std::to_string(n) + " x " + std::to_string(n));
  }
  y_.setZero(n, reduction::kCentrifugalCases);
}

void GeometricStiffeningForce::Matrix(const Vec3& om, Eigen::Ref<MatX> out) const {
  const auto p = reduction::CentrifugalProducts(om);
  out.setZero();
  for (int c = 0; c < reduction::kCentrifugalCases; ++c) out += p[c] * kg_[c];
}

void GeometricStiffeningForce::Add(const Vec3& om, const double* w, Eigen::Ref<VecX> Qw, Eigen::Ref<MatX> dQw_dom,
                                   Eigen::Ref<MatX> dQw_dw) const {
  const Eigen::Map<const VecX> wv(w, n_);
  const auto p = reduction::CentrifugalProducts(om);
  for (int c = 0; c < reduction::kCentrifugalCases; ++c) {
    y_.col(c).noalias() = kg_[c] * wv;
    Qw.noalias() -= p[c] * y_.col(c);
    dQw_dw.noalias() -= p[c] * kg_[c];
  }
  // dp/dom: rows c, columns om_x, om_y, om_z
  Eigen::Matrix<double, 6, 3> dp = Eigen::Matrix<double, 6, 3>::Zero();
  dp(0, 0) = 2.0 * om.x();
  dp(1, 1) = 2.0 * om.y();
  dp(2, 2) = 2.0 * om.z();
  dp(3, 0) = om.y(), dp(3, 1) = om.x();
  dp(4, 1) = om.z(), dp(4, 2) = om.y();
  dp(5, 2) = om.x(), dp(5, 0) = om.z();
  dQw_dom.noalias() -= y_ * dp;
}

std::unique_ptr<GeometricStiffeningForce> MakeGeometricStiffening(const std::string& body,
                                                                  const reduction::ReducedBody& reduced,
                                                                  GeometricStiffening mode) {
  return MakeStiffening<GeometricStiffeningForce>(body, reduced.geometric_stiffness, reduced.invariants.n, mode,
                                                  "geometric stiffness", "--geometric-stiffening");
}

}  // namespace flexmb
