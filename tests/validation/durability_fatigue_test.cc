// Rainflow counting and fatigue damage against ASTM E1049-85's worked
// example, an independent implementation of the standard's steps written
// here, and the closed form of the S-N curves (docs/validation.md,
// "Durability").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/common/error.h"
#include "flexmb/durability/element_fatigue.h"
#include "flexmb/durability/rainflow.h"
#include "flexmb/durability/sn_curve.h"

namespace durability_fatigue_test {

using flexmb::InputError;
using flexmb::durability::CountRainflow;
using flexmb::durability::EquivalentRange;
using flexmb::durability::MeanStress;
using flexmb::durability::MeanStressCorrection;
using flexmb::durability::MinerDamage;
using flexmb::durability::RainflowCycle;
using flexmb::durability::SnCurve;

// ASTM E1049-85 (2017), Fig. 6 and Table 4: the example history and its
// rainflow count (range -> cycles)
TEST(DurabilityRainflow, AstmWorkedExample) {
  const std::vector<double> x = {-2, 1, -3, 5, -1, 3, -4, 4, -2};
  std::vector<RainflowCycle> cycles;
  CountRainflow(x.data(), static_cast<int>(x.size()), cycles);
  std::map<double, double> counts;
  for (const RainflowCycle& c : cycles) counts[c.range] += c.count;
  const std::map<double, double> table4 = {{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(counts, table4);
  // the example's samples in between the reversals change nothing
  const std::vector<double> dense = {-2, -1, 1, 0, -3, 0, 2, 5, 5, -1, 3, 2, -4, 4, 1, -2};
  CountRainflow(dense.data(), static_cast<int>(dense.size()), cycles);
  std::map<double, double> dense_counts;
  for (const RainflowCycle& c : cycles) dense_counts[c.range] += c.count;
  EXPECT_EQ(dense_counts, table4);
}

// an independent transcription of ASTM E1049-85 5.4.4 steps 1 to 6 on the
// whole signal: reversals by the sign change of the slope, a list of
// points with an explicit starting point index
std::vector<RainflowCycle> ReferenceRainflow(const std::vector<double>& x) {
  std::vector<double> peaks;
  std::vector<double> y;
  for (double v : x)
    if (y.empty() || v != y.back()) y.push_back(v);
  for (size_t i = 0; i < y.size(); ++i) {
    const bool end = i == 0 || i + 1 == y.size();
    if (end || (y[i] - y[i - 1]) * (y[i + 1] - y[i]) < 0) peaks.push_back(y[i]);
  }
  std::vector<RainflowCycle> out;
  std::vector<double> pts;  // points read and not discarded
  size_t start = 0;         // index in pts of the starting point S
  for (double p : peaks) {
    pts.push_back(p);
    for (;;) {
      if (pts.size() - start < 3) break;
      const size_t n = pts.size();
      const double X = std::abs(pts[n - 1] - pts[n - 2]), Y = std::abs(pts[n - 2] - pts[n - 3]);
      if (X < Y) break;
      if (n - 3 == start) {
        out.push_back({Y, 0.5 * (pts[n - 2] + pts[n - 3]), 0.5});
        ++start;
      } else {
        out.push_back({Y, 0.5 * (pts[n - 2] + pts[n - 3]), 1.0});
        pts.erase(pts.begin() + static_cast<long>(n - 3), pts.begin() + static_cast<long>(n - 1));
      }
    }
  }
  for (size_t i = start + 1; i < pts.size(); ++i)
    out.push_back({std::abs(pts[i] - pts[i - 1]), 0.5 * (pts[i] + pts[i - 1]), 0.5});
  return out;
}

// reference S-N damage of one range on the EN 1993-1-9 curve written from
// the standard's formulas (7.2) and (7.3) with its knee values
double ReferenceEurocodeDamage(double s, double dc) {
  const double dd = 0.737 * dc, dl = 0.549 * dd;
  if (s >= dd) return std::pow(s / dc, 3) / 2e6;
  if (s >= dl) return std::pow(s / dd, 5) / 5e6;
  return 0.0;
}

TEST(DurabilityRainflow, RandomSignalAgainstIndependentImplementation) {
  std::mt19937 gen(20261127);
  std::normal_distribution<double> noise(0.0, 40e6);
  // a filtered random signal with plateaus and a mean drift
  std::vector<double> x(20000);
  double a = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    a = 0.7 * a + noise(gen);
    x[i] = i % 97 == 0 && i > 0 ? x[i - 1] : a + 20e6 * std::sin(1e-3 * static_cast<double>(i));
  }
  std::vector<RainflowCycle> cycles;
  CountRainflow(x.data(), static_cast<int>(x.size()), cycles);
  const std::vector<RainflowCycle> ref = ReferenceRainflow(x);
  ASSERT_EQ(cycles.size(), ref.size());
  for (size_t i = 0; i < ref.size(); ++i) {
    EXPECT_EQ(cycles[i].range, ref[i].range) << i;
    EXPECT_EQ(cycles[i].count, ref[i].count) << i;
  }
  const SnCurve curve = SnCurve::Eurocode(71);
  double d_ref = 0.0;
  for (const RainflowCycle& c : ref) d_ref += c.count * ReferenceEurocodeDamage(c.range, 71e6);
  std::vector<double> rev, stack;
  const double d = MinerDamage(x.data(), static_cast<int>(x.size()), curve, {}, rev, stack);
  ASSERT_GT(d_ref, 0.0);
  // the standard's knee values are rounded to 3 digits
  EXPECT_NEAR(d, d_ref, 2e-3 * d_ref);
}

// k periods of S_m + A cos, 4 samples per period: k cycles of range 2 A
std::vector<double> DurabilityCosine(double mean, double amp, int k) {
  std::vector<double> x;
  for (int i = 0; i <= 4 * k; ++i) x.push_back(mean + amp * std::cos(0.5 * M_PI * i));
  return x;
}

TEST(DurabilityDamage, ConstantAmplitudeAgainstClosedForm) {
  std::vector<double> rev, stack;
  const int k = 1000;
  // Basquin without knee: D = k (2A / S_ref)^m / N_ref
  const SnCurve basquin = SnCurve::Basquin(200e6, 1e6, 4.0, 0, 0, 0);
  const std::vector<double> x = DurabilityCosine(0.0, 60e6, k);
  EXPECT_NEAR(MinerDamage(x.data(), static_cast<int>(x.size()), basquin, {}, rev, stack),
              k * std::pow(120.0 / 200.0, 4) / 1e6, 1e-12 * k);
  // EN 1993-1-9 category 90 in each part of the curve
  const SnCurve en = SnCurve::Eurocode(90);
  for (double range : {150e6, 60e6, 30e6}) {
    const std::vector<double> y = DurabilityCosine(10e6, 0.5 * range, k);
    const double d = MinerDamage(y.data(), static_cast<int>(y.size()), en, {}, rev, stack);
    EXPECT_NEAR(d, k * ReferenceEurocodeDamage(range, 90e6), 2e-3 * k * ReferenceEurocodeDamage(range, 90e6))
        << range;
  }
  // the curve's knees as EN 1993-1-9 Fig. 7.1 gives them
  EXPECT_NEAR(en.Cycles(0.737 * 90e6), 5e6, 0.002 * 5e6);
  // (the standard's factors are rounded to 3 digits: 0.2 % either side)
  EXPECT_NEAR(en.Cycles(0.549 * 0.737 * 90e6 * 1.002), 1e8, 0.02 * 1e8);
  EXPECT_TRUE(std::isinf(en.Cycles(0.549 * 0.737 * 90e6 * 0.998)));
  // Goodman: the range grows by 1 / (1 - S_m / S_u)
  MeanStress goodman{MeanStressCorrection::kGoodman, 500e6, 0.0};
  const std::vector<double> z = DurabilityCosine(100e6, 60e6, k);
  EXPECT_NEAR(MinerDamage(z.data(), static_cast<int>(z.size()), basquin, goodman, rev, stack),
              k * std::pow(120.0 / (1.0 - 100.0 / 500.0) / 200.0, 4) / 1e6, 1e-12 * k);
}

TEST(DurabilityDamage, FkmRegionsAreContinuousAndMatchTheGuideline) {
  const MeanStress fkm{MeanStressCorrection::kFkm, 0.0, 0.3};
  const double sa = 50.0;
  // region II: S_a + M S_m; the region borders R = -inf, 0, 0.5 are continuous
  EXPECT_DOUBLE_EQ(EquivalentRange(2 * sa, 0.0, fkm), 2 * sa);
  EXPECT_DOUBLE_EQ(EquivalentRange(2 * sa, 20.0, fkm), 2 * (sa + 0.3 * 20.0));
  for (double border : {-sa, sa, 3 * sa})
    EXPECT_NEAR(EquivalentRange(2 * sa, border - 1e-9, fkm), EquivalentRange(2 * sa, border + 1e-9, fkm), 1e-6);
  // region IV: constant, 3 S_a (1 + M)^2 / (3 + M)
  EXPECT_NEAR(EquivalentRange(2 * sa, 400.0, fkm), 2 * 3 * sa * 1.69 / 3.3, 1e-12);
}

TEST(DurabilityBadInput, NonMonotonicSnTableNamesFileAndLine) {
  const std::filesystem::path p = std::filesystem::temp_directory_path() / ("durability_bad_sn_" + std::to_string(::getpid()) + ".csv");
  {
    std::ofstream f(p);
    f << "cycles, range_Pa\n1e4, 300e6\n1e5, 200e6\n# comment\n1e6, 250e6\n";
  }
  try {
    SnCurve::ReadCsv(p.string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.context().file, p.string());
    EXPECT_EQ(e.context().line, 5);
    EXPECT_NE(std::string(e.what()).find("not monotonic"), std::string::npos) << e.what();
  }
  {
    std::ofstream f(p);
    f << "1e4, 300e6\n1e4, 200e6\n";
  }
  EXPECT_THROW(SnCurve::ReadCsv(p.string()), InputError);
  std::filesystem::remove(p);
  EXPECT_THROW(SnCurve::Preset("en1993-70"), InputError);
  EXPECT_THROW(SnCurve::Basquin(100e6, 1e6, -3, 0, 0, 0), InputError);
  EXPECT_THROW(SnCurve::Basquin(100e6, 1e6, 3, 5e6, 5, 1e6), InputError);
}

}  // namespace durability_fatigue_test
