#include "flexmb/fe/elements/shell_quad4.h"

#include <Eigen/Dense>
#include <cmath>

#include "flexmb/fe/elements/shell_common.h"
#include "flexmb/fe/elements/shell_drilling.h"

namespace flexmb::fe {
namespace {

using Mat24 = Eigen::Matrix<double, 24, 24>;
using Mat2x4 = Eigen::Matrix<double, 2, 4>;

constexpr double kQuadXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kQuadEta[4] = {-1.0, -1.0, 1.0, 1.0};

// bilinear shape functions and their natural derivatives (rows d/dxi, d/deta)
void Shape(double xi, double eta, Eigen::Vector4d& n, Mat2x4& dn) {
  for (int i = 0; i < 4; ++i) {
    n(i) = 0.25 * (1.0 + xi * kQuadXi[i]) * (1.0 + eta * kQuadEta[i]);
    dn(0, i) = 0.25 * kQuadXi[i] * (1.0 + eta * kQuadEta[i]);
    dn(1, i) = 0.25 * kQuadEta[i] * (1.0 + xi * kQuadXi[i]);
  }
}

// mean-plane frame, projected coordinates and rigid offsets of the nodes
shell::LocalFrame<4> Frame(const ElementInput& in, const shell::ShellData& s) { return shell::QuadFrame(in, s.offset); }

}  // namespace

void ShellQuad4Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const shell::ShellData s = shell::CheckShellInput(in, 4);
  const shell::LocalFrame<4> f = Frame(in, s);
  const shell::SectionConstants sc = shell::Constants(s);
  const Eigen::Matrix3d& cm = sc.membrane;
  const Eigen::Matrix3d& cb = sc.bending;
  const Eigen::Matrix2d& ks = sc.shear;
  const double kd = sc.drilling_stabilization, m0 = sc.m0, m2 = sc.m2;
  const Eigen::Matrix<double, 4, 2> xy = f.xy;

  Eigen::Vector4d n;
  Mat2x4 dn;
  Shape(0.0, 0.0, n, dn);
  const Eigen::Matrix2d j0 = dn * xy;
  const Eigen::Matrix2d j0_inv = j0.inverse();
  const double det0 = j0.determinant();

  // mitc4 tying points: A (0, 1), C (0, -1) for e_xi; B (-1, 0), D (1, 0) for e_eta;
  // rows of each: covariant strain over node (w, rx, ry)
  Eigen::Matrix<double, 4, 12> tie;
  const double tp[4][2] = {{0.0, 1.0}, {0.0, -1.0}, {-1.0, 0.0}, {1.0, 0.0}};
  for (int k = 0; k < 4; ++k) {
    Shape(tp[k][0], tp[k][1], n, dn);
    tie.row(k) = shell::CovariantShear<4>(n, dn, dn * xy, k < 2 ? 0 : 1);
  }

  Eigen::Matrix<double, 8, 8> kcc = Eigen::Matrix<double, 8, 8>::Zero();
  Eigen::Matrix<double, 8, 4> kci = Eigen::Matrix<double, 8, 4>::Zero();
  Eigen::Matrix4d kii = Eigen::Matrix4d::Zero();
  // a laminate's membrane-bending coupling: compatible and incompatible
  // membrane strains against the curvatures
  const Eigen::Matrix3d& cmb = sc.coupling;
  const bool coupled = !cmb.isZero(0.0);
  Eigen::Matrix<double, 8, 12> kmb = Eigen::Matrix<double, 8, 12>::Zero();
  Eigen::Matrix<double, 4, 12> kib = Eigen::Matrix<double, 4, 12>::Zero();
  Eigen::Matrix<double, 12, 12> dd_sum = Eigen::Matrix<double, 12, 12>::Zero();
  Eigen::Matrix4d nn_sum = Eigen::Matrix4d::Zero();
  Mat24 kl = Mat24::Zero();
  Mat24 ml = Mat24::Zero();
  const double g = 1.0 / std::sqrt(3.0);
  for (int gp = 0; gp < 4; ++gp) {
    const double xi = kQuadXi[gp] * g, eta = kQuadEta[gp] * g;
    Shape(xi, eta, n, dn);
    const Eigen::Matrix2d j = dn * xy;
    const double det = j.determinant();
    if (!(det > 0.0))
      throw InputError("inverted quad (negative Jacobian)", ElementContext(*in.element));
    const Eigen::Matrix2d j_inv = j.inverse();
    const Mat2x4 dx = j_inv * dn;  // rows d/dx, d/dy

    // membrane: compatible part over (u_i, v_i)
    const Eigen::Matrix<double, 3, 8> bm = shell::MembraneStrain<4>(dx);
    // incompatible modes (1 - xi^2), (1 - eta^2) in u and v, with J0 and det0 / det
    Eigen::Matrix2d dp;
    dp << -2.0 * xi, 0.0, 0.0, -2.0 * eta;
    const Eigen::Matrix2d dpx = j0_inv * dp * (det0 / det);  // rows d/dx, d/dy; cols mode
    // the two modes act like two more nodes in u and v
    const Eigen::Matrix<double, 3, 4> bi = shell::MembraneStrain<2>(dpx);
    kcc += bm.transpose() * cm * bm * det;
    kci += bm.transpose() * cm * bi * det;
    kii += bi.transpose() * cm * bi * det;

    // bending over (w, rx, ry) per node
    const Eigen::Matrix<double, 3, 12> bb = shell::BendingStrain<4>(dx);
    if (coupled) {
      kmb += bm.transpose() * cmb * bb * det;
      kib += bi.transpose() * cmb * bb * det;
    }
    // assumed covariant shear, then cartesian: gamma = J^-1 e
    Eigen::Matrix<double, 2, 12> bn;
    bn.row(0) = 0.5 * (1.0 + eta) * tie.row(0) + 0.5 * (1.0 - eta) * tie.row(1);
    bn.row(1) = 0.5 * (1.0 - xi) * tie.row(2) + 0.5 * (1.0 + xi) * tie.row(3);
    const Eigen::Matrix<double, 2, 12> bs = j_inv * bn;
    const Eigen::Matrix<double, 12, 12> kp =
        (bb.transpose() * cb * bb + bs.transpose() * ks * bs) * det;

    // drilling: theta_z - omega over (u, v, rz) per node
    const Eigen::Matrix<double, 1, 12> bd = shell::DrillingStrain<4>(dx, n);
    dd_sum += bd.transpose() * bd * det;
    shell::AddNodal<4, 3>(kp, shell::kPlateDofs, 1.0, kl);

    // mass: translations and the two bending rotations
    const Eigen::Matrix4d nn = n * n.transpose() * det;
    nn_sum += nn;
    shell::AddTranslationalAndRotaryMass<4>(nn, m0, m2, ml);
  }

  // condense the incompatible modes
  const Eigen::Matrix<double, 8, 8> km = kcc - kci * kii.ldlt().solve(kci.transpose());
  shell::AddNodal<4, 2>(km, shell::kMembraneDofs, 1.0, kl);
  if (coupled) {  // the condensation of the modes reaches the plate through B
    const Eigen::Matrix<double, 4, 12> kii_kib = kii.ldlt().solve(kib);
    const Eigen::Matrix<double, 8, 12> kmb_c = kmb - kci * kii_kib;
    const Eigen::Matrix<double, 12, 12> kbb_c = -kib.transpose() * kii_kib;
    shell::AddCoupling<4, 2, 3>(kmb_c, shell::kMembraneDofs, shell::kPlateDofs, kl);
    shell::AddNodal<4, 3>(kbb_c, shell::kPlateDofs, 1.0, kl);
  }

  const bool lumped = in.mass_form == MassForm::kLumped;
  Eigen::Vector4d share = Eigen::Vector4d::Zero();
  if (lumped) {
    // area shares int N_i dA; translations and all rotations diagonal
    for (int gp = 0; gp < 4; ++gp) {
      Shape(kQuadXi[gp] * g, kQuadEta[gp] * g, n, dn);
      share += n * (dn * xy).determinant();
    }
    ml = shell::LumpedMass<4>(share, m0, m2, 0.0);
  }

  // drilling tie at the centroid
  Shape(0.0, 0.0, n, dn);
  const Eigen::Matrix<double, 1, 12> bd0 = shell::DrillingStrain<4>(Mat2x4(j0_inv * dn), n);
  const Eigen::Matrix<double, 12, 12> drill_tie = bd0.transpose() * bd0 * (4.0 * det0);

  // drilling inertia from the physical part (before any drilling term): the
  // stabilized and the tied drilling modes both above the physical range
  const double lambda = m2 > 0.0 ? shell::MaxPhysicalEigenvalue<4>(kl, ml) : 0.0;
  const double mu = lumped && m2 > 0.0 ? shell::LumpedDrillingRatio(nn_sum, share) : 1.0;
  const double md = m2 > 0.0 ? shell::DrillingInertia(sc, kd, lambda, mu) : 0.0;
  const double mt = m2 > 0.0 ? shell::DrillingInertia(sc, sc.drilling_tie, lambda, 1.0) : 0.0;
  shell::AddNodal<4, 3>(dd_sum, shell::kDrillingDofs, kd, kl);
  shell::AddNodal<4, 3>(drill_tie, shell::kDrillingDofs, sc.drilling_tie, kl);
  if (lumped) {
    for (int i = 0; i < 4; ++i) ml(6 * i + 5, 6 * i + 5) = md * share(i);
  } else {
    shell::AddNodal<4, 3>(dd_sum, shell::kDrillingDofs, md, ml);
    shell::AddNodal<4, 3>(drill_tie, shell::kDrillingDofs, mt - md, ml);
  }

  shell::ToBasic<4>(f, kl, K);
  shell::ToBasic<4>(f, ml, M);
}

void ShellQuad4Stress(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  const shell::ShellData s = shell::CheckShellInput(in, 4);
  const shell::LocalFrame<4> f = Frame(in, s);
  Eigen::Vector4d n;
  Mat2x4 dn;
  Shape(0.0, 0.0, n, dn);
  const Eigen::Matrix2d j0 = dn * f.xy;
  const Mat2x4 dx = j0.inverse() * dn;
  S = shell::SurfaceStress<4>(f, s, dx);
  axes = f.R;
}

void ShellQuad4GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG) {
  const shell::ShellData s = shell::CheckShellInput(in, 4);
  const shell::LocalFrame<4> f = Frame(in, s);
  Eigen::Vector4d n;
  Mat2x4 dn;
  Shape(0.0, 0.0, n, dn);
  const Eigen::Vector3d nres =
      shell::MembraneResultants<4>(f, s, Mat2x4((dn * f.xy).inverse() * dn), u.head<24>());
  Mat24 kl = Mat24::Zero();
  const double g = 1.0 / std::sqrt(3.0);
  for (int gp = 0; gp < 4; ++gp) {
    Shape(kQuadXi[gp] * g, kQuadEta[gp] * g, n, dn);
    const Eigen::Matrix2d j = dn * f.xy;
    shell::AddMembranePrestress<4>(Mat2x4(j.inverse() * dn), nres, j.determinant(), kl);
  }
  shell::ToBasic<4>(f, kl, KG);
}

}  // namespace flexmb::fe
