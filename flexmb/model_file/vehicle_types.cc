// Vehicle element entries of the model file (reference: docs/model-file.md,
// "Vehicle elements"): the tire, the wheel brake and the joint of a tire's
// contact-patch body, so that a vehicle can be built in a model file as well
// as by the truck template.

#include <filesystem>
#include <memory>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/model/model.h"
#include "flexmb/model_file/element_registry.h"
#include "flexmb/model_file/joint_entry.h"
#include "flexmb/model_file/parse_context.h"
#include "flexmb/vehicle/contact_patch_joint.h"
#include "flexmb/vehicle/truck.h"
#include "flexmb/vehicle/wheel_brake.h"

namespace flexmb {
namespace {

// tire data: a tire file (relative to the model file's folder) or a map of TireData keys
vehicle::TireData TireDataOf(const YAML::Node& node, ParseContext& ctx) {
  if (node["file"] && node["data"]) ctx.Fail(node["data"], "give either 'file' or 'data', not both");
  if (node["data"]) {
    const std::string owner = ctx.entity();
    auto d = vehicle::ReadTireData(node["data"], ctx);
    ctx.SetEntity(owner);
    return d;
  }
  if (!node["file"]) ctx.Fail(node, "a tire needs 'file' (a tire data file) or 'data' (its coefficients)");
  std::filesystem::path path = ctx.String(node, "file");
  if (path.is_relative()) path = std::filesystem::path(ctx.file()).parent_path() / path;
  return ctx.Guard(node["file"], [&] { return vehicle::LoadTireFile(path.string()); });
}

void ParseTireEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "i", "j", "file", "data", "mu"});
  const vehicle::TireData d = TireDataOf(node, ctx);
  const double mu = ctx.Double(node, "mu", 1.0);
  if (!(mu > 0.0)) ctx.Fail(node["mu"], "'mu' (road friction) must be positive");
  const int i = ctx.Marker(node, "i");
  int j = -1;
  if (d.relaxation_length > 0.0) {
    if (!node["j"])
      ctx.Fail(node, "a tire with a relaxation length needs 'j', the marker of its contact-patch body");
    j = ctx.Marker(node, "j");
  } else if (node["j"]) {
    ctx.Fail(node["j"], "'j' (a contact-patch marker) needs a tire with a positive relaxation_length");
  }
  ctx.Guard(node, [&] { ctx.model().AddForce(std::make_unique<vehicle::Tire>(name, d, mu), i, j); });
}

void ParseWheelBrakeEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "i", "j", "torque", "smoothing_spin"});
  const int i = ctx.Marker(node, "i"), j = ctx.Marker(node, "j");
  auto torque = ctx.Function(node, "torque", "t");
  const double spin = ctx.Double(node, "smoothing_spin", 0.5);
  ctx.Guard(node, [&] {
    ctx.model().AddForce(std::make_unique<vehicle::WheelBrake>(name, torque, spin), i, j);
  });
}

void ParseContactPatchEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  AddJointEntry(node, name, ctx, {}, [&](int, int) { return std::make_unique<vehicle::ContactPatchJoint>(name); });
}

// A whole truck of the vehicle template (vehicle/truck.h) in a model file:
// its truck map read from `file` (a lane-change file or any file with a
// top-level `truck` map; tire and subsystem files relative to it), built at
// rest or rolling at `speed_kmh`, its steering-wheel angle [rad], drive and
// brake torques [N m] functions of t; markers on its bodies for the rest of
// the model (a crane on the frame). Its bodies keep the template's names
// (frame, cab, cargo, front_axle, wheel_fl, ...).
void ParseTruckEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx) {
  ctx.CheckKeys(node, {"name", "type", "file", "frame", "speed_kmh", "mu", "steering_wheel", "drive_torque",
                       "brake_torque", "markers"});
  std::filesystem::path path = ctx.String(node, "file");
  if (path.is_relative()) path = std::filesystem::path(ctx.file()).parent_path() / path;
  const std::string frame = ctx.String(node, "frame", "rigid");
  if (frame != "rigid")
    ctx.Fail(node["frame"], "a truck in a model file has a rigid frame ('frame: rigid'); the elastic frame runs in the "
                            "truck tests (flexmb run/truck of a lane-change file), got '" + frame + "'");
  const double speed = ctx.Double(node, "speed_kmh", 0.0) / 3.6;
  if (!(speed >= 0.0)) ctx.Fail(node["speed_kmh"], "'speed_kmh' must be >= 0");
  const double mu = ctx.Double(node, "mu", 0.8);
  if (!(mu > 0.0)) ctx.Fail(node["mu"], "'mu' (road friction) must be positive");
  // the truck map, read in its own file's context
  vehicle::TruckData d;
  ctx.Guard(node["file"], [&] {
    YAML::Node root;
    try {
      root = YAML::LoadFile(path.string());
    } catch (const YAML::Exception& e) {
      throw InputError(std::string("cannot read the truck file: ") + e.what(), {path.string(), 0, ""});
    }
    YamlContext file_ctx(path.string());
    const YAML::Node t = root.IsMap() ? root["truck"] : YAML::Node();
    if (!t) file_ctx.Fail(root, "expected a top-level 'truck' map");
    d = vehicle::ParseTruck(t, file_ctx, path.parent_path().string());
    if (d.frame_body) file_ctx.Fail(t["frame"], "a truck in a model file has the generated rigid frame, not a body file");
  });
  vehicle::TruckInputs in;
  in.steering_wheel = node["steering_wheel"] ? ctx.Function(node, "steering_wheel") : std::make_shared<ConstantFunction>(0.0);
  in.drive_torque = node["drive_torque"] ? ctx.Function(node, "drive_torque") : std::make_shared<ConstantFunction>(0.0);
  if (node["brake_torque"]) in.brake_torque = ctx.Function(node, "brake_torque");
  Model& m = ctx.model();
  ctx.Guard(node, [&] { vehicle::BuildTruck(d, speed, mu, in, m); });
  // markers on the truck's bodies: {body, name, position, orientation}
  if (const YAML::Node list = ctx.MapChild(node, "markers")) {
    if (!list.IsSequence()) ctx.Fail(list, "'markers' must be a list of {body, name, position, orientation}");
    for (const YAML::Node& entry : list) {
      if (!entry.IsMap()) ctx.Fail(entry, "a marker is a map {body, name, position, orientation}");
      const int body = ctx.Body(entry, "body");
      YAML::Node one;
      one["markers"].push_back(entry);
      ctx.ParseMarkerList(one, body, {"body", "name", "position", "orientation"}, nullptr, ctx.lines());
      ctx.SetEntity("body '" + name + "'");
    }
  }
}

}  // namespace

void RegisterVehicleTypes(ElementRegistry& r) {
  r.Add(ElementKind::kBody, "truck", ParseTruckEntry);
  r.Add(ElementKind::kForce, "tire", ParseTireEntry);
  r.Add(ElementKind::kForce, "wheel_brake", ParseWheelBrakeEntry);
  r.Add(ElementKind::kJoint, "contact_patch", ParseContactPatchEntry);
}

}  // namespace flexmb
