#include "flexmb/fe/elements/shell_common.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace flexmb::fe::shell {

ShellData CheckShellInput(const ElementInput& in, int n_nodes) {
  const Element& e = CheckElementNodes(in, n_nodes, "shell");
  const ErrorContext ctx = ElementContext(e);
  if (in.shell == nullptr) throw InputError("missing shell section (property)", ctx);
  const ShellSection& sec = *in.shell;
  ShellData s;
  s.nsm = sec.nsm;
  s.offset = e.shell_offset;
  if (sec.laminate) {
    if (!std::isfinite(e.shell_theta)) throw InputError("non-finite material angle", ctx);
    s.laminate = InElementAxes(*sec.laminate, e.shell_theta);
    const ShellLaminate& l = *s.laminate;
    s.t = l.thickness;
    s.G = l.A(2, 2) / l.thickness;  // the in-plane shear modulus the drilling terms scale with
  } else {
    if (in.material == nullptr) throw InputError("missing material of the shell section", ctx);
    const Material& mat = *in.material;
    s.E = mat.E;
    s.nu = mat.nu;
    s.G = mat.G > 0.0 ? mat.G : mat.E / (2.0 * (1.0 + mat.nu));
    s.rho = mat.rho;
    s.t = sec.thickness;
    CheckElasticConstants(mat, ctx);
  }
  if (!(s.t > 0.0) || !std::isfinite(s.t))
    throw InputError("non-positive shell thickness " + std::to_string(s.t), ctx);
  if (!(s.rho >= 0.0) || !(s.nsm >= 0.0) || !std::isfinite(s.rho) || !std::isfinite(s.nsm))
    throw InputError("negative or non-finite density or non-structural mass", ctx);
  if (!std::isfinite(s.offset)) throw InputError("non-finite shell offset", ctx);
  if (s.laminate && s.laminate->membrane_only && s.offset != 0.0)
    throw InputError("an offset membrane (" + s.laminate->card +
                         " has no bending material) is not supported: its offset needs the nodes' rotations",
                     ctx);
  return s;
}

SectionConstants Constants(const ShellData& s) {
  SectionConstants c;
  c.membrane = MembraneMatrix(s);
  c.bending = BendingMatrix(s);
  c.shear = kShearFactor * s.G * s.t * Eigen::Matrix2d::Identity();
  c.drilling_tie = kDrillingFactor * s.G * s.t;
  c.drilling_stabilization = kDrillingStabilization * s.G * s.t;
  c.m0 = s.rho * s.t + s.nsm;
  c.m2 = s.rho * s.t * s.t * s.t / 12.0;
  if (s.laminate) {
    c.coupling = s.laminate->B;
    c.shear = s.laminate->S;
    c.m0 = s.laminate->mass + s.nsm;
    c.m2 = s.laminate->rotary;
    if (s.laminate->membrane_only) c.drilling_tie = c.drilling_stabilization = c.m2 = 0.0;
  }
  return c;
}

double LongestEdge(const Vec3* x, int n, const ErrorContext& ctx) {
  double max_edge = 0.0, min_edge = INFINITY;
  for (int i = 0; i < n; ++i) {
    const double len = (x[(i + 1) % n] - x[i]).norm();
    max_edge = std::max(max_edge, len);
    min_edge = std::min(min_edge, len);
  }
  if (!(min_edge > 1e-8 * max_edge)) throw InputError("coincident nodes", ctx);
  return max_edge;
}

LocalFrame<4> QuadFrame(const ElementInput& in, double offset) {
  const ErrorContext ctx = ElementContext(*in.element);
  const Vec3* x = in.x;
  const double max_edge = LongestEdge(x, 4, ctx);
  const Vec3 c = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  const Vec3 n_raw = (x[2] - x[0]).cross(x[3] - x[1]);
  const double area = 0.5 * n_raw.norm();
  if (!(area > 1e-10 * max_edge * max_edge)) throw InputError("zero area", ctx);
  const Vec3 e3 = n_raw.normalized();
  const Vec3 e1 = ((x[1] - x[0]) - e3 * e3.dot(x[1] - x[0])).normalized();
  const Vec3 e2 = e3.cross(e1);
  LocalFrame<4> f;
  f.R = FrameAxes(e1, e3);
  double warp = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 r = x[i] - c;
    const double h = e3.dot(r);
    warp = std::max(warp, std::abs(h));
    f.xy(i, 0) = e1.dot(r);
    f.xy(i, 1) = e2.dot(r);
    f.d.col(i) = (offset - h) * e3;
  }
  if (warp > kMaxWarpRatio * std::sqrt(area))
    throw InputError("badly warped quad: corner " + std::to_string(warp) +
                         " off the mean plane, limit " + std::to_string(kMaxWarpRatio) +
                         " * sqrt(area)",
                     ctx);
  // convex, positively ordered: every corner turns the same way
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = f.xy.row((i + 1) % 4) - f.xy.row(i);
    const Eigen::Vector2d b = f.xy.row((i + 3) % 4) - f.xy.row(i);
    if (!(a.x() * b.y() - a.y() * b.x() > 1e-6 * area))
      throw InputError("non-convex or degenerate quad at its node " + std::to_string(i + 1), ctx);
  }
  return f;
}

Eigen::Matrix3d FrameAxes(const Vec3& e1, const Vec3& e3) {
  Eigen::Matrix3d r;
  r.col(0) = e1;
  r.col(1) = e3.cross(e1);
  r.col(2) = e3;
  return r;
}

Eigen::Matrix3d MembraneMatrix(const ShellData& s) {
  if (s.laminate) return s.laminate->A;
  Eigen::Matrix3d c;
  c << 1.0, s.nu, 0.0, s.nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - s.nu);
  return c * (s.E * s.t / (1.0 - s.nu * s.nu));
}

Eigen::Matrix3d BendingMatrix(const ShellData& s) {
  if (s.laminate) return s.laminate->D;
  return MembraneMatrix(s) * (s.t * s.t / 12.0);
}

Eigen::Matrix3d PlaneStressMatrix(const ShellData& s) {
  Eigen::Matrix3d c;
  c << 1.0, s.nu, 0.0, s.nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - s.nu);
  return c * (s.E / (1.0 - s.nu * s.nu));
}

template <int N>
Eigen::Matrix<double, 6 * N, 6 * N> LocalTransform(const LocalFrame<N>& frame) {
  // node block by node block
  Eigen::Matrix<double, 6 * N, 6 * N> t = Eigen::Matrix<double, 6 * N, 6 * N>::Zero();
  const Eigen::Matrix3d rt = frame.R.transpose();
  for (int i = 0; i < N; ++i) {
    t.template block<3, 3>(6 * i, 6 * i) = rt;
    t.template block<3, 3>(6 * i, 6 * i + 3) = -rt * Skew(frame.d.col(i));
    t.template block<3, 3>(6 * i + 3, 6 * i + 3) = rt;
  }
  return t;
}

template <int N>
void ToBasic(const LocalFrame<N>& frame, const Eigen::Matrix<double, 6 * N, 6 * N>& local,
             MatX& out) {
  const Eigen::Matrix<double, 6 * N, 6 * N> t = LocalTransform<N>(frame);
  out = t.transpose() * local * t;
  out = 0.5 * (out + out.transpose()).eval();
}

template <int N>
Eigen::Matrix<double, 6, 6 * N> SurfaceStress(const LocalFrame<N>& frame, const ShellData& s,
                                              const Eigen::Matrix<double, 2, N>& dx) {
  // bottom and top: the stiffness of the outer material and its z
  Eigen::Matrix3d c[2], cb[2];
  double z[2];
  if (s.laminate) {
    c[0] = s.laminate->q_bottom;
    c[1] = s.laminate->q_top;
    cb[0] = s.laminate->qb_bottom;
    cb[1] = s.laminate->qb_top;
    z[0] = s.laminate->z_bottom;
    z[1] = s.laminate->z_top;
  } else {
    c[0] = c[1] = cb[0] = cb[1] = PlaneStressMatrix(s);
    z[0] = -0.5 * s.t;
    z[1] = 0.5 * s.t;
  }
  const Eigen::Matrix<double, 3, 2 * N> em = MembraneStrain<N>(dx);
  const Eigen::Matrix<double, 3, 3 * N> eb = BendingStrain<N>(dx);
  // local: rows bottom then top, columns node by node u v w rx ry rz
  Eigen::Matrix<double, 6, 6 * N> local = Eigen::Matrix<double, 6, 6 * N>::Zero();
  for (int side = 0; side < 2; ++side) {
    const Eigen::Matrix<double, 3, 2 * N> sm = c[side] * em;
    const Eigen::Matrix<double, 3, 3 * N> sb = cb[side] * eb * z[side];
    for (int i = 0; i < N; ++i) {
      for (int a = 0; a < 2; ++a) local.template block<3, 1>(3 * side, 6 * i + kMembraneDofs[a]) = sm.col(2 * i + a);
      for (int a = 0; a < 3; ++a) local.template block<3, 1>(3 * side, 6 * i + kPlateDofs[a]) = sb.col(3 * i + a);
    }
  }
  return local * LocalTransform<N>(frame);
}

template Eigen::Matrix<double, 18, 18> LocalTransform<3>(const LocalFrame<3>&);
template Eigen::Matrix<double, 24, 24> LocalTransform<4>(const LocalFrame<4>&);
template void ToBasic<3>(const LocalFrame<3>&, const Eigen::Matrix<double, 18, 18>&, MatX&);
template void ToBasic<4>(const LocalFrame<4>&, const Eigen::Matrix<double, 24, 24>&, MatX&);
template Eigen::Matrix<double, 6, 18> SurfaceStress<3>(const LocalFrame<3>&, const ShellData&,
                                                       const Eigen::Matrix<double, 2, 3>&);
template Eigen::Matrix<double, 6, 24> SurfaceStress<4>(const LocalFrame<4>&, const ShellData&,
                                                       const Eigen::Matrix<double, 2, 4>&);

}  // namespace flexmb::fe::shell
