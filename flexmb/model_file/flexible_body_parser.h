#pragma once
/// \file flexible_body_parser.h
/// Model-file entries for floating-frame flexible bodies (reference:
/// docs/model-file.md, "Flexible bodies"): a body with `type: flexible`
/// referring to a body file written by `flexmb reduce`.

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "flexmb/model_file/parse_context.h"

namespace flexmb {

/// Reads the body file named by node["file"] (relative to the model file's
/// folder), builds the FlexibleBody, adds it and its markers to ctx.model()
/// and records the line of each entity in `lines`. Markers are given by
/// `node: <id>` (the FE node id); a node that is not an interface node of
/// the reduction gives a warning (its motion is only as exact as the modes
/// make it). Throws InputError naming file, line, body (and node) for a
/// missing or unreadable body file, a node id the body does not have, or
/// wrong initial modal values or damping.
void ParseFlexibleBody(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines);

}  // namespace flexmb
