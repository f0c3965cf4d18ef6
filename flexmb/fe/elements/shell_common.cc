#include "flexmb/fe/elements/shell_common.h"

#include <cmath>

namespace flexmb::fe::shell {

ErrorContext Context(const Element& element) {
  return ErrorContext{element.origin.file, element.origin.line,
                      std::string(TypeName(element.type)) + " " + std::to_string(element.id)};
}

ShellData CheckShellInput(const ElementInput& in, int n_nodes) {
  if (in.element == nullptr) throw InputError("shell element input without an element");
  const Element& e = *in.element;
  const ErrorContext ctx = Context(e);
  if (static_cast<int>(e.nodes.size()) != n_nodes || in.x == nullptr)
    throw InputError("expected " + std::to_string(n_nodes) + " nodes, got " +
                         std::to_string(e.nodes.size()), ctx);
  if (in.shell == nullptr) throw InputError("missing shell section (property)", ctx);
  if (in.material == nullptr) throw InputError("missing material of the shell section", ctx);
  const ShellSection& sec = *in.shell;
  const Material& mat = *in.material;
  ShellData s;
  s.E = mat.E;
  s.nu = mat.nu;
  s.G = mat.G > 0.0 ? mat.G : mat.E / (2.0 * (1.0 + mat.nu));
  s.rho = mat.rho;
  s.t = sec.thickness;
  s.nsm = sec.nsm;
  s.offset = e.shell_offset;
  if (!(s.t > 0.0) || !std::isfinite(s.t))
    throw InputError("non-positive shell thickness " + std::to_string(s.t), ctx);
  if (!(s.E > 0.0) || !std::isfinite(s.E))
    throw InputError("material Young's modulus must be positive, got " + std::to_string(s.E), ctx);
  if (!(s.nu > -1.0 && s.nu < 0.5))
    throw InputError("material Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(s.nu),
                     ctx);
  if (!(s.rho >= 0.0) || !(s.nsm >= 0.0) || !std::isfinite(s.rho) || !std::isfinite(s.nsm))
    throw InputError("negative or non-finite density or non-structural mass", ctx);
  if (!std::isfinite(s.offset)) throw InputError("non-finite shell offset", ctx);
  for (int i = 0; i < n_nodes; ++i)
    if (!in.x[i].allFinite()) throw InputError("non-finite node coordinates", ctx);
  return s;
}

Eigen::Matrix3d MembraneMatrix(const ShellData& s) {
  Eigen::Matrix3d c;
  c << 1.0, s.nu, 0.0, s.nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - s.nu);
  return c * (s.E * s.t / (1.0 - s.nu * s.nu));
}

Eigen::Matrix3d BendingMatrix(const ShellData& s) {
  return MembraneMatrix(s) * (s.t * s.t / 12.0);
}

template <int N>
void ToBasic(const LocalFrame<N>& frame, const Eigen::Matrix<double, 6 * N, 6 * N>& local,
             MatX& out) {
  // T maps basic nodal dof to local mid-surface dof, node block by node block
  Eigen::Matrix<double, 6 * N, 6 * N> t = Eigen::Matrix<double, 6 * N, 6 * N>::Zero();
  const Eigen::Matrix3d rt = frame.R.transpose();
  for (int i = 0; i < N; ++i) {
    const Eigen::Vector3d d = frame.d.col(i);
    Eigen::Matrix3d skew_d;
    skew_d << 0.0, -d.z(), d.y(), d.z(), 0.0, -d.x(), -d.y(), d.x(), 0.0;
    t.template block<3, 3>(6 * i, 6 * i) = rt;
    t.template block<3, 3>(6 * i, 6 * i + 3) = -rt * skew_d;
    t.template block<3, 3>(6 * i + 3, 6 * i + 3) = rt;
  }
  out = t.transpose() * local * t;
  out = 0.5 * (out + out.transpose()).eval();
}

template void ToBasic<3>(const LocalFrame<3>&, const Eigen::Matrix<double, 18, 18>&, MatX&);
template void ToBasic<4>(const LocalFrame<4>&, const Eigen::Matrix<double, 24, 24>&, MatX&);

}  // namespace flexmb::fe::shell
