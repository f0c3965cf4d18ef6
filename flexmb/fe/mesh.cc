#include "flexmb/fe/mesh.h"

#include "flexmb/fe/element_traits.h"

namespace flexmb::fe {

namespace {

// the row of `type`, or null for an id without one
const ElementTraits* MeshTypeRow(ElementType type) {
  const std::span<const ElementTraits> rows = AllElementTraits();
  const size_t k = static_cast<size_t>(type);
  return k < rows.size() ? &rows[k] : nullptr;
}

}  // namespace

int NodeCount(ElementType type) {
  const ElementTraits* t = MeshTypeRow(type);
  return t ? t->nodes : 0;
}

int DofsPerNode(ElementType type) {
  const ElementTraits* t = MeshTypeRow(type);
  return t ? t->DofsPerNode() : 3;
}

const char* TypeName(ElementType type) {
  const ElementTraits* t = MeshTypeRow(type);
  return t ? t->description : "element";
}

int Mesh::NodeIndex(int id) const {
  auto it = node_index_.find(id);
  return it == node_index_.end() ? -1 : it->second;
}

void Mesh::IndexNodes() {
  node_index_.clear();
  for (size_t k = 0; k < nodes.size(); ++k) node_index_[nodes[k].id] = static_cast<int>(k);
}

}  // namespace flexmb::fe
