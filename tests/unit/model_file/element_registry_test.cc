// The model file's element registry: every registered type is reachable by
// name (the vehicle elements and the gear joint too), a duplicate
// registration is refused, and entries of the new types are read with their
// parameters and their errors name file, line and entity.

#include "flexmb/model_file/element_registry.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <stdexcept>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/joints/gear.h"
#include "flexmb/model_file/model_file.h"

namespace flexmb {
namespace element_registry_test {

// two bodies on revolute joints of ground (shafts along z and x: a gear pair)
// and a wheel on a carrier, followed by the `joints:`/`forces:` lines under test
std::string RegistryModel(const std::string& extra) {
  return R"(name: registry
ground:
  markers:
    - {name: a, orientation: {z_axis: [0, 0, 1]}}
    - {name: b, position: [1, 0, 0], orientation: {z_axis: [1, 0, 0], x_axis: [0, 0, 1]}}
bodies:
  - name: s1
    mass: 1
    inertia: [1, 1, 1]
    markers:
      - {name: axis, orientation: {z_axis: [0, 0, 1], x_axis: [1, 0, 0]}}
  - name: s2
    mass: 1
    inertia: [1, 1, 1]
    position: [1, 0, 0]
    markers:
      - {name: axis, orientation: {z_axis: [1, 0, 0], x_axis: [0, 0, 1]}}
  - name: wheel
    mass: 40
    inertia: [1, 2, 1]
    position: [0, 3, 0.5]
    markers:
      - {name: centre, orientation: {z_axis: [0, 1, 0]}}
  - name: patch
    mass: 0.5
    inertia: [0.01, 0.01, 0.01]
    position: [0, 3, 0.5]
    markers:
      - {name: m, orientation: {z_axis: [0, 1, 0]}}
)" + extra;
}

const char* kRegistryJoints = R"(joints:
  - {name: j1, type: revolute, i: ground.a, j: s1.axis}
  - {name: j2, type: revolute, i: ground.b, j: s2.axis}
  - {name: pair, type: gear, i: s1.axis, j: s2.axis, ratio: 20}
  - {name: carcass, type: contact_patch, i: wheel.centre, j: patch.m}
)";

void ExpectRegistryError(const std::string& yaml, int line, std::initializer_list<const char*> parts) {
  try {
    LoadModelString(yaml, "reg.yaml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("reg.yaml:" + std::to_string(line) + ":"), std::string::npos) << what;
    for (const char* p : parts) EXPECT_NE(what.find(p), std::string::npos) << what;
  }
}

TEST(ElementRegistry, EveryKindHasItsTypesByName) {
  const ElementRegistry& r = ModelFileTypes();
  for (const char* t : {"rigid", "flexible", "ancf_beam", "ancf_beam3d", "ancf_cable"})
    EXPECT_NE(r.Find(ElementKind::kBody, t), nullptr) << t;
  for (const char* t : {"fixed", "revolute", "prismatic", "cylindrical", "spherical", "universal", "planar",
                        "distance", "gear", "contact_patch"})
    EXPECT_NE(r.Find(ElementKind::kJoint, t), nullptr) << t;
  for (const char* t : {"spring_damper", "rotational_spring_damper", "bushing", "point_force", "point_torque",
                        "joint_motor", "tire", "wheel_brake", "plane_contact", "rope"})
    EXPECT_NE(r.Find(ElementKind::kForce, t), nullptr) << t;
  EXPECT_NE(r.Find(ElementKind::kDriver, "coordinate"), nullptr);
  EXPECT_EQ(r.Names(ElementKind::kSensor).size(), 17u);
  EXPECT_NE(r.Find(ElementKind::kSensor, "force_element"), nullptr);
  // a name belongs to its kind only
  EXPECT_EQ(r.Find(ElementKind::kForce, "revolute"), nullptr);
}

TEST(ElementRegistry, DuplicateRegistrationIsRefused) {
  ElementRegistry r;
  RegisterJointTypes(r);
  EXPECT_THROW(r.Add(ElementKind::kJoint, "gear", nullptr), std::logic_error);
  EXPECT_NO_THROW(r.Add(ElementKind::kForce, "gear", nullptr));
}

TEST(ElementRegistry, GearContactPatchTireAndBrakeFromTheModelFile) {
  const std::string forces = R"(forces:
  - {name: tire, type: tire, i: wheel.centre, j: patch.m, mu: 0.9,
     data: {unloaded_radius: 0.5, vertical_stiffness: 8.0e5, nominal_load: 25000, relaxation_length: 0.6,
            longitudinal_relaxation_length: 0.4}}
  - {name: brake, type: wheel_brake, i: patch.m, j: wheel.centre, torque: 500, smoothing_spin: 0.2}
)";
  const auto m = LoadModelString(RegistryModel(std::string(kRegistryJoints) + forces), "reg.yaml");
  ASSERT_EQ(m->joints.size(), 4u);
  EXPECT_STREQ(m->joints[2]->type(), "gear");
  EXPECT_DOUBLE_EQ(dynamic_cast<const GearJoint&>(*m->joints[2]).ratio(), 20.0);
  EXPECT_STREQ(m->joints[3]->type(), "contact_patch");
  ASSERT_EQ(m->forces.size(), 2u);
  EXPECT_STREQ(m->forces[0]->type(), "tire");
  EXPECT_STREQ(m->forces[1]->type(), "wheel_brake");
}

TEST(ElementRegistry, ErrorsOfTheNewTypesNameLineAndEntity) {
  const std::string base = RegistryModel(kRegistryJoints);
  // the model text has 29 lines; `joints:` is line 30, its first entry 31,
  // and after the four joints of kRegistryJoints a force entry is line 36
  const int forces_line = 36;
  ExpectRegistryError(RegistryModel("joints:\n  - {name: pair, type: gear, i: s1.axis, j: s2.axis}\n"), 31,
                      {"joint 'pair'", "missing required key 'ratio'"});
  ExpectRegistryError(RegistryModel("joints:\n  - {name: pair, type: gear, i: s1.axis, j: s2.axis, ratio: 0}\n"),
                      31, {"joint 'pair'"});
  ExpectRegistryError(base + "forces:\n  - {name: t, type: tire, i: wheel.centre}\n", forces_line,
                      {"force 't'", "'file'", "'data'"});
  ExpectRegistryError(
      base + "forces:\n  - {name: t, type: tire, i: wheel.centre, j: patch.m, data: {unloaded_radius: 0.5, "
             "vertical_stiffness: 8.0e5, nominal_load: 25000}}\n",
      forces_line, {"force 't'", "'j'", "relaxation_length"});
  ExpectRegistryError(base + "forces:\n  - {name: b, type: wheel_brake, i: patch.m, j: wheel.centre}\n", forces_line,
                      {"force 'b'", "missing required key 'torque'"});
  ExpectRegistryError(base + "forces:\n  - {name: b, type: brake, i: patch.m, j: wheel.centre}\n", forces_line,
                      {"unknown force type 'brake'", "wheel_brake"});
}

}  // namespace element_registry_test
}  // namespace flexmb
