#include "flexmb/fe/elements/beam2.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/element_common.h"

namespace flexmb::fe {
namespace {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat6x12 = Eigen::Matrix<double, 6, 12>;

// transport of end dof along the axis by a distance s: rigid motion
// (u, theta) at x maps to (u - s e1 x theta, theta) at x + s e1
Mat6 Transport(double s) {
  Mat6 g = Mat6::Identity();
  g.block<3, 3>(0, 3) = -Skew(Vec3(s, 0.0, 0.0));
  return g;
}

void CheckPositive(double v, const char* what, const ErrorContext& ctx) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(std::string(what) + " must be positive, got " + std::to_string(v), ctx);
}

// everything the stiffness, mass and section forces share: checks, element
// frame, section compliance, local stiffness and the map to the local end dof
struct BeamLocal {
  const Material* mat = nullptr;
  const BeamSection* sec = nullptr;
  double L = 0.0;
  Eigen::Matrix3d R;  // basic from element
  Mat6 C, bc, cb, bcb, kbb, gt;
  Mat12 kl;  // local end stiffness
  Mat12 t;   // basic nodal dof -> local end dof
};

BeamLocal Setup(const ElementInput& in) {
  BeamLocal b;
  const Element& e = CheckElementNodes(in, 2, "beam");
  const ErrorContext ctx = ElementContext(e);
  if (in.beam == nullptr) throw InputError("missing beam section (property)", ctx);
  if (in.material == nullptr) throw InputError("missing material of the beam section", ctx);
  const BeamSection& sec = *in.beam;
  const Material& mat = *in.material;
  b.mat = &mat;
  b.sec = &sec;

  CheckPositive(mat.E, "material Young's modulus", ctx);
  const double G = mat.G > 0.0 ? mat.G : mat.E / (2.0 * (1.0 + mat.nu));
  CheckPositive(G, "material shear modulus", ctx);
  if (!(mat.rho >= 0.0) || !std::isfinite(mat.rho) || !(sec.nsm >= 0.0) || !std::isfinite(sec.nsm))
    throw InputError("negative or non-finite density or non-structural mass", ctx);
  CheckPositive(sec.A, "section area A", ctx);
  CheckPositive(sec.Iy, "section moment Iy", ctx);
  CheckPositive(sec.Iz, "section moment Iz", ctx);
  CheckPositive(sec.J, "section torsion constant J", ctx);
  if (!std::isfinite(sec.Iyz) || !(sec.Iy * sec.Iz - sec.Iyz * sec.Iyz > 1e-12 * sec.Iy * sec.Iz))
    throw InputError("section product of inertia Iyz = " + std::to_string(sec.Iyz) +
                         " too large: need Iy Iz > Iyz^2",
                     ctx);
  if (!(sec.ky >= 0.0) || !(sec.kz >= 0.0) || !std::isfinite(sec.ky) || !std::isfinite(sec.kz))
    throw InputError("negative or non-finite shear factor", ctx);

  // ends, element frame
  const Vec3& oa = e.offset_a;
  const Vec3& ob = e.offset_b;
  if (!in.x[0].allFinite() || !in.x[1].allFinite() || !oa.allFinite() || !ob.allFinite() ||
      !e.orientation.allFinite())
    throw InputError("non-finite node coordinates, offsets or orientation vector", ctx);
  const Vec3 xa = in.x[0] + oa;
  const Vec3 xb = in.x[1] + ob;
  const double L = (xb - xa).norm();
  b.L = L;
  const double scale = std::max({xa.norm(), xb.norm(), oa.norm(), ob.norm()});
  if (!(L > 1e-10 * scale) || !(L > 0.0))
    throw InputError("zero length (ends A and B coincide)", ctx);
  const Vec3 ex = (xb - xa) / L;
  const Vec3& v = e.orientation;
  const Vec3 vy = v - ex * ex.dot(v);
  if (!(vy.norm() > 1e-8 * v.norm()) || !(v.norm() > 0.0))
    throw InputError(v.norm() > 0.0 ? "orientation vector parallel to the beam axis"
                                    : "zero orientation vector",
                     ctx);
  const Vec3 ey = vy.normalized();
  const Vec3 ez = ex.cross(ey);
  Eigen::Matrix3d& R = b.R;
  R.col(0) = ex;
  R.col(1) = ey;
  R.col(2) = ez;

  // section compliance over (N, Vy, Vz, T, My, Mz)
  Mat6& C = b.C;
  C.setZero();
  C(0, 0) = 1.0 / (mat.E * sec.A);
  C(1, 1) = sec.ky > 0.0 ? 1.0 / (sec.ky * G * sec.A) : 0.0;
  C(2, 2) = sec.kz > 0.0 ? 1.0 / (sec.kz * G * sec.A) : 0.0;
  C(3, 3) = 1.0 / (G * sec.J);
  Eigen::Matrix2d eb;
  eb << sec.Iy, -sec.Iyz, -sec.Iyz, sec.Iz;
  C.block<2, 2>(4, 4) = (mat.E * eb).inverse();
  // a neutral axis at (ey, ez) off the beam axis (the shear centre's): the
  // section forces about it are P S, N the same, My - ez N, Mz + ey N, so
  // the compliance about the beam axis is P^T C P
  const double na_y = sec.neutral_axis[0], na_z = sec.neutral_axis[1];
  if (!std::isfinite(na_y) || !std::isfinite(na_z) || !std::isfinite(sec.nsm_offset[0]) ||
      !std::isfinite(sec.nsm_offset[1]) || !(sec.nsm_inertia >= 0.0) || !std::isfinite(sec.nsm_inertia))
    throw InputError("non-finite neutral axis or non-structural mass offset, or a negative NSM inertia", ctx);
  if (na_y != 0.0 || na_z != 0.0) {
    Mat6 p = Mat6::Identity();
    p(4, 0) = -na_z;
    p(5, 0) = na_y;
    C = (p.transpose() * C * p).eval();
  }

  // section resultants at distance s before end B under an end-B load P:
  // S = (I + s B1) P, B1 = [0 0; skew(e1) 0]
  Mat6 B1 = Mat6::Zero();
  B1.block<3, 3>(3, 0) = Skew(Vec3::UnitX());
  const Mat6 cb = b.cb = C * B1;
  const Mat6 bc = b.bc = B1.transpose() * C;
  const Mat6 bcb = b.bcb = B1.transpose() * C * B1;
  // cantilever flexibility of end B (A clamped), closed form of int B^T C B
  const Mat6 F = L * C + 0.5 * L * L * (bc + cb) + L * L * L / 3.0 * bcb;
  Mat6& kbb = b.kbb;
  kbb = F.inverse();
  kbb = 0.5 * (kbb + kbb.transpose()).eval();

  // local stiffness: end-A wrench = -Gamma end-B wrench, Gamma^T = Transport(L)
  const Mat6 gt = b.gt = Transport(L);
  Mat12& kl = b.kl;
  kl.block<6, 6>(0, 0) = gt.transpose() * kbb * gt;
  kl.block<6, 6>(0, 6) = -gt.transpose() * kbb;
  kl.block<6, 6>(6, 0) = -kbb * gt;
  kl.block<6, 6>(6, 6) = kbb;

  // basic nodal dof -> local end dof: u_end = R^T (u + theta x offset), theta_end = R^T theta
  Mat12& t = b.t;
  t.setZero();
  const Eigen::Matrix3d rt = R.transpose();
  const Vec3 off[2] = {oa, ob};
  for (int i = 0; i < 2; ++i) {
    t.block<3, 3>(6 * i, 6 * i) = rt;
    t.block<3, 3>(6 * i, 6 * i + 3) = -rt * Skew(off[i]);
    t.block<3, 3>(6 * i + 3, 6 * i + 3) = rt;
  }
  return b;
}

}  // namespace

void Beam2Matrices(const ElementInput& in, MatX& K, MatX& M) {
  const BeamLocal b = Setup(in);
  const Material& mat = *b.mat;
  const BeamSection& sec = *b.sec;
  const double L = b.L;
  const Mat6 &C = b.C, &bc = b.bc, &cb = b.cb, &bcb = b.bcb, &kbb = b.kbb, &gt = b.gt;
  const Mat12 &kl = b.kl, &t = b.t;

  // section mass per length: translations, rotary inertia; the structural
  // mass on the neutral axis, the non-structural mass at its own centre
  // (each moved to the beam axis: a point at e moves by u + theta x e)
  const double m0 = mat.rho * sec.A + sec.nsm;
  Mat6 ms = Mat6::Zero();
  ms.block<3, 3>(0, 0).diagonal().setConstant(m0);
  ms(3, 3) = mat.rho * (sec.Iy + sec.Iz) + sec.nsm_inertia;
  ms(4, 4) = mat.rho * sec.Iy;
  ms(5, 5) = mat.rho * sec.Iz;
  ms(4, 5) = ms(5, 4) = -mat.rho * sec.Iyz;
  const Vec3 e_na(0.0, sec.neutral_axis[0], sec.neutral_axis[1]), e_nsm(0.0, sec.nsm_offset[0], sec.nsm_offset[1]);
  const bool offsets = sec.HasAxisOffsets();
  if (offsets) {
    auto moved = [](const Vec3& e, double m) {  // translational mass m at e, about the axis
      Mat6 h = Mat6::Identity();
      h.block<3, 3>(0, 3) = -Skew(e);
      Mat6 mm = Mat6::Zero();
      mm.block<3, 3>(0, 0).diagonal().setConstant(m);
      return Mat6(h.transpose() * mm * h);
    };
    ms.block<3, 3>(0, 0).setZero();
    ms += moved(e_na, mat.rho * sec.A) + moved(e_nsm, sec.nsm);
  }

  Mat12 ml = Mat12::Zero();
  if (in.mass_form == MassForm::kConsistent) {
    // exact static field N(x) = [Gamma_x^T - D(x) Kbb Gamma^T, D(x) Kbb], D(x) the
    // displacement at x per end-B load; cubic in x, so 4-point Gauss is exact
    constexpr double kGp[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                               0.8611363115940526};
    constexpr double kGw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                               0.3478548451374538};
    for (int g = 0; g < 4; ++g) {
      const double x = 0.5 * L * (1.0 + kGp[g]);
      const Mat6 D = x * C + 0.5 * x * x * bc + (L * x - 0.5 * x * x) * cb +
                     ((L - x) * x * x / 2.0 + x * x * x / 3.0) * bcb;
      const Mat6 dk = D * kbb;
      Mat6x12 n;
      n.block<6, 6>(0, 0) = Transport(x) - dk * gt;
      n.block<6, 6>(0, 6) = dk;
      ml += n.transpose() * ms * n * (0.5 * L * kGw[g]);
    }
  } else if (offsets) {
    // half the section's mass, with its offsets, at each end
    for (int end = 0; end < 2; ++end) ml.block<6, 6>(6 * end, 6 * end) = 0.5 * L * ms;
  } else {
    for (int end = 0; end < 2; ++end) {
      for (int a = 0; a < 3; ++a) ml(6 * end + a, 6 * end + a) = 0.5 * L * m0;
      for (int a = 3; a < 6; ++a) ml(6 * end + a, 6 * end + a) = 0.5 * L * ms(a, a);
    }
  }

  K = t.transpose() * kl * t;
  K = 0.5 * (K + K.transpose()).eval();
  M = t.transpose() * ml * t;
  M = 0.5 * (M + M.transpose()).eval();
}

void Beam2SectionForces(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  const BeamLocal b = Setup(in);
  // end wrenches on the element: f = kl t u; section forces at A = -f_A, at B = f_B
  Mat12 sign = Mat12::Identity();
  sign.topLeftCorner<6, 6>() *= -1.0;
  S = sign * b.kl * b.t;
  axes = b.R;
}

void Beam2GeometricStiffness(const ElementInput& in, double N, MatX& KG) {
  const BeamLocal b = Setup(in);
  // the Wagner term and the couplings of a neutral axis off the shear
  // centre are not in this geometric stiffness
  if (b.sec->neutral_axis[0] != 0.0 || b.sec->neutral_axis[1] != 0.0)
    throw InputError("the geometric stiffness of a beam whose neutral axis lies off its axis (PBEAM N1, N2) is not "
                     "supported",
                     ElementContext(*in.element));
  const double L = b.L;
  // bending in one plane, dofs (v_a, v'_a, v_b, v'_b)
  Eigen::Matrix4d kb;
  kb << 36.0, 3.0 * L, -36.0, 3.0 * L, 3.0 * L, 4.0 * L * L, -3.0 * L, -L * L, -36.0, -3.0 * L, 36.0, -3.0 * L,
      3.0 * L, -L * L, -3.0 * L, 4.0 * L * L;
  kb *= N / (30.0 * L);
  Mat12 kg = Mat12::Zero();
  // x-y plane: v = uy, v' = rz; x-z plane: w = uz, w' = -ry
  const int xy[4] = {1, 5, 7, 11}, xz[4] = {2, 4, 8, 10};
  const double sz[4] = {1.0, -1.0, 1.0, -1.0};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      kg(xy[i], xy[j]) += kb(i, j);
      kg(xz[i], xz[j]) += sz[i] * sz[j] * kb(i, j);
    }
  }
  // twist: Wagner term of the axial stress about the centroid
  const double kt = N * (b.sec->Iy + b.sec->Iz) / (b.sec->A * L);
  kg(3, 3) += kt, kg(9, 9) += kt, kg(3, 9) -= kt, kg(9, 3) -= kt;
  KG = b.t.transpose() * kg * b.t;
  KG = 0.5 * (KG + KG.transpose()).eval();
}

void Beam2GeometricStiffnessUnder(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG, double* axial_force) {
  MatX S;
  Eigen::Matrix3d axes;
  Beam2SectionForces(in, S, axes);
  const double N = 0.5 * (S.row(0).dot(u) + S.row(6).dot(u));
  if (axial_force != nullptr) *axial_force = N;
  Beam2GeometricStiffness(in, N, KG);
}

}  // namespace flexmb::fe
