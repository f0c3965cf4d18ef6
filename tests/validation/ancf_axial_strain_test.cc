// Validation of the axial strain measures of the ANCF bodies (model-file
// key axial_strain, docs/validation.md "ANCF axial strain measures"):
// - a bar pulled along its axis to 30 % strain: the tip stretch lambda is
//   the analytic root of EA eps(lambda) deps/dlambda = P for each measure
//   (3D cable and 3D beam with torsion, direct static solver);
// - Mattiasson's elastica (slender, strains < 1e-6) with the Green-Lagrange
//   measure against the published table, and the tip positions of the two
//   measures against each other (they agree to second order in the strain);
// - Berzeri and Shabana's soft pendulum with the Green-Lagrange measure:
//   energy balance, and the two measures against each other (stiffer in
//   tension with Green-Lagrange: it stretches less; the same path when the
//   beam is made 1000 times stiffer, strain ~ 1e-4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/validation/sampled_path.h"
#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/ancf/ancf_beam3d_body.h"
#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/ancf/ancf_statics.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/solver/simulator.h"

namespace flexmb::ancf {
namespace ancf_axial_strain_test {

using flexmb::testing::SampledPathDistance;

constexpr AxialStrainMeasure kEng = AxialStrainMeasure::kEngineering;
constexpr AxialStrainMeasure kGL = AxialStrainMeasure::kGreenLagrange;

const char* MeasureName(AxialStrainMeasure m) { return m == kGL ? "green_lagrange" : "engineering"; }

// stretch lambda of a bar under axial force P = f EA: engineering lambda - 1 = f;
// Green-Lagrange lambda (lambda^2 - 1) / 2 = f, solved by Newton from 1 + f
double AnalyticStretch(AxialStrainMeasure m, double f) {
  if (m == kEng) return 1.0 + f;
  double l = 1.0 + f;
  for (int it = 0; it < 50; ++it) l -= (0.5 * l * (l * l - 1.0) - f) / (0.5 * (3.0 * l * l - 1.0));
  return l;
}

TEST(AncfAxialStrain, BarUnderLargeAxialLoad) {
  const double L = 1.5, f = 0.3;
  for (AxialStrainMeasure m : {kEng, kGL}) {
    const double lambda = AnalyticStretch(m, f);
    // 3D cable along x: node 0 held, slope direction held
    AncfCable3dData c;
    c.length = L;
    c.elements = 3;
    c.section.E = 2.0e7;
    c.section.A = 1e-4;
    c.section.I = 1e-9;
    c.section.rho = 1000.0;
    c.section.axial_strain = m;
    const AncfCable3dBody cable("bar", c);
    VecX q(cable.nq()), v(cable.nv());
    cable.InitialCoordinates(q.data(), v.data());
    VecX load = VecX::Zero(cable.nv());
    load(6 * c.elements) = f * c.section.E * c.section.A;
    SolveAncfStatics(cable, {0, 1, 2, 4, 5}, load, Vec3::Zero(), q);
    // 3D beam: node 0 held with its slope direction and twist
    AncfBeam3dData b;
    b.length = L;
    b.elements = 3;
    b.section.E = 2.0e7;
    b.section.G = 0.8e7;
    b.section.A = 1e-4;
    b.section.Iy = 1e-9;
    b.section.Iz = 2e-9;
    b.section.J = 1.5e-9;
    b.section.rho = 1000.0;
    b.section.axial_strain = m;
    const AncfBeam3dBody beam("bar3d", b);
    VecX qb(beam.nq()), vb(beam.nv());
    beam.InitialCoordinates(qb.data(), vb.data());
    VecX loadb = VecX::Zero(beam.nv());
    loadb(7 * b.elements) = f * b.section.E * b.section.A;
    SolveBodyStatics(beam, L, {0, 1, 2, 4, 5, 6}, loadb, Vec3::Zero(), qb);
    std::printf("bar, %s, P = %.1f EA: analytic lambda %.12f, cable %.12f, beam3d %.12f\n", MeasureName(m), f,
                lambda, q(6 * c.elements) / L, qb(7 * b.elements) / L);
    EXPECT_NEAR(q(6 * c.elements), lambda * L, 1e-9 * L) << MeasureName(m);
    EXPECT_NEAR(qb(7 * b.elements), lambda * L, 1e-9 * L) << MeasureName(m);
  }
  // the two differ: engineering 1.3, Green-Lagrange 1.22120 (root of
  // lambda^3 - lambda - 0.6)
  EXPECT_NEAR(AnalyticStretch(kGL, f), 1.22120, 1e-5);
}

// Mattiasson (1981), Table 1 (as in ancf_elastica_test): tip deflection w/L, shortening u/L
constexpr double kElasticaW[10] = {0.30172, 0.49346, 0.60325, 0.66996, 0.71379,
                                   0.74457, 0.76737, 0.78498, 0.79906, 0.81061};
constexpr double kElasticaU[10] = {0.05643, 0.16064, 0.25442, 0.32894, 0.38763,
                                   0.43459, 0.47293, 0.50483, 0.53182, 0.55500};

// tip (w/L, u/L) of the planar cantilever at PL^2/EI = 1..10, section h = L / slender
std::vector<Eigen::Vector2d> ElasticaTips(int elements, AxialStrainMeasure m, double slender) {
  const double L = 2.0, h = L / slender;
  AncfBeam2dData d;
  d.length = L;
  d.elements = elements;
  d.section.E = 2.1e11;
  d.section.A = h * h;
  d.section.I = h * h * h * h / 12.0;
  d.section.rho = 7850.0;
  d.section.axial_strain = m;
  const AncfBeam2dBody beam("cantilever", d);
  const double EI = d.section.E * d.section.I;
  VecX q(beam.nq()), v(beam.nv());
  beam.InitialCoordinates(q.data(), v.data());
  const int tip = NodeCoordinate(elements);
  std::vector<Eigen::Vector2d> tips;
  for (int k = 1; k <= 10; ++k) {
    VecX load = VecX::Zero(beam.nv());
    load(tip + 1) = -k * EI / (L * L);
    AncfStaticsSettings s;
    s.load_steps = 2;
    s.initial_load_factor = (k - 1.0) / k;
    s.tolerance = 1e-12;
    SolveAncfStatics(beam, {0, 1, 3}, load, Vec3::Zero(), q, s);
    tips.emplace_back(-q(tip + 1) / L, 1.0 - q(tip) / L);
  }
  return tips;
}

TEST(AncfAxialStrain, MattiassonElasticaWithBothMeasures) {
  const std::vector<Eigen::Vector2d> gl = ElasticaTips(16, kGL, 1000.0), eng = ElasticaTips(16, kEng, 1000.0);
  double err = 0.0, diff = 0.0;
  for (int k = 0; k < 10; ++k) {
    err = std::max({err, std::abs(gl[k].x() - kElasticaW[k]), std::abs(gl[k].y() - kElasticaU[k])});
    diff = std::max(diff, (gl[k] - eng[k]).norm());
  }
  // a stockier section, h = L / 20 (axial strain up to about 2e-3): the
  // measures differ by O(eps^2), far less than the axial strain's own
  // effect on the tip (the distance from the slender beam's tip, O(eps))
  const std::vector<Eigen::Vector2d> gl20 = ElasticaTips(16, kGL, 20.0), eng20 = ElasticaTips(16, kEng, 20.0);
  double diff20 = 0.0, ext20 = 0.0;
  for (int k = 0; k < 10; ++k) {
    diff20 = std::max(diff20, (gl20[k] - eng20[k]).norm());
    ext20 = std::max(ext20, (eng20[k] - eng[k]).norm());
  }
  std::printf("elastica, 16 elements: Green-Lagrange error %.3e L; |GL - engineering| %.3e L (h = L/1000), "
              "%.3e L (h = L/20, extensibility effect %.3e L)\n",
              err, diff, diff20, ext20);
  EXPECT_LT(err, 2e-5);
  EXPECT_LT(diff, 1e-9);
  EXPECT_LT(diff20, 1e-2 * ext20);
}

std::string AxialPendulumModel(AxialStrainMeasure m, double E, int elements, double dt) {
  return "name: ancf_pendulum\n"
         "gravity: [0, -9.81, 0]\n"
         "ground:\n"
         "  markers:\n"
         "    - {name: pivot, position: [0, 0, 0]}\n"
         "bodies:\n"
         "  - name: beam\n"
         "    type: ancf_beam\n"
         "    length: 1.2\n"
         "    elements: " + std::to_string(elements) + "\n"
         "    section: {area: 0.0018, inertia: 1.215e-8}\n"
         "    material: {E: " + std::to_string(E) + ", rho: 5540}\n"
         "    axial_strain: " + MeasureName(m) + "\n"
         "    markers:\n"
         "      - {name: pin, end: start}\n"
         "joints:\n"
         "  - {name: pin, type: revolute, i: ground.pivot, j: beam.pin}\n"
         "solver: {t_end: 1.0, dt: " + std::to_string(dt) + ", rho_inf: 0.95}\n";
}

struct AxialPendulumRun {
  double max_drift = 0.0;    // largest |E(t) - E0| / (m g L)
  double max_stretch = 0.0;  // largest distance pivot-tip / L
  double min_tip_y = 0.0;    // lowest tip position [m]
  std::vector<Vec3> path;    // tip every 4 ms
};

AxialPendulumRun SimulateAxialPendulum(AxialStrainMeasure m, double E, int elements, double dt, double t_end) {
  auto model = LoadModelString(AxialPendulumModel(m, E, elements, dt), "ancf_pendulum.yaml");
  const auto& beam = dynamic_cast<const AncfBeam2dBody&>(*model->bodies[model->FindBody("beam")]);
  EXPECT_EQ(beam.element().section().axial_strain, m);
  Simulator sim(*model);
  sim.Initialize();
  const double mgL = 5540.0 * 0.0018 * 1.2 * 9.81 * 1.2;
  auto energy = [&](const State& s) {
    const double* q = s.q.data() + beam.q_offset;
    const double* v = s.v.data() + beam.v_offset;
    return beam.KineticEnergy(q, v) + beam.GravityPotential(q, model->gravity_W) + beam.StrainEnergy(q);
  };
  const double e0 = energy(sim.state());
  AxialPendulumRun r;
  r.path.assign(static_cast<size_t>(std::lround(t_end / 4e-3)) + 1, Vec3::Constant(NAN));
  sim.Run(t_end, 0.0, [&](const State& s, const Workspace&) {
    r.max_drift = std::max(r.max_drift, std::abs(energy(s) - e0) / mgL);
    const Vec3 tip = beam.PositionAt(s.q.data() + beam.q_offset, 1.2);
    r.max_stretch = std::max(r.max_stretch, tip.norm() / 1.2);
    r.min_tip_y = std::min(r.min_tip_y, tip.y());
    const long k = std::lround(s.t / 4e-3);
    if (k < static_cast<long>(r.path.size()) && std::abs(s.t - k * 4e-3) < 1e-3 * dt) r.path[k] = tip;
  });
  return r;
}

TEST(AncfAxialStrain, SoftPendulumGreenLagrange) {
  const AxialPendulumRun coarse = SimulateAxialPendulum(kGL, 0.7e6, 4, 2e-3, 1.0);
  const AxialPendulumRun fine = SimulateAxialPendulum(kGL, 0.7e6, 4, 1e-3, 1.0);
  const AxialPendulumRun eng = SimulateAxialPendulum(kEng, 0.7e6, 4, 1e-3, 1.0);
  std::printf("soft pendulum, Green-Lagrange: energy drift / (m g L) dt 2e-3 %.3e, dt 1e-3 %.3e; lowest tip "
              "%.4f m; stretch %.4f (engineering: %.4f, lowest tip %.4f m)\n",
              coarse.max_drift, fine.max_drift, fine.min_tip_y, fine.max_stretch, eng.max_stretch, eng.min_tip_y);
  // tip at t = 0.5 s and 1.0 s (samples every 4 ms), reported for comparison with published plots
  std::printf("tip at t = 0.5 s / 1.0 s, 4 elements, dt 1e-3: Green-Lagrange (%.4f, %.4f) / (%.4f, %.4f) m, "
              "engineering (%.4f, %.4f) / (%.4f, %.4f) m\n",
              fine.path[125].x(), fine.path[125].y(), fine.path[250].x(), fine.path[250].y(), eng.path[125].x(),
              eng.path[125].y(), eng.path[250].x(), eng.path[250].y());
  // it falls, swings through and stretches
  EXPECT_LT(fine.min_tip_y, -1.0);
  EXPECT_GT(fine.max_stretch, 1.03);
  // energy: constant to the integrator's dissipation, falling with dt
  EXPECT_LT(fine.max_drift, 1e-4);
  EXPECT_GT(coarse.max_drift / fine.max_drift, 3.0);
  // the Green-Lagrange tension is lambda (lambda + 1) / 2 > 1 times the
  // engineering one at the same stretch: the beam stretches less
  EXPECT_LT(fine.max_stretch - 1.0, 0.97 * (eng.max_stretch - 1.0));
}

// The soft pendulum against an independent discrete model of the same
// extensible elastica (scripts/soft_pendulum_chain.py: point masses on
// axial springs with the same strain measure and discrete bending springs,
// velocity Verlet; Green-Lagrange 800 segments at 1e-5 s, engineering 400 at
// 2e-5 s): the tip at t = 0.3, 0.5 and 0.7 s with 64 elements and dt = 1e-3
// s. Measured: Green-Lagrange 1.8e-4 m, engineering 1.8e-4 m at most; the
// chain converges at second order (3.7e-4 m from 200 to 400 segments,
// 9e-5 m from 400 to 800); bound 1e-3 m. The two measures' paths differ by 3e-2 m at
// t = 0.5 s, so either run compared with the other's reference fails.
TEST(AncfAxialStrain, SoftPendulumAgainstADiscreteChainModel) {
  struct Reference {
    AxialStrainMeasure measure;
    Vec3 tip[3];  // t = 0.3, 0.5, 0.7 s
  };
  const Reference refs[] = {
      {kGL, {Vec3(1.07428, -0.44127, 0), Vec3(0.36445, -1.21502, 0), Vec3(-0.69925, -0.99937, 0)}},
      {kEng, {Vec3(1.07874, -0.44127, 0), Vec3(0.39498, -1.21524, 0), Vec3(-0.68720, -1.09480, 0)}},
  };
  for (const Reference& ref : refs) {
    const AxialPendulumRun run = SimulateAxialPendulum(ref.measure, 0.7e6, 64, 1e-3, 0.7);
    const size_t at[3] = {75, 125, 175};  // samples every 4 ms
    for (int k = 0; k < 3; ++k) {
      const double d = (run.path[at[k]] - ref.tip[k]).norm();
      std::printf("soft pendulum %s, t = %.1f s: tip (%.5f, %.5f) m, chain (%.5f, %.5f) m, distance %.2e m\n",
                  MeasureName(ref.measure), 0.3 + 0.2 * k, run.path[at[k]].x(), run.path[at[k]].y(),
                  ref.tip[k].x(), ref.tip[k].y(), d);
      EXPECT_LT(d, 1e-3) << MeasureName(ref.measure) << " t = " << 0.3 + 0.2 * k;
    }
  }
}

TEST(AncfAxialStrain, PendulumMeasuresAgreeAtSmallStrain) {
  // 1000 times stiffer (E = 0.7 GPa, axial strain ~ 1e-4): the paths agree
  // to second order in the strain; the soft pendulum's paths differ at first
  const double t_end = 0.4;
  const AxialPendulumRun gl = SimulateAxialPendulum(kGL, 0.7e9, 8, 1e-3, t_end);
  const AxialPendulumRun eng = SimulateAxialPendulum(kEng, 0.7e9, 8, 1e-3, t_end);
  const AxialPendulumRun gl_soft = SimulateAxialPendulum(kGL, 0.7e6, 8, 1e-3, t_end);
  const AxialPendulumRun eng_soft = SimulateAxialPendulum(kEng, 0.7e6, 8, 1e-3, t_end);
  const double d_stiff = SampledPathDistance(gl.path, eng.path), d_soft = SampledPathDistance(gl_soft.path, eng_soft.path);
  std::printf("pendulum tip paths, t <= %.1f s, |GL - engineering|: E = 0.7 GPa %.3e m (stretch %.2e), "
              "E = 0.7 MPa %.3e m (stretch %.2e)\n",
              t_end, d_stiff, gl.max_stretch - 1.0, d_soft, gl_soft.max_stretch - 1.0);
  EXPECT_LT(d_stiff, 1e-3 * d_soft);
  EXPECT_GT(d_soft, 1e-3);
}

}  // namespace ancf_axial_strain_test
}  // namespace flexmb::ancf
