#include "flexmb/fe/elements/element_common.h"

#include <cmath>
#include <string>

namespace flexmb::fe {

ErrorContext ElementContext(const Element& element) {
  return ErrorContext{element.origin.file, element.origin.line,
                      std::string(TypeName(element.type)) + " " + std::to_string(element.id)};
}

const Element& CheckElementNodes(const ElementInput& in, int n_nodes, const char* family) {
  if (in.element == nullptr)
    throw InputError(std::string(family) + " element input without an element");
  const Element& e = *in.element;
  if (static_cast<int>(e.nodes.size()) != n_nodes || in.x == nullptr)
    throw InputError(
        "expected " + std::to_string(n_nodes) + " nodes, got " + std::to_string(e.nodes.size()),
        ElementContext(e));
  for (int i = 0; i < n_nodes; ++i)
    if (!in.x[i].allFinite()) throw InputError("non-finite node coordinates", ElementContext(e));
  return e;
}

void CheckElasticConstants(const Material& material, const ErrorContext& ctx) {
  if (!(material.E > 0.0) || !std::isfinite(material.E))
    throw InputError("material Young's modulus must be positive, got " + std::to_string(material.E),
                     ctx);
  if (!(material.nu > -1.0 && material.nu < 0.5))
    throw InputError(
        "material Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(material.nu), ctx);
}

Eigen::Matrix3d Skew(const Vec3& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace flexmb::fe
