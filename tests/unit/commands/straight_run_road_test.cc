// The straight run's road (StraightRunRoad, apps/flexmb/commands/straight_run.h):
// the generated road against GenerateIso8608 of the same seed (cut to the
// asked length, the fade-in (1 - cos(pi x / L_f)) / 2 over the first
// metres, untouched after), a CSV road shifted to start at x = 0, the flat
// road, and the options' errors.
#include "apps/flexmb/commands/straight_run.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/common/error.h"

namespace flexmb::vehicle {
namespace {

TEST(StraightRunRoad, GeneratedRoadIsCutAndFadesIn) {
  StraightRunOptions o;
  o.file = "truck.yaml";
  o.road_class = "C";
  o.road_length = 60.0;
  o.seed = 7;
  o.fade_in = 5.0;
  const RoadProfile p = StraightRunRoad(o, 1.9);
  Iso8608Options g;
  g.road_class = 'C';
  g.length = 60.0;
  g.seed = 7;
  g.track_width = 1.9;
  const RoadProfile ref = GenerateIso8608(g);
  ASSERT_GT(ref.x.back(), 60.0);
  EXPECT_NEAR(p.x.back(), 60.0, 1e-9);
  ASSERT_EQ(p.x.size(), p.z_left.size());
  ASSERT_EQ(p.x.size(), p.z_right.size());
  EXPECT_EQ(p.z_left.front(), 0.0);
  EXPECT_EQ(p.z_right.front(), 0.0);
  for (size_t i = 0; i < p.x.size(); ++i) {
    EXPECT_EQ(p.x[i], ref.x[i]);
    const double w = p.x[i] < 5.0 ? 0.5 * (1 - std::cos(std::numbers::pi * p.x[i] / 5.0)) : 1.0;
    EXPECT_NEAR(p.z_left[i], w * ref.z_left[i], 1e-15) << i;
    EXPECT_NEAR(p.z_right[i], w * ref.z_right[i], 1e-15) << i;
  }
}

TEST(StraightRunRoad, CsvRoadStartsAtZeroAndFlatRoadIsLevel) {
  const std::filesystem::path csv = std::filesystem::temp_directory_path() / ("flexmb_straight_run_road_" + std::to_string(::getpid()) + ".csv");
  {
    std::ofstream f(csv);
    f << "x, z_left, z_right\n100, 0.01, 0.02\n110, 0.03, 0.04\n120, 0.05, 0.06\n";
  }
  StraightRunOptions o;
  o.road = "csv";
  o.road_csv = csv.string();
  o.fade_in = 0.0;
  const RoadProfile p = StraightRunRoad(o, 2.0);
  ASSERT_EQ(p.x.size(), 3u);
  EXPECT_EQ(p.x[0], 0.0);
  EXPECT_EQ(p.x[2], 20.0);
  EXPECT_EQ(p.z_left[1], 0.03);
  EXPECT_EQ(p.z_right[2], 0.06);
  std::filesystem::remove(csv);
  o.road = "flat";
  o.road_length = 80.0;
  const RoadProfile f = StraightRunRoad(o, 2.0);
  EXPECT_EQ(f.x.back(), 80.0);
  for (double z : f.z_left) EXPECT_EQ(z, 0.0);
  for (double z : f.z_right) EXPECT_EQ(z, 0.0);
}

TEST(StraightRunRoad, BadOptionsNameTheOption) {
  StraightRunOptions o;
  o.file = "truck.yaml";
  auto message = [](const StraightRunOptions& opt) {
    try {
      StraightRunRoad(opt, 2.0);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  o.road_class = "BB";
  EXPECT_NE(message(o).find("--road-class"), std::string::npos) << message(o);
  o.road_class = "I";
  EXPECT_NE(message(o).find("--road-class"), std::string::npos) << message(o);
  o.road_class = "B";
  o.road_length = -1.0;
  EXPECT_NE(message(o).find("--road-length"), std::string::npos) << message(o);
  o.road_length = 100.0;
  o.fade_in = -1.0;
  EXPECT_NE(message(o).find("--fade-in"), std::string::npos) << message(o);
  o.fade_in = 5.0;
  o.road = "csv";
  EXPECT_NE(message(o).find("--road-csv"), std::string::npos) << message(o);
  o.road = "gravel";
  EXPECT_NE(message(o).find("--road"), std::string::npos) << message(o);
  EXPECT_NE(message(o).find("truck.yaml"), std::string::npos) << message(o);
}

}  // namespace
}  // namespace flexmb::vehicle
