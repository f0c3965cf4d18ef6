#pragma once
/// \file yaml_context.h
/// Helpers for reading YAML input files. Every error names the file, the
/// line of the offending node and the entity being read.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Reading one YAML file with located errors: the file name and the entity
/// currently read, so that every message reads "FILE:LINE: ENTITY: message".
/// Used by every YAML input (model file, FE model file, vehicle files); the
/// model file's ParseContext adds the model under construction.
class YamlContext {
 public:
  explicit YamlContext(std::string file) : file_(std::move(file)) {}
  virtual ~YamlContext() = default;

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
  void CheckKeys(const YAML::Node& node, const std::vector<const char*>& allowed) const;

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
  /// node[key] of a map, or an undefined node if the key is absent; fails
  /// if `node` is not a map.
  YAML::Node MapChild(const YAML::Node& node, const char* key) const;
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

 private:
  std::string file_;
  std::string entity_;
};

}  // namespace flexmb
