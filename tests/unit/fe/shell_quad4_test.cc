// 4-node shell: symmetry, rigid-body modes (rotated, warped and offset
// elements), exact rigid-body mass, lumped mass, membrane and bending patch
// tests (MacNeal & Harder 1985 five-element patch), invariance to node
// numbering, and errors for degenerate input. The checks themselves are in
// shell_test_util.h, shared with the 3-node shell.

#include "flexmb/fe/elements/shell_quad4.h"

#include <gtest/gtest.h>

#include "tests/unit/fe/shell_test_util.h"

namespace flexmb::fe::testing {
namespace {

const std::vector<Eigen::Vector2d> kQuad = {{0.0, 0.0}, {1.3, 0.1}, {1.1, 0.9}, {-0.2, 0.8}};

TEST(ShellQuad4, RigidBodyModesOfRotatedElement) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::Matrix3d R = RandomRotation(seed);
    ExpectRigidBodyModes(
        ShellFixture(ElementType::kQuad4, Place(kQuad, R, Vec3::Random() * 5.0), 0.02));
  }
}

TEST(ShellQuad4, RigidBodyModesOfWarpedAndOffsetElement) {
  const Eigen::Matrix3d R = RandomRotation(4);
  ShellFixture f(ElementType::kQuad4, Place(kQuad, R, Vec3(1, 2, 3), {0.03, -0.03, 0.03, -0.03}),
                 0.05);
  f.element.shell_offset = 0.04;
  ExpectRigidBodyModes(f);
}

TEST(ShellQuad4, ConsistentMassGivesExactRigidBodyInertia) {
  ExpectExactRigidBodyMass(ElementType::kQuad4, kQuad, RandomRotation(5), Vec3(0.3, -1.2, 2.0),
                           0.02);
}

TEST(ShellQuad4, LumpedMassKeepsMassAndFirstMoment) {
  ExpectLumpedMass(ElementType::kQuad4, kQuad, RandomRotation(6), Vec3(0.3, -1.2, 2.0));
}

TEST(ShellQuad4, InvariantToCyclicNodeOrder) {
  const Eigen::Matrix3d R = RandomRotation(7);
  ExpectInvariantToCyclicNodeOrder(
      ElementType::kQuad4, Place(kQuad, R, Vec3(0.5, 0.5, 0.5), {0.01, -0.01, 0.01, -0.01}), 1);
}

TEST(ShellQuad4, MembranePatchTest) { MembranePatch(Patch().quads); }
TEST(ShellQuad4, BendingPatchTest) { BendingPatch(Patch().quads); }

TEST(ShellQuad4, DegenerateInputIsAnInputError) {
  const Eigen::Matrix3d R = RandomRotation(8);
  const Vec3 c0(1, 1, 1);
  ExpectInputError(
      ShellFixture(ElementType::kQuad4, Place({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, R, c0)),
      "zero area");
  ExpectInputError(
      ShellFixture(ElementType::kQuad4, Place({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, R, c0)),
      "coincident nodes");
  ExpectInputError(
      ShellFixture(ElementType::kQuad4, Place({{0, 0}, {1, 0}, {0.2, 0.2}, {0, 1}}, R, c0)),
      "non-convex");
  ExpectInputError(ShellFixture(ElementType::kQuad4, Place({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, R, c0,
                                                           {0.2, -0.2, 0.2, -0.2})),
                   "warped");
  ExpectInputError(ShellFixture(ElementType::kQuad4, Place(kQuad, R, c0), 0.0), "thickness");
  ExpectInputError(ShellFixture(ElementType::kQuad4, Place(kQuad, R, c0), -0.1), "thickness");
  ExpectMissingMaterialError(ShellFixture(ElementType::kQuad4, Place(kQuad, R, c0)));
}

}  // namespace
}  // namespace flexmb::fe::testing
