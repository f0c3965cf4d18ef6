// Rotating beam spin-up (Kane, Ryan and Banerjee 1987; Simo and Vu-Quoc
// 1987; issue 5; docs/validation.md, "Rotating beam: geometric
// stiffening"): a 10 m beam clamped to a hub spun up to 6 rad/s in 15 s
// (bench/rotating_beam.h). Its first cantilever bending frequency is
// 3.80 rad/s. The reference is a planar ANCF beam of 20 elements (exact
// nonlinear strains, so the centrifugal stiffening is in it) on the same
// driven hub. Checked, over 0..20 s with dt = 10 ms:
// - frame attached to the root (cantilever modes, the "conventional"
//   linear model): without geometric stiffening the model softens the
//   bending by Om^2 and diverges once the hub turns faster than its first
//   frequency, 3.80 rad/s (at t = 8.5 s): the tip deflection passes 5 m
//   (half the length) or the solver gives up, after that time and before
//   the spin-up ends (15 s); with it the tip deflection follows
//   the ANCF beam within 1 % of its peak (0.57 m);
// - free frame (free-free modes, the reduction's default): the rigid
//   rotation of the frame is exact, so the model stays bounded at 6 rad/s
//   even without stiffening, but is off by more than 10 % of the peak; with
//   stiffening it follows the ANCF beam within 1 % of the peak.
// The full 30 s run and an ANCF mesh study: bench/rotating_beam.cc.
// Command line: `flexmb reduce --geometric-stiffening` stores the matrices
// (a beam model and a shell model); `body info` reports it; `--units`
// records the unit system and refuses an unknown one; a model in mm, t, s
// numbers reduced without it warns.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench/rotating_beam.h"
#include "flexmb/body_file/body_file.h"
#include "tests/validation/cli_runner.h"

namespace flexmb {
namespace rotating_beam_test {

using rotating_beam::Frame;
using rotating_beam::Result;

constexpr double kDt = 0.01, kEnd = 20.0;

const Result& Ancf() {
  static const Result r = rotating_beam::RunAncf(20, kEnd, kDt);
  return r;
}

// max |a - b| over the common samples, and the time of the first |a| > limit (-1: none)
double MaxDiff(const Result& a, const Result& b) {
  double d = 0.0;
  for (size_t k = 0; k < std::min(a.samples.size(), b.samples.size()); ++k)
    d = std::max(d, std::abs(a.samples[k].deflection - b.samples[k].deflection));
  return d;
}

double Peak(const Result& a) {
  double p = 0.0;
  for (const auto& s : a.samples) p = std::max(p, std::abs(s.deflection));
  return p;
}

double FirstBeyond(const Result& a, double limit) {
  for (const auto& s : a.samples) {
    if (std::abs(s.deflection) > limit) return s.t;
  }
  return -1.0;
}

TEST(RotatingBeam, RootAttachedFrameDivergesWithoutStiffeningAndMatchesAncfWithIt) {
  const Result& ancf = Ancf();
  ASSERT_TRUE(ancf.failure.empty()) << ancf.failure;
  const double peak = Peak(ancf);
  const auto reduced = rotating_beam::ReducedBeam(20, 8, Frame::kRootAttached);
  const Result on = rotating_beam::RunFloatingFrame(reduced, true, kEnd, kDt);
  const Result off = rotating_beam::RunFloatingFrame(reduced, false, kEnd, kDt);
  ASSERT_TRUE(on.failure.empty()) << on.failure;
  ASSERT_EQ(on.samples.size(), ancf.samples.size());
  const double diff = MaxDiff(on, ancf);
  const double beyond = FirstBeyond(off, 0.5 * rotating_beam::kL);
  const double end_off = off.samples.empty() ? 0.0 : off.samples.back().t;
  std::printf("root-attached frame, %d cantilever modes: ANCF tip deflection peak %.4f m; with stiffening max "
              "|FFR - ANCF| = %.5f m (%.2f %% of the peak); without: |deflection| > 5 m at t = %.2f s, run %s at "
              "t = %.2f s%s%s\n",
              reduced->invariants.n, peak, diff, 100.0 * diff / peak, beyond,
              off.failure.empty() ? "ended" : "failed", end_off, off.failure.empty() ? "" : ": ",
              off.failure.c_str());
  // the lag is quasi-static (the spin-up is slow against the 1.65 s period):
  // below the static tip deflection under the largest angular acceleration
  // (0.8 rad/s^2 at 7.5 s), 11 rho A alpha L^5 / (120 EI), which the
  // centrifugal stiffening lowers
  const double quasi_static = 11.0 * rotating_beam::kRhoA * 0.8 * std::pow(rotating_beam::kL, 5) /
                              (120.0 * rotating_beam::kEI);
  EXPECT_LT(peak, quasi_static);
  EXPECT_GT(peak, 0.8 * quasi_static);
  EXPECT_LT(diff, 0.01 * peak);
  // unbounded growth: 5 m passed or the solver gave up, before 15 s
  const double diverged = beyond >= 0.0 ? beyond : (off.failure.empty() ? -1.0 : end_off);
  // the time the hub passes the first cantilever frequency (bisection)
  const double omega1 = 2.0 * M_PI * reduced->frequencies_hz[0];
  const rotating_beam::SpinUp theta;
  double lo = 0.0, hi = 15.0;
  for (int k = 0; k < 60; ++k) (theta.Derivative(0.5 * (lo + hi)) < omega1 ? lo : hi) = 0.5 * (lo + hi);
  std::printf("first cantilever frequency %.4f rad/s (Euler-Bernoulli 3.5160 sqrt(EI/(rho A L^4)) = %.4f), "
              "passed at t = %.3f s\n",
              omega1, 3.5160 * std::sqrt(rotating_beam::kEI / (rotating_beam::kRhoA * std::pow(rotating_beam::kL, 4))), lo);
  EXPECT_GT(diverged, lo);
  EXPECT_LT(diverged, 15.0);
}

TEST(RotatingBeam, FreeFrameIsBoundedButWrongWithoutStiffeningAndMatchesAncfWithIt) {
  const Result& ancf = Ancf();
  ASSERT_TRUE(ancf.failure.empty()) << ancf.failure;
  const double peak = Peak(ancf);
  const auto reduced = rotating_beam::ReducedBeam(20, 8, Frame::kFree);
  const Result on = rotating_beam::RunFloatingFrame(reduced, true, kEnd, kDt);
  const Result off = rotating_beam::RunFloatingFrame(reduced, false, kEnd, kDt);
  ASSERT_TRUE(on.failure.empty()) << on.failure;
  ASSERT_TRUE(off.failure.empty()) << off.failure;
  ASSERT_EQ(on.samples.size(), ancf.samples.size());
  const double d_on = MaxDiff(on, ancf), d_off = MaxDiff(off, ancf);
  std::printf("free frame, %d free-free modes: max |FFR - ANCF| with stiffening %.5f m (%.2f %% of the peak), "
              "without %.5f m (%.1f %%), peak without %.4f m\n",
              reduced->invariants.n, d_on, 100.0 * d_on / peak, d_off, 100.0 * d_off / peak, Peak(off));
  EXPECT_LT(d_on, 0.01 * peak);
  EXPECT_GT(d_off, 0.1 * peak);
  EXPECT_LT(Peak(off), 2.0 * peak);
}

class RotatingBeamCli : public testing::CliTest {
 protected:
  RotatingBeamCli() : CliTest("flexmb_gs_cli_") {}
};

TEST_F(RotatingBeamCli, ReduceStoresTheGeometricStiffnessAndBodyInfoShowsIt) {
  std::string bdf = "BEGIN BULK\nMAT1,1,2.1+11,,0.3,7850.\nPBAR,1,1,1.-4,8.3-10,8.3-10,1.4-9\n";
  for (int k = 0; k <= 5; ++k) bdf += "GRID," + std::to_string(k + 1) + ",," + std::to_string(0.2 * k) + ",0.,0.\n";
  for (int k = 1; k <= 5; ++k)
    bdf += "CBAR," + std::to_string(k) + ",1," + std::to_string(k) + "," + std::to_string(k + 1) + ",0.,0.,1.\n";
  bdf += "ENDDATA\n";
  testing::WriteFile(dir_ / "beam.bdf", bdf);
  const testing::CliResult r =
      testing::RunCli(dir_, "reduce beam.bdf --interface 1 --modes 4 --geometric-stiffening -o beam.h5");
  ASSERT_EQ(r.code, 0) << r.err;
  const reduction::ReducedBody body = io::ReadBody((dir_ / "beam.h5").string());
  ASSERT_EQ(body.geometric_stiffness.size(), 6u);
  EXPECT_GT(body.geometric_stiffness[2].norm(), 0.0);
  const testing::CliResult info = testing::RunCli(dir_, "body info beam.h5 --json");
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("\"geometric_stiffening\": true"), std::string::npos) << info.out;
  ASSERT_EQ(testing::RunCli(dir_, "reduce beam.bdf --interface 1 --modes 4 -o plain.h5").code, 0);
  EXPECT_NE(testing::RunCli(dir_, "body info plain.h5").out.find("geometric stiffness: none"), std::string::npos);
  const testing::CliResult shells = testing::RunCli(
      dir_, std::string("reduce ") + FLEXMB_SOURCE_DIR +
                "/tests/data/fe/nastran/cli_strip.bdf --interface 1 --modes 4 --geometric-stiffening -o s.h5");
  // shells have a geometric stiffness too (tests/unit/reduction/shell_solid_geometric_stiffness_test.cc)
  ASSERT_EQ(shells.code, 0) << shells.err;
  EXPECT_EQ(io::ReadBody((dir_ / "s.h5").string()).geometric_stiffness.size(), 6u);
  // --units is recorded; an unknown system is refused naming the known ones
  ASSERT_EQ(testing::RunCli(dir_, "reduce beam.bdf --interface 1 --modes 4 --units mm-t-s -o mm.h5").code, 0);
  EXPECT_EQ(io::ReadBody((dir_ / "mm.h5").string()).units, "mm-t-s (mm, t, s, N, MPa)");
  const testing::CliResult bad = testing::RunCli(dir_, "reduce beam.bdf --interface 1 --modes 4 --units cubit -o x.h5");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("unknown unit system 'cubit'"), std::string::npos) << bad.err;
  // the same beam in mm, t, s numbers reduced without --units: recorded as SI, with a warning
  std::string mm = "BEGIN BULK\nMAT1,1,2.1+5,,0.3,7.85-9\nPBAR,1,1,100.,830.,830.,1400.\n";
  for (int k = 0; k <= 5; ++k) mm += "GRID," + std::to_string(k + 1) + ",," + std::to_string(200 * k) + ".,0.,0.\n";
  for (int k = 1; k <= 5; ++k)
    mm += "CBAR," + std::to_string(k) + ",1," + std::to_string(k) + "," + std::to_string(k + 1) + ",0.,0.,1.\n";
  mm += "ENDDATA\n";
  testing::WriteFile(dir_ / "beam_mm.bdf", mm);
  const testing::CliResult forgot = testing::RunCli(dir_, "reduce beam_mm.bdf --interface 1 --modes 4 -o forgot.h5");
  ASSERT_EQ(forgot.code, 0) << forgot.err;
  EXPECT_NE(forgot.err.find("material 1 has the density 7.85e-09, implausible in kg/m^3"), std::string::npos)
      << forgot.err;
  const testing::CliResult told =
      testing::RunCli(dir_, "reduce beam_mm.bdf --interface 1 --modes 4 --units mm-t-s -o told.h5");
  ASSERT_EQ(told.code, 0) << told.err;
  EXPECT_EQ(told.err, "");
}

}  // namespace rotating_beam_test
}  // namespace flexmb
