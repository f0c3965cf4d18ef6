#pragma once
/// \file crane_template.h
/// The crane template (docs/crane-file.md): a model file with a top-level
/// `crane` map is expanded, before it is read, into the bodies, joints,
/// drivers, forces and sensors of a slewing luffing-boom crane, and the
/// crane keys of its manoeuvres (`hoist`, `slew`, `luff`, `release_time`,
/// `crane`) into driver functions and joint release times. The rest of the
/// file (solver, output, extra bodies or sensors) is read as usual.

#include <yaml-cpp/yaml.h>

#include <string>

#include "flexmb/yaml/yaml_context.h"

namespace flexmb::crane {

/// True if `root` (a model file) has a `crane` map.
bool IsCraneFile(const YAML::Node& root);

/// Expands root["crane"] in place (see the file comment) for the manoeuvre
/// `requested` (empty: the file's `manoeuvre`, if any): the crane's entries
/// are appended to root's lists, the crane keys of every manoeuvre are
/// checked and those of the selected one applied, and `crane` is removed.
/// Throws InputError naming the file, line and part of the crane for bad
/// data: a boom node that is not an interface node of its body file, a
/// luffing angle outside the cylinder's stroke, a hoist that empties the
/// drum or hauls the hook into the sheave, ... Body files are read relative
/// to the folder of ctx.file().
void ExpandCraneFile(YAML::Node& root, const std::string& requested, YamlContext& ctx);

}  // namespace flexmb::crane

namespace flexmb::crane {

/// The model file that the crane file at `path` expands to for the
/// manoeuvre `manoeuvre` (empty: the file's), as YAML text: the crane's
/// entries written out, and of `manoeuvres` only the selected one with its
/// model-file keys. Relative paths in it (the boom's body file) are as in
/// the crane file: write it next to it. Throws InputError as LoadModelFile.
std::string ExpandedCraneFile(const std::string& path, const std::string& manoeuvre);

}  // namespace flexmb::crane
