#pragma once
/// \file parse_context.h
/// The model file's reading state: a YamlContext plus the model under
/// construction, with look-ups of markers, joints and bodies by name.

#include <functional>
#include <initializer_list>
#include <map>
#include <string>

#include "flexmb/yaml/yaml_context.h"

namespace flexmb {

class Model;

/// State of one model-file load: the file, the model under construction,
/// and the entity currently read (for messages).
class ParseContext : public YamlContext {
 public:
  ParseContext(std::string file, Model& model) : YamlContext(std::move(file)), model_(model) {}

  /// The model being built.
  Model& model() { return model_; }
  /// Line of each entity read so far ("joint 'j1'" -> line), for errors
  /// raised later (e.g. by Model::Finalize) that name only the entity.
  std::map<std::string, int>& lines() { return lines_; }

  /// Index of the marker named at node[key] ("body.marker"); throws naming
  /// the marker and, if its body is missing, the body.
  int Marker(const YAML::Node& node, const char* key) const;
  /// Index of the joint named at node[key].
  int Joint(const YAML::Node& node, const char* key) const;
  /// Index of the force element named at node[key].
  int Force(const YAML::Node& node, const char* key) const;
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
  Model& model_;
  std::map<std::string, int> lines_;
};

}  // namespace flexmb
