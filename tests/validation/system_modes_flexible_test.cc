// Validation of the linearized modes (solver/linearization.h,
// solver/system_modes.h) of a floating-frame flexible body: alone and free,
// the system's modes are six rigid-body modes and the body's Craig-Bampton
// free-free frequencies; clamped to the ground at its interface node, they
// are the fixed-interface frequencies, i.e. those of the FE model clamped at
// that node (docs/validation.md, "Linearized modes of the whole machine").

#include <gtest/gtest.h>

#include <cstdio>

#include "flexible_body_fixture.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/modal.h"
#include "flexmb/joints/fixed.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/system_modes.h"

namespace flexmb {
namespace system_modes_flexible_test {

using testing::AddFinalizedPosedFlexibleBody;
using testing::Reduced;
using testing::RoundBeamAlongX;

// the modes of m (finalized) at its consistent initial state
std::vector<SystemMode> SystemModesOf(const Model& m) {
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  const LinearizedSystem L = Linearize(m, s, VecX::Zero(m.nv), ws);
  return SolveSystemModes(L);
}

TEST(SystemModesFlexible, FreeBodyHasItsCraigBamptonFrequencies) {
  // steel beam 1 m, radius 1 cm, 10 elements, interface at both ends, 6
  // fixed-interface modes; no gravity
  const auto reduced = Reduced(RoundBeamAlongX(10, 1.0, 0.01, 2.1e11, 7850.0), {0, 10}, 6);
  Model m;
  m.gravity_W = Vec3::Zero();
  AddFinalizedPosedFlexibleBody(m, "beam", reduced, VecX::Zero(reduced->frequencies_hz.size()));
  const std::vector<SystemMode> modes = SystemModesOf(m);
  const VecX& f = reduced->frequencies_hz;
  ASSERT_EQ(modes.size(), static_cast<size_t>(6 + f.size()));
  for (int k = 0; k < 6; ++k) EXPECT_EQ(modes[k].kind, ModeKind::kRigid) << k;
  for (int k = 0; k < f.size(); ++k) {
    std::printf("free beam mode %d: %.9f Hz, Craig-Bampton %.9f Hz\n", k + 1, modes[6 + k].frequency_hz, f(k));
    EXPECT_EQ(modes[6 + k].kind, ModeKind::kOscillatory);
    EXPECT_NEAR(modes[6 + k].frequency_hz / f(k), 1.0, 1e-8) << k;
  }
}

TEST(SystemModesFlexible, ClampedAtTheInterfaceHasTheFixedInterfaceFrequencies) {
  // interface node 0 only: its static modes are the rigid-body modes, so the
  // basis is the 6 fixed-interface normal modes, which a clamp of node 0
  // leaves alone: the FE model clamped at node 0
  const fe::FeModel fem = RoundBeamAlongX(10, 1.0, 0.01, 2.1e11, 7850.0);
  const auto reduced = Reduced(fem, {0}, 6);
  Model m;
  m.gravity_W = Vec3::Zero();
  FlexibleBodyData d;
  d.reduced = reduced;
  d.p_WB = Vec3(0.5, -1.0, 2.0);
  d.R_WB = ExpSO3(Vec3(0.3, 0.2, -0.4));
  d.w0 = VecX::Zero(reduced->frequencies_hz.size());
  const int b = m.AddBody(std::make_unique<FlexibleBody>("beam", d));
  const int mb = m.AddMarker(b, "root", Vec3::Zero(), Mat3::Identity(), 0);
  const int mg = m.AddMarker(0, "clamp", d.p_WB, d.R_WB);
  m.AddJoint(std::make_unique<FixedJoint>("clamp"), mg, mb);
  m.Finalize();
  const std::vector<SystemMode> modes = SystemModesOf(m);
  fe::AssemblyOptions ao;
  ao.extra_fixed_nodes = {0};
  fe::ModalOptions mo;
  mo.count = 6;
  const VecX ref = fe::SolveModes(fe::Assemble(fem.mesh, ao), mo).frequencies_hz;
  ASSERT_EQ(modes.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    std::printf("clamped beam mode %d: %.9f Hz, FE clamped %.9f Hz\n", k + 1, modes[k].frequency_hz, ref(k));
    EXPECT_NEAR(modes[k].frequency_hz / ref(k), 1.0, 1e-8) << k;
  }
}

}  // namespace system_modes_flexible_test
}  // namespace flexmb
