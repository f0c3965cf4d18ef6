// A closed loop with a redundant equation that turns as a whole: a crane's
// luffing loop (boom on a foot pin, cylinder barrel on a base pin, rod on a
// prismatic joint in the barrel, rod eye on a ball joint at the boom) on a
// platform slewing by 90 degrees about world z and stopping there. The loop is planar, so one
// of its equations is redundant (the ball joint's lateral one) and is removed
// at the start. Its equations must keep that row redundant at every slewing
// angle (they are stated along the axes of marker i, lower_pair.h); stated in
// world axes, the removed row turned into an essential one at 90 degrees and
// the run stopped there with Newton diverging (as the example crane with a
// rigid boom did at t = 19.76 s).
// References: the loop's geometry is rigid under the held cylinder length, so
// the boom's elevation angle and the eye's position in the platform's axes
// stay at their initial values (kinematics), and the ball joint's origins
// coincide (1e-9 m); docs/validation.md, "Closed loops turning as a whole".
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/simulator.h"

namespace flexmb {
namespace {

// slew: 90 degrees in 3 s (smooth start and stop), then held; the cylinder held; gravity on
const char* kLuffingLoop =
    "name: luffing_loop\n"
    "gravity: [0, 0, -9.81]\n"
    "bodies:\n"
    "  - {name: platform, mass: 5000, inertia: [4000, 6000, 8000],\n"
    "     markers: [{name: slew}, {name: foot, position: [1.0, 0, 1.2], orientation: {z_axis: [0, 1, 0]}},\n"
    "               {name: base, position: [1.6, 0, 0.3], orientation: {z_axis: [0, 1, 0]}}]}\n"
    "  - name: boom\n"
    "    mass: 2000\n"
    "    center_of_mass: [8, 0, 0]\n"
    "    inertia: [200, 50000, 50000]\n"
    "    position: [1.0, 0, 1.2]\n"
    "    orientation: {roll_pitch_yaw_deg: [0, -40, 0]}\n"
    "    markers: [{name: foot, orientation: {z_axis: [0, 1, 0]}}, {name: eye, position: [4.0, 0, -0.5]}]\n"
    "  - name: barrel\n"
    "    mass: 300\n"
    "    inertia: [5, 150, 150]\n"
    "    position: [1.6, 0, 0.3]\n"
    "    orientation: {roll_pitch_yaw_deg: [0, PITCH, 0]}\n"
    "    markers: [{name: base, orientation: {z_axis: [0, 1, 0]}}, {name: axis, orientation: {z_axis: [1, 0, 0]}}]\n"
    "  - name: rod\n"
    "    mass: 100\n"
    "    inertia: [1, 60, 60]\n"
    "    position: [1.6, 0, 0.3]\n"
    "    orientation: {roll_pitch_yaw_deg: [0, PITCH, 0]}\n"
    "    markers: [{name: axis, orientation: {z_axis: [1, 0, 0]}}, {name: eye, position: [LENGTH, 0, 0]}]\n"
    "joints:\n"
    "  - {name: slewing_ring, type: revolute, i: ground.origin, j: platform.slew}\n"
    "  - {name: foot_pin, type: revolute, i: platform.foot, j: boom.foot}\n"
    "  - {name: cylinder_base, type: revolute, i: platform.base, j: barrel.base}\n"
    "  - {name: cylinder_stroke, type: prismatic, i: barrel.axis, j: rod.axis}\n"
    "  - {name: cylinder_eye, type: spherical, i: rod.eye, j: boom.eye}\n"
    "ground:\n"
    "  markers: [{name: origin}]\n"
    "drivers:\n"
    "  - {name: luffing, joint: cylinder_stroke, function: 0}\n"
    "  - name: slew\n"
    "    joint: slewing_ring\n"
    "    function: {expression: \"t < 3 ? pi/2 * (t/3 - sin(2*pi*t/3)/(2*pi)) : pi/2\"}\n"
    "solver: {t_end: 5.0, dt: 0.01}\n";

TEST(ClosedLoopRotation, RedundantLuffingLoopSlewsByNinetyDegreesAndStops) {
  // the rod's eye on the boom's eye: the base pin (1.6, 0.3) to the eye at
  // 40 degrees, rotated from the boom frame (4.0, -0.5)
  const double a = 40.0 * std::numbers::pi / 180.0;
  const double ex = 1.0 + 4.0 * std::cos(a) + 0.5 * std::sin(a), ez = 1.2 + 4.0 * std::sin(a) - 0.5 * std::cos(a);
  const double length = std::hypot(ex - 1.6, ez - 0.3);
  const double pitch_deg = -std::atan2(ez - 0.3, ex - 1.6) * 180.0 / std::numbers::pi;
  auto exact = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.15g", x);
    return std::string(buf);
  };
  std::string text = kLuffingLoop;
  text.replace(text.find("LENGTH"), 6, exact(length));
  for (int k = 0; k < 2; ++k) text.replace(text.find("PITCH"), 5, exact(pitch_deg));
  auto model = LoadModelString(text, "luffing_loop.yaml");
  Simulator sim(*model);
  const ConstraintReport& rep = sim.Initialize();
  ASSERT_EQ(rep.redundant.size(), 1u);
  EXPECT_EQ(rep.dof, 0);
  const int platform = model->FindMarker("platform.slew"), boom_eye = model->FindMarker("boom.eye"),
            rod_eye = model->FindMarker("rod.eye");
  ASSERT_GE(platform, 0);
  double max_gap = 0.0, max_eye_shift = 0.0, last_t = 0.0;
  Vec3 eye0_P = Vec3::Zero();
  bool first = true;
  sim.Run(5.0, 0.05, [&](const State& s, const Workspace& ws) {
    const MarkerState& P = ws.markers[platform];
    const Vec3 eye_P = P.R_WM.transpose() * (ws.markers[boom_eye].p_WM - P.p_WM);
    if (first) eye0_P = eye_P, first = false;
    max_eye_shift = std::max(max_eye_shift, (eye_P - eye0_P).norm());
    max_gap = std::max(max_gap, (ws.markers[rod_eye].p_WM - ws.markers[boom_eye].p_WM).norm());
    last_t = s.t;
  });
  EXPECT_NEAR(last_t, 5.0, 1e-9);
  EXPECT_LT(max_gap, 1e-9);
  EXPECT_LT(max_eye_shift, 1e-9);
  EXPECT_NEAR((eye0_P - Vec3(ex, 0.0, ez)).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace flexmb
