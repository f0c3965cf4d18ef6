// The 20-node hexahedron (C3D20 full and C3D20R reduced integration):
// shape functions interpolate (Kronecker delta at the nodes, partition of
// unity), exactly six rigid-body modes with full integration on a curved,
// distorted element, the consistent mass of a parallelepiped (rho V and the
// analytic first and second moments through the rigid-body modes), positive
// HRZ lumped masses with the total kept, the stress of a linear
// displacement field (D eps, exact for the isoparametric element with
// straight edges), v^T KG v = V tr(B S B^T) for a homogeneous stress, and
// errors for inverted elements. Side by side with CalculiX:
// tests/validation/fe_hex20_calculix_test.cc.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_common.h"
#include "flexmb/fe/elements/solid_hex20.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace solid_hex20_test {

// the 20-node hexahedron on its corners (mid-edge nodes halfway), id 7 on
// line 30 of block.inp, steel of 2.1e11 Pa and 7850 kg/m^3
std::vector<Vec3> WithMidEdgeNodes(const std::vector<Vec3>& corners) {
  std::vector<Vec3> x = corners;
  for (const auto& edge : kHex20EdgeCorners) x.push_back(0.5 * (corners[edge[0]] + corners[edge[1]]));
  return x;
}

struct Hex20Element : testing::OneSolid {
  explicit Hex20Element(const std::vector<Vec3>& corners, ElementType type = kHex20)
      : OneSolid(type, WithMidEdgeNodes(corners), 7, {"block.inp", 30}) {
    material.E = 2.1e11;
    material.rho = 7850.0;
  }
};

// a parallelepiped spanned by a, b, c from o, corners in flexmb's order
std::vector<Vec3> Parallelepiped(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
  return {o, o + a, o + a + b, o + b, o + c, o + a + c, o + a + b + c, o + b + c};
}

// a distorted hexahedron with straight edges (no two faces parallel)
std::vector<Vec3> DistortedCorners() {
  return {{0.0, 0.0, 0.0},   {0.5, 0.05, 0.02}, {0.55, 0.42, -0.03}, {0.03, 0.38, 0.01},
          {0.02, -0.03, 0.3}, {0.47, 0.02, 0.33}, {0.58, 0.45, 0.36},  {-0.02, 0.4, 0.29}};
}

TEST(Hex20Element, MassOfAnObliqueParallelepipedIsRhoV) {
  // the x-block of the consistent mass sums to rho V (partition of unity)
  const Vec3 a(0.6, 0.1, 0.0), b(0.05, 0.4, 0.02), c(0.03, -0.02, 0.3);
  const Hex20Element h(Parallelepiped({0.1, 0.2, 0.3}, a, b, c));
  MatX K, M;
  h.Compute(K, M);
  ASSERT_EQ(K.rows(), 60);
  const double volume = std::abs(a.dot(b.cross(c)));
  double total = 0.0;
  for (int i = 0; i < 60; i += 3)
    for (int j = 0; j < 60; j += 3) total += M(i, j);
  EXPECT_NEAR(total, h.material.rho * volume, 1e-12 * h.material.rho * volume);
}

TEST(Hex20Element, SixRigidBodyModesWithFullIntegration) {
  Hex20Element h(DistortedCorners());
  h.x[8] += Vec3(0.0, -0.02, 0.01);  // a curved edge
  MatX K, M;
  h.Compute(K, M);
  testing::ExpectSixRigidModes(K, h.x, 3);
  // the reduced element keeps the rigid-body modes and has the same
  // (27-point) mass
  Hex20Element hr(DistortedCorners(), kHex20R);
  hr.x = h.x;
  MatX Kr, Mr;
  hr.Compute(Kr, Mr);
  const MatX r = testing::RigidModes(h.x, 3);
  EXPECT_LT((Kr * r).cwiseAbs().maxCoeff(), 1e-9 * K.cwiseAbs().maxCoeff());
  EXPECT_EQ(Mr, M);
}

// on a parallelepiped (constant Jacobian) the strain energy of linear
// fields is a constant integrand: both rules integrate it exactly, v^T K u
// = V eps(v)^T D eps(u) for full and reduced integration alike
TEST(Hex20Element, ConstantStrainEnergyIsExactForBothIntegrations) {
  const Vec3 a(0.6, 0.1, 0.0), b(0.05, 0.4, 0.02), c(0.03, -0.02, 0.3);
  const double volume = std::abs(a.dot(b.cross(c)));
  Eigen::Matrix3d A, B;
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 6.0e-4, 1.5e-3;
  B << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.15, -0.3;
  auto strain = [](const Eigen::Matrix3d& g) {
    Eigen::Matrix<double, 6, 1> e;
    e << g(0, 0), g(1, 1), g(2, 2), g(0, 1) + g(1, 0), g(1, 2) + g(2, 1), g(2, 0) + g(0, 2);
    return e;
  };
  for (ElementType type : {kHex20, kHex20R}) {
    const Hex20Element h(Parallelepiped({0.1, 0.2, 0.3}, a, b, c), type);
    Eigen::VectorXd u(60), v(60);
    for (int i = 0; i < 20; ++i) {
      u.segment<3>(3 * i) = A * h.x[i];
      v.segment<3>(3 * i) = B * h.x[i];
    }
    MatX K, M;
    h.Compute(K, M);
    solid::SolidData sd;
    sd.E = h.material.E;
    sd.nu = h.material.nu;
    const double expected = volume * strain(B).dot(solid::ElasticityMatrix(sd) * strain(A));
    EXPECT_NEAR(v.dot(K * u), expected, 1e-10 * std::abs(expected)) << Traits(type).name;
  }
}

TEST(Hex20Element, ConsistentMassGivesTheRigidBodyInertia) {
  // parallelepiped: the kinetic energy of a rigid motion r is r^T M r = int
  // rho |v|^2 dV; for the rotation about axis k through the origin, that is
  // the inertia tensor's J_kk, here computed analytically for a box
  const Vec3 o(0.1, -0.2, 0.3);
  const double lx = 0.6, ly = 0.4, lz = 0.3;
  const Hex20Element h(Parallelepiped(o, {lx, 0, 0}, {0, ly, 0}, {0, 0, lz}));
  MatX K, M;
  h.Compute(K, M);
  const MatX r = testing::RigidModes(h.x, 3);
  const MatX rigid_mass = r.transpose() * M * r;
  const double m = h.material.rho * lx * ly * lz;
  const Vec3 cg = o + 0.5 * Vec3(lx, ly, lz);
  // J about the origin's axes: box J_c + m (|cg|^2 - cg_k^2)
  const Vec3 jc = m / 12.0 * Vec3(ly * ly + lz * lz, lx * lx + lz * lz, lx * lx + ly * ly);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(rigid_mass(k, k), m, 1e-12 * m);
    const double j = jc(k) + m * (cg.squaredNorm() - cg(k) * cg(k));
    EXPECT_NEAR(rigid_mass(3 + k, 3 + k), j, 1e-11 * j) << k;
  }
  // lumped: positive diagonal, same total mass
  MatX Kl, Ml;
  h.Compute(Kl, Ml, MassForm::kLumped);
  EXPECT_GT(Ml.diagonal().minCoeff(), 0.0);
  EXPECT_NEAR(Ml.diagonal().sum(), 3.0 * m, 1e-12 * m);
}

TEST(Hex20Element, StressAndGeometricStiffnessOfAHomogeneousField) {
  const Hex20Element h(DistortedCorners());
  Eigen::Matrix3d A;
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 6.0e-4, 1.5e-3;
  Eigen::VectorXd u(60);
  for (int i = 0; i < 20; ++i) u.segment<3>(3 * i) = Vec3(1e-3, 2e-3, -1e-3) + A * h.x[i];
  MatX S;
  SolidHex20Stress(h.Input(), S);
  const Eigen::Matrix<double, 6, 1> stress = S * u;
  Eigen::Matrix<double, 6, 1> eps;
  eps << A(0, 0), A(1, 1), A(2, 2), A(0, 1) + A(1, 0), A(1, 2) + A(2, 1), A(2, 0) + A(0, 2);
  solid::SolidData sd;
  sd.E = h.material.E;
  sd.nu = h.material.nu;
  const Eigen::Matrix<double, 6, 1> expected = solid::ElasticityMatrix(sd) * eps;
  EXPECT_LT((stress - expected).cwiseAbs().maxCoeff(), 1e-6 * expected.cwiseAbs().maxCoeff());
  // homogeneous stress T: v^T KG v = V tr(B T B^T) for v = B x; V from the
  // rigid translation mass / rho
  MatX KG, K, M;
  SolidHex20GeometricStiffness(h.Input(), u, KG);
  Eigen::Matrix3d T;
  T << expected(0), expected(3), expected(5), expected(3), expected(1), expected(4), expected(5), expected(4),
      expected(2);
  Eigen::Matrix3d B;
  B << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.15, -0.3;
  Eigen::VectorXd v(60);
  for (int i = 0; i < 20; ++i) v.segment<3>(3 * i) = B * h.x[i];
  h.Compute(K, M);
  double volume = 0.0;
  for (int i = 0; i < 60; i += 3)
    for (int j = 0; j < 60; j += 3) volume += M(i, j) / h.material.rho;
  const double expected_kg = volume * (B * T * B.transpose()).trace();
  EXPECT_NEAR(v.dot(KG * v), expected_kg, 1e-8 * std::abs(expected_kg));
}

TEST(Hex20Element, InvertedElementsAreInputErrors) {
  std::vector<Vec3> c = DistortedCorners();
  std::swap(c[1], c[3]);
  std::swap(c[5], c[7]);
  MatX K, M;
  testing::ExpectInputErrorWith([&] { Hex20Element(c).Compute(K, M); },
                                {"block.inp:30", "20-node hexahedron 7", "inverted"});
  // a mid-edge node moved past the far corner folds the element at a corner
  Hex20Element folded(DistortedCorners());
  folded.x[8] = folded.x[1] + 0.3 * (folded.x[1] - folded.x[0]);
  testing::ExpectInputErrorWith([&] { folded.Compute(K, M); }, {"block.inp:30", "20-node hexahedron 7"});
}

}  // namespace solid_hex20_test
}  // namespace flexmb::fe
