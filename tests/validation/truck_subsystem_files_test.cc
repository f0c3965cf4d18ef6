// Vehicle data files per subsystem (issue 18, the data tier): the truck
// map's cab, rear suspension, steering and brakes moved into files of their
// own (each under its top-level kind: part, suspension, steering, brakes)
// and named in the truck file read back to the same truck as the inline
// file (reference: examples/truck_lane_change/truck.yaml itself); errors in
// a subsystem file name that file and line; a missing file names the truck
// file's line.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "flexmb/common/error.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_subsystem_files_test {

namespace fs = std::filesystem;

// the truck map's entry at `key`: a key of the truck map, or
// "axles.<index>.<key>" of an axle's map; returns its parent map and its key
std::pair<YAML::Node, std::string> TruckEntry(YAML::Node truck, const std::string& key) {
  if (!key.starts_with("axles.")) return {truck, key};
  const size_t dot = key.find('.', 6);
  return {truck["axles"][std::stoi(key.substr(6, dot - 6))], key.substr(dot + 1)};
}

// the example's lane-change file with the truck's `moved` entries
// (TruckEntry) in files of their own, named after the entry with '.' as
// '_'; returns the new lane-change file's path
std::string SplitTruck(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& moved) {
  fs::create_directories(dir);
  const std::string example = std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/";
  YAML::Node root = YAML::LoadFile(example + "truck.yaml");
  for (const char* tire : {"tire_11r22_5.yaml", "tire_11r22_5_twin.yaml"})
    fs::copy_file(example + tire, dir + "/" + tire, fs::copy_options::overwrite_existing);
  for (const auto& [key, kind] : moved) {
    auto [parent, leaf] = TruckEntry(root["truck"], key);
    std::string name = key;
    std::replace(name.begin(), name.end(), '.', '_');
    YAML::Node file;
    file[kind] = YAML::Clone(parent[leaf]);
    std::ofstream(dir + "/" + name + ".yaml") << "# " << key << " of the example truck\n" << YAML::Dump(file) << "\n";
    parent[leaf] = name + ".yaml";
  }
  const std::string path = dir + "/truck_split.yaml";
  std::ofstream(path) << YAML::Dump(root) << "\n";
  return path;
}

std::string ErrorOf(const std::string& path) {
  try {
    LoadLaneChangeTruck(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TruckSubsystemFiles, SplitFileIsTheSameTruck) {
  const std::string dir = ::testing::TempDir() + "truck_split";
  const std::string split = SplitTruck(dir, {{"cab", "part"}, {"axles.1.suspension", "suspension"},
                                             {"axles.1.wheel", "part"}, {"steering", "steering"},
                                             {"brakes", "brakes"}});
  const TruckData a = LoadLaneChangeTruck(TruckFile()), b = LoadLaneChangeTruck(split);
  EXPECT_EQ(b.cab.mass, a.cab.mass);
  EXPECT_EQ(b.cab.cg, a.cab.cg);
  EXPECT_EQ(b.cab.inertia, a.cab.inertia);
  EXPECT_EQ(b.cab_mounts.x, a.cab_mounts.x);
  EXPECT_EQ(b.cab_mounts.stiffness, a.cab_mounts.stiffness);
  EXPECT_EQ(b.axles[1].suspension.spring_stiffness, a.axles[1].suspension.spring_stiffness);
  EXPECT_EQ(b.axles[1].suspension.stabilizer_stiffness, a.axles[1].suspension.stabilizer_stiffness);
  EXPECT_EQ(b.axles[1].suspension.extra_arm_height, a.axles[1].suspension.extra_arm_height);
  EXPECT_EQ(b.steering_ratio, a.steering_ratio);
  EXPECT_EQ(b.steering_stiffness, a.steering_stiffness);
  EXPECT_EQ(b.column_inclination, a.column_inclination);
  EXPECT_EQ(b.drag_link_length, a.drag_link_length);
  EXPECT_EQ(b.axles[0].brake_share, a.axles[0].brake_share);
  EXPECT_EQ(StaticAxleLoads(b, 9.81), StaticAxleLoads(a, 9.81));
  // and it runs the same: 20 m of the lane change at 45 km/h
  LaneChangeOptions o;
  o.file = TruckFile();
  o.speed_kmh = 45.0;
  o.frame = "rigid";
  o.stop_distance = 20.0;
  const LaneChangeResult ra = RunLaneChange(o);
  o.file = split;
  const LaneChangeResult rb = RunLaneChange(o);
  EXPECT_EQ(ra.max_lateral_acceleration, rb.max_lateral_acceleration);
  EXPECT_EQ(ra.min_corridor_margin, rb.min_corridor_margin);
}

TEST(TruckSubsystemFiles, ErrorsNameTheSubsystemFile) {
  const std::string dir = ::testing::TempDir() + "truck_split_bad";
  const std::string split = SplitTruck(dir, {{"axles.0.suspension", "suspension"}});
  // an unknown key in the suspension file: that file and its line
  std::string text;
  {
    std::ifstream in(dir + "/axles_0_suspension.yaml");
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const size_t at = text.find("spring_damping");
  ASSERT_NE(at, std::string::npos);
  std::string bad = text;
  bad.replace(at, std::string("spring_damping").size(), "spring_dampning");
  std::ofstream(dir + "/axles_0_suspension.yaml") << bad;
  std::string e = ErrorOf(split);
  EXPECT_NE(e.find("axles_0_suspension.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("spring_dampning"), std::string::npos) << e;
  EXPECT_EQ(e.find("truck_split.yaml"), std::string::npos) << e;
  // the wrong top-level kind
  std::ofstream(dir + "/axles_0_suspension.yaml") << "steering:\n  ratio: 20\n";
  e = ErrorOf(split);
  EXPECT_NE(e.find("axles_0_suspension.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("'suspension'"), std::string::npos) << e;
  // a file that is not there: the truck file's line
  fs::remove(dir + "/axles_0_suspension.yaml");
  e = ErrorOf(split);
  EXPECT_NE(e.find("truck_split.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("no suspension file"), std::string::npos) << e;
}

}  // namespace truck_subsystem_files_test
}  // namespace flexmb::vehicle::testing
