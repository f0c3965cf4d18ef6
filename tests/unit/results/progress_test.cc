#include "flexmb/results/progress.h"

#include <gtest/gtest.h>

#include <string>

namespace flexmb {
namespace {

TEST(ProgressBar, LineShowsFractionTimeRealTimeFactorAndSteps) {
  char buf[200];
  // half of 2 s simulated in 0.25 s wall: 4x real time, 12 of 24 bar cells
  ProgressBar::Format(buf, sizeof(buf), 0.0, 2.0, 1.0, 1234, 0.25);
  EXPECT_EQ(std::string(buf),
            "[############............]  50.0%  t = 1 / 2 s  4x real time  1234 steps");
  // a run starting at t0 = 1 s: the fraction counts from t0
  ProgressBar::Format(buf, sizeof(buf), 1.0, 3.0, 2.5, 7, 3.0);
  EXPECT_EQ(std::string(buf),
            "[##################......]  75.0%  t = 2.5 / 3 s  0.5x real time  7 steps");
}

TEST(ProgressBar, DisabledBarWritesNothing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressBar bar(f, false, 0.0, 1.0);
    bar.Update(0.5, 10);
    bar.Finish(1.0, 20);
  }
  EXPECT_EQ(std::ftell(f), 0);
  std::fclose(f);
}

TEST(ProgressBar, RedrawsAtMostOncePerInterval) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    // a long interval: only the first update and the finish are drawn
    ProgressBar bar(f, true, 0.0, 1.0, 3600.0);
    for (int i = 0; i < 1000; ++i) bar.Update(0.001 * i, i);
    bar.Finish(1.0, 1000);
  }
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
  std::fclose(f);
  size_t redraws = 0;
  for (char c : text) redraws += c == '\r';
  EXPECT_EQ(redraws, 2u) << text;
  EXPECT_NE(text.find("100.0%"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace flexmb
