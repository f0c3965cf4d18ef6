// The truck's straight run over a road (apps/flexmb/commands/straight_run.h)
// with the elastic and the rigid frame, at 60 km/h over 40 m of road after
// the run-up. References:
// - the flat road does no fatigue damage: the truck driving straight at
//   constant speed on z = 0 loads the frame statically; the frame's stress
//   ranges over the run (every element, the counted measure) are noise far
//   below the cut-off of the EN 1993-1-9 detail category 71 curve
//   (Delta sigma_L = 0.549 x 0.737 x 71 MPa = 28.7 MPa): von Mises ranges
//   below 5 % of it, the counted measure's below it, Miner's sum exactly
//   0, while the class C road (ISO 8608) loads it with ranges of
//   several MPa and non-zero damage on the same curve;
// - equilibrium: averaged over the run, the vertical forces of each part's
//   mounts on the frame carry the part's weight and the springs carry the
//   sprung weight (lever rule, StaticAxleLoads), whatever the frame's
//   stiffness: the means agree between the rigid and the elastic frame and
//   with the weights to 1 %. Single mounts of the cargo (ten along the
//   rails: statically indeterminate) are not compared in mean: the elastic
//   frame shifts their static loads by up to 40 % (a real effect of the
//   frame's compliance). Dynamic parts (standard deviations): the springs'
//   agree within 5 % (the axles' motion), the cab mounts' are larger on
//   the elastic frame (by 1.3x at least; 2 to 3x measured): the frame's
//   modes under the cab.
// docs/validation.md, "Rough roads".
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "apps/flexmb/commands/lane_change.h"
#include "apps/flexmb/commands/straight_run.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/common/error.h"
#include "flexmb/durability/element_fatigue.h"
#include "flexmb/durability/modal_history.h"
#include "flexmb/durability/sn_curve.h"
#include "flexmb/durability/stress_recovery.h"

namespace truck_rough_road_test {

using flexmb::vehicle::ForceStatistics;
using flexmb::vehicle::StraightRunOptions;
using flexmb::vehicle::StraightRunResult;

std::string TruckRoadFile() { return std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/truck.yaml"; }

// the elastic frame, reduced once for the file's tests
std::shared_ptr<const flexmb::reduction::ReducedBody> TruckRoadFrame() {
  static const std::shared_ptr<const flexmb::reduction::ReducedBody> body = flexmb::vehicle::ReduceTruckFrame(
      flexmb::vehicle::LoadLaneChangeTruck(TruckRoadFile()), flexmb::vehicle::LaneChangeFrameReduction(TruckRoadFile()));
  return body;
}

struct TruckRoadRun {
  StraightRunResult result;
  flexmb::durability::ElementResults elements;   // elastic frame only: the default measure, EN 1993-1-9 cat. 71
  flexmb::durability::ElementResults von_mises;  // elastic frame only: von Mises (ranges only)
};

// 60 km/h over 40 m of `road` ("flat" or an ISO 8608 class letter)
TruckRoadRun RunTruckRoad(const std::string& road, const std::string& frame) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("flexmb_truck_rough_road_" + road + "_" + frame + "_" + std::to_string(::getpid()));  // ctest -j: own folder
  std::filesystem::remove_all(dir);
  StraightRunOptions o;
  o.file = TruckRoadFile();
  o.out_dir = dir.string();
  o.speed_kmh = 60.0;
  o.frame = frame;
  o.road = road == "flat" ? "flat" : "iso8608";
  o.road_class = road;
  o.road_length = 40.0;
  o.seed = 3;
  if (frame == "elastic") o.frame_body = TruckRoadFrame();
  TruckRoadRun run;
  run.result = flexmb::vehicle::RunStraight(o);
  if (frame == "elastic" && run.result.completed) {
    const flexmb::durability::ModalHistory h = flexmb::durability::ReadRunModalHistory(dir.string());
    const int b = h.Body("frame");
    const flexmb::reduction::ReducedBody body = flexmb::io::ReadBody(h.bodies[static_cast<size_t>(b)].body_file);
    flexmb::durability::StressRecovery rec(body.stress.shell, h.coordinates[static_cast<size_t>(b)]);
    flexmb::durability::FatigueOptions fo;
    fo.curve = flexmb::durability::SnCurve::Preset("en1993-71");
    run.elements = flexmb::durability::AnalyzeElements(rec, fo);
    flexmb::durability::FatigueOptions vm;
    vm.measure = flexmb::durability::StressMeasure::kVonMises;
    run.von_mises = flexmb::durability::AnalyzeElements(rec, vm);
  }
  std::filesystem::remove_all(dir);
  return run;
}

// sum of the mean vertical forces of the mounts whose name starts with `prefix` [N]
double TruckRoadMeanSum(const StraightRunResult& r, const std::string& prefix) {
  double s = 0;
  for (const ForceStatistics& f : r.mounts)
    if (f.name.rfind(prefix, 0) == 0) s += f.mean;
  return s;
}

TEST(TruckRoughRoad, FlatRoadDoesNoDamageClassCRoadDoes) {
  const TruckRoadRun flat = RunTruckRoad("flat", "elastic");
  const TruckRoadRun rough = RunTruckRoad("C", "elastic");
  ASSERT_TRUE(flat.result.completed) << flat.result.message;
  ASSERT_TRUE(rough.result.completed) << rough.result.message;
  EXPECT_NEAR(flat.result.distance, 40.0, 0.5);
  // von Mises ranges: the noise of the flat road (the signed measures can
  // flip sign in near-pure shear, where the two principal stresses have
  // nearly equal magnitudes, and count twice the stress as a range)
  const auto& fv = flat.von_mises.range;
  const auto& rv = rough.von_mises.range;
  const double flat_range = *std::max_element(fv.begin(), fv.end());
  const double rough_range = *std::max_element(rv.begin(), rv.end());
  double flat_damage = 0, rough_damage = 0;
  for (double d : flat.elements.damage) flat_damage += d;
  for (double d : rough.elements.damage) rough_damage += d;
  const double flat_counted = *std::max_element(flat.elements.range.begin(), flat.elements.range.end());
  std::printf("flat road: largest von Mises range %.4f MPa (counted measure %.3f MPa), damage %.3g; class C: %.3f MPa, "
              "damage %.3g (%d, %d rows)\n",
              flat_range / 1e6, flat_counted / 1e6, flat_damage, rough_range / 1e6, rough_damage, flat.result.rows,
              rough.result.rows);
  EXPECT_LT(flat_range, 0.05 * 28.7e6);
  EXPECT_LT(flat_counted, 28.7e6);
  EXPECT_EQ(flat_damage, 0.0);
  EXPECT_GT(rough_range, 28.7e6);
  EXPECT_GT(rough_damage, 0.0);
}

TEST(TruckRoughRoad, RigidAndElasticMountForcesCarryTheSameWeights) {
  const TruckRoadRun rigid = RunTruckRoad("C", "rigid");
  const TruckRoadRun elastic = RunTruckRoad("C", "elastic");
  ASSERT_TRUE(rigid.result.completed) << rigid.result.message;
  ASSERT_TRUE(elastic.result.completed) << elastic.result.message;
  const flexmb::vehicle::TruckData d = flexmb::vehicle::LoadLaneChangeTruck(TruckRoadFile());
  const double g = 9.81;
  // each part's mounts carry its weight (force on the frame: downward)
  const std::map<std::string, double> weight = {
      {"cab_mount", d.cab.mass * g}, {"powertrain_mount", d.powertrain.mass * g}, {"cargo_mount", d.cargo.mass * g}};
  for (const auto& w : weight) {
    const double r = -TruckRoadMeanSum(rigid.result, w.first), e = -TruckRoadMeanSum(elastic.result, w.first);
    std::printf("%s: weight %.1f N, mean on the frame rigid %.1f N, elastic %.1f N\n", w.first.c_str(), w.second, r, e);
    EXPECT_NEAR(r / w.second, 1.0, 0.01) << w.first;
    EXPECT_NEAR(e / w.second, 1.0, 0.01) << w.first;
    EXPECT_NEAR(e / r, 1.0, 0.01) << w.first;
  }
  // the springs carry the sprung weight of their axle
  const std::vector<double> axle = flexmb::vehicle::StaticAxleLoads(d, g);
  for (const char* side : {"front_spring", "rear_spring"}) {
    const double r = TruckRoadMeanSum(rigid.result, side), e = TruckRoadMeanSum(elastic.result, side);
    std::printf("%s: mean on the frame rigid %.1f N, elastic %.1f N (axle load %.1f N)\n", side, r, e,
                axle[side[0] == 'f' ? 0 : 1]);
    EXPECT_NEAR(e / r, 1.0, 0.01) << side;
  }
  // per mount: mean and dynamic part (standard deviation), rigid against elastic
  ASSERT_EQ(rigid.result.mounts.size(), elastic.result.mounts.size());
  for (size_t k = 0; k < rigid.result.mounts.size(); ++k) {
    const ForceStatistics &r = rigid.result.mounts[k], &e = elastic.result.mounts[k];
    ASSERT_EQ(r.name, e.name);
    std::printf("  %-26s mean %9.1f / %9.1f N, std %8.1f / %8.1f N (rigid / elastic)\n", r.name.c_str(), r.mean, e.mean,
                r.std, e.std);
    EXPECT_GT(r.std, 0.0) << r.name;
    EXPECT_GT(e.std, 0.0) << e.name;
    // the suspension springs see the axles' motion, nearly the same for both
    // frames; the cab mounts sit on the frame's front overhang, where its
    // bending and torsion modes add to the rigid frame's motion
    if (r.name.find("spring") != std::string::npos) EXPECT_NEAR(e.std / r.std, 1.0, 0.05) << r.name;
    if (r.name.rfind("cab_mount", 0) == 0) EXPECT_GT(e.std, 1.3 * r.std) << r.name;
  }
}

// bad input: an InputError naming the truck file and the option, or the
// road file and its line
TEST(TruckRoughRoad, BadInputNamesTheFileAndTheOption) {
  auto message = [](const StraightRunOptions& o) {
    try {
      flexmb::vehicle::RunStraight(o);
    } catch (const flexmb::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  StraightRunOptions base;
  base.file = TruckRoadFile();
  base.road_length = 50.0;
  StraightRunOptions o = base;
  o.road_class = "X";
  std::string m = message(o);
  EXPECT_NE(m.find("truck.yaml"), std::string::npos) << m;
  EXPECT_NE(m.find("--road-class"), std::string::npos) << m;
  o = base;
  o.speed_kmh = -5.0;
  m = message(o);
  EXPECT_NE(m.find("--speed"), std::string::npos) << m;
  o = base;
  o.distance = 80.0;
  m = message(o);
  EXPECT_NE(m.find("--distance"), std::string::npos) << m;
  EXPECT_NE(m.find("longer than the road"), std::string::npos) << m;
  const std::filesystem::path csv = std::filesystem::temp_directory_path() / ("flexmb_truck_rough_road_nan_" + std::to_string(::getpid()) + ".csv");
  {
    std::ofstream f(csv);
    f << "x, z_left, z_right\n0, 0, 0\n1, nan, 0\n2, 0, 0\n";
  }
  o = base;
  o.road = "csv";
  o.road_csv = csv.string();
  m = message(o);
  EXPECT_NE(m.find(csv.string() + ":3"), std::string::npos) << m;
  std::filesystem::remove(csv);
}

}  // namespace truck_rough_road_test
