// Trucks as data (issue 18): the axles as a list.
// - The example 4x2 written in the former two-axle form (wheelbase,
//   front_/rear_ keys, tires, brakes.front_share) reads to the same truck
//   and drives the same lane change bit for bit (reference: the example
//   file itself, examples/truck_lane_change/truck.yaml, in the axles form).
// - The 6x4 with a balancer bogie (examples/truck_6x4/truck.yaml): the
//   static axle loads against a hand calculation (the front axle and the
//   bogie's trunnion as the frame's two supports, the lever rule; the
//   trunnion load shared by the balancer's lever ratio; the unsprung weights
//   straight on their axles), also with the trunnion off the middle so that
//   the two bogie axles carry different loads; and the standing truck's tire
//   loads after settling against the same numbers (the balancer beams'
//   moment balance holds in the multibody model).
// - Bad axle lists are errors naming the file and the axle or bogie; so is
//   a generated frame's element size that would make millions of shells.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/forces/spring_damper.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_axles_test {

namespace fs = std::filesystem;

std::string Example6x4() { return std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_6x4/truck.yaml"; }

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// the example 4x2 in the former two-axle form, beside copies of its tires
std::string TwoAxleForm(const std::string& dir) {
  fs::create_directories(dir);
  const std::string example = std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/";
  for (const char* tire : {"tire_11r22_5.yaml", "tire_11r22_5_twin.yaml"})
    fs::copy_file(example + tire, dir + "/" + tire, fs::copy_options::overwrite_existing);
  YAML::Node root = YAML::LoadFile(example + "truck.yaml");
  YAML::Node t = root["truck"];
  const YAML::Node f = t["axles"][0], r = t["axles"][1];
  t["wheelbase"] = -r["x"].as<double>();
  t["front_track"] = f["track"];
  t["rear_track"] = r["track"];
  t["front_axle"] = f["axle"];
  t["rear_axle"] = r["axle"];
  t["front_wheel"] = f["wheel"];
  t["rear_wheel"] = r["wheel"];
  t["front_suspension"] = f["suspension"];
  t["rear_suspension"] = r["suspension"];
  t["tires"]["front"] = f["tire"];
  t["tires"]["rear"] = r["tire"];
  t["brakes"]["front_share"] = f["brake_share"];
  t.remove("axles");
  const std::string path = dir + "/truck_two_axle_form.yaml";
  std::ofstream(path) << YAML::Dump(root) << "\n";
  return path;
}

TEST(TruckAxles, TwoAxleFormIsTheSameTruck) {
  const std::string dir = ::testing::TempDir() + "truck_two_axle_form";
  const std::string old_form = TwoAxleForm(dir);
  const TruckData a = LoadLaneChangeTruck(TruckFile()), b = LoadLaneChangeTruck(old_form);
  ASSERT_EQ(a.axles.size(), 2u);
  ASSERT_EQ(b.axles.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const AxleData &x = a.axles[i], &y = b.axles[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.x, y.x);
    EXPECT_EQ(x.track, y.track);
    EXPECT_EQ(x.steered, y.steered);
    EXPECT_EQ(x.driven, y.driven);
    EXPECT_EQ(x.brake_share, y.brake_share);
    EXPECT_EQ(x.axle.mass, y.axle.mass);
    EXPECT_EQ(x.axle.inertia, y.axle.inertia);
    EXPECT_EQ(x.wheel.mass, y.wheel.mass);
    EXPECT_EQ(x.wheel.inertia, y.wheel.inertia);
    EXPECT_EQ(x.suspension.spring_stiffness, y.suspension.spring_stiffness);
    EXPECT_EQ(x.suspension.extra_arm_height, y.suspension.extra_arm_height);
    EXPECT_EQ(x.tire.vertical_stiffness, y.tire.vertical_stiffness);
    EXPECT_EQ(x.tire.count, y.tire.count);
  }
  EXPECT_EQ(a.axles[0].name, "front");
  EXPECT_EQ(a.axles[1].name, "rear");
  EXPECT_EQ(StaticAxleLoads(b, 9.81), StaticAxleLoads(a, 9.81));
  // and it drives the same: 20 m of the lane change at 45 km/h, every row equal
  LaneChangeOptions o;
  o.speed_kmh = 45.0;
  o.frame = "rigid";
  o.stop_distance = 20.0;
  o.file = TruckFile();
  o.out_dir = dir + "/new";
  RunLaneChange(o);
  o.file = old_form;
  o.out_dir = dir + "/old";
  RunLaneChange(o);
  const std::string rows_new = ReadText(dir + "/new/results.csv"), rows_old = ReadText(dir + "/old/results.csv");
  EXPECT_GT(rows_new.size(), 10000u);
  EXPECT_EQ(rows_new, rows_old);
}

// hand calculation of the axle loads of a truck with the first axle on its
// own springs and the others on one balancer bogie: the frame rests on the
// front axle (x = 0) and the trunnion (x_t); unsprung weights and half of
// each arm on the axles, the arm's other half at its pivot on the frame
std::vector<double> HandAxleLoads(const TruckData& d, double g) {
  EXPECT_EQ(d.axles.size(), 3u);
  EXPECT_EQ(d.bogies.size(), 1u);
  const double xt = d.bogies[0].x;
  std::vector<double> direct;
  double sprung = 0, moment0 = 0;  // on the frame, moment about x = 0
  auto frame_load = [&](double m, double x) {
    sprung += m * g;
    moment0 += m * g * x;
  };
  for (const PartData* p : {&d.frame, &d.cab, &d.powertrain, &d.cargo}) frame_load(p->mass, p->cg.x());
  frame_load(d.pitman_arm_mass, d.drag_link_length);
  frame_load(d.column_mass, d.drag_link_length - 0.5 * d.column_length * std::sin(d.column_inclination));
  frame_load(2 * d.bogies[0].beam.mass, xt);
  for (const AxleData& a : d.axles) {
    const double patches = a.tire.relaxation_length > 0 ? 2 * a.tire.count * a.tire.patch_mass : 0.0;
    const double unsprung = a.axle.mass + 2 * a.wheel.mass + (a.steered ? 2 * d.knuckle.mass : 0.0) + patches +
                            (a.suspension.extra_arm_height > 0 ? kAxleHubMass : 0.0);
    direct.push_back((unsprung + 0.5 * d.arm.mass) * g);
    frame_load(0.5 * d.arm.mass, a.x + a.suspension.arm_length);
  }
  const double trunnion = moment0 / xt, front = sprung - trunnion;
  const double xm = d.axles[1].x, xr = d.axles[2].x;
  const double middle = trunnion * (xt - xr) / (xm - xr);
  return {direct[0] + front, direct[1] + middle, direct[2] + trunnion - middle};
}

TEST(TruckAxles, BogieStaticAxleLoadsMatchTheHandCalculationAndTheStandingTruck) {
  TruckData d = LoadLaneChangeTruck(Example6x4());
  ASSERT_EQ(d.axles.size(), 3u);
  for (const double xt : {-3.5, -3.2}) {  // the example's trunnion midway, then 0.3 m forward
    d.bogies[0].x = xt;
    const std::vector<double> hand = HandAxleLoads(d, 9.81), loads = StaticAxleLoads(d, 9.81);
    ASSERT_EQ(loads.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(loads[i], hand[i], 1e-9 * hand[i]) << "axle " << i << ", x_t " << xt;
    if (xt == -3.5) {
      EXPECT_NEAR(hand[1], hand[2], 1e-9 * hand[1]);  // a balancer pivoted midway shares equally
      // about 22.6 t gross, 6.1 t on the front axle
      EXPECT_NEAR((hand[0] + hand[1] + hand[2]) / 9.81, 22557.0, 5.0);
      EXPECT_NEAR(hand[0] / 9.81, 6118.0, 5.0);
    } else {
      EXPECT_GT(hand[1], 1.15 * hand[2]);  // the trunnion nearer the middle axle loads it more
    }
    // the standing truck's tire loads after 2 s
    TruckSample last;
    RunTruck(d, 0.0, 0.0, 2.0, false, [&](const TruckSample& s) { last = s; });
    ASSERT_EQ(last.axle_load.size(), 3u);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(last.axle_load[i], hand[i], 2e-3 * hand[i]) << "axle " << i << ", x_t " << xt;
  }
}

// writes the 6x4 example's text `text` to the temporary folder as `name`,
// its tires named by their full paths; returns the path
std::string Write6x4(std::string text, const std::string& name) {
  const std::string tires = "../truck_lane_change/", full = std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/";
  for (size_t p = text.find(tires); p != std::string::npos; p = text.find(tires, p + full.size()))
    text.replace(p, tires.size(), full);
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// the error of loading the 6x4 example with `from` replaced by `to` in its text
std::string ErrorOf6x4With(const std::string& from, const std::string& to, const std::string& name) {
  std::string text = ReadText(Example6x4());
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return "";
  text.replace(at, from.size(), to);
  const std::string path = Write6x4(text, name);
  std::string e;
  try {
    LoadLaneChangeTruck(path);
  } catch (const InputError& err) {
    e = err.what();
  }
  fs::remove(path);
  return e;
}

TEST(TruckAxles, BadAxleListsAreErrorsNamingTheFileAndTheAxle) {
  std::string e = ErrorOf6x4With("x: -4.16", "x: -2.5", "bad_order.yaml");
  EXPECT_NE(e.find("bad_order.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("axle 'rear'"), std::string::npos) << e;
  EXPECT_NE(e.find("front to rear"), std::string::npos) << e;
  e = ErrorOf6x4With("      driven: true\n      brake_share: 0.35\n      axle:  {mass: 750, inertia: [235, 32, 235]}\n"
                     "      wheel: {mass: 260, inertia: [20, 32, 20]}\n      tire: ../truck_lane_change/tire_11r22_5_twin.yaml\n"
                     "      bogie: rear\n      suspension:\n        spring_stiffness: 9.0e5  # per side",
                     "      driven: true\n      brake_share: 0.45\n      axle:  {mass: 750, inertia: [235, 32, 235]}\n"
                     "      wheel: {mass: 260, inertia: [20, 32, 20]}\n      tire: ../truck_lane_change/tire_11r22_5_twin.yaml\n"
                     "      bogie: rear\n      suspension:\n        spring_stiffness: 9.0e5  # per side",
                     "bad_shares.yaml");
  EXPECT_NE(e.find("bad_shares.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("brake_share must sum to 1"), std::string::npos) << e;
  e = ErrorOf6x4With("      bogie: rear\n", "      bogie: tandem\n", "bad_bogie.yaml");
  EXPECT_NE(e.find("bad_bogie.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("no bogie 'tandem'"), std::string::npos) << e;
  e = ErrorOf6x4With("      x: -2.84", "      x: -2.84\n      steered: true", "bad_steer.yaml");
  EXPECT_NE(e.find("axle 'middle'"), std::string::npos) << e;
  EXPECT_NE(e.find("needs an unsteered axle behind it and its own springs"), std::string::npos) << e;
  e = ErrorOf6x4With("      x: -4.16", "      x: -4.16\n      steered: true", "bad_steer3.yaml");
  EXPECT_NE(e.find("axle 'rear'"), std::string::npos) << e;
  EXPECT_NE(e.find("only the first two axles can be steered"), std::string::npos) << e;
  e = ErrorOf6x4With("  kingpin_offset: 0.15", "  kingpin_offset: 0.15\n  wheelbase: 4.2", "bad_key.yaml");
  EXPECT_NE(e.find("bad_key.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("wheelbase"), std::string::npos) << e;
  // a missing part: the truck file's line, not yaml-cpp's "invalid node"
  e = ErrorOf6x4With("  knuckle:    {mass: 45, inertia: [0.7, 0.7, 0.45]}\n", "", "bad_missing.yaml");
  EXPECT_NE(e.find("bad_missing.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("missing part 'knuckle'"), std::string::npos) << e;
  e = ErrorOf6x4With("      beam: {mass: 110,", "      beam: {cg: [0, 0, 1], mass: 110,", "bad_beam.yaml");
  EXPECT_NE(e.find("no 'cg'"), std::string::npos) << e;
  e = ErrorOf6x4With("    - name: middle", "    - name: pitman", "bad_name.yaml");
  EXPECT_NE(e.find("is taken by the truck's other parts"), std::string::npos) << e;
  e = ErrorOf6x4With("      x: -3.5 ", "      x: -4.5 ", "bad_trunnion.yaml");
  EXPECT_NE(e.find("bogie 'rear'"), std::string::npos) << e;
  EXPECT_NE(e.find("between the bogie's axles"), std::string::npos) << e;
}

// inter-leaf friction of the bogie's springs from the file: the springs'
// rate law is the damper plus the smoothed Coulomb force; the standing truck
// still starts in equilibrium (the friction acts on rates only)
TEST(TruckAxles, LeafSpringFrictionActsOnTheSpringsRate) {
  std::string text = ReadText(Example6x4());
  const std::string from = "        spring_damping: 2.5e4\n";
  size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), from + "        friction_force: 3000\n        friction_velocity: 0.02\n");
  const TruckData d = LoadLaneChangeTruck(Write6x4(text, "friction_6x4.yaml"));
  EXPECT_EQ(d.axles[1].suspension.friction_force, 3000.0);
  EXPECT_EQ(d.axles[2].suspension.friction_force, 0.0);
  auto zero = std::make_shared<double>(0.0);
  Model m;
  BuildTruck(d, 0.0, 0.8, zero, zero, m);
  const auto& spring = dynamic_cast<const SpringDamper&>(*m.forces[static_cast<size_t>(m.FindForce("middle_spring_left"))]);
  ASSERT_TRUE(spring.law().force_velocity);
  EXPECT_NEAR(spring.law().force_velocity->Value(0.02), 2.5e4 * 0.02 + 3000.0 * std::tanh(1.0), 1e-9);
  const auto& rear = dynamic_cast<const SpringDamper&>(*m.forces[static_cast<size_t>(m.FindForce("rear_spring_left"))]);
  EXPECT_FALSE(rear.law().force_velocity);
  TruckSample last;
  RunTruck(d, 0.0, 0.0, 1.0, false, [&](const TruckSample& sample) { last = sample; });
  const std::vector<double> loads = StaticAxleLoads(d, 9.81);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(last.axle_load[i], loads[i], 2e-3 * loads[i]) << i;
}

std::string Example8x4() { return std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_8x4/truck.yaml"; }

// The 8x4 (examples/truck_8x4): the second steered axle turns by the
// Ackermann ratio r = (x_2 + L) / L of the first axle's angle (the relay
// rod's levers b and b / r), here at 5 m/s with a held steering-wheel angle,
// both left knuckles' kingpin angles; the three supports (two front axles on
// their springs and the bogie) start in equilibrium: the standing truck's
// tire loads equal the static loads.
TEST(TruckAxles, SecondSteeredAxleTurnsByTheAckermannRatio) {
  const TruckData d = LoadLaneChangeTruck(Example8x4());
  ASSERT_EQ(d.axles.size(), 4u);
  ASSERT_TRUE(d.axles[1].steered);
  const double L = Wheelbase(d), r = SteerRatio(d, 1);
  EXPECT_NEAR(L, 5.74, 1e-12);  // to the trunnion
  EXPECT_NEAR(r, (-1.9 + 5.74) / 5.74, 1e-12);
  auto steer = std::make_shared<double>(0.0), torque = std::make_shared<double>(0.0);
  Model m;
  m.solver.dt = 0.004;
  m.solver.dt_min = 1e-8;
  m.solver.newton_tol = 1e-8;
  const TruckHandles h = BuildTruck(d, 5.0, 0.8, steer, torque, m);
  const int second = m.FindJoint("knuckle_second_left_kingpin");
  ASSERT_GE(second, 0);
  ASSERT_GE(m.FindJoint("relay_rod"), 0);
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  double first_angle = 0, second_angle = 0;
  sim.Run(3.0, 0.0, [&](const State& st, const Workspace& ws) {
    auto angle = [&](int joint) {
      const Joint& j = *m.joints[static_cast<size_t>(joint)];
      return j.Coordinate(0, ws.markers[j.marker_i], ws.markers[j.marker_j], nullptr);
    };
    first_angle = angle(h.kingpin_joint[0]);
    second_angle = angle(second);
    *steer = d.steering_ratio * 0.05 * std::min(1.0, st.t);  // 0.05 rad at the road wheels
  });
  EXPECT_GT(first_angle, 0.03);
  EXPECT_NEAR(second_angle / first_angle, r, 0.01 * r);
  // standing: the static loads of the three supports hold
  const std::vector<double> loads = StaticAxleLoads(d, 9.81);
  double total = 0;
  for (double w : loads) total += w;
  EXPECT_NEAR(total / 9.81, 30000.0, 2000.0);
  TruckSample last;
  RunTruck(d, 0.0, 0.0, 2.0, false, [&](const TruckSample& sample) { last = sample; });
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(last.axle_load[i], loads[i], 2e-3 * loads[i]) << i;
  EXPECT_NEAR(loads[2], loads[3], 1e-9 * loads[2]);  // the trunnion midway
}

// a mistyped element size of the generated frame: an error in the file's
// line before any memory is taken (0.0004 m would make 55 million shells)
TEST(TruckAxles, MistypedFrameElementSizeIsAnError) {
  const std::string e = ErrorOf6x4With("    element_size: 0.04", "    element_size: 0.0004", "bad_mesh.yaml");
  EXPECT_NE(e.find("bad_mesh.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("element_size 0.0004 m makes about"), std::string::npos) << e;
  LadderFrameData l;
  l.element_size = 1e-9;  // the division counts would overflow an int
  EXPECT_THROW(GenerateLadderFrame(l, {}), InputError);
}

}  // namespace truck_axles_test
}  // namespace flexmb::vehicle::testing
