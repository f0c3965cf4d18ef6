#include "flexmb/fe/elements/shell_tria3.h"

#include <Eigen/Dense>
#include <cmath>

#include "flexmb/fe/elements/shell_common.h"
#include "flexmb/fe/elements/shell_drilling.h"

namespace flexmb::fe {
namespace {

using Mat18 = Eigen::Matrix<double, 18, 18>;

// plane frame and local coordinates (node 1 at the origin, e1 along edge 1-2)
shell::LocalFrame<3> Frame(const ElementInput& in, const shell::ShellData& s, double& area) {
  const ErrorContext ctx = ElementContext(*in.element);
  const Vec3* x = in.x;
  const double max_edge = shell::LongestEdge(x, 3, ctx);
  const Vec3 n_raw = (x[1] - x[0]).cross(x[2] - x[0]);
  area = 0.5 * n_raw.norm();
  if (!(area > 1e-10 * max_edge * max_edge)) throw InputError("zero area", ctx);
  const Vec3 e3 = n_raw.normalized();
  const Vec3 e1 = (x[1] - x[0]).normalized();
  const Vec3 e2 = e3.cross(e1);
  shell::LocalFrame<3> f;
  f.R = shell::FrameAxes(e1, e3);
  for (int i = 0; i < 3; ++i) {
    f.xy(i, 0) = e1.dot(x[i] - x[0]);
    f.xy(i, 1) = e2.dot(x[i] - x[0]);
    f.d.col(i) = s.offset * e3;
  }
  return f;
}

// rows d/dx, d/dy of the shape functions N = (1 - r - s, r, s) in the local
// frame (constant over the element)
Eigen::Matrix<double, 2, 3> Tria3ShapeDerivatives(const shell::LocalFrame<3>& f) {
  Eigen::Matrix<double, 2, 3> dn;
  dn << -1.0, 1.0, 0.0, -1.0, 0.0, 1.0;
  return (dn * f.xy).inverse() * dn;
}

}  // namespace

void ShellTria3Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const shell::ShellData s = shell::CheckShellInput(in, 3);
  double area = 0.0;
  const shell::LocalFrame<3> f = Frame(in, s, area);
  const shell::SectionConstants sc = shell::Constants(s);
  const Eigen::Matrix3d& cm = sc.membrane;
  const Eigen::Matrix3d& cb = sc.bending;
  const Eigen::Matrix2d& ks = sc.shear;
  const double kd = sc.drilling_stabilization, m0 = sc.m0, m2 = sc.m2;

  // natural coordinates r, s: N = (1 - r - s, r, s); J rows d/dr, d/ds
  Eigen::Matrix<double, 2, 3> dn;
  dn << -1.0, 1.0, 0.0, -1.0, 0.0, 1.0;
  const Eigen::Matrix2d j = dn * f.xy;
  const Eigen::Matrix2d j_inv = j.inverse();
  const Eigen::Matrix<double, 2, 3> dx = j_inv * dn;  // rows d/dx, d/dy (constant)

  // constant strain membrane over (u_i, v_i)
  const Eigen::Matrix<double, 3, 6> bm = shell::MembraneStrain<3>(dx);
  const Eigen::Matrix<double, 6, 6> km = bm.transpose() * cm * bm * area;

  // constant curvature over (w, rx, ry) per node
  const Eigen::Matrix<double, 3, 9> bb = shell::BendingStrain<3>(dx);
  Eigen::Matrix<double, 9, 9> kp = bb.transpose() * cb * bb * area;

  // mitc3: covariant shear e_r, e_s tied at (1/2, 0), (0, 1/2), (1/2, 1/2)
  auto covariant = [&](double r, double s_nat, int dir) {
    return shell::CovariantShear<3>(Eigen::Vector3d(1.0 - r - s_nat, r, s_nat), dn, j, dir);
  };
  const Eigen::Matrix<double, 1, 9> er1 = covariant(0.5, 0.0, 0);
  const Eigen::Matrix<double, 1, 9> es2 = covariant(0.0, 0.5, 1);
  const Eigen::Matrix<double, 1, 9> er3 = covariant(0.5, 0.5, 0);
  const Eigen::Matrix<double, 1, 9> es3 = covariant(0.5, 0.5, 1);
  // e_r = er1 + c s, e_s = es2 - c r; c from the tangential strain on edge 2-3
  const Eigen::Matrix<double, 1, 9> c = (es2 - er1) - (es3 - er3);
  // 3-point rule at the edge midpoints (exact for the quadratic integrands)
  const double qp[3][2] = {{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}};
  Mat18 kl = Mat18::Zero();
  Mat18 ml = Mat18::Zero();
  Eigen::Matrix<double, 9, 9> dd = Eigen::Matrix<double, 9, 9>::Zero();
  Eigen::Matrix3d nn = Eigen::Matrix3d::Zero();
  for (const auto& p : qp) {
    Eigen::Matrix<double, 2, 9> bn;
    bn.row(0) = er1 + c * p[1];
    bn.row(1) = es2 - c * p[0];
    const Eigen::Matrix<double, 2, 9> bs = j_inv * bn;
    kp += bs.transpose() * ks * bs * (area / 3.0);
    const Eigen::Vector3d n(1.0 - p[0] - p[1], p[0], p[1]);
    // drilling: theta_z - omega over (u, v, rz) per node
    const Eigen::Matrix<double, 1, 9> bd = shell::DrillingStrain<3>(dx, n);
    dd += bd.transpose() * bd * (area / 3.0);
    nn += n * n.transpose() * (area / 3.0);
  }

  // drilling tie at the centroid
  const Eigen::Matrix<double, 1, 9> bd0 =
      shell::DrillingStrain<3>(dx, Eigen::Vector3d::Constant(1.0 / 3.0));
  const Eigen::Matrix<double, 9, 9> tie = bd0.transpose() * bd0;

  shell::AddNodal<3, 3>(kp, shell::kPlateDofs, 1.0, kl);
  shell::AddNodal<3, 2>(km, shell::kMembraneDofs, 1.0, kl);
  // a laminate's membrane-bending coupling: eps0^T B kappa, both constant
  if (!sc.coupling.isZero(0.0)) {
    const Eigen::Matrix<double, 6, 9> kmb = bm.transpose() * sc.coupling * bb * area;
    shell::AddCoupling<3, 2, 3>(kmb, shell::kMembraneDofs, shell::kPlateDofs, kl);
  }
  shell::AddTranslationalAndRotaryMass<3>(nn, m0, m2, ml);
  const bool lumped = in.mass_form == MassForm::kLumped;
  const Eigen::Vector3d share = Eigen::Vector3d::Constant(area / 3.0);
  if (lumped) ml = shell::LumpedMass<3>(share, m0, m2, 0.0);

  // drilling inertia from the physical part (before any drilling term): the
  // stabilized and the tied drilling modes both above the physical range
  const double lambda = m2 > 0.0 ? shell::MaxPhysicalEigenvalue<3>(kl, ml) : 0.0;
  const double mu = lumped && m2 > 0.0 ? shell::LumpedDrillingRatio(nn, share) : 1.0;
  const double md = m2 > 0.0 ? shell::DrillingInertia(sc, kd, lambda, mu) : 0.0;
  const double mt = m2 > 0.0 ? shell::DrillingInertia(sc, sc.drilling_tie, lambda, 1.0) : 0.0;
  shell::AddNodal<3, 3>(dd, shell::kDrillingDofs, kd, kl);
  shell::AddNodal<3, 3>(tie, shell::kDrillingDofs, sc.drilling_tie * area, kl);
  if (lumped) {
    for (int i = 0; i < 3; ++i) ml(6 * i + 5, 6 * i + 5) = md * share(i);
  } else {
    shell::AddNodal<3, 3>(dd, shell::kDrillingDofs, md, ml);
    shell::AddNodal<3, 3>(tie, shell::kDrillingDofs, (mt - md) * area, ml);
  }

  shell::ToBasic<3>(f, kl, K);
  shell::ToBasic<3>(f, ml, M);
}

void ShellTria3Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  const shell::ShellData s = shell::CheckShellInput(in, 3);
  double area = 0.0;
  const shell::LocalFrame<3> f = Frame(in, s, area);
  const Eigen::Matrix<double, 2, 3> dx = Tria3ShapeDerivatives(f);
  S = shell::SurfaceStress<3>(f, s, dx);
  axes = f.R;
}

void ShellTria3GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const shell::ShellData s = shell::CheckShellInput(in, 3);
  double area = 0.0;
  const shell::LocalFrame<3> f = Frame(in, s, area);
  const Eigen::Matrix<double, 2, 3> dx = Tria3ShapeDerivatives(f);
  const Eigen::Vector3d nres = shell::MembraneResultants<3>(f, s, dx, u.head<18>());
  Mat18 kl = Mat18::Zero();
  shell::AddMembranePrestress<3>(dx, nres, area, kl);
  shell::ToBasic<3>(f, kl, KG);
}

}  // namespace flexmb::fe
