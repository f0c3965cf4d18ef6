// The crane's drive motions (flexmb/crane/crane_motion.h): the trapezoidal
// move's distance against the integral of its speed profile, written here
// independently (speed ramps linearly up, holds, ramps linearly down) and
// integrated by the trapezoidal rule on a fine grid; the muparser
// expression against the closed form; the cosine luffing ramp's ends.
#include <gtest/gtest.h>

#include <cmath>

#include "flexmb/crane/crane_motion.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb::crane {
namespace {

// the speed of the move at time t, from its definition
double Speed(const TrapezoidMove& m, double t) {
  const double t1 = m.start + m.ramp, t2 = m.CruiseEnd(), t3 = t2 + m.stop_ramp;
  if (t <= m.start || t >= t3) return 0.0;
  if (t < t1) return m.speed * (t - m.start) / m.ramp;
  if (t < t2) return m.speed;
  return m.speed * (t3 - t) / m.stop_ramp;
}

TEST(CraneMotion, DistanceIsTheIntegralOfTheSpeedProfile) {
  TrapezoidMove hoist{0.2, 0.3, 0.5, 0.5, 1.2, -1};           // the example's lift-off
  TrapezoidMove lower{6.0, -0.3, 0.5, 0.2, -1, 8.0};          // lowering with a brake stop
  TrapezoidMove slew{6.0, 0.15, 3.0, 3.0, M_PI / 2, -1};      // 90 degrees
  for (const TrapezoidMove& m : {hoist, lower, slew}) {
    EXPECT_EQ(CheckMove(m), "");
    const ExpressionFunction f(m.Expression());
    const double dt = 1e-4;
    double s = 0, t = 0;
    for (int k = 0; t < m.End() + 1.0; ++k) {
      const double t_next = (k + 1) * dt;
      s += 0.5 * dt * (Speed(m, t) + Speed(m, t_next));
      t = t_next;
      if (k % 97 == 0) {
        EXPECT_NEAR(m.At(t), s, 1e-7) << "t = " << t;
        EXPECT_NEAR(f.Value(t), m.At(t), 1e-12) << "t = " << t;
      }
    }
    EXPECT_NEAR(m.Total(), s, 1e-7);
  }
  EXPECT_NEAR(hoist.Total(), 1.2, 1e-15);
  EXPECT_NEAR(slew.Total(), M_PI / 2, 1e-15);
  EXPECT_DOUBLE_EQ(lower.CruiseEnd(), 8.0);
  EXPECT_NEAR(lower.Total(), -(0.075 + 0.3 * 1.5 + 0.03), 1e-15);  // 0.555 m paid out
}

TEST(CraneMotion, CheckNamesWhatIsWrong) {
  EXPECT_NE(CheckMove({0, 0.3, 0, 0.5, 1, -1}).find("ramps must be positive"), std::string::npos);
  EXPECT_NE(CheckMove({0, 0, 0.5, 0.5, 1, -1}).find("'speed' must not be zero"), std::string::npos);
  EXPECT_NE(CheckMove({0, 0.3, 0.5, 0.5, 1, 3}).find("either 'distance' or 'until'"), std::string::npos);
  EXPECT_NE(CheckMove({0, 0.3, 0.5, 0.5, 0.1, -1}).find("shorter than the ramps take (0.15)"), std::string::npos);
  EXPECT_NE(CheckMove({1, 0.3, 0.5, 0.5, -1, 1.2}).find("'until' comes before"), std::string::npos);
}

TEST(CraneMotion, CosineRampGoesFromItsStartToItsEndWithZeroSpeedAtBoth) {
  const CosineRamp r{6.0, 6.0, 4.157, 4.336};
  const ExpressionFunction f(r.Expression());
  EXPECT_DOUBLE_EQ(f.Value(5.0), 0.0);
  EXPECT_NEAR(f.Value(6.0), 0.0, 1e-15);
  EXPECT_NEAR(f.Value(9.0), 0.5 * (4.336 - 4.157), 1e-14);
  EXPECT_NEAR(f.Value(12.0), 4.336 - 4.157, 1e-14);
  EXPECT_NEAR(f.Value(20.0), 4.336 - 4.157, 1e-14);
  EXPECT_NEAR((f.Value(6.0 + 1e-4) - f.Value(6.0)) / 1e-4, 0.0, 1e-5);
}

}  // namespace
}  // namespace flexmb::crane
