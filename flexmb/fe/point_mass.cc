#include "flexmb/fe/point_mass.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::fe {

namespace {

[[noreturn]] void Fail(const PointMass& pm, const std::string& message) {
  throw InputError(message, {pm.origin.file, pm.origin.line, "point mass " + std::to_string(pm.id)});
}

}  // namespace

Mat6 PointMassMatrix(const PointMass& pm) {
  if (pm.general) {
    if (!pm.matrix.allFinite()) Fail(pm, "mass matrix is not finite");
    const double scale = pm.matrix.cwiseAbs().maxCoeff();
    if ((pm.matrix - pm.matrix.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale)
      Fail(pm, "mass matrix is not symmetric");
    if (scale > 0.0) {
      const double min_eig =
          Eigen::SelfAdjointEigenSolver<Mat6>(pm.matrix, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
      if (min_eig < -1e-12 * scale) Fail(pm, "mass matrix is not positive semi-definite");
    }
    return 0.5 * (pm.matrix + pm.matrix.transpose());
  }
  if (!std::isfinite(pm.mass) || pm.mass < 0.0) Fail(pm, "mass must be finite and >= 0");
  if (!pm.offset.allFinite()) Fail(pm, "offset is not finite");
  if (!pm.inertia.allFinite()) Fail(pm, "inertia is not finite");
  const double scale = pm.inertia.cwiseAbs().maxCoeff();
  if ((pm.inertia - pm.inertia.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    Fail(pm, "inertia matrix is not symmetric");
  }
  if (scale > 0.0) {
    const double min_eig = Eigen::SelfAdjointEigenSolver<Mat3>(pm.inertia, Eigen::EigenvaluesOnly)
                               .eigenvalues()
                               .minCoeff();
    if (min_eig < -1e-12 * scale) Fail(pm, "inertia matrix is not positive semi-definite");
  }
  const Mat3 s = Skew(pm.offset);
  Mat6 m = Mat6::Zero();
  m.topLeftCorner<3, 3>() = pm.mass * Mat3::Identity();
  m.topRightCorner<3, 3>() = -pm.mass * s;
  m.bottomLeftCorner<3, 3>() = pm.mass * s;
  m.bottomRightCorner<3, 3>() = 0.5 * (pm.inertia + pm.inertia.transpose()) - pm.mass * s * s;
  return m;
}

}  // namespace flexmb::fe
