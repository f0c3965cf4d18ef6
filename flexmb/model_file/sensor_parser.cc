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

#include "flexmb/common/error.h"

#include "flexmb/model_file/parse_context.h"
#include "flexmb/model/model.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/sensors/body_sensors.h"
#include "flexmb/sensors/flexible_sensors.h"
#include "flexmb/sensors/joint_sensors.h"
#include "flexmb/sensors/marker_sensors.h"

namespace flexmb {
namespace {

/// Index of the joint coordinate named (or numbered) at node["coordinate"];
/// 0 if the key is absent.
int CoordinateIndex(const YAML::Node& node, const flexmb::Joint& joint, ParseContext& ctx) {
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

}  // namespace

void ParseSensor(const YAML::Node& node, ParseContext& ctx) {
  if (!node.IsMap()) ctx.Fail(node, "a sensor must be a map with at least 'name' and 'type'");
  const std::string name = ctx.String(node, "name");
  ctx.SetEntity("sensor '" + name + "'");
  const std::string type = ctx.String(node, "type");
  Model& model = ctx.model();
  std::unique_ptr<Sensor> sensor;

  if (type == "marker_position") {
    ctx.CheckKeys(node, {"name", "type", "marker", "relative_to"});
    sensor = std::make_unique<MarkerPositionSensor>(name, ctx.Marker(node, "marker"),
                                                    OptionalMarker(node, "relative_to", ctx));
  } else if (type == "marker_velocity") {
    ctx.CheckKeys(node, {"name", "type", "marker", "angular"});
    sensor = std::make_unique<MarkerVelocitySensor>(name, ctx.Marker(node, "marker"),
                                                    ctx.Bool(node, "angular", false));
  } else if (type == "marker_acceleration") {
    ctx.CheckKeys(node, {"name", "type", "marker", "angular"});
    sensor = std::make_unique<MarkerAccelerationSensor>(name, ctx.Marker(node, "marker"),
                                                        ctx.Bool(node, "angular", false));
  } else if (type == "marker_orientation") {
    ctx.CheckKeys(node, {"name", "type", "marker", "relative_to", "quaternion"});
    sensor = std::make_unique<MarkerOrientationSensor>(
        name, ctx.Marker(node, "marker"), OptionalMarker(node, "relative_to", ctx),
        ctx.Bool(node, "quaternion", false));
  } else if (type == "joint_coordinate") {
    ctx.CheckKeys(node, {"name", "type", "joint", "coordinate"});
    const int j = ctx.Joint(node, "joint");
    const flexmb::Joint& joint = *model.joints[j];
    if (joint.NumCoordinates() == 0)
      ctx.Fail(node["joint"], "joint '" + joint.name() + "' (" + joint.type() +
                                  ") has no joint coordinate to measure");
    sensor = std::make_unique<JointCoordinateSensor>(name, j, joint, CoordinateIndex(node, joint, ctx));
  } else if (type == "joint_reaction") {
    ctx.CheckKeys(node, {"name", "type", "joint", "frame"});
    const int j = ctx.Joint(node, "joint");
    const std::string frame = ctx.String(node, "frame", "marker_i");
    if (frame != "marker_i" && frame != "world")
      ctx.Fail(node["frame"], "frame must be 'marker_i' or 'world', got '" + frame + "'");
    sensor = std::make_unique<JointReactionSensor>(name, j, frame == "world");
  } else if (type == "body_energy") {
    ctx.CheckKeys(node, {"name", "type", "body"});
    sensor = std::make_unique<BodyEnergySensor>(name, ctx.Body(node, "body"));
  } else if (type == "body_position") {
    ctx.CheckKeys(node, {"name", "type", "body"});
    sensor = std::make_unique<BodyPositionSensor>(name, ctx.Body(node, "body"));
  } else if (type == "modal_coordinates") {
    ctx.CheckKeys(node, {"name", "type", "body"});
    const int b = ctx.Body(node, "body");
    sensor = std::make_unique<ModalCoordinatesSensor>(name, b, FlexibleAt(node, b, ctx));
  } else if (type == "node_displacement") {
    ctx.CheckKeys(node, {"name", "type", "body", "node"});
    const int b = ctx.Body(node, "body");
    sensor = std::make_unique<NodeDisplacementSensor>(name, b, NodeAt(node, FlexibleAt(node, b, ctx), ctx));
  } else if (type == "node_position" || type == "node_velocity") {
    ctx.CheckKeys(node, {"name", "type", "body", "node"});
    const int b = ctx.Body(node, "body");
    const int k = NodeAt(node, FlexibleAt(node, b, ctx), ctx);
    if (type == "node_position") {
      sensor = std::make_unique<NodePositionSensor>(name, b, k);
    } else {
      sensor = std::make_unique<NodeVelocitySensor>(name, b, k);
    }
  } else if (type == "element_stress") {
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
  } else if (type == "node_stress") {
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
  } else if (type == "strain_energy") {
    ctx.CheckKeys(node, {"name", "type", "body"});
    const int b = ctx.Body(node, "body");
    FlexibleAt(node, b, ctx);
    sensor = std::make_unique<StrainEnergySensor>(name, b);
  } else if (type == "system_energy") {
    ctx.CheckKeys(node, {"name", "type"});
    sensor = std::make_unique<SystemEnergySensor>(name);
  } else {
    ctx.Fail(node["type"],
             "unknown sensor type '" + type +
                 "' (known: marker_position, marker_velocity, marker_acceleration, "
                 "marker_orientation, joint_coordinate, joint_reaction, body_energy, "
                 "body_position, system_energy, modal_coordinates, node_displacement, node_position, "
                 "node_velocity, element_stress, node_stress, strain_energy)");
  }
  try {
    model.AddSensor(std::move(sensor));
  } catch (const InputError& e) {
    ctx.Fail(node["name"], e.message());
  }
}

}  // namespace flexmb
