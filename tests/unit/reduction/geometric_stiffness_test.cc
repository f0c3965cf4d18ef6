// Centrifugal geometric stiffness of a reduced body (ComputeGeometricStiffness):
// the axial force of a cantilever spinning about an axis through its root
// against N(x) = rho A Om^2 (L^2 - x^2) / 2 (element means, exact for the
// nodally exact bar solution), the flapping frequencies of the rotating
// cantilever from K + Om^2 Kg against the published values (Hodges and
// Rutkowski 1981; docs/validation.md, "Rotating beam: geometric
// stiffening"), the decomposition om x (om x x) = sum p_c a_c, the body file's
// optional dataset (bit for bit back; a body without it reads as none), and
// an element without its section named in the error.

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/geometric_stiffness.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction {
namespace {

constexpr double kL = 10.0, kEA = 2.8e7, kEI = 1.4e4, kRhoA = 1.2;

// Simo and Vu-Quoc's beam along x, as a round-section beam with these values
fe::FeModel Beam(int ne) {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "beam.bdf";
  const double A = kEA * kEA / (12.0 * kEI);  // any A with EA and EI: E = EA / A, I = EI / E
  const double E = kEA / A;
  const int mat = fe::testing::AddMaterial(mesh, E, 0.3, kRhoA / A);
  fe::BeamSection s;
  s.id = 1;
  s.material = mat;
  s.A = A;
  s.Iy = s.Iz = kEI / E;
  s.J = 2.0 * s.Iy;
  mesh.beam_sections.push_back(s);
  for (int k = 0; k <= ne; ++k) fe::testing::AddNode(mesh, fe::Vec3(kL * k / ne, 0.0, 0.0));
  for (int k = 0; k < ne; ++k) fe::testing::AddBeam(mesh, 0, k, k + 1, fe::Vec3(0.0, 1.0, 0.0));
  return model;
}

TEST(GeometricStiffness, CentrifugalAccelerationDecomposition) {
  const Vec3 om(0.3, -1.1, 0.7), x(0.4, 2.0, -1.3);
  const auto p = CentrifugalProducts(om);
  Vec3 sum = Vec3::Zero();
  for (int c = 0; c < kCentrifugalCases; ++c) sum += p[c] * CentrifugalAcceleration(c, x);
  EXPECT_LT((sum - om.cross(om.cross(x))).norm(), 1e-14);
}

TEST(GeometricStiffness, AxialForceAndRotatingCantileverFrequencies) {
  const int ne = 16;
  const fe::FeModel model = Beam(ne);
  // clamped in the body (cantilever modes, no rigid-body modes)
  ReductionOptions o;
  o.fixed_nodes = {0};
  o.normal_modes = 12;
  o.geometric_stiffening = true;
  const ReducedBody body = ReduceCraigBampton(model, o);
  GeometricStiffnessInfo info;
  const std::vector<MatX> kg = ComputeGeometricStiffness(model.mesh, body.modes, {0}, fe::MassForm::kConsistent, &info);
  ASSERT_EQ(body.geometric_stiffness.size(), 6u);
  for (int c = 0; c < kCentrifugalCases; ++c) EXPECT_LT((body.geometric_stiffness[c] - kg[c]).norm(), 1e-12 * kg[2].norm());
  ASSERT_EQ(kg.size(), 6u);
  // spin about z (case wz*wz): tension rho A (L^2 - x^2) / 2 per (rad/s)^2, mean over each element
  for (int e = 0; e < ne; ++e) {
    const double a = kL * e / ne, b = kL * (e + 1) / ne;
    const double ref = 0.5 * kRhoA * (kL * kL - (a * a + a * b + b * b) / 3.0);
    EXPECT_NEAR(info.axial_force[2][e], ref, 1e-9 * kRhoA * kL * kL) << "element " << e;
    EXPECT_NEAR(info.axial_force[1][e], ref, 1e-9 * kRhoA * kL * kL) << "element " << e;
    EXPECT_NEAR(info.axial_force[0][e], 0.0, 1e-9 * kRhoA * kL * kL) << "element " << e;
  }
  // flapping (no centrifugal softening out of the plane of rotation):
  // omega sqrt(rho A L^4 / EI) at lambda = Om sqrt(rho A L^4 / EI) = 0, 1, 2
  const double scale = std::sqrt(kRhoA * std::pow(kL, 4) / kEI);
  const double lambda[3] = {0.0, 1.0, 2.0}, ref[3] = {3.5160, 3.6816, 4.1373};
  for (int k = 0; k < 3; ++k) {
    const double om = lambda[k] / scale;
    const MatX Kt = body.stiffness + om * om * kg[2];
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<MatX>(0.5 * (Kt + Kt.transpose())).eigenvalues();
    // the round section bends alike in both planes: the lowest pair
    EXPECT_NEAR(std::sqrt(ev(0)) * scale, ref[k], 2e-4 * ref[k]) << "lambda " << lambda[k];
    EXPECT_NEAR(std::sqrt(ev(1)) * scale, ref[k], 2e-4 * ref[k]) << "lambda " << lambda[k];
  }
}

TEST(GeometricStiffness, BodyFileKeepsItAndOlderLayoutsReadAsNone) {
  ReductionOptions o;
  o.interface_nodes = {0};
  o.normal_modes = 4;
  o.geometric_stiffening = true;
  ReducedBody body = ReduceCraigBampton(Beam(4), o);
  ASSERT_EQ(body.geometric_stiffness.size(), 6u);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("flexmb_gs_" + std::to_string(::getpid()) + ".h5")).string();
  io::WriteBody(body, path);
  const ReducedBody back = io::ReadBody(path);
  ASSERT_EQ(back.geometric_stiffness.size(), 6u);
  for (int c = 0; c < kCentrifugalCases; ++c) EXPECT_EQ(back.geometric_stiffness[c], body.geometric_stiffness[c]);
  body.geometric_stiffness.clear();
  io::WriteBody(body, path);
  EXPECT_TRUE(io::ReadBody(path).geometric_stiffness.empty());
  body.geometric_stiffness.assign(2, MatX::Zero(4, 4));
  EXPECT_THROW(io::WriteBody(body, path), InputError);
  std::filesystem::remove(path);
}

TEST(GeometricStiffness, ElementWithoutSectionIsNamed) {
  // shells have a geometric stiffness now; a shell without its section is refused by name
  fe::FeModel model = Beam(2);
  fe::testing::AddElement(model.mesh, fe::ElementType::kTria3, 0, {0, 1, 2});
  fe::testing::ExpectInputErrorWith([&] { ComputeGeometricStiffness(model.mesh, MatX::Zero(6 * 3, 1), {0}); },
                                    {"test.bdf:1003", "has no shell section"});
}

}  // namespace
}  // namespace flexmb::reduction
