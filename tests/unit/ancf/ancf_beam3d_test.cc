// Unit tests of the 3D ANCF beam with torsion (element and body): strains
// against finite differences of the section frame along the beam (torsion
// d3 . d2', bending -d3 . t', d2 . t'), elastic and damping tangents and the
// force against the strain-energy gradient (central differences), mass
// matrix against the rigid translation and spin energies, marker kinematics
// and body force tangents against finite differences, the arc reference
// state, bad input; the model-file entry `type: ancf_beam3d` and its errors.
#include "flexmb/ancf/ancf_beam3d.h"
#include "flexmb/ancf/ancf_beam3d_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/math/rotation.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

Beam3dSection Beam3dTestSection(double damping) {
  Beam3dSection s;
  s.E = 2e9;
  s.G = 0.8e9;
  s.A = 1e-3;
  s.Iy = 2e-7;
  s.Iz = 5e-7;
  s.J = 3e-7;
  s.rho = 2700.0;
  s.damping = damping;
  return s;
}

Mat3 Beam3dTestFrame() {
  return ExpSO3(Vec3(0.3, -0.2, 0.5));
}

// a deformed, twisted element state near the straight reference along R0.col(0)
AncfBeam3d::Vec Beam3dTestState(const Mat3& R0, double L) {
  AncfBeam3d::Vec e;
  const Vec3 t0 = R0.col(0);
  e.segment<3>(0) = Vec3(0.1, -0.2, 0.3);
  e.segment<3>(3) = t0 + Vec3(0.05, 0.2, -0.1);
  e(6) = 0.3;
  e.segment<3>(7) = e.segment<3>(0) + L * t0 + Vec3(0.02, -0.03, 0.04);
  e.segment<3>(10) = 1.02 * t0 + Vec3(-0.1, 0.15, 0.2);
  e(13) = -0.4;
  return e;
}

TEST(AncfBeam3d, StrainsAreTheRatesOfTheSectionFrame) {
  const Mat3 R0 = Beam3dTestFrame();
  const AncfBeam3d el(0.5, Beam3dTestSection(0.0), R0);
  const AncfBeam3d::Vec e = Beam3dTestState(R0, 0.5);
  for (double xi : {0.2, 0.55, 0.9}) {
    const double h = 1e-6;
    const Mat3 F = el.SectionFrame(e, xi);
    const Mat3 dF = (el.SectionFrame(e, xi + h) - el.SectionFrame(e, xi - h)) / (2.0 * h * el.length());
    const AncfBeam3d::Strains s = el.StrainsAt(e, xi);
    EXPECT_LT((F.transpose() * F - Mat3::Identity()).norm(), 1e-13);
    EXPECT_LT((F.col(0) - (el.Position(e, xi + h) - el.Position(e, xi - h)).normalized()).norm(), 1e-8);
    EXPECT_NEAR(s(1), F.col(2).dot(dF.col(1)), 1e-7);
    EXPECT_NEAR(s(2), -F.col(2).dot(dF.col(0)), 1e-7);
    EXPECT_NEAR(s(3), F.col(1).dot(dF.col(0)), 1e-7);
    const Vec3 rp = (el.Position(e, xi + h) - el.Position(e, xi - h)) / (2.0 * h * el.length());
    EXPECT_NEAR(s(0), rp.norm() - 1.0, 1e-7);
  }
}

TEST(AncfBeam3d, TangentsMatchFiniteDifferences) {
  const Mat3 R0 = Beam3dTestFrame();
  const AncfBeam3d el(0.5, Beam3dTestSection(0.01), R0);
  const AncfBeam3d::Vec e = Beam3dTestState(R0, 0.5);
  AncfBeam3d::Vec edot;
  for (int j = 0; j < AncfBeam3d::kDof; ++j) edot(j) = 0.3 * std::sin(1.7 * j + 0.4);
  test_util::ExpectTangentsMatchCentralDifferences(el, e, edot);
  const AncfBeam3d el0(0.5, Beam3dTestSection(0.0), R0);
  test_util::ExpectForceIsMinusEnergyGradient(el0, e);
  // with a curved, twisted reference the same holds
  AncfBeam3d elr(0.5, Beam3dTestSection(0.0), R0);
  AncfBeam3d::Vec e0 = e;
  e0(13) += 0.2;
  e0.segment<3>(10) += Vec3(0.1, 0.0, -0.05);
  elr.SetReference(e0);
  test_util::ExpectForceIsMinusEnergyGradient(elr, e);
  EXPECT_LT(elr.StrainEnergy(e0), 1e-25);
}

TEST(AncfBeam3d, MassMatrixGivesTranslationAndSpinEnergy) {
  const Mat3 R0 = Beam3dTestFrame();
  const Beam3dSection sec = Beam3dTestSection(0.0);
  const double L = 0.5;
  const AncfBeam3d el(L, sec, R0);
  AncfBeam3d::Vec v = AncfBeam3d::Vec::Zero();
  const Vec3 u(0.3, -1.2, 0.7);
  v.segment<3>(0) = u;
  v.segment<3>(7) = u;
  EXPECT_NEAR(v.dot(el.MassMatrix() * v), sec.rho * sec.A * L * u.squaredNorm(), 1e-12);
  v.setZero();
  v(6) = v(13) = 2.0;
  EXPECT_NEAR(v.dot(el.MassMatrix() * v), sec.rho * (sec.Iy + sec.Iz) * L * 4.0, 1e-15);
}

AncfBeam3dData Beam3dBodyData() {
  AncfBeam3dData d;
  d.length = 1.5;
  d.elements = 3;
  d.section = Beam3dTestSection(0.01);
  d.start_W = Vec3(0.5, -1.0, 2.0);
  d.direction_W = Vec3(1.0, 1.0, 0.3);
  d.normal_W = Vec3(0.0, -0.3, 1.0);
  d.radius = 2.0;
  d.load_per_length_W = Vec3(2.0, -3.0, 1.0);
  return d;
}

TEST(AncfBeam3dBody, MarkerKinematicsMatchFiniteDifferences) {
  const AncfBeam3dBody b("beam", Beam3dBodyData());
  VecX q, v;
  test_util::PerturbedBodyState(b, 0.15, q, v);
  test_util::ExpectNodeMarkerKinematicsMatchCentralDifferences(b, q, v, {0, 2, 3});
  // the node frame is the elements' section frame at the node
  const Mat3 F = b.element(1).SectionFrame(q.segment<14>(7), 1.0);
  EXPECT_LT((b.NodeFrame(q.data(), 2) - F).norm(), 1e-13);
}

TEST(AncfBeam3dBody, ArcReferenceIsStressFreeAndTangentsMatch) {
  const AncfBeam3dData d = Beam3dBodyData();
  const AncfBeam3dBody b("beam", d);
  VecX q0(b.nq()), v0(b.nv());
  b.InitialCoordinates(q0.data(), v0.data());
  // nodes on the arc about centre start + R y0, section z axis = z0 at every node
  const Vec3 centre = d.start_W + d.radius * b.R_W0().col(1);
  for (int k = 0; k < b.nodes(); ++k) {
    EXPECT_NEAR((q0.segment<3>(7 * k) - centre).norm(), d.radius, 1e-12);
    EXPECT_LT((b.NodeFrame(q0.data(), k).col(2) - b.R_W0().col(2)).norm(), 1e-12);
  }
  EXPECT_LT(b.ElasticEnergy(q0.data()), 1e-20);
  VecX q, v;
  test_util::PerturbedBodyState(b, 0.15, q, v);
  test_util::ExpectBodyForceTangentsMatchCentralDifferences(b, q, v, Vec3(0.0, 0.0, -9.81));
  AncfBeam3dData d0 = d;
  d0.load_per_length_W.setZero();
  d0.section.damping = 0.0;
  test_util::ExpectBodyForcesArePotentialGradients(AncfBeam3dBody("beam", d0), q, Vec3(0.0, 0.0, -9.81));
  MatX M;
  b.MassMatrix(q.data(), M);
  EXPECT_NEAR(0.5 * v.dot(M * v), b.KineticEnergy(q.data(), v.data()), 1e-12 * v.dot(M * v));
}

TEST(AncfBeam3dBody, BadInputThrowsNamingTheBody) {
  AncfBeam3dData d = Beam3dBodyData();
  d.elements = 0;
  try {
    AncfBeam3dBody("boom", d);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().entity, "body 'boom'");
  }
  d = Beam3dBodyData();
  d.length = -1.0;
  EXPECT_THROW(AncfBeam3dBody("boom", d), InputError);
  d = Beam3dBodyData();
  d.section.J = 0.0;
  EXPECT_THROW(AncfBeam3dBody("boom", d), InputError);
  d = Beam3dBodyData();
  d.section.Iz = -1.0;
  EXPECT_THROW(AncfBeam3dBody("boom", d), InputError);
  d = Beam3dBodyData();
  d.radius = 0.4;  // arc of more than 180 degrees
  EXPECT_THROW(AncfBeam3dBody("boom", d), InputError);
  const AncfBeam3dBody b("boom", Beam3dBodyData());
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  EXPECT_THROW(b.EvaluateMarker(q.data(), v.data(), test_util::NodeTestMarker("beam.m", 4), ms), InputError);
}

const char* kBeam3dModel =
    "name: bend\n"                                               // 1
    "bodies:\n"                                                  // 2
    "  - name: arc\n"                                            // 3
    "    type: ancf_beam3d\n"                                    // 4
    "    length: 78.539816339744831\n"                           // 5
    "    elements: 8\n"                                          // 6
    "    radius: 100\n"                                          // 7
    "    section: {area: 1, Iy: 0.0833333, Iz: 0.0833333, J: 0.1666667}\n"  // 8
    "    material: {E: 1.0e7, nu: 0, rho: 1}\n"                  // 9
    "    direction: [1, 0, 0]\n"                                 // 10
    "    normal: [0, 0, 1]\n"                                    // 11
    "    markers:\n"                                             // 12
    "      - {name: root, end: start}\n"                         // 13
    "      - {name: tip, node: 8}\n";                            // 14

TEST(AncfBeam3dModelFile, ArcWithMarkersAndBadInput) {
  auto model = LoadModelString(kBeam3dModel, "bend.yaml");
  const int ib = model->FindBody("arc");
  ASSERT_GT(ib, 0);
  const auto& b = dynamic_cast<const AncfBeam3dBody&>(*model->bodies[ib]);
  EXPECT_EQ(b.elements(), 8);
  EXPECT_DOUBLE_EQ(b.element(0).section().G, 0.5e7);
  VecX q(b.nq()), v(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), model->markers[model->FindMarker("arc.tip")], ms);
  const double c = std::sqrt(0.5);
  EXPECT_LT((ms.p_WM - Vec3(100.0 * c, 100.0 * (1.0 - c), 0.0)).norm(), 1e-12);
  EXPECT_LT((ms.R_WM.col(0) - Vec3(c, c, 0.0)).norm(), 1e-12);
  const test_util::ModelFileErrorCase cases[] = {
      {"length: 78.539816339744831", "length: 0", "bend.yaml:5", "body 'arc'"},
      {"elements: 8", "elements: 0", "bend.yaml:6", "body 'arc'"},
      {"radius: 100", "radius: -1", "bend.yaml:7", "body 'arc'"},
      {"radius: 100", "radius: 10", "bend.yaml:", "body 'arc'"},
      {"J: 0.1666667", "J: 0", "bend.yaml:8", "body 'arc'"},
      {"Iy: 0.0833333", "Iy: -1", "bend.yaml:8", "body 'arc'"},
      {"area: 1", "area: 0", "bend.yaml:8", "body 'arc'"},
      {"nu: 0", "nu: 0, G: 1.0e6", "bend.yaml:9", "body 'arc'"},
      {"nu: 0, ", "", "bend.yaml:9", "body 'arc'"},
      {"{name: tip, node: 8}", "{name: tip, node: 9}", "bend.yaml:14", "marker 'arc.tip'"},
      // a list of sections: one per element
      {"section: {area: 1, Iy: 0.0833333, Iz: 0.0833333, J: 0.1666667}",
       "section: [{area: 1, Iy: 0.08, Iz: 0.08, J: 0.16}, {area: 1, Iy: 0.08, Iz: 0.08, J: 0.16}]", "bend.yaml:8",
       "body 'arc'"},
      {"section: {area: 1, Iy: 0.0833333, Iz: 0.0833333, J: 0.1666667}", "section: [1, 2, 3, 4, 5, 6, 7, 8]",
       "bend.yaml:8", "body 'arc'"},
  };
  test_util::ExpectModelFileErrorsNameLineAndEntity(kBeam3dModel, "bend.yaml", cases);
}

TEST(AncfBeam3dModelFile, SectionPerElement) {
  std::string text = kBeam3dModel;
  const std::string one = "section: {area: 1, Iy: 0.0833333, Iz: 0.0833333, J: 0.1666667}";
  std::string list = "section: [";
  for (int i = 0; i < 8; ++i)
    list += (i ? ", " : "") + std::string("{area: ") + std::to_string(1.0 + i) + ", Iy: 0.08, Iz: 0.09, J: 0.16}";
  text.replace(text.find(one), one.size(), list + "]");
  text.replace(text.find("radius: 100\n"), 12, "radius: 100\n    damping: 0.01\n    axial_strain: green_lagrange\n");
  auto model = LoadModelString(text, "stepped.yaml");
  const auto& b = dynamic_cast<const AncfBeam3dBody&>(*model->bodies[model->FindBody("arc")]);
  for (int i = 0; i < 8; ++i) {
    const Beam3dSection& s = b.element(i).section();
    EXPECT_DOUBLE_EQ(s.A, 1.0 + i);
    EXPECT_DOUBLE_EQ(s.Iz, 0.09);
    // the body's material, damping and strain measure in every element
    EXPECT_DOUBLE_EQ(s.G, 0.5e7);
    EXPECT_DOUBLE_EQ(s.rho, 1.0);
    EXPECT_DOUBLE_EQ(s.damping, 0.01);
    EXPECT_EQ(s.axial_strain, AxialStrainMeasure::kGreenLagrange);
  }
}

}  // namespace
}  // namespace flexmb::ancf
