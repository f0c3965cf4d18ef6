// 3-node shell: symmetry, rigid-body modes, exact rigid-body mass, membrane
// and bending patch tests (MacNeal & Harder 1985 patch, quads split in two),
// isotropy (invariance to node numbering) and errors for degenerate input.

#include <gtest/gtest.h>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/shell_tria3.h"
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

const std::vector<Eigen::Vector2d> kTria = {{0.1, -0.2}, {1.3, 0.1}, {0.4, 0.9}};

std::vector<Vec3> Place(const std::vector<Eigen::Vector2d>& p, const Eigen::Matrix3d& R,
                        const Vec3& c0) {
  std::vector<Vec3> x;
  for (const auto& q : p) x.push_back(c0 + R * Vec3(q.x(), q.y(), 0.0));
  return x;
}

TEST(ShellTria3, RigidBodyModesOfRotatedElement) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::Matrix3d R = RandomRotation(seed);
    ShellFixture f(ElementType::kTria3, Place(kTria, R, Vec3::Random() * 5.0), 0.02);
    f.element.shell_offset = seed == 3u ? 0.03 : 0.0;
    MatX K, M;
    f.Compute(K, M);
    const MatX r = RigidModes(f.x);
    EXPECT_LT((K * r).norm(), 1e-12 * K.norm() * r.norm());
    ExpectSixRigidModes(K);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
  }
}

TEST(ShellTria3, ConsistentMassGivesExactRigidBodyInertia) {
  const Eigen::Matrix3d R = RandomRotation(5);
  const Vec3 c0(0.3, -1.2, 2.0);
  const double t = 0.08, rho = 2700.0, nsm = 3.5, offset = -0.03;
  ShellFixture f(ElementType::kTria3, Place(kTria, R, c0), t, 7e10, 0.33, rho, nsm);
  f.element.shell_offset = offset;
  MatX K, M;
  f.Compute(K, M);
  const MatX r = RigidModes(f.x);
  const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(kTria, R, c0, t, offset, rho, nsm);
  EXPECT_LT((r.transpose() * M * r - expected).norm(), 1e-12 * expected.norm());
}

TEST(ShellTria3, LumpedMassKeepsMassAndFirstMoment) {
  const Eigen::Matrix3d R = RandomRotation(6);
  const Vec3 c0(0.3, -1.2, 2.0);
  const double t = 0.08, rho = 2700.0, nsm = 3.5;
  ShellFixture f(ElementType::kTria3, Place(kTria, R, c0), t, 7e10, 0.33, rho, nsm);
  MatX K, M;
  f.Compute(K, M, MassForm::kLumped);
  EXPECT_LT((M - MatX(M.diagonal().asDiagonal())).norm(), 1e-12 * M.norm());
  const MatX r = RigidModes(f.x);
  const Eigen::Matrix<double, 6, 6> expected = PlateRigidMass(kTria, R, c0, t, 0.0, rho, nsm);
  EXPECT_LT(((r.transpose() * M * r).topRows(3) - expected.topRows(3)).norm(),
            1e-12 * expected.norm());
}

// MITC3 is built to be isotropic: renumbering the nodes permutes K only
TEST(ShellTria3, InvariantToNodeOrder) {
  const std::vector<Vec3> x = Place(kTria, RandomRotation(7), Vec3(0.5, 0.5, 0.5));
  ShellFixture f(ElementType::kTria3, x, 0.05);
  MatX K, M;
  f.Compute(K, M);
  for (int shift = 1; shift < 3; ++shift) {
    ShellFixture g(ElementType::kTria3, {x[shift % 3], x[(shift + 1) % 3], x[(shift + 2) % 3]},
                   0.05);
    MatX K2, M2;
    g.Compute(K2, M2);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const int pa = (a + 3 - shift) % 3, pb = (b + 3 - shift) % 3;
        EXPECT_LT((K.block<6, 6>(6 * a, 6 * b) - K2.block<6, 6>(6 * pa, 6 * pb)).norm(),
                  1e-10 * K.norm());
        EXPECT_LT((M.block<6, 6>(6 * a, 6 * b) - M2.block<6, 6>(6 * pa, 6 * pb)).norm(),
                  1e-12 * M.norm());
      }
  }
}

TEST(ShellTria3, MembranePatchTest) { MembranePatch(Patch().Trias()); }
TEST(ShellTria3, BendingPatchTest) { BendingPatch(Patch().Trias()); }

TEST(ShellTria3, DegenerateInputIsAnInputError) {
  const Eigen::Matrix3d R = RandomRotation(8);
  const Vec3 c0(1, 1, 1);
  ExpectInputError(ShellFixture(ElementType::kTria3, Place({{0, 0}, {1, 0}, {2, 0}}, R, c0)),
                   "zero area");
  ExpectInputError(ShellFixture(ElementType::kTria3, Place({{0, 0}, {1, 0}, {1, 0}}, R, c0)),
                   "coincident nodes");
  ExpectInputError(ShellFixture(ElementType::kTria3, Place(kTria, R, c0), 0.0), "thickness");
  ShellFixture f(ElementType::kTria3, Place(kTria, R, c0));
  ElementInput in = f.Input();
  in.shell = nullptr;
  MatX K, M;
  EXPECT_THROW(ShellTria3Matrices(in, K, M), InputError);
  in = f.Input();
  in.material = nullptr;
  try {
    ShellTria3Matrices(in, K, M);
    ADD_FAILURE() << "no InputError for a missing material";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plate.bdf:12: 3-node shell 7: missing material"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexmb::fe
