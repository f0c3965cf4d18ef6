// fe/laminate.h against independent references: the rotated plane-stress
// stiffness stores the same energy as the ply's own stiffness under the
// strain tensor rotated as a tensor (R^T eps R); isotropic plies are
// invariant; identical isotropic plies stack to the homogeneous shell
// (A = E t / (1 - nu^2) [...], D = A t^2 / 12, S = 5/6 G t, rho t,
// rho t^3 / 12); a cross-ply [0/90]s laminate has the closed forms D11 =
// t^3 (7 Q11 + Q22) / 96, D22 = t^3 (Q11 + 7 Q22) / 96, D12 = t^3 Q12 / 12,
// D66 = t^3 Q66 / 12 and B = 0; the unsymmetric [0/90] has B11 = t^2 (Q22
// - Q11) / 8.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "flexmb/fe/laminate.h"

namespace flexmb::fe {
namespace {

constexpr double kE1 = 138e9, kE2 = 9e9, kNu12 = 0.3, kG12 = 7.1e9;

TEST(Laminate, RotatedStiffnessStoresTheEnergyOfTheRotatedStrainTensor) {
  const Eigen::Matrix3d q = OrthotropicPlaneStress(kE1, kE2, kNu12, kG12);
  for (double deg : {0.0, 17.0, 45.0, 90.0, -60.0, 135.0}) {
    const double th = deg * M_PI / 180.0;
    const Eigen::Matrix3d qb = RotatePlaneStress(q, th);
    // ply axes (1, 2) at th from x: columns of r
    Eigen::Matrix2d r;
    r << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);
    for (const Eigen::Vector3d e : {Eigen::Vector3d(1e-3, 0, 0), Eigen::Vector3d(0, 2e-4, 0),
                                    Eigen::Vector3d(0, 0, 5e-4), Eigen::Vector3d(3e-4, -1e-4, 7e-4)}) {
      Eigen::Matrix2d eps;  // tensor: engineering shear halved
      eps << e(0), 0.5 * e(2), 0.5 * e(2), e(1);
      const Eigen::Matrix2d em = r.transpose() * eps * r;
      const Eigen::Vector3d ev(em(0, 0), em(1, 1), 2.0 * em(0, 1));
      EXPECT_NEAR(e.dot(qb * e), ev.dot(q * ev), 1e-12 * ev.dot(q * ev) + 1e-3) << deg << " deg";
    }
    // transverse shear: gamma_m = R^T gamma as a vector
    Eigen::Matrix2d s;
    s << 5e8, 0, 0, 2e8;
    const Eigen::Vector2d g(1e-3, -4e-4), gm = r.transpose() * g;
    EXPECT_NEAR(g.dot(RotateShear(s, th) * g), gm.dot(s * gm), 1e-9) << deg << " deg";
  }
  const Eigen::Matrix3d iso = IsotropicPlaneStress(2.1e11, 0.3);
  EXPECT_LT((RotatePlaneStress(iso, 0.7) - iso).cwiseAbs().maxCoeff(), 1e-5 * iso(0, 0));
  // a quarter turn swaps the axes
  const Eigen::Matrix3d q90 = RotatePlaneStress(q, M_PI / 2);
  EXPECT_NEAR(q90(0, 0), q(1, 1), 1e-6 * q(0, 0));
  EXPECT_NEAR(q90(1, 1), q(0, 0), 1e-6 * q(0, 0));
}

TEST(Laminate, IdenticalIsotropicPliesStackToTheHomogeneousShell) {
  const double E = 2.1e11, nu = 0.3, G = E / (2 * (1 + nu)), rho = 7850, t = 0.012;
  std::vector<LaminatePly> plies;
  for (double deg : {0.0, 45.0, -30.0, 90.0}) {
    LaminatePly p;
    p.q = IsotropicPlaneStress(E, nu);
    p.g13 = p.g23 = G;
    p.rho = rho;
    p.t = t / 4;
    p.theta = deg * M_PI / 180.0;
    plies.push_back(p);
  }
  const ShellLaminate l = StackPlies(plies, -t / 2);
  const Eigen::Matrix3d a = IsotropicPlaneStress(E, nu) * t;
  EXPECT_LT((l.A - a).cwiseAbs().maxCoeff(), 1e-12 * a(0, 0));
  EXPECT_LT((l.D - a * t * t / 12).cwiseAbs().maxCoeff(), 1e-12 * a(0, 0) * t * t);
  EXPECT_LT(l.B.cwiseAbs().maxCoeff(), 1e-12 * a(0, 0) * t);
  EXPECT_NEAR(l.S(0, 0), 5.0 / 6.0 * G * t, 1e-6 * G * t);
  EXPECT_NEAR(l.S(1, 1), 5.0 / 6.0 * G * t, 1e-6 * G * t);
  EXPECT_NEAR(l.S(0, 1), 0.0, 1e-6 * G * t);
  EXPECT_NEAR(l.mass, rho * t, 1e-12);
  EXPECT_NEAR(l.rotary, rho * t * t * t / 12, 1e-15);
  EXPECT_NEAR(l.thickness, t, 1e-15);
  EXPECT_NEAR(l.z_top, t / 2, 1e-15);
}

std::vector<LaminatePly> CrossPly(const std::vector<double>& degrees, double t) {
  std::vector<LaminatePly> plies;
  for (double deg : degrees) {
    LaminatePly p;
    p.q = OrthotropicPlaneStress(kE1, kE2, kNu12, kG12);
    p.g13 = p.g23 = kG12;
    p.t = t / static_cast<double>(degrees.size());
    p.theta = deg * M_PI / 180.0;
    plies.push_back(p);
  }
  return plies;
}

TEST(Laminate, CrossPlyClosedForms) {
  const double t = 0.01;
  const Eigen::Matrix3d q = OrthotropicPlaneStress(kE1, kE2, kNu12, kG12);
  const ShellLaminate l = StackPlies(CrossPly({0, 90, 90, 0}, t), -t / 2);
  const double t3 = t * t * t, tol = 1e-12 * q(0, 0) * t3;
  EXPECT_NEAR(l.D(0, 0), t3 * (7 * q(0, 0) + q(1, 1)) / 96, tol);
  EXPECT_NEAR(l.D(1, 1), t3 * (q(0, 0) + 7 * q(1, 1)) / 96, tol);
  EXPECT_NEAR(l.D(0, 1), t3 * q(0, 1) / 12, tol);
  EXPECT_NEAR(l.D(2, 2), t3 * q(2, 2) / 12, tol);
  EXPECT_NEAR(l.D(0, 2), 0.0, tol);
  EXPECT_NEAR(l.A(0, 0), t * (q(0, 0) + q(1, 1)) / 2, 1e-12 * q(0, 0) * t);
  EXPECT_LT(l.B.cwiseAbs().maxCoeff(), 1e-12 * q(0, 0) * t * t);
  // the top ply's stiffness is the 0 degree ply's, the bottom's too
  EXPECT_LT((l.q_top - q).cwiseAbs().maxCoeff(), 1e-6 * q(0, 0));
  const ShellLaminate u = StackPlies(CrossPly({0, 90}, t), -t / 2);
  EXPECT_NEAR(u.B(0, 0), t * t * (q(1, 1) - q(0, 0)) / 8, 1e-12 * q(0, 0) * t * t);
  // in element axes at 90 degrees from the material axis: D11 and D22 swap
  const ShellLaminate r = InElementAxes(l, M_PI / 2);
  EXPECT_NEAR(r.D(0, 0), l.D(1, 1), 1e-9 * l.D(0, 0));
  EXPECT_NEAR(r.D(1, 1), l.D(0, 0), 1e-9 * l.D(0, 0));
}

}  // namespace
}  // namespace flexmb::fe
