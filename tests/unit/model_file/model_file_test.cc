#include "flexmb/model_file/model_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/joints/distance.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/model/workspace.h"
#include "flexmb/solver/initial_conditions.h"

namespace flexmb {
namespace {

// joins lines with '\n' so that line k of the text is element k-1
std::string Text(std::initializer_list<const char*> lines) {
  std::string out;
  for (const char* l : lines) out += std::string(l) + "\n";
  return out;
}

// loads `yaml` as "bad.yaml" and checks the error names the file and `line` (0: none)
// and contains every one of `parts`
void ExpectError(const std::string& yaml, int line, std::initializer_list<const char*> parts) {
  try {
    LoadModelString(yaml, "bad.yaml");
    ADD_FAILURE() << "no error for:\n" << yaml;
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string where = line > 0 ? "bad.yaml:" + std::to_string(line) + ": " : "bad.yaml: ";
    EXPECT_EQ(what.rfind(where, 0), 0u) << "expected to start with '" << where << "': " << what;
    for (const char* p : parts) EXPECT_NE(what.find(p), std::string::npos) << "missing '" << p << "' in: " << what;
  }
}

// a valid two-body model; the bad-input cases edit copies of it
const std::string kGood = Text({
    "name: four_bar",                                                             // 1
    "gravity: [0, -9.81, 0]",                                                     // 2
    "ground:",                                                                    // 3
    "  markers:",                                                                 // 4
    "    - {name: o, position: [0, 0, 0]}",                                       // 5
    "    - {name: p, position: [2, 0, 0], orientation: {z_axis: [0, 0, 1]}}",     // 6
    "  shape: {type: sphere, radius: 0.05}",                                      // 7
    "bodies:",                                                                    // 8
    "  - name: crank",                                                            // 9
    "    type: rigid",                                                            // 10
    "    mass: 2.0",                                                              // 11
    "    center_of_mass: [0.5, 0, 0]",                                            // 12
    "    inertia: [0.7, 0.4, 1.0]",                                               // 13
    "    inertia_frame: {position: [0, 0.2, 0], orientation: {rotation_vector: [0, 0, 1.5707963267948966]}}",  // 14
    "    orientation: {roll_pitch_yaw_deg: [0, 0, 90]}",                          // 15
    "    angular_velocity: [0, 0, 3]",                                            // 16
    "    markers:",                                                               // 17
    "      - {name: o}",                                                          // 18
    "      - name: tip",                                                          // 19
    "        position: [1, 0, 0]",                                                // 20
    "        orientation: {rotation_vector: [0, 0, 1.5707963267948966]}",         // 21
    "    shape: {type: box, size: [1, 0.05, 0.05], position: [0.5, 0, 0]}",       // 22
    "  - name: rod",                                                              // 23
    "    mass: 1.5",                                                              // 24
    "    inertia: [1, 2, 2.5, 0.1, 0.2, 0.3]",                                    // 25
    "    position: [0.6, 1.8, 0]",                                                // 26
    "    velocity: [1, 0, 0]",                                                    // 27
    "    markers:",                                                               // 28
    "      - {name: a}",                                                          // 29
    "      - {name: b, position: [1, 0, 0]}",                                     // 30
    "    shape: {type: cylinder, radius: 0.02, length: 1, orientation: {z_axis: [1, 0, 0]}}",  // 31
    "joints:",                                                                    // 32
    "  - {name: j1, type: revolute, i: ground.o, j: crank.o}",                    // 33
    "  - {name: link, type: distance, i: crank.tip, j: rod.a}",                   // 34
    "  - {name: slide, type: distance, i: ground.p, j: rod.b, length: 1.25}",     // 35
    "drivers:",                                                                   // 36
    "  - {name: drive, joint: j1, coordinate: angle, function: {expression: \"2*pi*t\"}}",  // 37
    "solver: {t_end: 2, dt: 0.001, rho_inf: 0.9, adaptive: true, max_newton: 8}",  // 38
    "output: {interval: 0.01, animation: true}",                                  // 39
});

// kGood with line `line` (1-based) replaced by `text`
std::string Replace(int line, const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  for (size_t end; (end = kGood.find('\n', start)) != std::string::npos; start = end + 1)
    lines.push_back(kGood.substr(start, end - start));
  lines.at(line - 1) = text;
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

TEST(ModelFile, LoadsGoodModel) {
  auto m = LoadModelString(kGood, "good.yaml");
  ASSERT_TRUE(m->finalized());
  EXPECT_EQ(m->name, "four_bar");
  EXPECT_EQ(m->gravity_W, Vec3(0, -9.81, 0));
  ASSERT_EQ(m->bodies.size(), 3u);  // ground, crank, rod
  EXPECT_EQ(m->markers.size(), 6u);
  ASSERT_EQ(m->joints.size(), 4u);  // j1, link, slide, drive
  EXPECT_EQ(m->nq, 14);
  EXPECT_EQ(m->nv, 12);
  EXPECT_EQ(m->nc, 5 + 1 + 1 + 1);

  const auto& crank = dynamic_cast<const RigidBody&>(*m->bodies[m->FindBody("crank")]);
  const auto& rod = dynamic_cast<const RigidBody&>(*m->bodies[m->FindBody("rod")]);
  EXPECT_DOUBLE_EQ(crank.mass(), 2.0);
  EXPECT_DOUBLE_EQ(rod.mass(), 1.5);

  // inertia (0.7, 0.4, 1.0) about F at (0, 0.2, 0) with F turned +90 deg about z:
  // in body axes diag(0.4, 0.7, 1.0); parallel axis to C = (0.5, 0, 0), d = C - F =
  // (0.5, -0.2, 0), m = 2: m(|d|^2 1 - d d^T) = [[0.08, 0.2, 0], [0.2, 0.5, 0], [0, 0, 0.58]]
  Mat3 expected;
  expected << 0.32, -0.2, 0, -0.2, 0.2, 0, 0, 0, 0.42;
  EXPECT_LT((crank.inertia_C() - expected).cwiseAbs().maxCoeff(), 1e-12) << crank.inertia_C();
  // six-entry form: products of inertia are tensor entries
  Mat3 rod_I;
  rod_I << 1, 0.1, 0.2, 0.1, 2, 0.3, 0.2, 0.3, 2.5;
  EXPECT_LT((rod.inertia_C() - rod_I).cwiseAbs().maxCoeff(), 1e-15);

  // markers are stored relative to the centre of mass, axes of the body frame
  const Marker& tip = m->markers[m->FindMarker("crank.tip")];
  EXPECT_LT((tip.p_BM - Vec3(0.5, 0, 0)).norm(), 1e-15);
  Mat3 Rz;
  Rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_LT((tip.R_BM - Rz).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((m->markers[m->FindMarker("crank.o")].p_BM - Vec3(-0.5, 0, 0)).norm(), 1e-15);
  EXPECT_LT((m->markers[m->FindMarker("ground.p")].p_BM - Vec3(2, 0, 0)).norm(), 1e-15);
  EXPECT_LT((m->markers[m->FindMarker("ground.p")].R_BM - Mat3::Identity()).norm(), 1e-15);

  // default distance = initial distance: crank turned 90 deg puts the tip at (0, 1, 0);
  // rod.a at (0.6, 1.8, 0) is 1.0 away
  const auto& link = dynamic_cast<const DistanceJoint&>(*m->joints[m->FindJoint("link")]);
  EXPECT_NEAR(link.length(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(dynamic_cast<const DistanceJoint&>(*m->joints[m->FindJoint("slide")]).length(), 1.25);

  const auto& drive = dynamic_cast<const MotionDriver&>(*m->joints[m->FindJoint("drive")]);
  EXPECT_EQ(drive.target(), m->joints[m->FindJoint("j1")].get());
  EXPECT_EQ(drive.marker_i, m->FindMarker("ground.o"));
  EXPECT_EQ(drive.marker_j, m->FindMarker("crank.o"));
  EXPECT_NEAR(drive.function().Value(0.25), M_PI / 2, 1e-12);

  // initial state: crank com at R_z(90) (0.5, 0, 0) = (0, 0.5, 0)
  const State s = m->InitialState();
  const int q = crank.q_offset;
  EXPECT_LT((s.q.segment<3>(q) - Vec3(0, 0.5, 0)).norm(), 1e-15);
  EXPECT_NEAR(s.q(q + 3), std::sqrt(0.5), 1e-15);  // quaternion w of 90 deg about z
  // v_C = w x (R c) = (0, 0, 3) x (0, 0.5, 0) = (-1.5, 0, 0)
  EXPECT_LT((s.v.segment<3>(crank.v_offset) - Vec3(-1.5, 0, 0)).norm(), 1e-14);
  EXPECT_LT((s.v.segment<3>(rod.v_offset) - Vec3(1, 0, 0)).norm(), 1e-15);

  EXPECT_EQ(m->bodies[0]->shape.type, Shape::Type::kSphere);
  EXPECT_EQ(crank.shape.type, Shape::Type::kBox);
  EXPECT_EQ(crank.shape.size, Vec3(1, 0.05, 0.05));
  EXPECT_EQ(rod.shape.type, Shape::Type::kCylinder);
  EXPECT_EQ(rod.shape.size, Vec3(0.02, 1, 0));
  EXPECT_LT((rod.shape.R_BS.col(2) - Vec3(1, 0, 0)).norm(), 1e-15);

  EXPECT_DOUBLE_EQ(m->solver.t_end, 2.0);
  EXPECT_DOUBLE_EQ(m->solver.dt, 0.001);
  EXPECT_DOUBLE_EQ(m->solver.rho_inf, 0.9);
  EXPECT_TRUE(m->solver.adaptive);
  EXPECT_EQ(m->solver.max_newton, 8);
  EXPECT_DOUBLE_EQ(m->solver.rtol, SolverSettings{}.rtol);
  EXPECT_FALSE(m->solver.jacobian_reuse);
  const auto reuse = LoadModelString(Replace(38, "solver: {jacobian_reuse: true, jacobian_reuse_rate: 0.1}"), "r.yaml");
  EXPECT_TRUE(reuse->solver.jacobian_reuse);
  EXPECT_DOUBLE_EQ(reuse->solver.jacobian_reuse_rate, 0.1);
  EXPECT_DOUBLE_EQ(m->output.interval, 0.01);
  EXPECT_TRUE(m->output.animation);
}

TEST(ModelFile, InertiaFormsAgree) {
  // the same body given about its centre of mass and about the body origin
  // (parallel axis: I_O = I_C + m (|c|^2 1 - c c^T), c = (0, 0, 0.5), m = 4)
  auto one = [](const char* inertia, const char* frame) {
    const std::string yaml = std::string("bodies:\n  - name: b\n    mass: 4\n    center_of_mass: [0, 0, 0.5]\n") +
                             "    inertia: " + inertia + "\n" + (frame ? std::string("    inertia_frame: ") + frame + "\n" : "");
    auto m = LoadModelString(yaml, "inertia.yaml");
    return dynamic_cast<const RigidBody&>(*m->bodies[1]).inertia_C();
  };
  const Mat3 Ic = one("[0.3, 0.3, 0.2]", nullptr);
  EXPECT_LT((one("[1.3, 1.3, 0.2]", "body") - Ic).norm(), 1e-14);
  EXPECT_LT((one("[[1.3, 0, 0], [0, 1.3, 0], [0, 0, 0.2]]", "body") - Ic).norm(), 1e-14);
  EXPECT_EQ(one("[0.3, 0.3, 0.2]", "com"), Ic);
}

TEST(ModelFile, OrientationForms) {
  auto marker_R = [](const char* orientation) {
    const std::string yaml = std::string("ground:\n  markers:\n    - {name: m, orientation: ") + orientation + "}\n";
    auto m = LoadModelString(yaml, "orientation.yaml");
    return m->markers.at(0).R_BM;
  };
  // 90 deg about x in every form: y -> z, z -> -y
  Mat3 Rx;
  Rx << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  for (const char* form :
       {"{quaternion: [1, 1, 0, 0]}", "{rotation_vector: [1.5707963267948966, 0, 0]}",
        "{roll_pitch_yaw: [1.5707963267948966, 0, 0]}", "{roll_pitch_yaw_deg: [90, 0, 0]}",
        "{z_axis: [0, -2, 0], x_axis: [1, 0.5, 0]}", "{matrix: [[1, 0, 0], [0, 0, -1], [0, 1, 0]]}"})
    EXPECT_LT((marker_R(form) - Rx).cwiseAbs().maxCoeff(), 1e-15) << form;
  // z_axis alone: an orthonormal right-handed frame with that z axis
  const Mat3 R = marker_R("{z_axis: [1, 2, 2]}");
  EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), 1e-15);
  EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
  EXPECT_LT((R.col(2) - Vec3(1, 2, 2) / 3.0).norm(), 1e-15);
  EXPECT_LT((marker_R("{z_axis: [0, 0, 5]}") - Mat3::Identity()).norm(), 1e-15);
}

TEST(ModelFile, FunctionForms) {
  auto driver_f = [](const char* f) {
    const std::string yaml = Text({"ground: {markers: [{name: o}]}",
                                   "bodies: [{name: b, mass: 1, inertia: [1, 1, 1], markers: [{name: o}]}]",
                                   "joints: [{name: j, type: prismatic, i: ground.o, j: b.o}]",
                                   "drivers:"}) +
                             "  - {name: d, joint: j, function: " + f + "}\n";
    auto m = LoadModelString(yaml, "function.yaml");
    return dynamic_cast<const MotionDriver&>(*m->joints.at(1)).function().Value(1.5);
  };
  EXPECT_DOUBLE_EQ(driver_f("0.25"), 0.25);
  EXPECT_NEAR(driver_f("{expression: \"t^2\"}"), 2.25, 1e-14);
  // linear table: halfway between (1, 2) and (2, 4)
  EXPECT_NEAR(driver_f("{table: [[0, 0], [1, 2], [2, 4]]}"), 3.0, 1e-14);
  // held at the end value without extrapolation, continued with it
  EXPECT_NEAR(driver_f("{table: [[0, 0], [1, 2]]}"), 2.0, 1e-14);
  EXPECT_NEAR(driver_f("{table: [[0, 0], [1, 2]], extrapolate: true}"), 3.0, 1e-14);
  // a spline through points of a straight line is that line
  EXPECT_NEAR(driver_f("{table: [[0, 1], [1, 2], [2, 3], [4, 5]], interpolation: spline}"), 2.5, 1e-12);
}

TEST(ModelFile, LoadModelFileReadsFile) {
  const std::string path = ::testing::TempDir() + "flexmb_model_file_test.yaml";
  {
    std::ofstream out(path);
    out << kGood;
  }
  auto m = LoadModelFile(path);
  EXPECT_EQ(m->bodies.size(), 3u);
  {
    std::ofstream out(path);
    out << Replace(24, "    mass: -3");
  }
  try {
    LoadModelFile(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ":24: body 'rod': 'mass' must be positive", 0), 0u) << e.what();
  }
  std::remove(path.c_str());
}

TEST(ModelFile, MissingFile) {
  try {
    LoadModelFile("/nonexistent/dir/pendulum.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("/nonexistent/dir/pendulum.yaml: ", 0), 0u) << what;
    EXPECT_NE(what.find("cannot open"), std::string::npos) << what;
  }
}

TEST(ModelFile, UnknownKeys) {
  ExpectError(Replace(38, "solvr: {t_end: 2}"), 38, {"unknown key 'solvr'", "allowed: name, gravity"});
  ExpectError(Replace(24, "    masss: 1.5"), 24, {"body #2", "unknown key 'masss'", "allowed: name, type, mass"});
  ExpectError(Replace(33, "  - {name: j1, type: revolute, i: ground.o, j: crank.o, axis: [0, 0, 1]}"), 33,
              {"joint 'j1'", "unknown key 'axis'", "allowed: name, type, i, j"});
  // length belongs to distance joints only
  ExpectError(Replace(33, "  - {name: j1, type: revolute, i: ground.o, j: crank.o, length: 1}"), 33,
              {"unknown key 'length'"});
  ExpectError(Replace(38, "solver: {t_end: 2, dt: 0.001, step: 2}"), 38, {"solver: unknown key 'step'"});
  ExpectError(Replace(21, "        orientation: {rotation_vector: [0, 0, 1], z_axis: [0, 0, 1]}"), 21,
              {"marker 'crank.tip'", "exactly one of"});
  ExpectError(Replace(22, "    shape: {type: box, size: [1, 1, 1], radius: 2}"), 22,
              {"body 'crank'", "unknown key 'radius'"});
  ExpectError(Replace(25, "    mass: 1.5"), 25, {"body #2", "duplicate key 'mass'"});
}

TEST(ModelFile, Names) {
  ExpectError(Replace(23, "  - nam: rod"), 23, {"body #2", "unknown key 'nam'"});
  ExpectError(Replace(23, "  - type: rigid"), 23, {"body #2", "missing required key 'name'"});
  ExpectError(Replace(23, "  - name: crank"), 23, {"body 'crank'", "duplicate name"});
  ExpectError(Replace(30, "      - {name: a, position: [1, 0, 0]}"), 30, {"marker 'rod.a'", "duplicate name"});
  ExpectError(Replace(34, "  - {name: j1, type: distance, i: crank.tip, j: rod.a}"), 34, {"joint 'j1'", "duplicate name"});
  ExpectError(Replace(37, "  - {name: j1, joint: j1, function: 1}"), 37, {"joint 'j1'", "duplicate name"});
  ExpectError(Replace(23, "  - name: ground"), 23, {"'ground' is reserved"});
  ExpectError(Replace(23, "  - name: rod.x"), 23, {"must not contain '.'"});
  ExpectError(Replace(29, "      - {position: [0, 0, 0]}"), 29, {"body 'rod'", "missing required key 'name'"});
}

TEST(ModelFile, MarkerReferences) {
  ExpectError(Replace(34, "  - {name: link, type: distance, i: crank.tip, j: bar.a}"), 34,
              {"joint 'link'", "marker 'bar.a'", "there is no body named 'bar'"});
  ExpectError(Replace(34, "  - {name: link, type: distance, i: crank.top, j: rod.a}"), 34,
              {"joint 'link'", "body 'crank' has no marker named 'top'"});
  ExpectError(Replace(34, "  - {name: link, type: distance, i: crank, j: rod.a}"), 34, {"must read 'body.marker'"});
  ExpectError(Replace(34, "  - {name: link, type: distance, i: rod.b, j: rod.a}"), 34,
              {"joint 'link'", "both on body 'rod'", "two different bodies"});
  ExpectError(Replace(37, "  - {name: drive, joint: j9, function: 1}"), 37, {"driver 'drive'", "no joint named 'j9'"});
}

TEST(ModelFile, BadBodyValues) {
  ExpectError(Replace(24, "    mass: 0"), 24, {"body 'rod'", "'mass' must be positive, got 0"});
  ExpectError(Replace(24, "    mass: -1.5"), 24, {"body 'rod'", "'mass' must be positive, got -1.5"});
  ExpectError(Replace(24, "    mass: .nan"), 24, {"body 'rod'", "'mass' must be a finite number"});
  ExpectError(Replace(24, "    mass: heavy"), 24, {"body 'rod'", "expected a number for 'mass', got 'heavy'"});
  ExpectError(Replace(24, "    mass: \"1.5\""), 24, {"body 'rod'", "expected a number for 'mass'"});
  ExpectError(Replace(26, "    position: [0.6, .inf, 0]"), 26, {"body 'rod'", "'position' entry 2 must be a finite number"});
  ExpectError(Replace(26, "    position: [0.6, 1.8]"), 26, {"body 'rod'", "expected 3 numbers", "'position'", "list of 2"});
  ExpectError(Replace(25, "    inertia: [1, 1, -1]"), 25, {"body 'rod'", "not positive definite"});
  ExpectError(Replace(25, "    inertia: [1, 1, 3]"), 25, {"body 'rod'", "triangle inequality"});
  ExpectError(Replace(25, "    inertia: [1, 1]"), 25, {"body 'rod'", "expected 'inertia' as"});
  ExpectError(Replace(25, "    inertia: [[1, 0, 0], [0.1, 1, 0], [0, 0, 1]]"), 25, {"body 'rod'", "not symmetric"});
  // inertia given about the body origin that is too small for the offset centre of mass
  ExpectError(Replace(14, "    inertia_frame: body"), 13, {"body 'crank'", "not positive definite"});
  ExpectError(Replace(10, "    type: elastic"), 10, {"body 'crank'", "'elastic' is not supported yet"});
  ExpectError(Replace(22, "    shape: {type: cone, radius: 1}"), 22, {"unknown shape type 'cone'"});
}

TEST(ModelFile, BadOrientations) {
  ExpectError(Replace(21, "        orientation: {z_axis: [0, 0, 0]}"), 21, {"marker 'crank.tip'", "'z_axis' must not be the zero vector"});
  ExpectError(Replace(21, "        orientation: {z_axis: [0, 0, 1], x_axis: [0, 0, -2]}"), 21, {"parallel"});
  ExpectError(Replace(21, "        orientation: {matrix: [[1, 0, 0], [0, 1, 0.01], [0, 0, 1]]}"), 21,
              {"marker 'crank.tip'", "not orthonormal"});
  ExpectError(Replace(21, "        orientation: {matrix: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]}"), 21, {"reflection"});
  ExpectError(Replace(21, "        orientation: {quaternion: [0, 0, 0, 0]}"), 21, {"'quaternion' must not be zero"});
  ExpectError(Replace(15, "    orientation: {roll_pitch_yaw_deg: [0, 0, .inf]}"), 15, {"body 'crank'", "finite"});
}

TEST(ModelFile, BadJointsAndDrivers) {
  ExpectError(Replace(33, "  - {name: j1, type: hinge, i: ground.o, j: crank.o}"), 33,
              {"joint 'j1'", "unknown joint type 'hinge'", "revolute"});
  // crank.o and ground.o coincide initially
  ExpectError(Replace(35, "  - {name: slide, type: distance, i: ground.o, j: crank.o}"), 35,
              {"joint 'slide'", "default length", "zero"});
  ExpectError(Replace(35, "  - {name: slide, type: distance, i: ground.p, j: rod.b, length: -1}"), 35,
              {"joint 'slide'", "'length' must be positive"});
  ExpectError(Replace(37, "  - {name: drive, joint: j1, function: {expression: \"2*pi*\"}}"), 37,
              {"driver 'drive'", "invalid expression '2*pi*'"});
  ExpectError(Replace(37, "  - {name: drive, joint: j1, function: {expression: \"2*x\"}}"), 37,
              {"driver 'drive'", "invalid expression"});
  ExpectError(Replace(37, "  - {name: drive, joint: j1, function: {table: [[0, 0], [1, 1], [0.5, 2]]}}"), 37,
              {"driver 'drive'", "must increase strictly"});
  ExpectError(Replace(37, "  - {name: drive, joint: j1, function: {table: [[0, 0], [1, 1]], interpolation: cubic}}"), 37,
              {"unknown interpolation 'cubic'"});
  ExpectError(Replace(37, "  - {name: drive, joint: j1, coordinate: translation, function: 1}"), 37,
              {"driver 'drive'", "no coordinate 'translation'", "angle"});
  ExpectError(Replace(33, "  - {name: j1, type: spherical, i: ground.o, j: crank.o}"), 37,
              {"driver 'drive'", "spherical joint, which has no joint coordinate"});
}

TEST(ModelFile, BadSettings) {
  ExpectError(Replace(38, "solver: {t_end: 2, dt: 0}"), 38, {"solver: 'dt' must be positive"});
  ExpectError(Replace(38, "solver: {t_end: 2, dt: -0.001}"), 38, {"solver: 'dt' must be positive"});
  ExpectError(Replace(38, "solver: {t_end: 2, rho_inf: 1.5}"), 38, {"solver: 'rho_inf' must lie in [0, 1]"});
  ExpectError(Replace(38, "solver: {t_end: 2, rho_inf: -0.1}"), 38, {"'rho_inf' must lie in [0, 1]"});
  ExpectError(Replace(38, "solver: {t_end: 0}"), 38, {"'t_end' must be positive"});
  ExpectError(Replace(38, "solver: {max_newton: 2.5}"), 38, {"'max_newton' must be a whole number"});
  ExpectError(Replace(38, "solver: {adaptive: maybe}"), 38, {"expected true or false for 'adaptive'"});
  ExpectError(Replace(38, "solver: {jacobian_reuse_rate: 1}"), 38, {"'jacobian_reuse_rate' must lie in (0, 1)"});
  ExpectError(Replace(39, "output: {animation_interval: 0}"), 39, {"output: 'animation_interval' must be positive"});
  ExpectError(Replace(2, "gravity: [0, -9.81, zero]"), 2, {"expected a number for 'gravity' entry 3"});
}

TEST(ModelFile, SyntaxErrors) {
  // unclosed flow sequence in line 26
  ExpectError(Replace(26, "    position: [0.6, 1.8, 0"), 27, {"YAML syntax error"});
  // a tab or a second colon in a plain block mapping value
  ExpectError(Replace(11, "    mass: 2.0: 3"), 11, {"YAML syntax error"});
  ExpectError("", 0, {"empty"});
  ExpectError("- a\n- b\n", 1, {"expected a map"});
}

// the example of docs/model-file.md and every examples/*/model.yaml load
TEST(ModelFile, DocumentedExamplesLoad) {
  std::ifstream doc(std::string(FLEXMB_SOURCE_DIR) + "/docs/model-file.md");
  ASSERT_TRUE(doc.good());
  std::string line, yaml;
  bool in_example = false, seen_heading = false;
  while (std::getline(doc, line)) {
    if (line.rfind("## Example", 0) == 0) seen_heading = true;
    if (seen_heading && line == "```yaml" && yaml.empty()) {
      in_example = true;
    } else if (in_example && line == "```") {
      break;
    } else if (in_example) {
      yaml += line + "\n";
    }
  }
  auto m = LoadModelString(yaml, "model-file.md");
  ASSERT_EQ(m->bodies.size(), 2u);
  // rod 0.3 kg (1 m) + bob 0.9 kg at 1 m, about the centre of mass c = 0.875:
  // 0.3/12 + 0.3 (0.5 - c)^2 + 0.9 (1 - c)^2 = 0.08125 (x axis: only the 1e-4 given)
  const Mat3& I = dynamic_cast<const RigidBody&>(*m->bodies[1]).inertia_C();
  EXPECT_NEAR(I(2, 2), 0.3 / 12 + 0.3 * 0.375 * 0.375 + 0.9 * 0.125 * 0.125, 1e-12);
  EXPECT_NEAR(I(1, 1), I(2, 2), 1e-12);
  EXPECT_NEAR(I(0, 0), 1e-4, 1e-15);

  int examples = 0;
  for (const auto& dir : std::filesystem::directory_iterator(std::string(FLEXMB_SOURCE_DIR) + "/examples")) {
    const auto path = dir.path() / "model.yaml";
    if (!std::filesystem::exists(path)) continue;
    ++examples;
    EXPECT_NO_THROW(LoadModelFile(path.string())) << path;
  }
  EXPECT_GT(examples, 0);
}

// a pendulum pinned by a second revolute joint on the same axis (redundant but
// consistent), or on an axis tilted by 0.1 rad (inconsistent)
std::string TwoPins(const char* second_axis) {
  return Text({"gravity: [0, -9.81, 0]",
               "ground:",
               "  markers:",
               "    - {name: a, position: [0, 0, 0]}"}) +
         "    - {name: b, position: [0, 0, 1], orientation: {z_axis: " + second_axis + "}}\n" +
         Text({"bodies:",
               "  - name: bob",
               "    mass: 1",
               "    inertia: [0.01, 0.01, 0.01]",
               "    position: [1, 0, 0]",
               "    markers:",
               "      - {name: a, position: [-1, 0, 0]}",
               "      - {name: b, position: [-1, 0, 1]}",
               "joints:",
               "  - {name: pin1, type: revolute, i: ground.a, j: bob.a}",
               "  - {name: pin2, type: revolute, i: ground.b, j: bob.b}"});
}

TEST(ModelFile, OverConstrainedIsFoundAtRunTime) {
  std::vector<std::string> warnings;
  const LogSink old = SetWarningSink([&](const std::string& w) { warnings.push_back(w); });
  {
    auto m = LoadModelString(TwoPins("[0, 0, 1]"), "two_pins.yaml");
    State s = m->InitialState();
    Workspace ws;
    const ConstraintReport rep = MakeConsistent(*m, s, ws);
    // pin2 repeats pin1: its 5 equations add nothing, one rotation is left
    EXPECT_EQ(rep.redundant.size(), 5u);
    EXPECT_EQ(rep.dof, 1);
    // one warning for the joint, naming its 5 removed equations
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("joint 'pin2': 5 redundant constraint equations removed ("), std::string::npos)
        << warnings[0];
  }
  {
    auto m = LoadModelString(TwoPins("[0.1, 0, 1]"), "two_pins.yaml");
    State s = m->InitialState();
    Workspace ws;
    try {
      MakeConsistent(*m, s, ws);
      ADD_FAILURE() << "no error for a misaligned second pin";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("joint 'pin2'"), std::string::npos) << what;
      EXPECT_NE(what.find("over-constrained"), std::string::npos) << what;
    }
  }
  SetWarningSink(old);
}

}  // namespace
}  // namespace flexmb
