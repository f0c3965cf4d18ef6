// The generated frame's flatbed platform (issue 18: "the frame, platform and
// brackets as an FE shell model"; ladder_frame.h, PlatformData).
// 1. Steel mass: the generated shells against the plates' areas by hand
//    (sills, cross bearers and side rails with their flanges, brackets), with dimensions on the
//    element grid so that the mesh holds them exactly; the non-structural
//    masses bring frame and platform to their given totals.
// 2. Connectivity: the platform touches the frame only through its
//    brackets: without the bracket shells the mesh falls into exactly two
//    parts (frame, platform), with them it is one; each bracket shares the
//    nodes of a rail web's top edge and of a sill web's bottom edge.
// 3. Cargo mounts: the cargo's attachment points lie on the platform's top
//    (PlatformTopZ) and the generated model's nodes carrying them are sill
//    nodes; the cab's stay on the rails.
// 4. Bad platforms are errors naming the problem (too narrow, a bracket off
//    the rails, a mass below the steel, fewer than two brackets).
// The deflection of the 6x4's frame with its platform in the standing truck
// against the full FE model: truck_frame_test.cc. docs/validation.md,
// "Truck frame platform".
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <functional>
#include <numeric>
#include <set>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/common/error.h"
#include "flexmb/vehicle/ladder_frame.h"
#include "flexmb/vehicle/truck_frame.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_platform_test {

// a frame and platform whose dimensions lie on the 0.05 m grid
LadderFrameData GridFrame() {
  LadderFrameData f;
  f.front_x = 1.0;
  f.length = 6.0;
  f.half_spacing = 0.45;
  f.web_height = 0.25;
  f.flange_width = 0.1;
  f.cross_members = {1.0, -2.0, -5.0};
  f.element_size = 0.05;
  f.total_mass = 900;
  PlatformData& p = f.platform;
  p.present = true;
  p.front_x = -1.0;
  p.length = 4.0;
  p.width = 2.5;
  p.spacer = 0.05;
  p.sill_height = 0.15;
  p.sill_flange_width = 0.1;
  p.bearer_spacing = 1.0;  // bearers at -1, -2, -3, -4, -5
  p.brackets = {-1.5, -3.0, -4.5};
  p.bracket_length = 0.2;
  p.mass = 700;
  return f;
}

// connected parts of the mesh through its elements (union-find over nodes)
int Parts(const fe::Mesh& mesh, const std::function<bool(const fe::Element&)>& use) {
  std::vector<int> parent(mesh.nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::function<int(int)> root = [&](int a) {
    int& p = parent[static_cast<size_t>(a)];
    return p == a ? a : p = root(p);
  };
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const fe::Element& e : mesh.elements) {
    if (!use(e)) continue;
    for (int n : e.nodes) {
      used[static_cast<size_t>(n)] = 1;
      parent[static_cast<size_t>(root(n))] = root(e.nodes[0]);
    }
  }
  std::set<int> roots;
  for (size_t k = 0; k < mesh.nodes.size(); ++k)
    if (used[k]) roots.insert(root(static_cast<int>(k)));
  return static_cast<int>(roots.size());
}

TEST(TruckPlatform, SteelMassEqualsThePlatesAreasAndTheTotalsAreKept) {
  const LadderFrameData f = GridFrame();
  const PlatformData& p = f.platform;
  const LadderFrame frame = GenerateLadderFrame(f, {});
  const double rho = f.rho;
  const double sills = 2 * p.length * (p.sill_height + 2 * p.sill_flange_width) * p.sill_thickness;
  // five bearers: a web across the width, a flange beside the sills' flanges
  const double bearers =
      5 * (p.width * p.sill_height + (p.width - 2 * p.sill_flange_width) * p.bearer_flange_width) * p.bearer_thickness;
  const double side_rails = 2 * p.length * (p.sill_height + p.side_rail_flange_width) * p.side_rail_thickness;
  const double brackets = 2 * 3 * p.bracket_length * p.spacer * p.bracket_thickness;
  const double steel = rho * (sills + bearers + side_rails + brackets);
  std::printf("platform steel %.3f kg (hand %.3f kg): sills %.2f, bearers %.2f, side rails %.2f, brackets %.2f kg\n",
              frame.platform_steel_mass, steel, rho * sills, rho * bearers, rho * side_rails, rho * brackets);
  EXPECT_NEAR(frame.platform_steel_mass, steel, 1e-9 * steel);
  const double rails = rho * (2 * f.length * (f.web_height + 2 * f.flange_width) * f.thickness +
                              3 * 2 * f.half_spacing * f.web_height * f.cross_member_thickness);
  EXPECT_NEAR(frame.steel_mass, rails, 1e-9 * rails);
  const MassProperties3 mp = ShellMassProperties(frame.mesh);
  EXPECT_NEAR(mp.mass, f.total_mass + p.mass, 1e-9 * mp.mass);
  // the platform's mass sits above the rails: the centre of mass rises
  // above the frame's alone
  LadderFrameData bare = f;
  bare.platform.present = false;
  EXPECT_GT(mp.cg.z(), ShellMassProperties(GenerateLadderFrame(bare, {}).mesh).cg.z() + 0.1);
}

TEST(TruckPlatform, PlatformTouchesTheFrameOnlyThroughItsBrackets) {
  const LadderFrameData f = GridFrame();
  const fe::Mesh& mesh = GenerateLadderFrame(f, {}).mesh;
  EXPECT_EQ(Parts(mesh, [](const fe::Element&) { return true; }), 1);
  EXPECT_EQ(Parts(mesh, [](const fe::Element& e) { return e.property != kBracketSection; }), 2);
  // each bracket's bottom edge on the rail web's top edge, its top edge on the sill web's bottom edge
  const double z_top = f.bottom_z + f.web_height, zs0 = z_top + f.platform.spacer;
  std::set<int> rail_nodes, sill_nodes;
  for (const fe::Element& e : mesh.elements)
    for (int n : e.nodes) {
      if (e.property == kRailSection) rail_nodes.insert(n);
      if (e.property == kSillSection) sill_nodes.insert(n);
    }
  int bottom = 0, top = 0;
  for (const fe::Element& e : mesh.elements) {
    if (e.property != kBracketSection) continue;
    for (int n : e.nodes) {
      const fe::Vec3& x = mesh.nodes[static_cast<size_t>(n)].x;
      EXPECT_NEAR(std::abs(x.y()), f.half_spacing, 1e-12);
      if (std::abs(x.z() - z_top) < 1e-9) bottom += rail_nodes.count(n) ? 1 : -1000;
      if (std::abs(x.z() - zs0) < 1e-9) top += sill_nodes.count(n) ? 1 : -1000;
    }
  }
  // 2 sides x 3 brackets x 4 elements along x, two corner nodes per element on each edge
  EXPECT_EQ(bottom, 2 * 3 * 4 * 2);
  EXPECT_EQ(top, 2 * 3 * 4 * 2);
}

TEST(TruckPlatform, CargoRestsOnThePlatformTheCabOnTheRails) {
  TruckData d = LoadLaneChangeTruck(std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_6x4/truck.yaml");
  ASSERT_TRUE(d.ladder.platform.present);
  const double top = PlatformTopZ(d.ladder), rails = d.ladder.bottom_z + d.ladder.web_height;
  const GeneratedFrameModel model = BuildGeneratedFrameModel(d, 9.81);
  std::set<int> sill_nodes;
  for (const fe::Element& e : model.mesh.elements)
    if (e.property == kSillSection)
      for (int n : e.nodes) sill_nodes.insert(n);
  int cargo = 0, cab = 0;
  for (const FrameAttachment& a : FrameAttachments(d, 9.81)) {
    const int node = std::find_if(model.mounts.begin(), model.mounts.end(), [&](const auto& m) {
                       return m.first == a.name;
                     })->second;
    if (a.name.rfind("cargo_mount", 0) == 0) {
      ++cargo;
      EXPECT_DOUBLE_EQ(a.point.z(), top) << a.name;
      EXPECT_TRUE(sill_nodes.count(node)) << a.name;
      // within half an element (the mount stations need not lie on the grid)
      EXPECT_LE((model.mesh.nodes[static_cast<size_t>(node)].x - a.point).norm(), 0.5 * d.ladder.element_size + 1e-9)
          << a.name;
    }
    if (a.name.rfind("cab_mount", 0) == 0) {
      ++cab;
      EXPECT_DOUBLE_EQ(a.point.z(), rails) << a.name;
      EXPECT_FALSE(sill_nodes.count(node)) << a.name;
    }
  }
  EXPECT_EQ(cargo, 10);
  EXPECT_EQ(cab, 4);
  // no spider joins the rails to the platform (they meet only at the
  // brackets): the powertrain's rear mounts at x = -1.1 m sit on the rails
  // under the platform, 0.02 m below its sills (found by a review)
  const std::vector<int> part = FramePartOfNodes(model.mesh);
  int under_platform = 0;
  for (const fe::RigidLink& link : model.mesh.rigid_links) {
    const fe::Vec3& x = model.mesh.nodes[static_cast<size_t>(link.independent)].x;
    if (x.x() < d.ladder.platform.front_x && part[static_cast<size_t>(link.independent)] == 0 &&
        x.z() > d.ladder.bottom_z + 0.5 * d.ladder.web_height)
      ++under_platform;
    for (int n : link.dependent)
      EXPECT_EQ(part[static_cast<size_t>(n)], part[static_cast<size_t>(link.independent)])
          << "rigid link " << link.id << " at x = " << x.x();
  }
  EXPECT_GE(under_platform, 2);  // the powertrain's two rear mounts: the case is there
}

TEST(TruckPlatform, BadPlatformsAreErrors) {
  auto message = [](const LadderFrameData& f) {
    try {
      GenerateLadderFrame(f, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  LadderFrameData f = GridFrame();
  f.platform.width = 0.9;
  EXPECT_NE(message(f).find("leaves no overhang"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.brackets = {-1.5, -5.5};  // off the platform (it ends at -5.0)
  EXPECT_NE(message(f).find("bracket at x = -5.5"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.brackets = {-1.5};
  EXPECT_NE(message(f).find("at least two"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.mass = 100;
  EXPECT_NE(message(f).find("below its steel mass"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.sill_height = -0.1;
  EXPECT_NE(message(f).find("'sill_height' must be positive, not -0.1"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.brackets = {-3.0, -3.0};  // twice the same (found by a user test: the elastic statics then failed)
  EXPECT_NE(message(f).find("brackets at x = -3 and -3 m overlap"), std::string::npos) << message(f);
  f.platform.brackets = {-1.5, -1.6};
  EXPECT_NE(message(f).find("overlap (bracket_length 0.2 m)"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.bracket_length = 0.01;  // shorter than an element: both land on one element of the grid
  f.platform.brackets = {-3.0, -3.015};
  EXPECT_NE(message(f).find("shares its elements with another"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.spacer = 1e-4;
  EXPECT_NE(message(f).find("'spacer' must be at least 1 mm"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.mass = 10;  // at the platform's line in a truck file: the message starts with "platform: "
  EXPECT_EQ(message(f).rfind("ladder frame: platform: mass 10 kg is below its steel mass", 0), 0u) << message(f);
  f = GridFrame();
  f.platform.width = 30;  // the shell count's estimate must see the bearers' flanges and side rails
  f.platform.side_rail_flange_width = 14;
  f.platform.bearer_spacing = 6.3;
  f.platform.bearer_flange_width = 3;
  f.element_size = 0.02;
  EXPECT_NE(message(f).find("or check the platform's size and bearer_spacing"), std::string::npos) << message(f);
  f = GridFrame();
  f.platform.front_x = 1.5;  // ahead of the rails' front end at 1.0
  f.platform.brackets = {-1.5, -3.0};
  EXPECT_NE(message(f).find("ahead of the rails' front end"), std::string::npos) << message(f);
}

// `flexmb check` summarises the generated frame and its platform (a user
// test found it silent about them)
TEST(TruckPlatform, CheckSummarisesThePlatform) {
  LaneChangeOptions opt;
  opt.file = std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_6x4/truck.yaml";
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  CheckLaneChange(opt, out);
  std::rewind(out);
  std::string text;
  for (int c; (c = std::fgetc(out)) != EOF;) text.push_back(static_cast<char>(c));
  std::fclose(out);
  EXPECT_NE(text.find("frame: generated ladder frame, 12068 shells, 1900 kg (rails and cross members 1000 kg, "
                      "platform 900 kg: x = -7.05 to -0.75 m, 2.50 m wide, 5 brackets per side; the cargo on its top "
                      "at z = 1.210 m)"),
            std::string::npos)
      << text;
}

// errors of a truck file's platform name the platform's line
TEST(TruckPlatform, TruckFileErrorsNameThePlatformsLine) {
  const std::string example = std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_6x4/truck.yaml";
  std::ifstream in(example);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  int platform_line = 0;
  {
    std::istringstream lines(text);
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n)
      if (line.rfind("    platform:", 0) == 0) platform_line = n;
  }
  ASSERT_GT(platform_line, 0);
  auto message = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) t.replace(at, from.size(), to);
    // the tire files by absolute paths, the file in the temporary folder
    for (size_t k; (k = t.find("../truck_lane_change/")) != std::string::npos;)
      t.replace(k, 2, std::string(FLEXMB_SOURCE_DIR) + "/examples");
    const std::string path =
        (std::filesystem::temp_directory_path() / ("flexmb_platform_test_" + std::to_string(::getpid()) + ".yaml"))
            .string();
    std::ofstream(path) << t;
    std::string what = "no error";
    try {
      LoadLaneChangeTruck(path);
    } catch (const InputError& e) {
      what = e.what();
    }
    std::filesystem::remove(path);
    return what;
  };
  // a block map's line is its first key's (yaml-cpp), the line after "platform:"
  const std::string at = ".yaml:" + std::to_string(platform_line + 1) + ":";
  // from the generator (the bracket off the platform), at the platform's line, not the frame's
  std::string m = message("brackets: [-1.0,", "brackets: [-0.5,");
  EXPECT_NE(m.find(at), std::string::npos) << m;
  EXPECT_NE(m.find("bracket at x = -0.5 m (bracket_length 0.2 m) is not under the platform"), std::string::npos) << m;
  // the cargo's mount stations on the platform
  m = message("mount_x: [-0.9, -1.9, -2.9, -3.9, -4.9]", "mount_x: [-0.5, -1.9, -2.9, -3.9, -4.9]");
  EXPECT_NE(m.find(at), std::string::npos) << m;
  EXPECT_NE(m.find("the cargo's mount station x = -0.5 m is off the platform"), std::string::npos) << m;
}

}  // namespace truck_platform_test
}  // namespace flexmb::vehicle::testing
