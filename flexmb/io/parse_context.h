#pragma once
/// \file parse_context.h
/// Shared helpers for reading the YAML model file. Every error names the
/// file, the line of the offending node and the entity being read.

#include <yaml-cpp/yaml.h>

#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

class Model;

/// State of one model-file load: the file name, the model under
/// construction, and the entity currently read (for messages).
class ParseContext {
 public:
  ParseContext(std::string file, Model& model) : file_(std::move(file)), model_(model) {}

  /// The model being built.
  Model& model() { return model_; }
  /// The file being read.
  const std::string& file() const { return file_; }
  /// Sets the entity named in messages, e.g. "force 'front_spring'".
  void SetEntity(std::string entity) { entity_ = std::move(entity); }
  const std::string& entity() const { return entity_; }

  /// Throws InputError "FILE:LINE: ENTITY: message" at node's line.
  [[noreturn]] void Fail(const YAML::Node& node, const std::string& message) const;

  /// Throws if `node` is not a map or has a key outside `allowed` (naming the
  /// key and listing the allowed ones).
  void CheckKeys(const YAML::Node& node, std::initializer_list<const char*> allowed) const;

  /// Required / optional finite number at node[key].
  double Double(const YAML::Node& node, const char* key) const;
  double Double(const YAML::Node& node, const char* key, double fallback) const;
  /// Required positive (> 0) finite number.
  double Positive(const YAML::Node& node, const char* key) const;
  /// The finite number held by the scalar node `value` (e.g. a list entry);
  /// `what` names it in messages, e.g. "'inertia' entry 2".
  double Number(const YAML::Node& value, const std::string& what) const;
  /// Optional whole number at node[key].
  int Integer(const YAML::Node& node, const char* key, int fallback) const;
  /// 1-based line of `node` in the file, 0 if unknown (e.g. a missing key).
  static int Line(const YAML::Node& node);
  /// Runs `body`; an InputError it throws without a file (e.g. from a
  /// constructor or Model::Add*) is rethrown with this file, node's line and,
  /// if the error names none, the current entity.
  template <class F>
  decltype(auto) Guard(const YAML::Node& node, F&& body) const {
    try {
      return body();
    } catch (const InputError& e) {
      Rethrow(node, e);
    }
  }
  /// Rethrows `e` as described at Guard (or unchanged if it has a file).
  [[noreturn]] void Rethrow(const YAML::Node& node, const InputError& e) const;
  /// Required / optional string.
  std::string String(const YAML::Node& node, const char* key) const;
  std::string String(const YAML::Node& node, const char* key, const std::string& fallback) const;
  /// Optional boolean.
  bool Bool(const YAML::Node& node, const char* key, bool fallback) const;
  /// Required / optional 3-vector [x, y, z] of finite numbers.
  Vec3 Vector3(const YAML::Node& node, const char* key) const;
  Vec3 Vector3(const YAML::Node& node, const char* key, const Vec3& fallback) const;
  /// Optional orientation at node[key] (identity if absent); one of
  /// {quaternion: [w,x,y,z]}, {rotation_vector: [..]} [rad],
  /// {roll_pitch_yaw: [..]} [rad], {roll_pitch_yaw_deg: [..]},
  /// {z_axis: [..], x_axis: [..] (optional)}, {matrix: [[..],[..],[..]]}.
  Mat3 Orientation(const YAML::Node& node, const char* key) const;
  /// A function at node[key]: a number (constant), {expression: "..."}
  /// in `variable`, or {table: [[x, y], ...], interpolation: linear|spline,
  /// extrapolate: bool}, or {input: NAME, initial: VALUE} (math/input_function.h).
  std::shared_ptr<const ScalarFunction> Function(const YAML::Node& node, const char* key,
                                                  const char* variable = "t") const;
  /// Index of the marker named at node[key] ("body.marker"); throws naming
  /// the marker and, if its body is missing, the body.
  int Marker(const YAML::Node& node, const char* key) const;
  /// Index of the joint named at node[key].
  int Joint(const YAML::Node& node, const char* key) const;
  /// Index of the body named at node[key].
  int Body(const YAML::Node& node, const char* key) const;

  /// Reads the list node["markers"] (absent: nothing) of body `body` (model
  /// index) and adds its markers to the model. Each entry may have the keys
  /// `allowed` (which include name, position, orientation); its name must be
  /// non-empty without '.'; `position` [m] and `orientation` default to zero
  /// and identity. While an entry is read the entity is "marker
  /// 'body.name'"; `node_of(entry)` (if given) returns the node index of a
  /// node-based body (it may Fail), otherwise the marker has node -1. Records
  /// each marker's line in `lines` ("marker 'b.m'" -> line) and restores the
  /// entity afterwards.
  void ParseMarkerList(const YAML::Node& node, int body, std::initializer_list<const char*> allowed,
                       const std::function<int(const YAML::Node&)>& node_of,
                       std::map<std::string, int>& lines);

 private:
  std::string file_;
  Model& model_;
  std::string entity_;
};

/// Builds a force element from its model-file node (type from node["type"])
/// and adds it to ctx.model(). Implemented in io/force_parser.cc.
void ParseForce(const YAML::Node& node, ParseContext& ctx);

/// Builds a sensor from its model-file node and adds it to ctx.model().
/// Implemented in io/sensor_parser.cc.
void ParseSensor(const YAML::Node& node, ParseContext& ctx);

}  // namespace flexmb
