// Shell elements as plates and strips, natural frequencies on sequences of
// meshes through flexmb's assembly and modal solver (fe::Assemble,
// fe::SolveModes):
// - simply supported square plate (hard support), four lowest modes,
//   against the exact Mindlin-plate frequencies of the theory the elements
//   discretize (Mindlin 1951) and against Leissa's thin-plate values
//   lambda = omega a^2 sqrt(rho t / D) = 2 pi^2, 5 pi^2, 5 pi^2, 8 pi^2;
// - clamped square plate against Leissa (1969): 35.992, 73.413, 73.413,
//   108.27;
// - cantilever and free-free strips (nu = 0, so the strip is a beam) against
//   the Timoshenko beam with kappa = 5/6 and rotary inertia, three bending
//   modes, whose Euler-Bernoulli limit is checked against Blevins.
// Reference values and sources: docs/validation.md, "FE: shells (obstacle
// course and plates)".

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/validation/fe_beam_theory.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_plate_test {

constexpr double kA = 1.0, kT = 0.01, kE = 2e11, kNu = 0.3, kRho = 7850.0;

// frequency parameter lambda = omega a^2 sqrt(rho t / D) of the square plate
double Lambda(double omega) {
  const double D = kE * kT * kT * kT / (12.0 * (1.0 - kNu * kNu));
  return omega * kA * kA * std::sqrt(kRho * kT / D);
}

// lambda of the lowest `count` modes of the square plate, simply supported
// (w and the tangential rotation fixed on the edges, in-plane rigid motion
// removed at two corners) or clamped
std::vector<double> PlateLambdas(int n, bool triangles, bool clamped, MassForm form, int count) {
  ShellGrid m(
      n, n, [&](double u, double v) { return Vec3(u * kA, v * kA, 0.0); }, kT, kE, kNu, kRho,
      triangles);
  if (clamped) {
    m.Fix([&](int i, int j) { return i == 0 || i == n || j == 0 || j == n; }, {0, 1, 2, 3, 4, 5});
  } else {
    m.Fix([&](int i, int) { return i == 0 || i == n; }, {2, 3});
    m.Fix([&](int, int j) { return j == 0 || j == n; }, {2, 4});
    m.Fix([&](int i, int j) { return i == 0 && j == 0; }, {0, 1});
    m.Fix([&](int i, int j) { return i == n && j == 0; }, {1});
  }
  const ModalResult r = SolveMeshModes(m.mesh, count, form);
  std::vector<double> out;
  for (int k = 0; k < count; ++k) out.push_back(Lambda(2.0 * kPi * r.frequencies_hz[k]));
  return out;
}

// exact Mindlin lambda of the simply supported plate in mode (p, q)
double MindlinLambda(int p, int q) {
  const double G = kE / (2.0 * (1.0 + kNu));
  BeamProperties plate;  // per unit width
  plate.EI = kE * kT * kT * kT / (12.0 * (1.0 - kNu * kNu));
  plate.shear_compliance = 1.0 / (5.0 / 6.0 * G * kT);
  plate.rhoA = kRho * kT;
  plate.rhoI = kRho * kT * kT * kT / 12.0;
  return Lambda(FlexuralOmega(plate, kPi / kA * std::sqrt(double(p * p + q * q))));
}

struct PlateRun {
  const char* name;
  bool triangles;
  MassForm form;
  std::vector<int> meshes;
};

TEST(FePlateValidation, SimplySupportedSquarePlate) {
  const int modes[4][2] = {{1, 1}, {1, 2}, {2, 1}, {2, 2}};
  const double leissa[4] = {2 * kPi * kPi, 5 * kPi * kPi, 5 * kPi * kPi, 8 * kPi * kPi};
  double consistent_error[4] = {0.0, 0.0, 0.0, 0.0};  // quad4, finest mesh
  for (const PlateRun& run :
       {PlateRun{"SS plate quad4", false, MassForm::kConsistent, {4, 8, 16, 32}},
        PlateRun{"SS plate tria3", true, MassForm::kConsistent, {8, 16, 32}},
        PlateRun{"SS plate quad4 lumped", false, MassForm::kLumped, {8, 16, 32}}}) {
    std::vector<std::vector<double>> lambdas;
    for (int n : run.meshes) lambdas.push_back(PlateLambdas(n, run.triangles, false, run.form, 4));
    for (int k = 0; k < 4; ++k) {
      const double mindlin = MindlinLambda(modes[k][0], modes[k][1]);
      Convergence c{
          std::string(run.name) + " mode " + std::to_string(k + 1), run.meshes, {}, mindlin};
      for (const auto& l : lambdas) c.values.push_back(l[k]);
      c.Report();
      std::printf("    reference Mindlin %.6f, Leissa thin plate %.6f\n", mindlin, leissa[k]);
      if (run.form == MassForm::kConsistent) {
        // both elements converge from above at O(h^2) in the frequency; we
        // ask for at least O(h) per halving
        c.ExpectConverges();
        c.ExpectErrorFallsBy(2.0);
        c.ExpectFinestWithinLastChange(1e-9);
      } else {
        // lumped mass: the lumping error (frequency too low) and the
        // stiffness error (too high) are both O(h^2) and of opposite sign,
        // so the sequence need not be monotone; the error must still shrink
        // from the coarsest to the finest mesh and stay below the consistent
        // mass's error on the finest mesh, whose stiffness part it shares
        EXPECT_LT(c.Error(c.values.size() - 1), c.Error(0)) << c.name;
        EXPECT_LT(c.Error(c.values.size() - 1), consistent_error[k]) << c.name;
      }
      if (run.form == MassForm::kConsistent && !run.triangles) {
        consistent_error[k] = c.Error(c.values.size() - 1);
        // against the thin plate: the same bound plus the exact
        // Mindlin-Kirchhoff difference
        Convergence thin = c;
        thin.reference = leissa[k];
        thin.ExpectFinestWithinLastChange(std::abs(mindlin / leissa[k] - 1.0));
      }
    }
  }
}

TEST(FePlateValidation, ClampedSquarePlate) {
  // Leissa 1969, thin plate (Kirchhoff); the Mindlin plate is lower by about
  // the same relative amount as the simply supported plate at the same lambda
  const double leissa[4] = {35.992, 73.413, 73.413, 108.27};
  for (const PlateRun& run :
       {PlateRun{"clamped plate quad4", false, MassForm::kConsistent, {8, 16, 32}},
        PlateRun{"clamped plate tria3", true, MassForm::kConsistent, {8, 16, 32}}}) {
    std::vector<std::vector<double>> lambdas;
    for (int n : run.meshes) lambdas.push_back(PlateLambdas(n, run.triangles, true, run.form, 4));
    for (int k = 0; k < 4; ++k) {
      Convergence c{
          std::string(run.name) + " mode " + std::to_string(k + 1), run.meshes, {}, leissa[k]};
      for (const auto& l : lambdas) c.values.push_back(l[k]);
      c.Report();
      c.ExpectConverges();
      c.ExpectErrorFallsBy(2.0);
      // thin-plate reference: allow the Mindlin-Kirchhoff difference of the
      // simply supported plate at the fundamental's lambda, scaled by lambda
      const double shear =
          std::abs(MindlinLambda(1, 1) / (2 * kPi * kPi) - 1.0) * leissa[k] / (2 * kPi * kPi);
      c.ExpectFinestWithinLastChange(shear);
    }
  }
}

// strip of length 1, width 0.1, thickness 0.01, nu = 0: a beam
constexpr double kL = 1.0, kB = 0.1;

BeamProperties StripBeam() {
  const double G = kE / 2.0;
  BeamProperties p;
  p.EI = kE * kB * kT * kT * kT / 12.0;
  p.shear_compliance = 1.0 / (5.0 / 6.0 * G * kB * kT);
  p.rhoA = kRho * kB * kT;
  p.rhoI = kRho * kB * kT * kT * kT / 12.0;
  p.L = kL;
  return p;
}

// omega [rad/s] of the three lowest out-of-plane bending modes (uz carries
// most of the kinetic energy) of a strip of nl x nw elements
std::vector<double> StripOmegas(int nl, int nw, bool triangles, BeamSupport support) {
  ShellGrid m(
      nl, nw, [&](double u, double v) { return Vec3(u * kL, v * kB, 0.0); }, kT, kE, 0.0, kRho,
      triangles);
  if (support == BeamSupport::kCantilever)
    m.Fix([&](int i, int) { return i == 0; }, {0, 1, 2, 3, 4, 5});
  const int rigid = support == BeamSupport::kFreeFree ? 6 : 0;
  AssembledModel model;
  const ModalResult r = SolveMeshModes(m.mesh, rigid + 8, MassForm::kConsistent, &model);
  std::vector<double> out;
  for (int k = rigid; k < r.frequencies_hz.size() && out.size() < 3; ++k)
    if (DirectionShares(m.mesh, model, r.modes.col(k)).z() > 0.9)
      out.push_back(2.0 * kPi * r.frequencies_hz[k]);
  EXPECT_EQ(out.size(), 3u);
  out.resize(3, 0.0);
  return out;
}

TEST(FePlateValidation, CantileverAndFreeFreeStrips) {
  const BeamProperties p = StripBeam();
  for (BeamSupport support : {BeamSupport::kCantilever, BeamSupport::kFreeFree}) {
    const bool cantilever = support == BeamSupport::kCantilever;
    for (bool triangles : {false, true}) {
      const std::vector<int> meshes = {8, 16, 32};
      std::vector<std::vector<double>> omegas;
      for (int nl : meshes) omegas.push_back(StripOmegas(nl, nl / 8, triangles, support));
      for (int k = 0; k < 3; ++k) {
        const double ref = TimoshenkoOmega(p, support, k + 1);
        const double beta = cantilever ? kCantileverBetaL[k] : kFreeFreeBetaL[k];
        const double eb = beta * beta * std::sqrt(p.EI / (p.rhoA * std::pow(kL, 4)));
        Convergence c{std::string(cantilever ? "cantilever" : "free-free") + " strip " +
                          (triangles ? "tria3" : "quad4") + " mode " + std::to_string(k + 1),
                      meshes,
                      {},
                      ref};
        for (const auto& o : omegas) c.values.push_back(o[k]);
        c.Report();
        std::printf("    reference Timoshenko %.6f rad/s, Euler-Bernoulli %.6f rad/s\n", ref, eb);
        c.ExpectConverges();
        c.ExpectFinestWithinLastChange(1e-9);
      }
    }
  }
}

}  // namespace fe_plate_test
}  // namespace flexmb::fe::validation
