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
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

using test_util::ExpectForceIsMinusEnergyGradient;
using test_util::ExpectTangentsMatchCentralDifferences;
using test_util::Forces;

using CableVec = AncfCable3d::Vec;
using CableMat = AncfCable3d::Mat;

BeamSection CableSection(double damping = 0.0) {
  return test_util::MakeSection(1.0e9, 2.0e-4, 5.0e-9, 1500.0, damping);
}

CableVec Deformed(const AncfCable3d& el) {
  CableVec e = el.StraightCoordinates(Eigen::Vector3d(0.1, -0.2, 0.3),
                                 Eigen::Vector3d(0.48, 0.6, 0.64));
  CableVec d;
  d << 0.01, -0.02, 0.03, 0.05, 0.13, -0.1, -0.03, 0.04, 0.02, -0.2, 0.07, 0.15;
  return e + d;
}

TEST(AncfCable3d, TangentsMatchCentralDifferences) {
  const AncfCable3d el(0.7, CableSection(0.03));
  const CableVec e = Deformed(el);
  CableVec edot;
  edot << 0.3, -0.1, 0.5, 0.2, -0.4, 0.6, 0.1, -0.3, 0.2, 0.4, -0.5, 0.1;
  ExpectTangentsMatchCentralDifferences(el, e, edot);
}

TEST(AncfCable3d, ElasticForceIsMinusEnergyGradient) {
  const AncfCable3d el(0.7, CableSection());
  ExpectForceIsMinusEnergyGradient(el, Deformed(el));
}

TEST(AncfCable3d, RigidMotionGivesNoElasticForce) {
  const AncfCable3d el(1.1, CableSection());
  const double scale = CableSection().E * CableSection().A;
  // a deformed state rotated by a finite rotation keeps its forces, rotated
  const CableVec e = Deformed(el);
  const CableVec Q = Forces(el, e, CableVec::Zero());
  const Mat3 R = ExpSO3(Vec3(0.7, -1.9, 1.2));
  CableVec eR, QR;
  for (int a = 0; a < 4; ++a) {
    eR.segment<3>(3 * a) = R * e.segment<3>(3 * a);
    QR.segment<3>(3 * a) = R * Q.segment<3>(3 * a);
  }
  for (int a = 0; a < 2; ++a) eR.segment<3>(6 * a) += Vec3(2.0, -1.0, 0.5);
  EXPECT_LT((Forces(el, eR, CableVec::Zero()) - QR).norm(), 1e-10 * Q.norm());
  EXPECT_NEAR(el.StrainEnergy(eR), el.StrainEnergy(e), 1e-10 * el.StrainEnergy(e));
  // a straight unstrained state in any orientation has no force
  for (const Vec3& phi : {Vec3(0, 0, 0), Vec3(0.3, 2.0, -1.0), Vec3(-2.5, 0.1, 0.4)}) {
    const Vec3 dir = ExpSO3(phi) * Vec3::UnitX();
    const CableVec e0 = el.StraightCoordinates(Vec3(1.0, 2.0, -3.0), dir);
    EXPECT_LT(Forces(el, e0, CableVec::Zero()).norm(), 1e-10 * scale);
  }
}

TEST(AncfCable3d, MassMatrixIntegratesMassAndFirstMoment) {
  const double L = 0.8;
  const BeamSection s = CableSection();
  const AncfCable3d el(L, s);
  const CableMat& M = el.MassMatrix();
  const double m = s.rho * s.A * L;
  const Vec3 p0(0.3, 2.0, -1.0), dir = Vec3(0.2, -0.4, 0.8).normalized();
  const CableVec e = el.StraightCoordinates(p0, dir);
  for (int d = 0; d < 3; ++d) {
    CableVec t = CableVec::Zero();
    t(d) = 1.0;
    t(6 + d) = 1.0;
    EXPECT_NEAR(t.dot(M * t), m, 1e-12 * m);
    EXPECT_NEAR(t.dot(M * e), m * (p0(d) + 0.5 * L * dir(d)), 1e-12 * m);
  }
  const Vec3 f(0.0, 0.0, -9.81 * s.rho * s.A);
  const CableVec Q = el.DistributedLoad(f);
  EXPECT_NEAR(Q(2) + Q(8), f.z() * L, 1e-12 * m * 9.81);
}

TEST(AncfCable3d, PlanarStatesMatchTheBeam2d) {
  const BeamSection s = CableSection(0.01);
  const AncfCable3d cable(0.6, s);
  const AncfBeam2d beam(0.6, s);
  AncfBeam2d::Vec e2, v2;
  e2 << 0.0, 0.1, 0.9, 0.3, 0.55, 0.2, 0.8, -0.5;
  v2 << 0.1, 0.2, -0.3, 0.4, 0.0, -0.1, 0.2, 0.3;
  CableVec e3 = CableVec::Zero(), v3 = CableVec::Zero();
  for (int a = 0; a < 4; ++a) {
    e3.segment<2>(3 * a) = e2.segment<2>(2 * a);
    v3.segment<2>(3 * a) = v2.segment<2>(2 * a);
  }
  AncfBeam2d::Vec Q2 = AncfBeam2d::Vec::Zero();
  AncfBeam2d::Mat K2 = AncfBeam2d::Mat::Zero(), C2 = AncfBeam2d::Mat::Zero();
  beam.AddInternalForces(e2, v2, Q2, K2, C2);
  const CableVec Q3 = Forces(cable, e3, v3);
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR((Q3.segment<2>(3 * a) - Q2.segment<2>(2 * a)).norm(), 0.0, 1e-10 * Q2.norm());
    EXPECT_NEAR(Q3(3 * a + 2), 0.0, 1e-10 * Q2.norm());
  }
}

TEST(AncfCable3d, NoSpuriousZeroEnergyModes) {
  // a straight free cable: 3 translations and 2 rotations (the spin about
  // its axis moves no coordinate) are the only zero-energy modes
  const AncfCable3d el(0.5, CableSection());
  const CableVec e = el.StraightCoordinates(Vec3(1.0, 2.0, 0.0), Vec3(0.48, 0.6, 0.64));
  CableVec Q = CableVec::Zero();
  CableMat K = CableMat::Zero(), C = CableMat::Zero();
  el.AddInternalForces(e, CableVec::Zero(), Q, K, C);
  Eigen::SelfAdjointEigenSolver<CableMat> eig(-K);
  const auto& l = eig.eigenvalues();
  for (int i = 0; i < 5; ++i) EXPECT_LT(std::abs(l(i)), 1e-9 * l(11));
  EXPECT_GT(l(5), 1e-3 * CableSection().E * CableSection().I / (0.5 * 0.5 * 0.5));
}

TEST(AncfCable3d, BadInputThrows) {
  BeamSection s = CableSection();
  EXPECT_THROW(AncfCable3d(0.0, s), InputError);
  s.rho = 0.0;
  EXPECT_THROW(AncfCable3d(1.0, s), InputError);
}

}  // namespace
}  // namespace flexmb::ancf
