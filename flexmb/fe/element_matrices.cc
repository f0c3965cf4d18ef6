#include "flexmb/fe/element_matrices.h"

#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"

namespace flexmb::fe {

namespace {

[[noreturn]] void Fail(const Element& e, const std::string& message) {
  throw InputError(message, {e.origin.file, e.origin.line,
                             std::string(TypeName(e.type)) + " element " + std::to_string(e.id)});
}

}  // namespace

void ElementMatrices(const ElementInput& in, MatX& K, MatX& M) {
  if (in.element == nullptr) throw InputError("ElementMatrices: no element given");
  const Element& e = *in.element;
  if (static_cast<int>(e.nodes.size()) != NodeCount(e.type)) {
    Fail(e, "has " + std::to_string(e.nodes.size()) + " nodes, expected " +
                std::to_string(NodeCount(e.type)));
  }
  if (in.x == nullptr) Fail(e, "no node coordinates given");
  const ElementTraits& t = Traits(e.type);
  const bool laminate = t.family == ElementFamily::kShell && in.shell != nullptr && in.shell->laminate;
  if (in.material == nullptr && !laminate) Fail(e, "no material");
  if (t.family == ElementFamily::kShell && in.shell == nullptr) Fail(e, "no shell section");
  if (t.family == ElementFamily::kBeam && in.beam == nullptr) Fail(e, "no beam section");
  t.matrices(in, K, M);
  const int n = NodeCount(e.type) * DofsPerNode(e.type);
  if (K.rows() != n || K.cols() != n || M.rows() != n || M.cols() != n) {
    Fail(e, "element routine returned matrices of the wrong size");
  }
  if (!K.allFinite() || !M.allFinite()) Fail(e, "stiffness or mass matrix is not finite");
}

}  // namespace flexmb::fe
