#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

int NodeCount(ElementType type) {
  switch (type) {
    case ElementType::kQuad4: return 4;
    case ElementType::kTria3: return 3;
    case ElementType::kBeam2: return 2;
    case ElementType::kTet4: return 4;
    case ElementType::kTet10: return 10;
    case ElementType::kHex8: return 8;
  }
  return 0;
}

int DofsPerNode(ElementType type) {
  switch (type) {
    case ElementType::kQuad4:
    case ElementType::kTria3:
    case ElementType::kBeam2: return 6;
    default: return 3;
  }
}

const char* TypeName(ElementType type) {
  switch (type) {
    case ElementType::kQuad4: return "4-node shell";
    case ElementType::kTria3: return "3-node shell";
    case ElementType::kBeam2: return "2-node beam";
    case ElementType::kTet4: return "4-node tetrahedron";
    case ElementType::kTet10: return "10-node tetrahedron";
    case ElementType::kHex8: return "8-node hexahedron";
  }
  return "element";
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
