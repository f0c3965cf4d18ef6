#pragma once
/// \file element_registry.h
/// The one registry of the element types a model file can name: bodies,
/// joints, drivers, force elements and sensors, each by its `type` name with
/// the function that reads its parameters. The registration lines are in
/// one file per element folder (model_file/*_types.cc) and are listed in
/// ModelFileTypes(); adding a type is its file pair, its test and one line
/// (docs/design.md, "Map").

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace flexmb {

class ParseContext;

/// The kinds of model-file entries, one per top-level list.
enum class ElementKind { kBody, kJoint, kDriver, kForce, kSensor };

/// The name of a kind as in messages ("body", "joint", ...).
const char* KindName(ElementKind kind);

/// Reads one model-file entry of a registered type and adds the element (and
/// anything it brings along, e.g. a body's markers) to ctx.model(). `node`
/// is a map; `name` is its validated "name". The context's entity already
/// names the element ("joint 'j1'"); errors go through ctx (file, line,
/// entity).
using ElementParser = void (*)(const YAML::Node& node, const std::string& name, ParseContext& ctx);

/// One registered type.
struct ElementType {
  ElementKind kind;
  std::string name;      ///< the `type` value in the model file
  ElementParser parse;   ///< reads and adds one entry
};

/// Element types by kind and name.
class ElementRegistry {
 public:
  /// Registers a type; throws std::logic_error for a duplicate name of a kind.
  void Add(ElementKind kind, std::string name, ElementParser parse);
  /// The type `name` of `kind`, or nullptr.
  const ElementType* Find(ElementKind kind, const std::string& name) const;
  /// The names of `kind`, in registration order.
  std::vector<std::string> Names(ElementKind kind) const;

 private:
  std::vector<ElementType> types_;
};

/// Reads entry `index` (0-based, for messages) of the top-level list of
/// `kind` (bodies, joints, ...): its name and type (bodies default to rigid,
/// drivers to coordinate), then the registered parser, which adds the
/// element to ctx.model(). Errors name the file, line and entity ("joint
/// 'j1'", or "body #2" before a body's name is read).
void ParseElement(ElementKind kind, const YAML::Node& node, int index, ParseContext& ctx);

/// Every type the model file knows, registered once on first use by the
/// Register*Types functions below (in this order).
const ElementRegistry& ModelFileTypes();

/// Registration lists, one per element folder (model_file/<folder>_types.cc).
void RegisterBodyTypes(ElementRegistry& r);     ///< rigid, flexible, ANCF
void RegisterJointTypes(ElementRegistry& r);    ///< joints and drivers
void RegisterForceTypes(ElementRegistry& r);    ///< force elements
void RegisterSensorTypes(ElementRegistry& r);   ///< sensors
void RegisterVehicleTypes(ElementRegistry& r);  ///< tire, wheel brake, contact patch

}  // namespace flexmb
