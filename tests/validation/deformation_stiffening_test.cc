// Validation of the stiffening of a reduced flexible body by its own
// deformation (reduction/deformation_stiffness.h; docs/validation.md,
// "Flexible bodies: stiffening by the body's own deformation"): a steel
// cantilever column (beam elements) reduced by Craig-Bampton with its root
// and tip as interface, clamped at the root by a fixed joint, loaded at the
// tip by an axial force P (world-fixed direction) and a small lateral force
// H, solved by statics. The classical beam-column solution (Timoshenko and
// Gere, Theory of Elastic Stability, 2nd ed., 1961, section 1.7; second
// order, small lateral deflection) gives the tip deflection
//
//   compression: delta = H (tan(kL) - kL) / (k^3 EI),
//   tension:     delta = H (kL - tanh(kL)) / (k^3 EI),   k = sqrt(|P| / EI),
//
// against H L^3 / (3 EI) without the axial force. At |P| = 0.3 and 0.6 of
// the Euler load pi^2 EI / (4 L^2) the amplification is 1.41 and 2.41 in
// compression, 0.77 and 0.63 in tension. Without the deformation stiffness
// the body gives the linear deflection at P = 0 but not the beam-column
// one under P: its floating frame turns with the beam's mean rotation, and
// the world-fixed P acting through that exact rotation gives the P-delta
// of the chord (x1.33 of linear at -0.3 P_Euler), not that of the
// curvature relative to the frame, which is what the cubic energy adds
// (the two together are the second-order solution). The test checks both.
// And a transverse load 30 times larger without axial force (tip deflection
// 2 % of the length) must stay linear: a cubic strain energy with its
// back-coupling onto the axial coordinates (foreshortening) but without the
// quartic term made that cantilever 9 % softer, which is why the force is
// -G(w) w alone (docs/design.md, "Stiffening by the body's own deformation").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/forces/point_force.h"
#include "flexmb/joints/fixed.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"
#include "tests/validation/flexible_body_fixture.h"

namespace flexmb {
namespace deformation_stiffening_test {

constexpr int kElements = 20;
constexpr double kLength = 2.0, kRadius = 0.02, kE = 2.1e11, kRho = 7850.0, kLateral = 10.0;

double EI() { return kE * M_PI * std::pow(kRadius, 4) / 4.0; }
double EulerLoad() { return M_PI * M_PI * EI() / (4.0 * kLength * kLength); }

// second-order tip deflection [m]; axial > 0 tension, < 0 compression [N]
double BeamColumn(double axial) {
  const double k = std::sqrt(std::abs(axial) / EI()), kl = k * kLength;
  if (axial < 0) return kLateral * (std::tan(kl) - kl) / (k * k * k * EI());
  return kLateral * (kl - std::tanh(kl)) / (k * k * k * EI());
}

std::shared_ptr<reduction::ReducedBody> Column() {
  const fe::FeModel model = testing::RoundBeamAlongX(kElements, kLength, kRadius, kE, kRho);
  reduction::ReductionOptions o;
  o.interface_nodes = {0, kElements};
  o.normal_modes = 12;
  o.deformation_stiffening = true;
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
}

// static tip deflection along z [m] under the axial force `axial` [N] along
// x and kLateral along z at the tip
double TipDeflection(const std::shared_ptr<reduction::ReducedBody>& reduced, GeometricStiffening mode,
                     double axial, double lateral = kLateral) {
  Model m;
  m.gravity_W = Vec3::Zero();
  FlexibleBodyData d;
  d.reduced = reduced;
  d.deformation_stiffening = mode;
  const int b = m.AddBody(std::make_unique<FlexibleBody>("column", d));
  const int root = m.AddMarker(b, "root", Vec3::Zero(), Mat3::Identity(), 0);
  const int tip = m.AddMarker(b, "tip", Vec3::Zero(), Mat3::Identity(), kElements);
  const int g = m.AddMarker(0, "clamp", Vec3::Zero(), Mat3::Identity());
  m.AddJoint(std::make_unique<FixedJoint>("clamp"), root, g);
  auto c = [](double v) { return std::make_shared<ConstantFunction>(v); };
  m.AddForce(std::make_unique<PointForce>("load", std::array<std::shared_ptr<const ScalarFunction>, 3>{c(axial), c(0.0), c(lateral)},
                                          LoadFrame::kWorld),
             tip, -1);
  m.Finalize();
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  SolveStatics(m, s, ws);
  const Body& body = *m.bodies[b];
  MarkerState ms;
  body.EvaluateMarker(s.q.data() + body.q_offset, s.v.data() + body.v_offset, m.markers[tip], ms);
  return ms.p_WM.z();
}

TEST(DeformationStiffening, BeamColumnTipDeflection) {
  const auto reduced = Column();
  const double linear = kLateral * std::pow(kLength, 3) / (3.0 * EI());
  // no axial force: the linear deflection with and without the stiffening
  EXPECT_NEAR(TipDeflection(reduced, GeometricStiffening::kOff, 0.0) / linear, 1.0, 2e-4);
  EXPECT_NEAR(TipDeflection(reduced, GeometricStiffening::kOn, 0.0) / linear, 1.0, 2e-4);
  // a large transverse load alone: linear to the frame's kinematics
  const double big = TipDeflection(reduced, GeometricStiffening::kOn, 0.0, 30.0 * kLateral);
  std::printf("transverse load alone, tip at %.2f %% of the length: x%.6f of linear\n",
              100.0 * big / kLength, big / (30.0 * linear));
  EXPECT_NEAR(big / (30.0 * linear), 1.0, 1e-3);
  // under P without it: only the frame's part, far from the beam column
  const double off = TipDeflection(reduced, GeometricStiffening::kOff, -0.3 * EulerLoad());
  std::printf("beam-column without the deformation stiffness, P = -0.3 P_Euler: x%.4f of linear\n", off / linear);
  EXPECT_GT(off / linear, 1.05);
  EXPECT_LT(off / BeamColumn(-0.3 * EulerLoad()), 0.95);
  for (double f : {-0.6, -0.3, 0.3, 0.6}) {
    const double P = f * EulerLoad();
    const double ref = BeamColumn(P), got = TipDeflection(reduced, GeometricStiffening::kOn, P);
    std::printf("beam-column, %d modes, P = %+.1f P_Euler: tip %.6e m, Timoshenko %.6e m (x%.4f of linear), "
                "error %+.2e\n",
                reduced->invariants.n, f, got, ref, ref / linear, got / ref - 1.0);
    EXPECT_NEAR(got / ref, 1.0, 5e-4) << "P = " << f << " P_Euler";
  }
}

}  // namespace deformation_stiffening_test
}  // namespace flexmb
