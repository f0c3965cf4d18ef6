// The 5-node pyramid (fe/elements/solid_pyramid5.h): symmetry and exactly
// six rigid-body modes on distorted elements; the consistent mass's exact
// rigid-body mass and inertia over a parallelogram base (two tetrahedra,
// analytic moments) and of a right square pyramid (m = rho a^2 h / 3, centre
// h / 4 above the base, I_axis = m a^2 / 10, I_transverse = m (a^2 / 20 +
// 3 h^2 / 80) about the centre of mass); positive lumped masses; the patch
// test on a distorted box of 2 x 2 x 2 cells, each split into six pyramids
// on its faces; the stress and geometric stiffness of a homogeneous field;
// errors for inverted and flat elements.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_common.h"
#include "flexmb/fe/elements/solid_pyramid5.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe {
namespace solid_pyramid_test {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using testing::RandomRotation;
using testing::RigidModes;
using testing::TetsRigidMass;

// a pyramid element, id 7 on line 40 of part.bdf
struct Pyramid : testing::OneSolid {
  explicit Pyramid(std::vector<Vec3> nodes) : OneSolid(kPyramid5, std::move(nodes), 7, {"part.bdf", 40}) {}
};

std::vector<Vec3> Place(const std::vector<Vec3>& p, const Eigen::Matrix3d& R, const Vec3& c) {
  std::vector<Vec3> out;
  for (const Vec3& q : p) out.push_back(c + R * q);
  return out;
}

// a parallelogram base (counter-clockwise seen from the apex) and an
// oblique apex
std::vector<Vec3> ObliquePyramid() {
  const Vec3 o(0.0, 0.0, 0.0), a(1.2, 0.1, 0.05), b(0.3, 0.9, -0.04);
  return {o, o + a, o + a + b, o + b, Vec3(0.9, 0.2, 0.8)};
}

TEST(PyramidElement, SixRigidBodyModesOnDistortedElements) {
  // a warped base and an apex off the axis, turned and moved
  const std::vector<Vec3> x = Place({{0.0, 0.0, 0.02}, {1.1, -0.1, -0.03}, {1.2, 0.9, 0.04}, {-0.1, 1.05, -0.02},
                                     {0.7, 0.3, 0.9}},
                                    RandomRotation(5), Vec3(0.3, -0.2, 0.1));
  MatX K, M;
  Pyramid(x).Compute(K, M);
  ASSERT_EQ(K.rows(), 15);
  testing::ExpectSixRigidModes(K, x, 3);
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
}

TEST(PyramidElement, ConsistentMassGivesExactRigidBodyInertia) {
  const std::vector<Vec3> c = Place(ObliquePyramid(), RandomRotation(3), Vec3(0.4, -0.1, 0.2));
  const Pyramid p(c);
  MatX K, M;
  p.Compute(K, M);
  const MatX R = RigidModes(c, 3);
  const Mat6 ref = TetsRigidMass({{c[0], c[1], c[2], c[4]}, {c[0], c[2], c[3], c[4]}}, p.material.rho);
  EXPECT_LT((R.transpose() * M * R - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.cwiseAbs().maxCoeff());
  // lumped: positive, the same mass and first moments
  MatX Kl, Ml;
  p.Compute(Kl, Ml, MassForm::kLumped);
  EXPECT_GT(Ml.diagonal().minCoeff(), 0.0);
  const Mat6 lumped = R.transpose() * Ml * R;
  EXPECT_LT((lumped.leftCols(3) - ref.leftCols(3)).cwiseAbs().maxCoeff(), 1e-12 * ref(0, 0));
}

TEST(PyramidElement, RightSquarePyramidMatchesTheTextbook) {
  const double a = 0.6, h = 0.9, rho = 7800.0;
  const std::vector<Vec3> x = {{-a / 2, -a / 2, 0.0}, {a / 2, -a / 2, 0.0}, {a / 2, a / 2, 0.0}, {-a / 2, a / 2, 0.0},
                               {0.0, 0.0, h}};
  MatX K, M;
  Pyramid(x).Compute(K, M);
  const MatX R = RigidModes(x, 3);
  const Mat6 mr = R.transpose() * M * R;
  const double m = rho * a * a * h / 3.0;
  EXPECT_NEAR(mr(0, 0), m, 1e-12 * m);
  const double zc = -mr(1, 3) / m;  // y translation against rotation about x: -int rho z dV
  EXPECT_NEAR(zc, h / 4.0, 1e-12 * h);
  EXPECT_NEAR(mr(5, 5), m * a * a / 10.0, 1e-12 * m * a * a);
  const double transverse = mr(3, 3) - m * zc * zc;  // parallel axes to the centre
  EXPECT_NEAR(transverse, m * (a * a / 20.0 + 3.0 * h * h / 80.0), 1e-12 * m * h * h);
}

// 2 x 2 x 2 cells, the inner grid node and the cell centres moved; each cell
// split into six pyramids, one per face (the face turned to see the centre
// on its left-hand side), apex at the cell centre
struct PyramidPatch {
  std::vector<Vec3> x;
  std::vector<std::vector<int>> elements;
  std::vector<bool> interior;
};

PyramidPatch MakePyramidPatch() {
  PyramidPatch p;
  auto grid = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        Vec3 q(0.5 * i, 0.4 * j, 0.6 * k);
        const bool inner = i == 1 && j == 1 && k == 1;
        if (inner) q += Vec3(0.06, -0.05, 0.07);
        p.x.push_back(q);
        p.interior.push_back(inner);
      }
  // hexahedron faces in Abaqus's S1..S6 order: their right-hand normals point into the cell
  const int faces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const int hex[8] = {grid(i, j, k),         grid(i + 1, j, k),         grid(i + 1, j + 1, k),
                            grid(i, j + 1, k),     grid(i, j, k + 1),         grid(i + 1, j, k + 1),
                            grid(i + 1, j + 1, k + 1), grid(i, j + 1, k + 1)};
        Vec3 centre = Vec3::Zero();
        for (int n : hex) centre += p.x[n] / 8.0;
        centre += Vec3(0.02 * (i - 0.5), -0.03 * (j - 0.5), 0.025 * (k - 0.5));
        p.x.push_back(centre);
        p.interior.push_back(true);
        const int apex = static_cast<int>(p.x.size()) - 1;
        for (const auto& f : faces) p.elements.push_back({hex[f[0]], hex[f[1]], hex[f[2]], hex[f[3]], apex});
      }
  return p;
}

TEST(PyramidElement, PatchTestOnADistortedBox) {
  const PyramidPatch p = MakePyramidPatch();
  ASSERT_EQ(p.elements.size(), 48u);
  const auto stiffness = [](const std::vector<Vec3>& xe) {
    MatX ke, me;
    Pyramid(xe).Compute(ke, me);
    return ke;
  };
  EXPECT_LT(testing::PatchTestError(p.x, p.elements, p.interior, stiffness), 1e-12);
  // and the test can fail: a quadratic field is not reproduced
  EXPECT_GT(testing::PatchTestError(p.x, p.elements, p.interior, stiffness, true), 1e-8);
}

// linear field u = u0 + A x: stress D eps(A) at the centre and the corners;
// under the stress S of that field, v^T KG v = V tr(B S B^T) for v = B x
TEST(PyramidElement, StressAndGeometricStiffnessOfAHomogeneousField) {
  const std::vector<Vec3> x = Place(ObliquePyramid(), RandomRotation(2), Vec3(0.1, 0.2, 0.3));
  const double v = (x[1] - x[0]).cross(x[3] - x[0]).dot(x[4] - x[0]) / 3.0;
  Eigen::Matrix3d A, B;
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 6.0e-4, 1.5e-3;
  B << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.15, -0.3;
  const Pyramid w(x);
  const ElementTraits& t = Traits(kPyramid5);
  Eigen::VectorXd u(15), vb(15);
  for (int i = 0; i < 5; ++i) {
    u.segment<3>(3 * i) = Vec3(1e-3, 2e-3, -1e-3) + A * x[i];
    vb.segment<3>(3 * i) = B * x[i];
  }
  const Eigen::Matrix3d eps = 0.5 * (A + A.transpose());
  Eigen::Matrix<double, 6, 1> strain;
  strain << eps(0, 0), eps(1, 1), eps(2, 2), 2 * eps(0, 1), 2 * eps(1, 2), 2 * eps(2, 0);
  solid::SolidData sd;
  sd.E = w.material.E;
  sd.nu = w.material.nu;
  const Eigen::Matrix<double, 6, 1> sigma = solid::ElasticityMatrix(sd) * strain;
  MatX S, C;
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  t.stress(w.Input(), S, axes);
  EXPECT_LT((S * u - sigma).norm(), 1e-10 * sigma.norm());
  t.corner_stress(w.Input(), C);
  ASSERT_EQ(C.rows(), 30);
  for (int c = 0; c < 5; ++c) EXPECT_LT((C.middleRows(6 * c, 6) * u - sigma).norm(), 1e-10 * sigma.norm()) << c;
  MatX KG;
  t.geometric_stiffness(w.Input(), u, KG, nullptr);
  Eigen::Matrix3d st;
  st << sigma(0), sigma(3), sigma(5), sigma(3), sigma(1), sigma(4), sigma(5), sigma(4), sigma(2);
  const double ref = v * (B * st * B.transpose()).trace();
  EXPECT_NEAR(vb.dot(KG * vb), ref, 1e-10 * std::abs(ref));
  EXPECT_LT((KG * RigidModes(x, 3).leftCols(3)).norm(), 1e-10 * KG.norm());
}

TEST(PyramidElement, InvertedAndFlatElementsAreInputErrors) {
  std::vector<Vec3> x = ObliquePyramid();
  std::swap(x[1], x[3]);  // the base turned: the apex below it
  MatX K, M;
  testing::ExpectInputErrorWith([&] { Pyramid(x).Compute(K, M); }, {"part.bdf:40", "5-node pyramid 7", "inverted"});
  std::vector<Vec3> flat = ObliquePyramid();
  flat[4] = 0.5 * (flat[0] + flat[2]);  // the apex in the base plane
  testing::ExpectInputErrorWith([&] { Pyramid(flat).Compute(K, M); }, {"5-node pyramid 7", "element"});
}

}  // namespace solid_pyramid_test
}  // namespace flexmb::fe
