// Reads one entry of the model file's `sensors:` list. Keys per type:
//   marker_position:     marker, relative_to (optional marker)
//   marker_velocity:     marker, angular (bool, default false)
//   marker_acceleration: marker, angular (bool, default false)
//   marker_orientation:  marker, relative_to (optional), quaternion (bool)
//   joint_coordinate:    joint, coordinate (name such as "angle", or index; default 0)
//   joint_reaction:      joint, frame (marker_i | world; default marker_i)
//   body_energy:         body
//   body_position:       body
//   system_energy:       (no further keys)
//   modal_coordinates:   body (flexible)
//   node_displacement:   body (flexible), node (FE node id)
//   node_position:       body (flexible), node (FE node id)
//   node_velocity:       body (flexible), node (FE node id)
//   element_stress:      body (flexible), element (FE element id)
//   node_stress:         body (flexible), node (FE node id)
//   strain_energy:       body (flexible)
//   force_element:       force

#include "flexmb/common/error.h"

#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/parse_context.h"
#include "flexmb/model/model.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/sensors/body_sensors.h"
#include "flexmb/sensors/flexible_sensors.h"
#include "flexmb/sensors/force_sensors.h"
#include "flexmb/sensors/joint_sensors.h"
#include "flexmb/sensors/marker_sensors.h"

namespace flexmb {
namespace {

/// Index of the joint coordinate named (or numbered) at node["coordinate"];
/// 0 if the key is absent.
int SensorCoordinateIndex(const YAML::Node& node, const flexmb::Joint& joint, ParseContext& ctx) {
  const YAML::Node c = node["coordinate"];
  if (!c) return 0;
  const std::string text = ctx.String(node, "coordinate");
  std::string known;
  for (int k = 0; k < joint.NumCoordinates(); ++k) {
    if (text == joint.CoordinateName(k) || text == std::to_string(k)) return k;
    known += (k ? ", " : "") + std::string(joint.CoordinateName(k));
  }
  if (joint.NumCoordinates() == 0)
    ctx.Fail(c, "joint '" + joint.name() + "' (" + joint.type() + ") has no joint coordinate");
  ctx.Fail(c, "joint '" + joint.name() + "' has no coordinate '" + text + "' (it has: " + known + ")");
}

int OptionalMarker(const YAML::Node& node, const char* key, ParseContext& ctx) {
  return node[key] ? ctx.Marker(node, key) : -1;
}

// the flexible body named at node["body"], or an error naming it
const FlexibleBody& FlexibleAt(const YAML::Node& node, int body, ParseContext& ctx) {
  const auto* f = dynamic_cast<const FlexibleBody*>(ctx.model().bodies[body].get());
  if (!f) ctx.Fail(node["body"], "body '" + ctx.model().bodies[body]->name() + "' is not a flexible body");
  return *f;
}

// the node index of the FE node id at node["node"], or an error naming it
int NodeAt(const YAML::Node& node, const FlexibleBody& f, ParseContext& ctx) {
  if (!node["node"]) ctx.Fail(node, "missing key 'node' (FE node id)");
  const int id = ctx.Integer(node, "node", -1);
  const int k = f.reduced().mesh.NodeIndex(id);
  if (k < 0) ctx.Fail(node["node"], "node " + std::to_string(id) + " does not exist in body '" + f.name() + "'");
  return k;
}

// the element index of the FE element id at node["element"], or an error
int ElementAt(const YAML::Node& node, const FlexibleBody& f, ParseContext& ctx) {
  if (!node["element"]) ctx.Fail(node, "missing key 'element' (FE element id)");
  const int id = ctx.Integer(node, "element", -1);
  const auto& elements = f.reduced().mesh.elements;
  for (size_t k = 0; k < elements.size(); ++k) {
    if (elements[k].id == id) return static_cast<int>(k);
  }
  ctx.Fail(node["element"], "element " + std::to_string(id) + " does not exist in body '" + f.name() + "'");
}

// adds the sensor; a duplicate name is an error at the entry's name
void AddSensorTo(const YAML::Node& node, ParseContext& ctx, std::unique_ptr<Sensor> sensor) {
  try {
    ctx.model().AddSensor(std::move(sensor));
  } catch (const InputError& e) {
    ctx.Fail(node["name"], e.message());
  }
}

void ParseMarkerPositionEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "marker", "relative_to"});
  sensor = std::make_unique<MarkerPositionSensor>(name, ctx.Marker(node, "marker"),
                                                  OptionalMarker(node, "relative_to", ctx));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseMarkerVelocityEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "marker", "angular"});
  sensor = std::make_unique<MarkerVelocitySensor>(name, ctx.Marker(node, "marker"),
                                                  ctx.Bool(node, "angular", false));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseMarkerAccelerationEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "marker", "angular"});
  sensor = std::make_unique<MarkerAccelerationSensor>(name, ctx.Marker(node, "marker"),
                                                      ctx.Bool(node, "angular", false));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseMarkerOrientationEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "marker", "relative_to", "quaternion"});
  sensor = std::make_unique<MarkerOrientationSensor>(
      name, ctx.Marker(node, "marker"), OptionalMarker(node, "relative_to", ctx),
      ctx.Bool(node, "quaternion", false));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseJointCoordinateEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  const Model& model = ctx.model();
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "joint", "coordinate"});
  const int j = ctx.Joint(node, "joint");
  const flexmb::Joint& joint = *model.joints[j];
  if (joint.NumCoordinates() == 0)
    ctx.Fail(node["joint"], "joint '" + joint.name() + "' (" + joint.type() +
                                ") has no joint coordinate to measure");
  sensor = std::make_unique<JointCoordinateSensor>(name, j, joint, SensorCoordinateIndex(node, joint, ctx));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseJointReactionEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "joint", "frame"});
  const int j = ctx.Joint(node, "joint");
  const std::string frame = ctx.String(node, "frame", "marker_i");
  if (frame != "marker_i" && frame != "world")
    ctx.Fail(node["frame"], "frame must be 'marker_i' or 'world', got '" + frame + "'");
  sensor = std::make_unique<JointReactionSensor>(name, j, frame == "world");
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseForceElementEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "force"});
  sensor = std::make_unique<ForceElementSensor>(name, ctx.Force(node, "force"));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseBodyEnergyEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body"});
  sensor = std::make_unique<BodyEnergySensor>(name, ctx.Body(node, "body"));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseBodyPositionEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body"});
  sensor = std::make_unique<BodyPositionSensor>(name, ctx.Body(node, "body"));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseModalCoordinatesEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body"});
  const int b = ctx.Body(node, "body");
  sensor = std::make_unique<ModalCoordinatesSensor>(name, b, FlexibleAt(node, b, ctx));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseNodeDisplacementEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body", "node"});
  const int b = ctx.Body(node, "body");
  sensor = std::make_unique<NodeDisplacementSensor>(name, b, NodeAt(node, FlexibleAt(node, b, ctx), ctx));
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseNodePositionEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body", "node"});
  const int b = ctx.Body(node, "body");
  const int k = NodeAt(node, FlexibleAt(node, b, ctx), ctx);
  sensor = std::make_unique<NodePositionSensor>(name, b, k);
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseNodeVelocityEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body", "node"});
  const int b = ctx.Body(node, "body");
  const int k = NodeAt(node, FlexibleAt(node, b, ctx), ctx);
  sensor = std::make_unique<NodeVelocitySensor>(name, b, k);
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseElementStressEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body", "element"});
  const int b = ctx.Body(node, "body");
  const FlexibleBody& f = FlexibleAt(node, b, ctx);
  const int e = ElementAt(node, f, ctx);
  try {
    sensor = std::make_unique<ElementStressSensor>(name, b, f, e);
  } catch (const InputError&) {
    ctx.Fail(node["element"], "element " + ctx.String(node, "element") + " of body '" + f.name() +
                                  "' has no stress modes in its body file");
  }
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseNodeStressEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body", "node"});
  const int b = ctx.Body(node, "body");
  const FlexibleBody& f = FlexibleAt(node, b, ctx);
  const int k = NodeAt(node, f, ctx);
  try {
    sensor = std::make_unique<NodeStressSensor>(name, b, f, k);
  } catch (const InputError&) {
    ctx.Fail(node["node"], "node " + ctx.String(node, "node") + " of body '" + f.name() +
                               "' has no shell or solid element with stress modes");
  }
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseStrainEnergyEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type", "body"});
  const int b = ctx.Body(node, "body");
  FlexibleAt(node, b, ctx);
  sensor = std::make_unique<StrainEnergySensor>(name, b);
  AddSensorTo(node, ctx, std::move(sensor));
}

void ParseSystemEnergyEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  std::unique_ptr<Sensor> sensor;
  ctx.CheckKeys(node, {"name", "type"});
  sensor = std::make_unique<SystemEnergySensor>(name);
  AddSensorTo(node, ctx, std::move(sensor));
}

}  // namespace

void RegisterSensorTypes(ElementRegistry& r) {
  r.Add(ElementKind::kSensor, "marker_position", ParseMarkerPositionEntry);
  r.Add(ElementKind::kSensor, "marker_velocity", ParseMarkerVelocityEntry);
  r.Add(ElementKind::kSensor, "marker_acceleration", ParseMarkerAccelerationEntry);
  r.Add(ElementKind::kSensor, "marker_orientation", ParseMarkerOrientationEntry);
  r.Add(ElementKind::kSensor, "joint_coordinate", ParseJointCoordinateEntry);
  r.Add(ElementKind::kSensor, "joint_reaction", ParseJointReactionEntry);
  r.Add(ElementKind::kSensor, "body_energy", ParseBodyEnergyEntry);
  r.Add(ElementKind::kSensor, "body_position", ParseBodyPositionEntry);
  r.Add(ElementKind::kSensor, "modal_coordinates", ParseModalCoordinatesEntry);
  r.Add(ElementKind::kSensor, "node_displacement", ParseNodeDisplacementEntry);
  r.Add(ElementKind::kSensor, "node_position", ParseNodePositionEntry);
  r.Add(ElementKind::kSensor, "node_velocity", ParseNodeVelocityEntry);
  r.Add(ElementKind::kSensor, "element_stress", ParseElementStressEntry);
  r.Add(ElementKind::kSensor, "node_stress", ParseNodeStressEntry);
  r.Add(ElementKind::kSensor, "strain_energy", ParseStrainEnergyEntry);
  r.Add(ElementKind::kSensor, "system_energy", ParseSystemEnergyEntry);
  r.Add(ElementKind::kSensor, "force_element", ParseForceElementEntry);
}

}  // namespace flexmb
