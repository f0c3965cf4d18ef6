#pragma once
/// \file cli_strip.h
/// The steel strip of tests/data/fe/nastran/cli_strip.bdf used by the
/// command-line tests (fe_cli_test, reduce_cli_test): its dimensions and the
/// closed-form mass properties its JSON reports must carry.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "json_reader.h"

namespace flexmb::testing {

/// The strip model file and its hinge variant.
inline const std::string kStrip = FLEXMB_SOURCE_DIR "/tests/data/fe/nastran/cli_strip.bdf";
inline const std::string kHinge = FLEXMB_SOURCE_DIR "/tests/data/fe/nastran/cli_hinge.bdf";
/// Steel (nu = 0) strip L x b x t [m], density [kg/m^3], Young's modulus [Pa].
constexpr double kStripE = 2.1e11, kStripRho = 7850.0, kStripL = 1.0, kStripB = 0.05, kStripT = 0.005;

/// Mass, centre of mass and inertia tensor in `j` ("mass_kg",
/// "center_of_mass_m", "inertia_kg_m2") equal those of the box L x b x t
/// with a corner at the origin (the consistent shell mass carries the rotary
/// inertia of the thickness, so the t^2 terms, 1 % of Ixx, are there too).
inline void ExpectStripMassProperties(const Json& j) {
  const double L = kStripL, b = kStripB, t = kStripT;
  const double m = kStripRho * L * b * t;
  EXPECT_NEAR(j["mass_kg"].number, m, 1e-12 * m);
  const std::vector<double> c = j["center_of_mass_m"].Numbers();
  ASSERT_EQ(c.size(), 3u);
  EXPECT_NEAR(c[0], 0.5 * L, 1e-12);
  EXPECT_NEAR(c[1], 0.5 * b, 1e-12);
  EXPECT_NEAR(c[2], 0.0, 1e-12);
  const Json& I = j["inertia_kg_m2"];
  ASSERT_EQ(I.array.size(), 3u);
  for (const Json& row : I.array) ASSERT_EQ(row.array.size(), 3u);
  const double diagonal[3] = {m * (b * b + t * t) / 12.0, m * (L * L + t * t) / 12.0, m * (L * L + b * b) / 12.0};
  for (int r = 0; r < 3; ++r) {
    for (int s = 0; s < 3; ++s) {
      const double ref = r == s ? diagonal[r] : 0.0;
      EXPECT_NEAR(I.array[r].array[s].number, ref, r == s ? 1e-9 * ref : 1e-12 * diagonal[2]) << r << s;
    }
  }
}

}  // namespace flexmb::testing
