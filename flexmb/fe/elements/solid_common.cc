#include "flexmb/fe/elements/solid_common.h"

#include <algorithm>
#include <cmath>

namespace flexmb::fe::solid {

SolidData CheckSolidInput(const ElementInput& in, int n_nodes, int n_corners) {
  const Element& e = CheckElementNodes(in, n_nodes, "solid");
  const ErrorContext ctx = ElementContext(e);
  if (in.material == nullptr) throw InputError("missing material of the solid section", ctx);
  const Material& mat = *in.material;
  CheckElasticConstants(mat, ctx);
  SolidData s;
  s.E = mat.E;
  s.nu = mat.nu;
  s.rho = mat.rho;
  if (!(s.rho >= 0.0) || !std::isfinite(s.rho))
    throw InputError("negative or non-finite density", ctx);
  for (int i = 1; i < n_corners; ++i) s.h = std::max(s.h, (in.x[i] - in.x[0]).norm());
  if (!(s.h > 0.0)) throw InputError("coincident corner nodes", ctx);
  return s;
}

Eigen::Matrix<double, 6, 6> ElasticityMatrix(const SolidData& s) {
  const double lambda = s.E * s.nu / ((1.0 + s.nu) * (1.0 - 2.0 * s.nu));
  const double mu = s.E / (2.0 * (1.0 + s.nu));
  Eigen::Matrix<double, 6, 6> d = Eigen::Matrix<double, 6, 6>::Zero();
  d.block<3, 3>(0, 0).setConstant(lambda);
  for (int i = 0; i < 3; ++i) {
    d(i, i) += 2.0 * mu;
    d(3 + i, 3 + i) = mu;
  }
  return d;
}

}  // namespace flexmb::fe::solid
