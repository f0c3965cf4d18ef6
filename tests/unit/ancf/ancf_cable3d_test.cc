// Unit tests of the 3D ANCF cable element: tangents against central finite
// differences, forces against the strain-energy gradient, rigid motion
// (translation and finite rotation) free of elastic force, exact mass and
// first moment, and agreement with the planar beam for planar states.
#include "flexmb/ancf/ancf_cable3d.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "flexmb/ancf/ancf_beam2d.h"
#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf {
namespace {

using Vec = AncfCable3d::Vec;
using Mat = AncfCable3d::Mat;

BeamSection Section(double damping = 0.0) {
  BeamSection s;
  s.E = 1.0e9;
  s.A = 2.0e-4;
  s.I = 5.0e-9;
  s.rho = 1500.0;
  s.damping = damping;
  return s;
}

Vec Deformed(const AncfCable3d& el) {
  Vec e = el.StraightCoordinates(Eigen::Vector3d(0.1, -0.2, 0.3),
                                 Eigen::Vector3d(0.48, 0.6, 0.64));
  Vec d;
  d << 0.01, -0.02, 0.03, 0.05, 0.13, -0.1, -0.03, 0.04, 0.02, -0.2, 0.07, 0.15;
  return e + d;
}

Vec Forces(const AncfCable3d& el, const Vec& e, const Vec& edot) {
  Vec Q = Vec::Zero();
  Mat K = Mat::Zero(), C = Mat::Zero();
  el.AddInternalForces(e, edot, Q, K, C);
  return Q;
}

TEST(AncfCable3d, TangentsMatchCentralDifferences) {
  const AncfCable3d el(0.7, Section(0.03));
  const Vec e = Deformed(el);
  Vec edot;
  edot << 0.3, -0.1, 0.5, 0.2, -0.4, 0.6, 0.1, -0.3, 0.2, 0.4, -0.5, 0.1;
  Vec Q = Vec::Zero();
  Mat K = Mat::Zero(), C = Mat::Zero();
  el.AddInternalForces(e, edot, Q, K, C);
  const double h = 1e-6;
  Mat Kfd, Cfd;
  for (int j = 0; j < 12; ++j) {
    Vec ep = e, em = e, vp = edot, vm = edot;
    ep(j) += h;
    em(j) -= h;
    vp(j) += h;
    vm(j) -= h;
    Kfd.col(j) = (Forces(el, ep, edot) - Forces(el, em, edot)) / (2 * h);
    Cfd.col(j) = (Forces(el, e, vp) - Forces(el, e, vm)) / (2 * h);
  }
  EXPECT_LT((K - Kfd).norm(), 1e-6 * K.norm());
  EXPECT_LT((C - Cfd).norm(), 1e-6 * C.norm());
}

TEST(AncfCable3d, ElasticForceIsMinusEnergyGradient) {
  const AncfCable3d el(0.7, Section());
  const Vec e = Deformed(el);
  const Vec Q = Forces(el, e, Vec::Zero());
  const double h = 1e-6;
  Vec g;
  for (int j = 0; j < 12; ++j) {
    Vec ep = e, em = e;
    ep(j) += h;
    em(j) -= h;
    g(j) = (el.StrainEnergy(ep) - el.StrainEnergy(em)) / (2 * h);
  }
  EXPECT_LT((Q + g).norm(), 1e-6 * Q.norm());
}

TEST(AncfCable3d, RigidMotionGivesNoElasticForce) {
  const AncfCable3d el(1.1, Section());
  const double scale = Section().E * Section().A;
  // a deformed state rotated by a finite rotation keeps its forces, rotated
  const Vec e = Deformed(el);
  const Vec Q = Forces(el, e, Vec::Zero());
  const Mat3 R = ExpSO3(Vec3(0.7, -1.9, 1.2));
  Vec eR, QR;
  for (int a = 0; a < 4; ++a) {
    eR.segment<3>(3 * a) = R * e.segment<3>(3 * a);
    QR.segment<3>(3 * a) = R * Q.segment<3>(3 * a);
  }
  for (int a = 0; a < 2; ++a) eR.segment<3>(6 * a) += Vec3(2.0, -1.0, 0.5);
  EXPECT_LT((Forces(el, eR, Vec::Zero()) - QR).norm(), 1e-10 * Q.norm());
  EXPECT_NEAR(el.StrainEnergy(eR), el.StrainEnergy(e), 1e-10 * el.StrainEnergy(e));
  // a straight unstrained state in any orientation has no force
  for (const Vec3& phi : {Vec3(0, 0, 0), Vec3(0.3, 2.0, -1.0), Vec3(-2.5, 0.1, 0.4)}) {
    const Vec3 dir = ExpSO3(phi) * Vec3::UnitX();
    const Vec e0 = el.StraightCoordinates(Vec3(1.0, 2.0, -3.0), dir);
    EXPECT_LT(Forces(el, e0, Vec::Zero()).norm(), 1e-10 * scale);
  }
}

TEST(AncfCable3d, MassMatrixIntegratesMassAndFirstMoment) {
  const double L = 0.8;
  const BeamSection s = Section();
  const AncfCable3d el(L, s);
  const Mat& M = el.MassMatrix();
  const double m = s.rho * s.A * L;
  const Vec3 p0(0.3, 2.0, -1.0), dir = Vec3(0.2, -0.4, 0.8).normalized();
  const Vec e = el.StraightCoordinates(p0, dir);
  for (int d = 0; d < 3; ++d) {
    Vec t = Vec::Zero();
    t(d) = 1.0;
    t(6 + d) = 1.0;
    EXPECT_NEAR(t.dot(M * t), m, 1e-12 * m);
    EXPECT_NEAR(t.dot(M * e), m * (p0(d) + 0.5 * L * dir(d)), 1e-12 * m);
  }
  const Vec3 f(0.0, 0.0, -9.81 * s.rho * s.A);
  const Vec Q = el.DistributedLoad(f);
  EXPECT_NEAR(Q(2) + Q(8), f.z() * L, 1e-12 * m * 9.81);
}

TEST(AncfCable3d, PlanarStatesMatchTheBeam2d) {
  const BeamSection s = Section(0.01);
  const AncfCable3d cable(0.6, s);
  const AncfBeam2d beam(0.6, s);
  AncfBeam2d::Vec e2, v2;
  e2 << 0.0, 0.1, 0.9, 0.3, 0.55, 0.2, 0.8, -0.5;
  v2 << 0.1, 0.2, -0.3, 0.4, 0.0, -0.1, 0.2, 0.3;
  Vec e3 = Vec::Zero(), v3 = Vec::Zero();
  for (int a = 0; a < 4; ++a) {
    e3.segment<2>(3 * a) = e2.segment<2>(2 * a);
    v3.segment<2>(3 * a) = v2.segment<2>(2 * a);
  }
  AncfBeam2d::Vec Q2 = AncfBeam2d::Vec::Zero();
  AncfBeam2d::Mat K2 = AncfBeam2d::Mat::Zero(), C2 = AncfBeam2d::Mat::Zero();
  beam.AddInternalForces(e2, v2, Q2, K2, C2);
  const Vec Q3 = Forces(cable, e3, v3);
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR((Q3.segment<2>(3 * a) - Q2.segment<2>(2 * a)).norm(), 0.0, 1e-10 * Q2.norm());
    EXPECT_NEAR(Q3(3 * a + 2), 0.0, 1e-10 * Q2.norm());
  }
}

TEST(AncfCable3d, NoSpuriousZeroEnergyModes) {
  // a straight free cable: 3 translations and 2 rotations (the spin about
  // its axis moves no coordinate) are the only zero-energy modes
  const AncfCable3d el(0.5, Section());
  const Vec e = el.StraightCoordinates(Vec3(1.0, 2.0, 0.0), Vec3(0.48, 0.6, 0.64));
  Vec Q = Vec::Zero();
  Mat K = Mat::Zero(), C = Mat::Zero();
  el.AddInternalForces(e, Vec::Zero(), Q, K, C);
  Eigen::SelfAdjointEigenSolver<Mat> eig(-K);
  const auto& l = eig.eigenvalues();
  for (int i = 0; i < 5; ++i) EXPECT_LT(std::abs(l(i)), 1e-9 * l(11));
  EXPECT_GT(l(5), 1e-3 * Section().E * Section().I / (0.5 * 0.5 * 0.5));
}

TEST(AncfCable3d, BadInputThrows) {
  BeamSection s = Section();
  EXPECT_THROW(AncfCable3d(0.0, s), InputError);
  s.rho = 0.0;
  EXPECT_THROW(AncfCable3d(1.0, s), InputError);
}

}  // namespace
}  // namespace flexmb::ancf
