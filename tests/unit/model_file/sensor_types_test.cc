// Sensor entries (ParseElement with ElementKind::kSensor): each sensor type from its model-file node, and errors that
// name the file line, the sensor and the offending value.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/parse_context.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/model/model.h"

namespace flexmb {
namespace {

std::unique_ptr<Model> SmallModel() {
  auto m = std::make_unique<Model>();
  RigidBodyData d;
  d.mass = 1.0;
  d.inertia_C = Mat3::Identity();
  const int b = m->AddBody(std::make_unique<RigidBody>("arm", d));
  const int g = m->AddMarker(0, "pin", Vec3::Zero(), Mat3::Identity());
  const int p = m->AddMarker(b, "pin", Vec3::Zero(), Mat3::Identity());
  m->AddMarker(b, "tip", Vec3(1, 0, 0), Mat3::Identity());
  m->AddJoint(std::make_unique<RevoluteJoint>("hinge"), g, p);
  m->AddJoint(std::make_unique<SphericalJoint>("ball"), g, p);
  return m;
}

/// Parses `yaml` (one sensor) into `model`; returns the new sensor.
const Sensor& Parse(Model& model, const std::string& yaml) {
  ParseContext ctx("model.yaml", model);
  ParseElement(ElementKind::kSensor, YAML::Load(yaml), 0, ctx);
  return *model.sensors.back();
}

/// Expects InputError whose message contains every string in `parts`.
void ExpectError(const std::string& yaml, std::initializer_list<const char*> parts) {
  auto model = SmallModel();
  try {
    Parse(*model, yaml);
    ADD_FAILURE() << "no error for: " << yaml;
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const char* p : parts) EXPECT_NE(what.find(p), std::string::npos) << what;
  }
}

TEST(SensorParser, EveryType) {
  auto model = SmallModel();
  using V = std::vector<std::string>;
  const Sensor& pos = Parse(*model, "{name: p, type: marker_position, marker: arm.tip, relative_to: ground.pin}");
  EXPECT_STREQ(pos.type(), "marker_position");
  EXPECT_EQ(pos.Components(), (V{"x", "y", "z"}));
  EXPECT_EQ(Parse(*model, "{name: v, type: marker_velocity, marker: arm.tip, angular: true}").Components(),
            (V{"x", "y", "z", "wx", "wy", "wz"}));
  EXPECT_EQ(Parse(*model, "{name: a, type: marker_acceleration, marker: arm.tip}").Components(),
            (V{"x", "y", "z"}));
  const Sensor& o = Parse(*model, "{name: o, type: marker_orientation, marker: arm.tip, quaternion: true}");
  EXPECT_EQ(o.Components(), (V{"roll", "pitch", "yaw", "qw", "qx", "qy", "qz"}));
  const Sensor& c = Parse(*model, "{name: c, type: joint_coordinate, joint: hinge, coordinate: angle}");
  EXPECT_EQ(c.Components(), (V{"value", "rate"}));
  EXPECT_TRUE(c.ComponentIsAngle(0));
  EXPECT_STREQ(Parse(*model, "{name: c0, type: joint_coordinate, joint: hinge}").type(), "joint_coordinate");
  EXPECT_EQ(Parse(*model, "{name: r, type: joint_reaction, joint: hinge, frame: world}").Components(),
            (V{"fx", "fy", "fz", "mx", "my", "mz"}));
  EXPECT_EQ(Parse(*model, "{name: e, type: body_energy, body: arm}").Components(), (V{"kinetic", "potential"}));
  EXPECT_EQ(Parse(*model, "{name: s, type: system_energy}").Components(), (V{"kinetic", "potential", "total"}));
  EXPECT_EQ(Parse(*model, "{name: b, type: body_position, body: arm}").Components(),
            (V{"x", "y", "z", "roll", "pitch", "yaw"}));
  EXPECT_EQ(model->sensors.size(), 10u);
}

TEST(SensorParser, ErrorsNameTheSensorAndTheValue) {
  ExpectError("{name: s1, type: marker_speed, marker: arm.tip}", {"model.yaml:1", "sensor 's1'", "marker_speed"});
  ExpectError("{name: s2, type: marker_position, marker: arm.toe}", {"sensor 's2'", "toe"});
  ExpectError("{name: s3, type: marker_position, marker: arm.tip, frame: world}", {"sensor 's3'", "frame"});
  ExpectError("{name: s4, type: joint_coordinate, joint: hinge, coordinate: translation}",
              {"sensor 's4'", "translation", "angle"});
  ExpectError("{name: s5, type: joint_coordinate, joint: ball}", {"sensor 's5'", "ball", "no joint coordinate"});
  ExpectError("{name: s6, type: joint_reaction, joint: hinge, frame: body}", {"sensor 's6'", "body"});
  ExpectError("{name: s7, type: joint_reaction, joint: door}", {"sensor 's7'", "door"});
  ExpectError("{name: s8, type: body_energy, body: leg}", {"sensor 's8'", "leg"});
  ExpectError("{type: system_energy}", {"name"});
  // duplicate names
  auto model = SmallModel();
  Parse(*model, "{name: dup, type: system_energy}");
  EXPECT_THROW(Parse(*model, "{name: dup, type: system_energy}"), InputError);
}

}  // namespace
}  // namespace flexmb
