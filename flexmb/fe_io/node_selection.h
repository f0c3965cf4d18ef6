#pragma once
/// \file node_selection.h
/// Nodes picked by geometry in an FE model file, where a mesh lacks the
/// sets one needs (a package's geometry file, imported matrices);
/// documented in docs/model-file.md, "Node references".

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "flexmb/fe/mesh.h"
#include "flexmb/yaml/yaml_context.h"

namespace flexmb::io {

/// The node indices, in mesh order, that the selection `v` picks:
///   {cylinder: {from: P, to: Q, radius: R, tolerance: t}}: the nodes at
///     R +- t from the axis P-Q, between the planes through P and Q normal
///     to it (+- t); t >= 0, default 1e-3 R;
///   {box: {min: A, max: B, tolerance: t}}: the nodes inside the box grown
///     by t >= 0 (default 0; faces included).
/// Fails through `ctx` (file, line, entity) for another form, bad values,
/// or a selection that picks no node (naming the nearest node, its position
/// and by how much it misses, beyond the tolerance); `mesh_name` names the
/// mesh in that message.
std::vector<int> SelectNodes(const fe::Mesh& mesh, const std::string& mesh_name, const YAML::Node& v,
                             const YamlContext& ctx);

}  // namespace flexmb::io
