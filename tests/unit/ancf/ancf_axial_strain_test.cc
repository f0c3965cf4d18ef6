// Unit tests of the axial strain measure option (AxialStrainMeasure) of the
// ANCF elements (planar beam, 3D cable, 3D beam with torsion): with the
// Green-Lagrange measure the force is minus the central-difference gradient
// of the strain energy and the tangents match central differences on a
// generally deformed element (with damping, hourglass control and full
// integration); under a uniform stretch lambda of a straight element the
// strain is exactly (lambda^2 - 1) / 2 resp. lambda - 1, the energy
// 1/2 EA L eps^2, and the damping dissipates beta EA L (deps/dt)^2 with the
// rate of the chosen measure; the model-file key `axial_strain`.
#include <gtest/gtest.h>

#include <string>

#include "flexmb/ancf/ancf_beam2d.h"
#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/ancf/ancf_beam3d.h"
#include "flexmb/ancf/ancf_beam3d_body.h"
#include "flexmb/ancf/ancf_cable3d.h"
#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/math/rotation.h"
#include "flexmb/model_file/model_file.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

constexpr AxialStrainMeasure kAxialGL = AxialStrainMeasure::kGreenLagrange;
constexpr AxialStrainMeasure kAxialEng = AxialStrainMeasure::kEngineering;

BeamSection AxialTestSection(AxialStrainMeasure m, double damping) {
  BeamSection s = test_util::MakeSection(2.0e9, 1.0e-3, 4.0e-7, 2700.0, damping);
  s.axial_strain = m;
  return s;
}

Beam3dSection AxialTestSection3d(AxialStrainMeasure m, double damping) {
  Beam3dSection s;
  s.E = 2e9;
  s.G = 0.8e9;
  s.A = 1e-3;
  s.Iy = 2e-7;
  s.Iz = 5e-7;
  s.J = 3e-7;
  s.rho = 2700.0;
  s.damping = damping;
  s.axial_strain = m;
  return s;
}

// an element state: straight along dir with every coordinate shifted by a
// fixed pattern of amplitude `amp` (strains of order amp)
template <class Vec>
Vec AxialTestPerturbed(Vec e, double amp) {
  for (int j = 0; j < e.size(); ++j) e(j) += amp * std::sin(2.3 * j + 0.7);
  return e;
}

template <class Vec>
Vec AxialTestRate(int n) {
  Vec v(n);
  for (int j = 0; j < n; ++j) v(j) = 0.5 * std::cos(1.1 * j + 0.3);
  return v;
}

// the quadrature settings the checks run with: default (reduced + hourglass),
// full integration, reduced without hourglass control
QuadratureOrder AxialTestOrder(int k) {
  QuadratureOrder o;
  if (k == 1) o.axial = 5;
  if (k == 2) o.hourglass = 0.0;
  return o;
}

TEST(AncfAxialStrain, GreenLagrangeForcesAndTangentsMatchFiniteDifferences2d) {
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE("order " + std::to_string(k));
    const AncfBeam2d el(0.4, AxialTestSection(kAxialGL, 0.02), 0.3, AxialTestOrder(k));
    const auto e = AxialTestPerturbed(el.StraightCoordinates(Eigen::Vector2d(0.1, -0.2), Eigen::Vector2d(0.6, 0.8)),
                                      0.05);
    test_util::ExpectForceIsMinusEnergyGradient(
        AncfBeam2d(0.4, AxialTestSection(kAxialGL, 0.0), 0.3, AxialTestOrder(k)), e);
    test_util::ExpectTangentsMatchCentralDifferences(el, e, AxialTestRate<AncfBeam2d::Vec>(8));
  }
}

TEST(AncfAxialStrain, GreenLagrangeForcesAndTangentsMatchFiniteDifferences3d) {
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE("order " + std::to_string(k));
    const AncfCable3d el(0.4, AxialTestSection(kAxialGL, 0.02), AxialTestOrder(k));
    const auto e = AxialTestPerturbed(
        el.StraightCoordinates(Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(0.48, 0.6, 0.64)), 0.05);
    test_util::ExpectForceIsMinusEnergyGradient(AncfCable3d(0.4, AxialTestSection(kAxialGL, 0.0), AxialTestOrder(k)),
                                                e);
    test_util::ExpectTangentsMatchCentralDifferences(el, e, AxialTestRate<AncfCable3d::Vec>(12));
  }
}

TEST(AncfAxialStrain, GreenLagrangeForcesAndTangentsMatchFiniteDifferencesBeam3d) {
  const Mat3 R0 = ExpSO3(Vec3(0.3, -0.2, 0.5));
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE("order " + std::to_string(k));
    AncfBeam3d el(0.5, AxialTestSection3d(kAxialGL, 0.02), R0, AxialTestOrder(k));
    AncfBeam3d el0(0.5, AxialTestSection3d(kAxialGL, 0.0), R0, AxialTestOrder(k));
    AncfBeam3d::Vec e0 = AncfBeam3d::Vec::Zero();
    e0.segment<3>(3) = R0.col(0);
    e0.segment<3>(7) = 0.5 * R0.col(0);
    e0.segment<3>(10) = R0.col(0);
    // a pre-strained reference (eps0 != 0) and a deformed, twisted state
    const AncfBeam3d::Vec ref = AxialTestPerturbed(e0, 0.02);
    el.SetReference(ref);
    el0.SetReference(ref);
    const AncfBeam3d::Vec e = AxialTestPerturbed(e0, 0.06);
    test_util::ExpectForceIsMinusEnergyGradient(el0, e);
    test_util::ExpectTangentsMatchCentralDifferences(el, e, AxialTestRate<AncfBeam3d::Vec>(14));
  }
}

// the stretched straight state: r = p0 + lambda s dir, r' = lambda dir
template <class El, class VecD>
typename El::Vec AxialTestStretched(const El& el, const VecD& p0, const VecD& dir, double lambda) {
  typename El::Vec e = el.StraightCoordinates(p0, dir);
  const int D = static_cast<int>(p0.size());
  e.segment(D, D) *= lambda;
  e.segment(2 * D, D) = p0 + lambda * el.length() * dir;
  e.segment(3 * D, D) *= lambda;
  return e;
}

// rate of the axial strain of the measure at stretch lambda and stretch rate lambda_dot
double AxialTestStrainRate(AxialStrainMeasure m, double lambda, double lambda_dot) {
  return m == kAxialGL ? lambda * lambda_dot : lambda_dot;
}

double AxialTestStrain(AxialStrainMeasure m, double lambda) {
  return m == kAxialGL ? 0.5 * (lambda * lambda - 1.0) : lambda - 1.0;
}

template <class El, class VecD>
void ExpectAxialUniformStretch(const El& el, AxialStrainMeasure m, const VecD& p0, const VecD& dir) {
  const BeamSection& s = el.section();
  const double L = el.length();
  for (double lambda : {0.7, 0.999, 1.0, 1.001, 1.3}) {
    SCOPED_TRACE("lambda " + std::to_string(lambda));
    const double eps = AxialTestStrain(m, lambda);
    const typename El::Vec e = AxialTestStretched(el, p0, dir, lambda);
    for (double xi : {0.0, 0.21, 0.5, 0.88, 1.0}) EXPECT_NEAR(el.AxialStrain(e, xi), eps, 1e-14);
    EXPECT_NEAR(el.StrainEnergy(e), 0.5 * s.E * s.A * L * eps * eps, 1e-12 * s.E * s.A * L);
    // stretching at rate lambda_dot: damping power -beta EA L eps_dot^2
    const double lambda_dot = 0.8;
    const typename El::Vec edot = (AxialTestStretched(el, p0, dir, lambda + 1e-3 * lambda_dot) -
                                   AxialTestStretched(el, p0, dir, lambda - 1e-3 * lambda_dot)) /
                                  2e-3;
    const typename El::Vec Qd = test_util::Forces(el, e, edot) - test_util::Forces(el, e, El::Vec::Zero());
    const double eps_dot = AxialTestStrainRate(m, lambda, lambda_dot);
    EXPECT_NEAR(Qd.dot(edot), -s.damping * s.E * s.A * L * eps_dot * eps_dot,
                1e-8 * s.damping * s.E * s.A * L);
  }
}

TEST(AncfAxialStrain, UniformStretchGivesExactStrainEnergyAndDamping) {
  for (AxialStrainMeasure m : {kAxialEng, kAxialGL}) {
    SCOPED_TRACE(m == kAxialGL ? "green-lagrange" : "engineering");
    ExpectAxialUniformStretch(AncfBeam2d(0.4, AxialTestSection(m, 0.01)), m, Eigen::Vector2d(0.1, -0.2),
                         Eigen::Vector2d(0.6, 0.8));
    ExpectAxialUniformStretch(AncfCable3d(0.4, AxialTestSection(m, 0.01)), m, Eigen::Vector3d(0.1, -0.2, 0.3),
                         Eigen::Vector3d(0.48, 0.6, 0.64));
  }
}

TEST(AncfAxialStrain, UniformStretchBeam3d) {
  const Mat3 R0 = ExpSO3(Vec3(0.3, -0.2, 0.5));
  const double L = 0.5;
  for (AxialStrainMeasure m : {kAxialEng, kAxialGL}) {
    SCOPED_TRACE(m == kAxialGL ? "green-lagrange" : "engineering");
    const Beam3dSection s = AxialTestSection3d(m, 0.0);
    const AncfBeam3d el(L, s, R0);
    for (double lambda : {0.7, 1.0, 1.001, 1.3}) {
      AncfBeam3d::Vec e = AncfBeam3d::Vec::Zero();
      e.segment<3>(0) = Vec3(0.1, 0.2, -0.3);
      e.segment<3>(3) = lambda * R0.col(0);
      e.segment<3>(7) = e.segment<3>(0) + lambda * L * R0.col(0);
      e.segment<3>(10) = lambda * R0.col(0);
      const double eps = AxialTestStrain(m, lambda);
      for (double xi : {0.0, 0.3, 1.0}) EXPECT_NEAR(el.StrainsAt(e, xi)(0), eps, 1e-14);
      EXPECT_NEAR(el.StrainEnergy(e), 0.5 * s.E * s.A * L * eps * eps, 1e-12 * s.E * s.A * L);
    }
  }
}

TEST(AncfAxialStrain, MeasuresAgreeToFirstOrderInTheStrain) {
  // force ratio GL / engineering at stretch lambda: lambda (lambda + 1) / 2
  const AncfCable3d eng(0.4, AxialTestSection(kAxialEng, 0.0)), gl(0.4, AxialTestSection(kAxialGL, 0.0));
  for (double lambda : {1.0 + 1e-6, 1.001, 1.05}) {
    const auto e = AxialTestStretched(eng, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1), lambda);
    const auto qe = test_util::Forces(eng, e, AncfCable3d::Vec::Zero());
    const auto qg = test_util::Forces(gl, e, AncfCable3d::Vec::Zero());
    EXPECT_LT((qg - 0.5 * lambda * (lambda + 1.0) * qe).norm(), 1e-8 * qe.norm()) << lambda;
  }
}

TEST(AncfAxialStrain, GreenLagrangeIsDefinedAtAVanishingSlope) {
  const AncfCable3d gl(0.4, AxialTestSection(kAxialGL, 0.0)), eng(0.4, AxialTestSection(kAxialEng, 0.0));
  const AncfCable3d::Vec e = AncfCable3d::Vec::Zero();
  EXPECT_DOUBLE_EQ(gl.AxialStrain(e, 0.5), -0.5);
  AncfCable3d::Vec Q = AncfCable3d::Vec::Zero();
  AncfCable3d::Mat K = AncfCable3d::Mat::Zero(), C = AncfCable3d::Mat::Zero();
  EXPECT_THROW(eng.AddInternalForces(e, e, Q, K, C), NumericalError);
}

const char* kAxialModel =
    "name: axial\n"                                 // 1
    "bodies:\n"                                     // 2
    "  - name: beam\n"                              // 3
    "    type: ancf_beam\n"                         // 4
    "    length: 1.2\n"                             // 5
    "    elements: 2\n"                             // 6
    "    section: {area: 0.0018, inertia: 1.215e-8}\n"  // 7
    "    material: {E: 0.7e6, rho: 5540}\n"         // 8
    "    axial_strain: green_lagrange\n"            // 9
    "  - name: rope\n"                              // 10
    "    type: ancf_cable\n"                        // 11
    "    length: 1.2\n"                             // 12
    "    elements: 2\n"                             // 13
    "    section: {diameter: 0.01}\n"               // 14
    "    material: {E: 0.7e6, rho: 5540}\n"         // 15
    "    axial_strain: engineering\n"               // 16
    "  - name: boom\n"                              // 17
    "    type: ancf_beam3d\n"                       // 18
    "    length: 1.2\n"                             // 19
    "    elements: 2\n"                             // 20
    "    section: {area: 1.0e-3, Iy: 2.0e-7, Iz: 5.0e-7, J: 3.0e-7}\n"  // 21
    "    material: {E: 2.0e9, nu: 0.3, rho: 2700}\n"  // 22
    "    axial_strain: green_lagrange\n";           // 23

TEST(AncfAxialStrain, ModelFileKey) {
  auto model = LoadModelString(kAxialModel, "axial.yaml");
  const auto& beam = dynamic_cast<const AncfBeam2dBody&>(*model->bodies[model->FindBody("beam")]);
  const auto& rope = dynamic_cast<const AncfCable3dBody&>(*model->bodies[model->FindBody("rope")]);
  const auto& boom = dynamic_cast<const AncfBeam3dBody&>(*model->bodies[model->FindBody("boom")]);
  EXPECT_EQ(beam.element().section().axial_strain, kAxialGL);
  EXPECT_EQ(rope.element().section().axial_strain, kAxialEng);
  EXPECT_EQ(boom.element(1).section().axial_strain, kAxialGL);
  // the default is engineering
  std::string plain = kAxialModel;
  const std::string key = "    axial_strain: green_lagrange\n";
  plain.erase(plain.find(key), key.size());
  auto model0 = LoadModelString(plain, "axial.yaml");
  EXPECT_EQ(dynamic_cast<const AncfBeam2dBody&>(*model0->bodies[model0->FindBody("beam")]).element().section().axial_strain,
            kAxialEng);
  const test_util::ModelFileErrorCase cases[] = {
      {"axial_strain: green_lagrange\n  - name: rope", "axial_strain: green\n  - name: rope", "axial.yaml:9",
       "body 'beam'"},
      {"axial_strain: engineering", "axial_strain: biot", "axial.yaml:16", "body 'rope'"},
      {"rho: 2700}\n    axial_strain: green_lagrange", "rho: 2700}\n    axial_strain: GreenLagrange",
       "axial.yaml:23", "body 'boom'"},
  };
  test_util::ExpectModelFileErrorsNameLineAndEntity(kAxialModel, "axial.yaml", cases);
}

}  // namespace
}  // namespace flexmb::ancf
