#include "flexmb/results/results_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <unistd.h>

#include "flexmb/common/error.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"

namespace flexmb {
namespace {

// A sensor with n components (k + 1) * scale * t; component `angle` (if >= 0)
// is an angle wrapped to (-pi, pi] as a real angle sensor reports it.
class FakeSensor final : public Sensor {
 public:
  FakeSensor(std::string name, int n, int angle, double scale)
      : Sensor(std::move(name)), n_(n), angle_(angle), scale_(scale) {}
  const char* type() const override { return "fake"; }
  std::vector<std::string> Components() const override {
    std::vector<std::string> c;
    for (int k = 0; k < n_; ++k) c.push_back("c" + std::to_string(k));
    return c;
  }
  bool ComponentIsAngle(int k) const override { return k == angle_; }
  void Evaluate(const Model&, const State& s, const Workspace&, double* out) const override {
    for (int k = 0; k < n_; ++k) {
      out[k] = (k + 1) * scale_ * s.t;
      if (k == angle_) out[k] = std::remainder(out[k], 2.0 * std::numbers::pi);
    }
  }

 private:
  int n_, angle_;
  double scale_;
};

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::vector<std::string>> ParseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    std::string cell;
    while (std::getline(ls, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// a fresh temporary directory per test, removed afterwards
class ResultsWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("flexmb_results_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string TempPath(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(ResultsWriterTest, HeaderAndRowsFlushedPerRow) {
  Model model;
  model.AddSensor(std::make_unique<FakeSensor>("a", 2, -1, 1.0));
  model.AddSensor(std::make_unique<FakeSensor>("b", 3, -1, 0.1));
  const std::string path = TempPath("rows.csv");
  ResultsWriter w(path, model);
  const std::vector<std::string> header = {"time", "a.c0", "a.c1", "b.c0", "b.c1", "b.c2"};
  EXPECT_EQ(w.column_names(), header);

  Workspace ws;
  State s;
  for (int i = 0; i < 4; ++i) {
    s.t = 0.1 * i + 1.0 / 3.0;
    w.Write(s, ws);
    // read back while the writer is still open: every row is on disk
    const auto rows = ParseCsv(ReadFile(path));
    ASSERT_EQ(rows.size(), static_cast<size_t>(i + 2));
    EXPECT_EQ(rows[0], header);
    const auto& r = rows.back();
    ASSERT_EQ(r.size(), header.size());
    // full precision: the values read back equal the computed ones to 1e-14
    EXPECT_NEAR(std::stod(r[0]), s.t, 1e-14);
    EXPECT_NEAR(std::stod(r[1]), 1.0 * s.t, 1e-14);
    EXPECT_NEAR(std::stod(r[2]), 2.0 * s.t, 1e-14);
    EXPECT_NEAR(std::stod(r[3]), 0.1 * s.t, 1e-15);
    EXPECT_NEAR(std::stod(r[5]), 0.3 * s.t, 1e-15);
  }
  EXPECT_EQ(w.rows(), 4);
}

TEST_F(ResultsWriterTest, UnwrapsAngleColumnsOnly) {
  // the angle column turns 2.5 rad/s for 10 s (about 4 turns); the sensor
  // reports it wrapped, the file must hold the continuous angle
  Model model;
  model.AddSensor(std::make_unique<FakeSensor>("j", 2, 0, 2.5));
  const std::string path = TempPath("unwrap.csv");
  {
    ResultsWriter w(path, model);
    Workspace ws;
    State s;
    for (int i = 0; i <= 100; ++i) {
      s.t = 0.1 * i;
      w.Write(s, ws);
    }
  }
  const auto rows = ParseCsv(ReadFile(path));
  ASSERT_EQ(rows.size(), 102u);
  for (size_t i = 1; i < rows.size(); ++i) {
    const double t = std::stod(rows[i][0]);
    EXPECT_NEAR(std::stod(rows[i][1]), 2.5 * t, 1e-12) << "t = " << t;
    // the second component (not an angle) passes unchanged, wrapped or not
    EXPECT_NEAR(std::stod(rows[i][2]), 5.0 * t, 1e-12) << "t = " << t;
  }
}

TEST_F(ResultsWriterTest, UnwrapsNegativeTurnsAndKeepsFirstValue) {
  Model model;
  model.AddSensor(std::make_unique<FakeSensor>("j", 1, 0, 1.0));
  const std::string path = TempPath("unwrap_neg.csv");
  const double pi = std::numbers::pi;
  // a value starting near -pi that goes down across -pi three times
  std::vector<double> truth;
  {
    ResultsWriter w(path, model);
    for (int i = 0; i < 60; ++i) {
      const double a = -3.0 - 0.35 * i;
      truth.push_back(a);
      const double wrapped = std::remainder(a, 2 * pi);
      w.WriteRow(0.01 * i, &wrapped);
    }
  }
  const auto rows = ParseCsv(ReadFile(path));
  ASSERT_EQ(rows.size(), truth.size() + 1);
  for (size_t i = 0; i < truth.size(); ++i) EXPECT_NEAR(std::stod(rows[i + 1][1]), truth[i], 1e-12);
}

TEST_F(ResultsWriterTest, UnwritablePathIsAnInputError) {
  Model model;
  EXPECT_THROW(ResultsWriter("/nonexistent_dir_flexmb/x.csv", model), InputError);
}

}  // namespace
}  // namespace flexmb
