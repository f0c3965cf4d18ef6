// Tire relaxation length (the contact-patch carcass model of Tire): the
// step-steer response of the lateral force at constant speed against the
// analytic first-order lag F(x) = F_ss (1 - exp(-x / sigma)) in travelled
// distance x, and the stateless limit sigma -> 0.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "flexmb/vehicle/tire.h"
#include "tests/unit/vehicle/tire_rig.h"
#include "tests/unit/vehicle/tire_test_data.h"

namespace flexmb::vehicle {
namespace tire_relaxation_test {

// The rig (tests/unit/vehicle/tire_rig.h): a carrier driven along world x
// at V, the wheel steered by psi about z at t = 0 (a step in slip angle) and
// rolling freely on its bearing; with relaxation the contact patch slides
// along the spin axis on the carrier. Returns the samples and the stateless
// tire's steady lateral force at the same slip.
std::vector<TireRigSample> RunStepSteer(const TireData& td, double V, double psi, double t_end, double dt,
                                        double* fy_steady) {
  TireRigRun run = RunTireStepRig(td, V, psi, std::nullopt, t_end, dt);
  *fy_steady = run.fy_steady;
  return std::move(run.samples);
}

// Step steer of 0.2 deg at 10 m/s, sigma = 0.6 m. Reference: the carcass
// model (Pacejka, Tire and Vehicle Dynamics, 3rd ed., sec. 7.2.1) with the
// patch mass neglected gives sigma dFy/dx + Fy = Fy_ss, sigma = Ky / k_y, so
// Fy(x) = Fy_ss (1 - exp(-x / sigma)). Deviations of the simulation from it:
// the patch mass (fast pole, relative ~ m V / Ky / (sigma / V) = 5e-4), the
// Magic Formula's curvature at B alpha = 0.018 (~3e-4), the slip
// regularisation (5e-5) and the time discretisation (dt = 1 ms against
// sigma / V = 60 ms, ~1e-4). Tolerance 3e-3 of Fy_ss; an error of 2 % in sigma
// would show as 7e-3.
TEST(TireRelaxation, StepSteerFollowsFirstOrderLagInDistance) {
  const double sigma = 0.6, V = 10.0, psi = 0.2 * M_PI / 180;
  double fss = 0.0;
  const std::vector<TireRigSample> s = RunStepSteer(Tire11R22Rig(sigma), V, psi, 5 * sigma / V, 1e-3, &fss);
  ASSERT_GT(std::abs(fss), 100.0);
  ASSERT_GT(s.size(), 250u);
  EXPECT_NEAR(s.front().fy_wheel, 0.0, 1e-9 * std::abs(fss));
  double worst = 0.0;
  for (const TireRigSample& r : s) {
    const double ref = fss * (1.0 - std::exp(-r.x / sigma));
    worst = std::max(worst, std::abs(r.fy_wheel - ref) / std::abs(fss));
  }
  EXPECT_LT(worst, 3e-3);
  // the distance to 63.2 % of the steady force is sigma (2 %)
  double x63 = 0.0;
  for (size_t k = 1; k < s.size(); ++k) {
    const double f0 = s[k - 1].fy_wheel / fss, f1 = s[k].fy_wheel / fss, target = 1.0 - std::exp(-1.0);
    if (f0 < target && f1 >= target) x63 = s[k - 1].x + (target - f0) / (f1 - f0) * (s[k].x - s[k - 1].x);
  }
  EXPECT_NEAR(x63, sigma, 0.02 * sigma);
}

// sigma -> 0: with sigma = 5 mm the lag is over after a few centimetres and
// the force equals the stateless tire's at the same slip; sigma = 0 is the
// stateless element itself (one marker), whose force is Fy_ss at once.
TEST(TireRelaxation, ShortRelaxationLengthRecoversStatelessTire) {
  const double V = 10.0, psi = 0.2 * M_PI / 180;
  double fss = 0.0, fss0 = 0.0;
  const std::vector<TireRigSample> s = RunStepSteer(Tire11R22Rig(0.005), V, psi, 0.05, 1e-3, &fss);
  const std::vector<TireRigSample> s0 = RunStepSteer(Tire11R22Rig(0.0), V, psi, 0.05, 1e-3, &fss0);
  EXPECT_EQ(fss, fss0);
  for (const TireRigSample& r : s0) EXPECT_NEAR(r.fy_wheel, fss0, 1e-6 * std::abs(fss0));
  for (const TireRigSample& r : s) {
    if (r.x < 0.1) continue;
    EXPECT_NEAR(r.fy_wheel, fss0, 1e-3 * std::abs(fss0)) << "x = " << r.x;
  }
}

}  // namespace tire_relaxation_test
}  // namespace flexmb::vehicle
