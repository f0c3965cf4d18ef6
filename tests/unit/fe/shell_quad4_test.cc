// 4-node shell: symmetry, rigid-body modes, exact rigid-body mass, membrane
// and bending patch tests (MacNeal & Harder 1985 five-element patch),
// invariance to node numbering, and errors for degenerate input.

#include <gtest/gtest.h>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "tests/unit/fe/shell_test_util.h"

namespace flexmb::fe {
namespace {

using testing::BendingPatch;
using testing::ExpectInputError;
using testing::ExpectSixRigidModes;
using testing::MembranePatch;
using testing::Patch;
using testing::PlateRigidMass;
using testing::RandomRotation;
using testing::RigidModes;
using testing::ShellFixture;

const std::vector<Eigen::Vector2d> kQuad = {{0.0, 0.0}, {1.3, 0.1}, {1.1, 0.9}, {-0.2, 0.8}};

std::vector<Vec3> Place(const std::vector<Eigen::Vector2d>& p, const Eigen::Matrix3d& R,
                        const Vec3& c0, const std::vector<double>& h = {}) {
  std::vector<Vec3> x;
  for (size_t i = 0; i < p.size(); ++i)
    x.push_back(c0 + R * Vec3(p[i].x(), p[i].y(), h.empty() ? 0.0 : h[i]));
  return x;
}

TEST(ShellQuad4, RigidBodyModesOfRotatedElement) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::Matrix3d R = RandomRotation(seed);
    const Vec3 c0 = Vec3::Random() * 5.0;
    ShellFixture f(ElementType::kQuad4, Place(kQuad, R, c0), 0.02);
    MatX K, M;
    f.Compute(K, M);
    // zero strain energy in the six rigid motions
    const MatX r = RigidModes(f.x);
    EXPECT_LT((K * r).norm(), 1e-12 * K.norm() * r.norm());
    ExpectSixRigidModes(K);
  }
}

TEST(ShellQuad4, RigidBodyModesOfWarpedAndOffsetElement) {
  const Eigen::Matrix3d R = RandomRotation(4);
  ShellFixture f(ElementType::kQuad4, Place(kQuad, R, Vec3(1, 2, 3), {0.03, -0.03, 0.03, -0.03}),
                 0.05);
  f.element.shell_offset = 0.04;
  MatX K, M;
  f.Compute(K, M);
  EXPECT_LT((K * RigidModes(f.x)).norm(), 1e-12 * K.norm() * RigidModes(f.x).norm());
  ExpectSixRigidModes(K);
  // mass is positive definite
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
}

TEST(ShellQuad4, ConsistentMassGivesExactRigidBodyInertia) {
  const Eigen::Matrix3d R = RandomRotation(5);
  const Vec3 c0(0.3, -1.2, 2.0);
  const double t = 0.08, rho = 2700.0, nsm = 3.5, offset = 0.02;
  ShellFixture f(ElementType::kQuad4, Place(kQuad, R, c0), t, 7e10, 0.33, rho, nsm);
  f.element.shell_offset = offset;
  MatX K, M;
  f.Compute(K, M);
  const MatX r = RigidModes(f.x);
  const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(kQuad, R, c0, t, offset, rho, nsm);
  const MatX got = r.transpose() * M * r;
  EXPECT_LT((got - expected).norm(), 1e-12 * expected.norm()) << got << "\n\n" << expected;
  EXPECT_LT((M - M.transpose()).norm(), 1e-14 * M.norm());
}

TEST(ShellQuad4, LumpedMassKeepsMassAndFirstMoment) {
  const Eigen::Matrix3d R = RandomRotation(6);
  const Vec3 c0(0.3, -1.2, 2.0);
  const double t = 0.08, rho = 2700.0, nsm = 3.5;
  ShellFixture f(ElementType::kQuad4, Place(kQuad, R, c0), t, 7e10, 0.33, rho, nsm);
  MatX K, M;
  f.Compute(K, M, MassForm::kLumped);
  // diagonal for a flat element without offset
  EXPECT_LT((M - MatX(M.diagonal().asDiagonal())).norm(), 1e-12 * M.norm());
  const MatX r = RigidModes(f.x);
  const MatX got = r.transpose() * M * r;
  const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(kQuad, R, c0, t, 0.0, rho, nsm);
  EXPECT_LT((got.topRows(3) - expected.topRows(3)).norm(), 1e-12 * expected.norm());
  // rotary inertia rho t^3 / 12 per unit area on every rotation dof
  const double area = 0.5 * ((kQuad[2] - kQuad[0]).x() * (kQuad[3] - kQuad[1]).y() -
                             (kQuad[2] - kQuad[0]).y() * (kQuad[3] - kQuad[1]).x());
  double rot = 0.0;
  for (int i = 0; i < 4; ++i) rot += M(6 * i + 3, 6 * i + 3);
  EXPECT_NEAR(rot, rho * t * t * t / 12.0 * area, 1e-12 * rot);
}

TEST(ShellQuad4, InvariantToCyclicNodeOrder) {
  const Eigen::Matrix3d R = RandomRotation(7);
  const std::vector<Vec3> x = Place(kQuad, R, Vec3(0.5, 0.5, 0.5), {0.01, -0.01, 0.01, -0.01});
  ShellFixture f(ElementType::kQuad4, x, 0.03);
  MatX K, M;
  f.Compute(K, M);
  ShellFixture g(ElementType::kQuad4, {x[1], x[2], x[3], x[0]}, 0.03);
  MatX K2, M2;
  g.Compute(K2, M2);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const int pa = (a + 3) % 4, pb = (b + 3) % 4;
      EXPECT_LT((K.block<6, 6>(6 * a, 6 * b) - K2.block<6, 6>(6 * pa, 6 * pb)).norm(),
                1e-10 * K.norm());
      EXPECT_LT((M.block<6, 6>(6 * a, 6 * b) - M2.block<6, 6>(6 * pa, 6 * pb)).norm(),
                1e-12 * M.norm());
    }
}

TEST(ShellQuad4, MembranePatchTest) { MembranePatch(Patch().quads); }
TEST(ShellQuad4, BendingPatchTest) { BendingPatch(Patch().quads); }

TEST(ShellQuad4, DegenerateInputIsAnInputError) {
  const Eigen::Matrix3d R = RandomRotation(8);
  const Vec3 c0(1, 1, 1);
  ExpectInputError(ShellFixture(ElementType::kQuad4,
                                Place({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, R, c0)),
                   "zero area");
  ExpectInputError(ShellFixture(ElementType::kQuad4,
                                Place({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, R, c0)),
                   "coincident nodes");
  ExpectInputError(ShellFixture(ElementType::kQuad4,
                                Place({{0, 0}, {1, 0}, {0.2, 0.2}, {0, 1}}, R, c0)),
                   "non-convex");
  ExpectInputError(ShellFixture(ElementType::kQuad4,
                                Place({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, R, c0, {0.2, -0.2, 0.2, -0.2})),
                   "warped");
  ExpectInputError(ShellFixture(ElementType::kQuad4, Place(kQuad, R, c0), 0.0), "thickness");
  ExpectInputError(ShellFixture(ElementType::kQuad4, Place(kQuad, R, c0), -0.1), "thickness");
  ShellFixture no_mat(ElementType::kQuad4, Place(kQuad, R, c0));
  MatX K, M;
  ElementInput in = no_mat.Input();
  in.material = nullptr;
  try {
    ShellQuad4Matrices(in, K, M);
    ADD_FAILURE() << "no InputError for a missing material";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plate.bdf:12: 4-node shell 7: missing material"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexmb::fe
