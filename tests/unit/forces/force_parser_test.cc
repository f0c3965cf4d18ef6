// The `forces:` section of the model file: every element type loads with its
// values, defaults are applied, and bad input is reported at its line naming
// the key.

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/forces/bushing.h"
#include "flexmb/forces/joint_motor.h"
#include "flexmb/forces/plane_contact.h"
#include "flexmb/forces/point_force.h"
#include "flexmb/forces/point_torque.h"
#include "flexmb/forces/rotational_spring_damper.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/model_file/model_file.h"

namespace flexmb {
namespace {

const std::string kBase =
    "ground:\n"                                                       // 1
    "  markers:\n"                                                    // 2
    "    - {name: o, position: [0, 0, 0]}\n"                          // 3
    "bodies:\n"                                                       // 4
    "  - name: a\n"                                                   // 5
    "    mass: 1.0\n"                                                 // 6
    "    inertia: [0.1, 0.1, 0.1]\n"                                  // 7
    "    position: [0, 0, 2]\n"                                       // 8
    "    orientation: {rotation_vector: [0, 0, 1.5707963267948966]}\n"  // 9
    "    center_of_mass: [0.3, 0, 0]\n"                               // 10
    "    markers:\n"                                                  // 11
    "      - {name: m, position: [1, 0, 0]}\n"                        // 12
    "joints:\n"                                                       // 13
    "  - {name: pin, type: revolute, i: ground.o, j: a.m}\n"          // 14
    "  - {name: ball, type: spherical, i: ground.o, j: a.m}\n"        // 15
    "forces:\n";                                                      // 16; forces from line 17

std::unique_ptr<Model> Load(const std::string& forces) { return LoadModelString(kBase + forces, "f.yaml"); }

void ExpectError(const std::string& force, std::initializer_list<const char*> parts) {
  try {
    Load(force);
    ADD_FAILURE() << "no error for:\n" << force;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("f.yaml:17: ", 0), 0u) << what;
    for (const char* p : parts) EXPECT_NE(what.find(p), std::string::npos) << "missing '" << p << "' in: " << what;
  }
}

TEST(ForceParser, LoadsEveryType) {
  auto m = Load(
      "  - {name: s, type: spring_damper, i: ground.o, j: a.m, stiffness: 100, damping: 2, preload: 5}\n"
      "  - {name: s2, type: spring_damper, i: ground.o, j: a.m, free_length: 0.5,\n"
      "     force_deflection: {table: [[-1, -50], [1, 60]]}, force_velocity: {expression: \"3*x\"}}\n"
      "  - {name: r, type: rotational_spring_damper, i: ground.o, j: a.m, stiffness: 10, damping: 1,\n"
      "     angle0: 0.2, preload: 0.5}\n"
      "  - name: b\n"
      "    type: bushing\n"
      "    i: ground.o\n"
      "    j: a.m\n"
      "    translational_stiffness: [1, 2, 3]\n"
      "    rotational_damping: [4, 5, 6]\n"
      "    preload_torque: [0, 0, 1]\n"
      "  - {name: f, type: point_force, marker: a.m, force: [1, {expression: \"2*t\"}, {table: [[0, 0], [1, 3]]}],\n"
      "     frame: marker}\n"
      "  - {name: t, type: point_torque, marker: a.m, torque: [0, 0, 7]}\n"
      "  - {name: mot, type: joint_motor, joint: pin, coordinate: angle, function: 2, target: {expression: \"t\"},\n"
      "     kp: 100, kd: 5}\n");
  ASSERT_EQ(m->forces.size(), 7u);
  const int o = m->FindMarker("ground.o"), am = m->FindMarker("a.m");
  // the marker starts at p_WB + R_WB (1, 0, 0) = (0, 1, 2): free length sqrt(5) by default
  const auto& s = dynamic_cast<const SpringDamper&>(*m->forces[0]);
  EXPECT_NEAR(s.law().free_length, std::sqrt(5.0), 1e-12);
  EXPECT_EQ(s.law().stiffness, 100.0);
  EXPECT_EQ(s.law().damping, 2.0);
  EXPECT_EQ(s.law().preload, 5.0);
  EXPECT_EQ(s.marker_i, o);
  EXPECT_EQ(s.marker_j, am);
  const auto& s2 = dynamic_cast<const SpringDamper&>(*m->forces[1]);
  EXPECT_EQ(s2.law().free_length, 0.5);
  ASSERT_TRUE(s2.law().force_deflection && s2.law().force_velocity);
  EXPECT_NEAR(s2.law().force_deflection->Value(0.0), 5.0, 1e-12);
  EXPECT_NEAR(s2.law().force_velocity->Value(2.0), 6.0, 1e-12);
  const auto& r = dynamic_cast<const RotationalSpringDamper&>(*m->forces[2]);
  EXPECT_EQ(r.law().angle0, 0.2);
  EXPECT_EQ(r.law().preload, 0.5);
  const auto& b = dynamic_cast<const Bushing&>(*m->forces[3]);
  EXPECT_EQ(b.data().translational_stiffness, Vec3(1, 2, 3));
  EXPECT_EQ(b.data().rotational_damping, Vec3(4, 5, 6));
  EXPECT_EQ(b.data().rotational_stiffness, Vec3::Zero());
  EXPECT_EQ(b.data().preload_torque, Vec3(0, 0, 1));
  const auto& f = dynamic_cast<const PointForce&>(*m->forces[4]);
  EXPECT_EQ(f.frame(), LoadFrame::kMarker);
  EXPECT_EQ(f.marker_j, -1);
  ForceEval e;
  f.Evaluate(MarkerState{}, MarkerState{}, 0.5, e);
  EXPECT_NEAR((e.wrench.head<3>() - Vec3(1, 1, 1.5)).norm(), 0.0, 1e-9);
  const auto& t = dynamic_cast<const PointTorque&>(*m->forces[5]);
  EXPECT_EQ(t.frame(), LoadFrame::kWorld);
  const auto& mot = dynamic_cast<const JointMotor&>(*m->forces[6]);
  EXPECT_EQ(mot.joint(), m->joints[0].get());
  EXPECT_EQ(mot.marker_i, o);
  EXPECT_EQ(mot.marker_j, am);
}

TEST(ForceParser, ReportsBadInputAtItsLine) {
  ExpectError("  - {name: s, type: spring_damper, i: ground.o, j: a.m, stifness: 1}\n",
              {"force 's'", "unknown key 'stifness'"});
  ExpectError("  - {name: s, type: spring_damper, i: ground.o, j: a.m, stiffness: 1, force_deflection: 2}\n",
              {"either 'stiffness' or 'force_deflection'"});
  ExpectError("  - {name: s, type: spring_damper, i: ground.o, j: a.m, damping: -1}\n",
              {"'damping' must not be negative"});
  ExpectError("  - {name: s, type: spring_damper, i: a.m, j: a.m}\n", {"same marker"});
  ExpectError("  - {name: s, type: spring, i: ground.o, j: a.m}\n", {"unknown force type 'spring'"});
  ExpectError("  - {name: b, type: bushing, i: ground.o, j: a.m, rotational_stiffness: [1, -2, 3]}\n",
              {"'rotational_stiffness'"});
  ExpectError("  - {name: f, type: point_force, marker: a.m, force: [1, 2]}\n", {"'force'", "3 components"});
  ExpectError("  - {name: f, type: point_force, marker: a.m, force: [1, 2, {expresion: t}]}\n",
              {"force 'f'", "expresion"});
  ExpectError("  - {name: f, type: point_torque, marker: a.m, torque: [1, 2, 3], frame: body}\n",
              {"unknown frame 'body'"});
  ExpectError("  - {name: m, type: joint_motor, joint: pin, kp: 3, function: 1}\n", {"'kp' needs a 'target'"});
  ExpectError("  - {name: m, type: joint_motor, joint: ball, function: 1}\n", {"joint 'ball'", "no joint coordinate"});
  ExpectError("  - {name: m, type: joint_motor, joint: pin, coordinate: translation, function: 1}\n",
              {"no coordinate 'translation'"});
  ExpectError("  - {name: m, type: joint_motor, joint: pin}\n", {"needs 'function'"});
}

TEST(ForceParser, PlaneContactAndItsSensor) {
  auto m = LoadModelString(kBase +
                               "  - {name: pad, type: plane_contact, marker: a.m, point: [0, 0, -1], normal: [0, 0, 2],\n"
                               "     stiffness: 1.0e6, damping: 500, friction: 0.4}\n"
                               "sensors:\n"
                               "  - {name: load, type: force_element, force: pad}\n",
                           "f.yaml");
  const auto* c = dynamic_cast<const PlaneContact*>(m->forces.at(0).get());
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->law().point_W, Vec3(0, 0, -1));
  EXPECT_EQ(c->law().normal_W, Vec3(0, 0, 1));
  EXPECT_EQ(c->law().stiffness, 1.0e6);
  EXPECT_EQ(c->law().damping, 500.0);
  EXPECT_EQ(c->law().friction, 0.4);
  EXPECT_EQ(c->law().slip_velocity, 1e-3);
  ASSERT_EQ(m->sensors.size(), 1u);
  EXPECT_EQ(m->sensors[0]->Components().size(), 7u);
  ExpectError("  - {name: pad, type: plane_contact, marker: a.m}\n", {"force 'pad'", "'stiffness'"});
  ExpectError("  - {name: pad, type: plane_contact, marker: a.m, stiffness: 1, normal: [0, 0, 0]}\n",
              {"'normal' must not be the zero vector"});
  ExpectError("  - {name: pad, type: plane_contact, marker: a.m, stiffness: 1, slip_velocity: 0}\n",
              {"'slip_velocity' must be > 0"});
  try {
    LoadModelString(kBase + "  - {name: pad, type: plane_contact, marker: a.m, stiffness: 1}\nsensors:\n"
                            "  - {name: load, type: force_element, force: pda}\n",
                    "f.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no force element named 'pda'"), std::string::npos) << e.what();
  }
}

TEST(ForceParser, DuplicateNameReported) {
  try {
    Load("  - {name: s, type: point_torque, marker: a.m, torque: [0, 0, 1]}\n"
         "  - {name: s, type: point_torque, marker: a.m, torque: [0, 0, 1]}\n");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.yaml:18"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("duplicate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace flexmb
