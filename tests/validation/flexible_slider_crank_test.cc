// Flexible slider-crank (issue 5) with Simeon's parameters: a rigid crank of
// 0.15 m turned at a constant 150 rad/s, an elastic steel connecting rod of
// 0.30 m (round, d = 6 mm, E = 200 GPa, rho = 7870 kg/m^3), a slider on a
// prismatic joint, no gravity, started from the rigid motion at crank angle
// 0 (consistent rigid velocities, no deformation). The rod is a beam FE
// model reduced by Craig-Bampton with its two end nodes as interface
// (floating frame of reference), and, as an independent peer model in our
// own code, a planar ANCF beam (flexmb/ancf, absolute nodal coordinates,
// geometrically exact). The quantity is the transverse deflection of the
// rod's midpoint from the chord of its ends. The test shows convergence in
// the FE mesh and in the number of fixed-interface modes, and agreement of
// the two formulations; docs/validation.md "Flexible slider-crank (issue 5)"
// compares the amplitude with Simeon's published figure.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/solver/simulator.h"
#include "tests/validation/flexible_body_fixture.h"

namespace flexmb {
namespace flexible_slider_crank_test {

constexpr double kCrank = 0.15, kRod = 0.30, kD = 0.006, kE = 2.0e11, kRho = 7870.0, kOmega = 150.0;
constexpr double kSliderMass = 0.076;  // [kg] (see docs/validation.md)
constexpr double kH = 1e-4, kEnd = 0.1;
const double kA = M_PI * kD * kD / 4.0, kI = M_PI * std::pow(kD, 4) / 64.0;

// the rod as one of two body types; markers at its ends
struct RodMarkers {
  int a = -1, b = -1;
};

// ground, crank and slider around the rod's end markers; returns nothing,
// the model is finalized by the caller
void AddMechanism(Model& m, const RodMarkers& rod, double omega) {
  m.gravity_W = Vec3::Zero();
  RigidBodyData c;
  c.mass = 0.36;
  c.c_B = Vec3(0.5 * kCrank, 0, 0);
  c.inertia_C = Vec3(1e-5, 0.002727, 0.002727).asDiagonal();
  c.w_WB = Vec3(0, 0, omega);
  const int crank = m.AddBody(std::make_unique<RigidBody>("crank", c));
  RigidBodyData s;
  s.mass = kSliderMass;
  s.inertia_C = 1e-6 * Mat3::Identity();
  s.p_WB = Vec3(kCrank + kRod, 0, 0);
  const int slider = m.AddBody(std::make_unique<RigidBody>("slider", s));
  const Mat3 along_x = ExpSO3(Vec3(0, M_PI / 2, 0));  // z axis along world x
  const int g0 = m.AddMarker(0, "pivot", Vec3::Zero(), Mat3::Identity());
  const int gx = m.AddMarker(0, "guide", Vec3::Zero(), along_x);
  const int c0 = m.AddMarker(crank, "pivot", Vec3::Zero(), Mat3::Identity());
  const int c1 = m.AddMarker(crank, "pin", Vec3(kCrank, 0, 0), Mat3::Identity());
  const int s0 = m.AddMarker(slider, "pin", Vec3::Zero(), Mat3::Identity());
  const int sx = m.AddMarker(slider, "guide", Vec3::Zero(), along_x);
  auto crank_joint = std::make_unique<RevoluteJoint>("crank");
  const Joint* target = crank_joint.get();
  m.AddJoint(std::move(crank_joint), g0, c0);
  m.AddJoint(std::make_unique<MotionDriver>(
                 "drive", target, 0,
                 std::make_shared<TableFunction>(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, omega},
                                                 TableFunction::Interpolation::kLinear, true)),
             g0, c0);
  m.AddJoint(std::make_unique<RevoluteJoint>("crank_rod"), c1, rod.a);
  m.AddJoint(std::make_unique<RevoluteJoint>("rod_slider"), rod.b, s0);
  m.AddJoint(std::make_unique<PrismaticJoint>("guide"), gx, sx);
  m.solver.dt = kH;
  m.solver.rho_inf = 0.9;
}

// transverse distance of m from the chord a-b in the x-y plane [m]
double Deflection(const Vec3& a, const Vec3& b, const Vec3& mid) {
  const Vec3 chord = b - a;
  return chord.cross(mid - a).z() / chord.norm();
}

struct History {
  std::vector<double> d;  // midpoint deflection at every step [m]
  double peak = 0.0;      // max |d| [m]
};

History Record(Simulator& sim, const std::function<double(const State&)>& deflection) {
  History h;
  sim.Run(kEnd, 0.0, [&](const State& s, const Workspace&) {
    h.d.push_back(deflection(s));
    h.peak = std::max(h.peak, std::abs(h.d.back()));
  });
  return h;
}

// rod: FE beam with `elements` elements (even), CB with `normal` modes;
// crank speed omega [rad/s]
History Ffr(int elements, int normal, double omega = kOmega) {
  const fe::FeModel fe_model = testing::RoundBeamAlongX(elements, kRod, 0.5 * kD, kE, kRho);
  const auto reduced = testing::Reduced(fe_model, {0, elements}, normal);
  Model m;
  FlexibleBodyData d;
  d.reduced = reduced;
  d.p_WB = Vec3(kCrank, 0, 0);
  d.v_WB = Vec3(0, omega * kCrank, 0);
  d.w_WB = Vec3(0, 0, -omega * kCrank / kRod);  // rigid motion at crank angle 0
  const int rod = m.AddBody(std::make_unique<FlexibleBody>("rod", d));
  RodMarkers mk;
  mk.a = m.AddMarker(rod, "a", Vec3::Zero(), Mat3::Identity(), 0);
  mk.b = m.AddMarker(rod, "b", Vec3::Zero(), Mat3::Identity(), elements);
  AddMechanism(m, mk, omega);
  m.Finalize();
  const auto& body = static_cast<const FlexibleBody&>(*m.bodies[rod]);
  Simulator sim(m);
  sim.Initialize();
  return Record(sim, [&](const State& s) {
    const double* q = s.q.data() + body.q_offset;
    return Deflection(body.NodePosition(q, 0), body.NodePosition(q, elements),
                      body.NodePosition(q, elements / 2));
  });
}

// rod: planar ANCF beam of `elements` elements; crank speed omega [rad/s]
History Ancf(int elements, double omega = kOmega) {
  ancf::AncfBeam2dData d;
  d.length = kRod;
  d.elements = elements;
  d.section.E = kE;
  d.section.A = kA;
  d.section.I = kI;
  d.section.rho = kRho;
  d.start_W = Vec3(kCrank, 0, 0);
  Model m;
  const int rod = m.AddBody(std::make_unique<ancf::AncfBeam2dBody>("rod", d));
  RodMarkers mk;
  mk.a = m.AddMarker(rod, "a", Vec3::Zero(), Mat3::Identity(), 0);
  mk.b = m.AddMarker(rod, "b", Vec3::Zero(), Mat3::Identity(), elements);
  AddMechanism(m, mk, omega);
  m.Finalize();
  const auto& body = static_cast<const ancf::AncfBeam2dBody&>(*m.bodies[rod]);
  Simulator sim(m);
  // rigid motion at crank angle 0: node velocities v_A + Omega x (s, 0), slopes turning at Omega
  const double Omega = -omega * kCrank / kRod;
  for (int k = 0; k <= elements; ++k) {
    double* v = sim.state().v.data() + body.v_offset + 4 * k;
    v[0] = 0.0, v[1] = omega * kCrank + Omega * kRod * k / elements, v[2] = 0.0, v[3] = Omega;
  }
  sim.Initialize();
  return Record(sim, [&](const State& s) {
    const double* q = s.q.data() + body.q_offset;
    return Deflection(body.PositionAt(q, 0.0), body.PositionAt(q, kRod), body.PositionAt(q, 0.5 * kRod));
  });
}

double MaxDifference(const History& a, const History& b) {
  double d = 0.0;
  for (size_t k = 0; k < std::min(a.d.size(), b.d.size()); ++k) d = std::max(d, std::abs(a.d[k] - b.d[k]));
  return d;
}

TEST(FlexibleSliderCrank, MidpointDeflectionConvergesInMeshAndModes) {
  const History m8 = Ffr(8, 4), m16 = Ffr(16, 4), n8 = Ffr(8, 8);
  const History ancf = Ancf(16);
  ASSERT_EQ(m8.d.size(), ancf.d.size());
  std::printf("flexible slider-crank (Simeon), 150 rad/s, %.2f s, h = %.0e s: peak |midpoint deflection| [mm]\n"
              "  FFR 8/16 elements (4 normal modes): %.4f %.4f; FFR 8 elements, 8 normal modes: %.4f\n"
              "  ANCF 16 elements: %.4f\n"
              "  max |FFR(8,4) - FFR(16,4)| %.4f mm, max |FFR(8,4) - FFR(8,8)| %.4f mm, "
              "max |FFR(16,4) - ANCF(16)| %.4f mm\n",
              kEnd, kH, 1e3 * m8.peak, 1e3 * m16.peak, 1e3 * n8.peak, 1e3 * ancf.peak, 1e3 * MaxDifference(m8, m16),
              1e3 * MaxDifference(m8, n8), 1e3 * MaxDifference(m16, ancf));
  for (size_t k = 0; k < m16.d.size(); k += m16.d.size() / 20)
    std::printf("  t = %.4f s: FFR %.4f mm, ANCF %.4f mm\n", (k + 1) * kH, 1e3 * m16.d[k], 1e3 * ancf.d[k]);
  EXPECT_GT(m16.peak, 1e-3);
  // convergence: a finer mesh and more modes change the history little
  EXPECT_LT(MaxDifference(m8, m16), 0.02 * m16.peak);
  EXPECT_LT(MaxDifference(m8, n8), 0.02 * n8.peak);
}

TEST(FlexibleSliderCrank, MatchesAncfWhenTheAxialForceIsSmall) {
  // at 150 rad/s the slider's inertia compresses the rod with up to ~30 % of
  // its Euler load; the ANCF beam has the axial-bending coupling, the linear
  // FFR rod does not (peaks differ by ~30 %, see docs/validation.md). At
  // 50 rad/s the axial force is 1/9 of that, so the two must agree closely
  const double omega = 50.0;
  const History ffr = Ffr(16, 4, omega), ancf = Ancf(16, omega);
  ASSERT_EQ(ffr.d.size(), ancf.d.size());
  std::printf("slider-crank at %.0f rad/s: peak |midpoint deflection| FFR %.4f mm, ANCF %.4f mm, max difference "
              "%.4f mm\n",
              omega, 1e3 * ffr.peak, 1e3 * ancf.peak, 1e3 * MaxDifference(ffr, ancf));
  EXPECT_GT(ffr.peak, 1e-4);
  EXPECT_NEAR(ancf.peak, ffr.peak, 0.1 * ffr.peak);
  EXPECT_LT(MaxDifference(ffr, ancf), 0.15 * ffr.peak);
}

}  // namespace flexible_slider_crank_test
}  // namespace flexmb
