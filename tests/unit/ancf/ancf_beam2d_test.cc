// Unit tests of the planar ANCF beam element: tangents against central
// finite differences, forces against the derivative of the strain energy,
// rigid motion free of elastic force, exact mass, first moment and loads.
#include "flexmb/ancf/ancf_beam2d.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

using test_util::ExpectForceIsMinusEnergyGradient;
using test_util::ExpectTangentsMatchCentralDifferences;

using Vec = AncfBeam2d::Vec;
using Mat = AncfBeam2d::Mat;

BeamSection Section(double damping = 0.0) {
  return test_util::MakeSection(2.0e9, 1.0e-3, 3.0e-7, 7800.0, damping);
}

// a deformed, stretched and bent state
Vec Deformed(const AncfBeam2d& el) {
  Vec e = el.StraightCoordinates(Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(0.8, 0.6));
  const Vec d = (Vec() << 0.01, -0.02, 0.05, 0.13, -0.03, 0.04, -0.2, 0.07).finished();
  return e + d;
}

TEST(AncfBeam2d, TangentsMatchCentralDifferences) {
  for (double kappa0 : {0.0, 0.7}) {
    const AncfBeam2d el(0.9, Section(0.02), kappa0);
    const Vec e = Deformed(el);
    const Vec edot = (Vec() << 0.3, -0.1, 0.5, 0.2, -0.4, 0.6, 0.1, -0.3).finished();
    SCOPED_TRACE("kappa0 " + std::to_string(kappa0));
    ExpectTangentsMatchCentralDifferences(el, e, edot);
  }
  // without damping the tangent is the negative Hessian of the energy
  const AncfBeam2d el(0.9, Section(), 0.3);
  Vec Q = Vec::Zero();
  Mat K = Mat::Zero(), C = Mat::Zero();
  el.AddInternalForces(Deformed(el), Vec::Zero(), Q, K, C);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
}

TEST(AncfBeam2d, ElasticForceIsMinusEnergyGradient) {
  const AncfBeam2d el(0.9, Section(), 0.4);
  ExpectForceIsMinusEnergyGradient(el, Deformed(el));
}

TEST(AncfBeam2d, RigidMotionGivesNoElasticForce) {
  const AncfBeam2d el(1.3, Section(0.05));
  // scale of the forces: axial stiffness times a unit strain
  const double scale = Section().E * Section().A;
  for (double angle : {0.0, 0.9, 2.5, -2.0}) {
    const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
    const Vec e = el.StraightCoordinates(Eigen::Vector2d(3.0, -1.5), dir);
    // rigid velocity: translation plus rotation rate 1.7 rad/s about node 0
    const Eigen::Vector2d t(0.4, -0.2);
    const Eigen::Vector2d n(-dir.y(), dir.x());
    Vec edot;
    edot << t, 1.7 * n, t + 1.7 * 1.3 * n, 1.7 * n;
    Vec Q = Vec::Zero();
    Mat K = Mat::Zero(), C = Mat::Zero();
    el.AddInternalForces(e, edot, Q, K, C);
    // the elastic tangent annihilates rigid translations and the infinitesimal rotation
    Vec Q0 = Vec::Zero();
    Mat K0 = Mat::Zero(), C0 = Mat::Zero();
    el.AddInternalForces(e, Vec::Zero(), Q0, K0, C0);
    EXPECT_LT((K0 * (Vec() << 1, 0, 0, 0, 1, 0, 0, 0).finished()).norm(), 1e-8 * K0.norm());
    Vec rot;
    rot << 0, 0, n, 1.3 * n, n;
    EXPECT_LT((K0 * rot).norm(), 1e-8 * K0.norm());
    // a rigid velocity has zero strain rates: no damping force either
    EXPECT_LT(Q.norm(), 1e-10 * scale) << "angle " << angle;
    EXPECT_LT(el.StrainEnergy(e), 1e-20 * scale);
  }
}

TEST(AncfBeam2d, MassMatrixIntegratesMassAndFirstMoment) {
  const double L = 1.7;
  const BeamSection s = Section();
  const AncfBeam2d el(L, s);
  const Mat& M = el.MassMatrix();
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
  const double m = s.rho * s.A * L;
  const Eigen::Vector2d p0(0.3, 2.0), dir(0.6, -0.8);
  const Vec e = el.StraightCoordinates(p0, dir);
  for (int d = 0; d < 2; ++d) {
    Vec t = Vec::Zero();
    t(d) = 1.0;
    t(4 + d) = 1.0;
    EXPECT_NEAR(t.dot(M * t), m, 1e-12 * m);
    // first moment int rho A r ds = m (p0 + L/2 dir)
    EXPECT_NEAR(t.dot(M * e), m * (p0(d) + 0.5 * L * dir(d)), 1e-12 * m);
  }
  // second moment int rho A |r - p0|^2 ds = m L^2 / 3 on the straight element
  const Vec e0 = el.StraightCoordinates(Eigen::Vector2d::Zero(), dir);
  EXPECT_NEAR(e0.dot(M * e0), m * L * L / 3.0, 1e-12 * m * L * L);
  Eigen::SelfAdjointEigenSolver<Mat> eig(M);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

TEST(AncfBeam2d, DistributedLoadResultantAndMoment) {
  const double L = 2.0;
  const AncfBeam2d el(L, Section());
  const Eigen::Vector2d f(0.0, -9.81);
  const Vec Q = el.DistributedLoad(f);
  // virtual translation: resultant f L; virtual rotation about node 0: moment
  EXPECT_NEAR(Q(1) + Q(5), f.y() * L, 1e-12);
  Vec rot = Vec::Zero();
  rot << 0, 0, 0, 1, 0, L, 0, 1;
  EXPECT_NEAR(Q.dot(rot), f.y() * L * L / 2.0, 1e-12);
}

TEST(AncfBeam2d, PureBendingConvergesQuadratically) {
  // a circular arc of curvature k interpolated by one element (end positions
  // and unit tangents exact): the Hermite cubic is not a circle, its
  // curvature and energy converge to k and EI k^2 L / 2 as (k L)^2
  const double k = 0.4;
  const BeamSection s = Section();
  double err[2];
  for (int i = 0; i < 2; ++i) {
    const double L = i == 0 ? 0.5 : 0.25;
    const AncfBeam2d el(L, s);
    Vec e;
    e << 0, 0, 1, 0, std::sin(k * L) / k, (1 - std::cos(k * L)) / k, std::cos(k * L),
        std::sin(k * L);
    const double exact = 0.5 * s.E * s.I * k * k * L;
    EXPECT_NEAR(el.StrainEnergy(e), exact, 1e-2 * exact);
    err[i] = std::abs(el.Curvature(e, 0.5)(0) - k);
  }
  EXPECT_LT(err[0], 0.01 * k);
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.3);
}

TEST(AncfBeam2d, NoSpuriousZeroEnergyModes) {
  // the 2-point axial integration alone leaves an axial hourglass mode: a
  // 4th zero eigenvalue of a free element at the straight state
  {
    QuadratureOrder none;
    none.hourglass = 0.0;
    const AncfBeam2d el(0.5, Section(), 0.0, none);
    const Vec e = el.StraightCoordinates(Eigen::Vector2d(1.0, 2.0), Eigen::Vector2d(1.0, 0.0));
    Vec Q = Vec::Zero();
    Mat K = Mat::Zero(), C = Mat::Zero();
    el.AddInternalForces(e, Vec::Zero(), Q, K, C);
    Eigen::SelfAdjointEigenSolver<Mat> eig(-K);
    EXPECT_LT(std::abs(eig.eigenvalues()(3)), 1e-9 * eig.eigenvalues()(7));
  }
  // with the default hourglass control the stiffness of a free element at
  // the straight state is singular only on the 3 rigid motions
  for (double angle : {0.0, 0.8}) {
    const AncfBeam2d el(0.5, Section());
    const Vec e = el.StraightCoordinates(Eigen::Vector2d(1.0, 2.0),
                                         Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    Vec Q = Vec::Zero();
    Mat K = Mat::Zero(), C = Mat::Zero();
    el.AddInternalForces(e, Vec::Zero(), Q, K, C);
    Eigen::SelfAdjointEigenSolver<Mat> eig(-K);
    const auto& l = eig.eigenvalues();
    for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(l(i)), 1e-9 * l(7));
    // smallest deformation stiffness: bending, EI / L^3 scale
    EXPECT_GT(l(3), 1e-3 * Section().E * Section().I / (0.5 * 0.5 * 0.5));
  }
}

TEST(AncfBeam2d, BadInputThrows) {
  BeamSection s = Section();
  EXPECT_THROW(AncfBeam2d(0.0, s), InputError);
  EXPECT_THROW(AncfBeam2d(-1.0, s), InputError);
  s.A = 0.0;
  EXPECT_THROW(AncfBeam2d(1.0, s), InputError);
  s = Section();
  s.I = -1.0;
  EXPECT_THROW(AncfBeam2d(1.0, s), InputError);
  s = Section();
  s.damping = -0.1;
  EXPECT_THROW(AncfBeam2d(1.0, s), InputError);
}

}  // namespace
}  // namespace flexmb::ancf
