#include "flexmb/fe/elements/solid_common.h"

#include <cmath>

namespace flexmb::fe::solid {

ErrorContext Context(const Element& element) {
  return ErrorContext{element.origin.file, element.origin.line,
                      std::string(TypeName(element.type)) + " " + std::to_string(element.id)};
}

SolidData CheckSolidInput(const ElementInput& in, int n_nodes, int n_corners) {
  if (in.element == nullptr) throw InputError("solid element input without an element");
  const Element& e = *in.element;
  const ErrorContext ctx = Context(e);
  if (static_cast<int>(e.nodes.size()) != n_nodes || in.x == nullptr)
    throw InputError("expected " + std::to_string(n_nodes) + " nodes, got " +
                         std::to_string(e.nodes.size()), ctx);
  if (in.material == nullptr) throw InputError("missing material of the solid section", ctx);
  const Material& mat = *in.material;
  SolidData s;
  s.E = mat.E;
  s.nu = mat.nu;
  s.rho = mat.rho;
  if (!(s.E > 0.0) || !std::isfinite(s.E))
    throw InputError("material Young's modulus must be positive, got " + std::to_string(s.E), ctx);
  if (!(s.nu > -1.0 && s.nu < 0.5))
    throw InputError("material Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(s.nu),
                     ctx);
  if (!(s.rho >= 0.0) || !std::isfinite(s.rho))
    throw InputError("negative or non-finite density", ctx);
  for (int i = 0; i < n_nodes; ++i)
    if (!in.x[i].allFinite()) throw InputError("non-finite node coordinates", ctx);
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
