#pragma once
/// \file ancf_body_parser.h
/// Model-file entries for ANCF bodies (reference: docs/model-file.md,
/// "ANCF beams"): a body with `type: ancf_beam` (planar beam),
/// `type: ancf_cable` (3D cable) or `type: ancf_beam3d` (3D beam with torsion).

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "flexmb/model_file/parse_context.h"

namespace flexmb {

/// Builds the ANCF body of the model-file node `node` (its `type` is an ANCF
/// type), adds it and its markers to ctx.model() and records the line of
/// each entity in `lines` ("body 'rope'" -> line). Throws InputError naming
/// file, line and entity on bad input (non-positive length, section, element
/// count; a marker on a node that does not exist).
void ParseAncfBody(const YAML::Node& node, ParseContext& ctx, std::map<std::string, int>& lines);

/// Once the forces are read: every ancf_hoist_rope without its own drum is
/// fed by exactly one thing, a reeved rope's `span` or a `winch` driver.
/// Throws InputError naming the body's file and line otherwise.
void CheckHoistRopeFeeds(ParseContext& ctx);

}  // namespace flexmb
