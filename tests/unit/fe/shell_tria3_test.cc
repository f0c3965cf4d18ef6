// 3-node shell: symmetry, rigid-body modes (rotated and offset elements),
// exact rigid-body mass, lumped mass, membrane and bending patch tests
// (MacNeal & Harder 1985 patch, quads split in two), isotropy (invariance
// to node numbering) and errors for degenerate input. The checks themselves
// are in shell_test_util.h, shared with the 4-node shell.

#include "flexmb/fe/elements/shell_tria3.h"

#include <gtest/gtest.h>

#include "tests/unit/fe/shell_test_util.h"

namespace flexmb::fe::testing {
namespace {

const std::vector<Eigen::Vector2d> kTria = {{0.1, -0.2}, {1.3, 0.1}, {0.4, 0.9}};

TEST(ShellTria3, RigidBodyModesOfRotatedElement) {
  for (unsigned seed : {1u, 2u, 3u}) {
    ShellFixture f(ElementType::kTria3, Place(kTria, RandomRotation(seed), Vec3::Random() * 5.0),
                   0.02);
    f.element.shell_offset = seed == 3u ? 0.03 : 0.0;
    ExpectRigidBodyModes(f);
  }
}

TEST(ShellTria3, ConsistentMassGivesExactRigidBodyInertia) {
  ExpectExactRigidBodyMass(ElementType::kTria3, kTria, RandomRotation(5), Vec3(0.3, -1.2, 2.0),
                           -0.03);
}

TEST(ShellTria3, LumpedMassKeepsMassAndFirstMoment) {
  ExpectLumpedMass(ElementType::kTria3, kTria, RandomRotation(6), Vec3(0.3, -1.2, 2.0));
}

// MITC3 is built to be isotropic: renumbering the nodes permutes K only
TEST(ShellTria3, InvariantToNodeOrder) {
  const std::vector<Vec3> x = Place(kTria, RandomRotation(7), Vec3(0.5, 0.5, 0.5));
  for (int shift = 1; shift < 3; ++shift)
    ExpectInvariantToCyclicNodeOrder(ElementType::kTria3, x, shift);
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
  ExpectInputErrorWith([&] { ShellTria3Matrices(in, K, M); },
                       {"plate.bdf:12: 3-node shell 7: missing shell section"});
  ExpectMissingMaterialError(f);
}

}  // namespace
}  // namespace flexmb::fe::testing
