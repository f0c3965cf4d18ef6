#pragma once
/// \file body_entry.h
/// Parts of body entries that the model file's other sections share: the
/// body name rules, the display shape and the marker list (also used by the
/// top-level `ground` section).

#include <yaml-cpp/yaml.h>

#include <string>

#include "flexmb/bodies/body.h"

namespace flexmb {

class ParseContext;

/// The entry's `name`: non-empty and without '.' (it separates body and
/// marker in "body.marker"); `kind` names the entity in messages ("body").
std::string BodyEntryName(const YAML::Node& node, const char* kind, const ParseContext& ctx);

/// Reads a display shape {type: box|cylinder|sphere, size|radius|length,
/// position, orientation} into `shape`.
void ParseBodyShape(const YAML::Node& s, Shape& shape, const ParseContext& ctx);

/// Reads node["markers"] (name, position, orientation) of body `body`.
void ParseBodyMarkers(const YAML::Node& node, int body, ParseContext& ctx);

}  // namespace flexmb
