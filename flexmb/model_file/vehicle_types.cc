// Vehicle element entries of the model file (reference: docs/model-file.md,
// "Vehicle elements"): the tire, the wheel brake and the joint of a tire's
// contact-patch body, so that a vehicle can be built in a model file as well
// as by the truck template.

#include <filesystem>
#include <memory>
#include <string>

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

}  // namespace

void RegisterVehicleTypes(ElementRegistry& r) {
  r.Add(ElementKind::kForce, "tire", ParseTireEntry);
  r.Add(ElementKind::kForce, "wheel_brake", ParseWheelBrakeEntry);
  r.Add(ElementKind::kJoint, "contact_patch", ParseContactPatchEntry);
}

}  // namespace flexmb
