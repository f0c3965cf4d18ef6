#pragma once
/// \file solver_section.h
/// The `solver:` section, read the same way in every file that has one (the
/// model file, the lane-change file): the same keys, the same rules.

#include <yaml-cpp/yaml.h>

#include <initializer_list>

#include "flexmb/model/settings.h"
#include "flexmb/yaml/yaml_context.h"

namespace flexmb {

/// Reads the keys of a `solver:` map into `s` (absent keys keep their value:
/// the caller's defaults) and checks the result by FindSolverSettingsProblem,
/// failing at the line of the key a broken rule is about. `extra` keys are
/// allowed as well and left to the caller. Keys: docs/model-file.md, "solver".
void ReadSolverSection(const YAML::Node& node, YamlContext& ctx, SolverSettings& s,
                       std::initializer_list<const char*> extra = {});

}  // namespace flexmb
