#include "flexmb/fe/elements/shell_quad8.h"

#include "flexmb/fe/elements/shell_macro.h"

namespace flexmb::fe {
namespace {

// corners 0-3, mid-edge nodes 4-7, the centre 8 (serendipity weights at
// xi = eta = 0); quarters counter-clockwise, each starting along the
// element's first edge direction
const shell::MacroLayout& Quad8Layout() {
  static const shell::MacroLayout layout{
      8,
      {{-0.25, -0.25, -0.25, -0.25, 0.5, 0.5, 0.5, 0.5}},
      {{0, 4, 8, 7}, {4, 1, 5, 8}, {8, 5, 2, 6}, {7, 8, 6, 3}},
      4};
  return layout;
}

}  // namespace

void ShellQuad8Matrices(const ElementInput& in, MatX& K, MatX& M) { shell::MacroMatrices(in, Quad8Layout(), K, M); }

void ShellQuad8Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  shell::MacroStress(in, Quad8Layout(), S, axes);
}

void ShellQuad8GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  shell::MacroGeometricStiffness(in, Quad8Layout(), u, KG);
}

}  // namespace flexmb::fe
