#include "flexmb/fe/elements/shell_tria6.h"

#include "flexmb/fe/elements/shell_macro.h"

namespace flexmb::fe {
namespace {

// corners 0-2, mid-edge nodes 3 (0-1), 4 (1-2), 5 (2-0): three corner
// triangles and the middle one, counter-clockwise
const shell::MacroLayout& Tria6Layout() {
  static const shell::MacroLayout layout{6, {}, {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}, 3};
  return layout;
}

}  // namespace

void ShellTria6Matrices(const ElementInput& in, MatX& K, MatX& M) { shell::MacroMatrices(in, Tria6Layout(), K, M); }

void ShellTria6Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  shell::MacroStress(in, Tria6Layout(), S, axes);
}

void ShellTria6GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  shell::MacroGeometricStiffness(in, Tria6Layout(), u, KG);
}

}  // namespace flexmb::fe
