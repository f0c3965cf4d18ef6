#pragma once
/// \file joint_entry.h
/// The part every joint entry of the model file shares: markers i and j on
/// two different bodies, then the type's own parameters.

#include <yaml-cpp/yaml.h>

#include <functional>
#include <initializer_list>
#include <memory>
#include <string>

#include "flexmb/joints/joint.h"

namespace flexmb {

class ParseContext;

/// Reads a joint entry: checks its keys (name, type, i, j, the optional
/// release_time [s] > 0 and limits [lower, upper] of the first coordinate,
/// and the type's `parameters`),
/// resolves markers i and j (which must lie on different bodies), builds the
/// joint by `make(mi, mj)` and adds it between them; errors name the file,
/// line and joint.
void AddJointEntry(const YAML::Node& node, const std::string& name, ParseContext& ctx,
                   std::initializer_list<const char*> parameters,
                   const std::function<std::unique_ptr<Joint>(int mi, int mj)>& make);

}  // namespace flexmb
