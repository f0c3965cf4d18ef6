#include "flexmb/fe/mesh_checks.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace flexmb::fe {
namespace {

// union-find over node indices
struct Parts {
  std::vector<int> up;
  explicit Parts(int n) : up(n) { std::iota(up.begin(), up.end(), 0); }
  int Root(int a) {
    while (up[a] != a) a = up[a] = up[up[a]];
    return a;
  }
  void Join(int a, int b) {
    if (a >= 0 && b >= 0) up[Root(a)] = Root(b);
  }
};

std::string At(const Origin& o) {
  if (o.file.empty()) return "";
  return " (" + o.file + (o.line > 0 ? ":" + std::to_string(o.line) : "") + ")";
}

}  // namespace

MeshCheck CheckMesh(const Mesh& mesh) {
  MeshCheck out;
  const int nn = static_cast<int>(mesh.nodes.size());
  if (mesh.elements.empty() || nn == 0) return out;
  Parts p(nn);
  std::vector<char> used(nn, 0);
  auto use = [&](int n) {
    if (n >= 0 && n < nn) used[n] = 1;
  };
  for (const Element& e : mesh.elements)
    for (int n : e.nodes) {
      use(n);
      p.Join(n, e.nodes.front());
    }
  for (const ScalarSpring& s : mesh.springs) {
    use(s.node_a);
    use(s.node_b);
    p.Join(s.node_a, s.node_b);
  }
  for (const RigidLink& l : mesh.rigid_links) {
    use(l.independent);
    for (int n : l.dependent) {
      use(n);
      p.Join(n, l.independent);
    }
  }
  for (const LinearConstraint& c : mesh.linear_constraints) {
    use(c.node);
    for (const MpcTerm& t : c.terms) {
      use(t.node);
      p.Join(t.node, c.node);
    }
  }
  for (const PointMass& m : mesh.point_masses) use(m.node);

  // the parts of the used nodes
  std::vector<int> part_of(nn, -1);
  for (int n = 0; n < nn; ++n) {
    if (!used[n]) {
      out.unused_nodes.push_back(n);
      continue;
    }
    const int r = p.Root(n);
    if (part_of[r] < 0) {
      part_of[r] = static_cast<int>(out.parts.size());
      out.parts.push_back(MeshPart{0, 0, -1, n, false});
    }
    ++out.parts[part_of[r]].nodes;
  }
  for (int k = 0; k < static_cast<int>(mesh.elements.size()); ++k) {
    MeshPart& part = out.parts[part_of[p.Root(mesh.elements[k].nodes.front())]];
    if (part.first_element < 0) part.first_element = k;
    ++part.elements;
  }
  for (const Constraint& c : mesh.constraints)
    if (c.node >= 0 && c.node < nn && used[c.node]) out.parts[part_of[p.Root(c.node)]].supported = true;
  std::stable_sort(out.parts.begin(), out.parts.end(), [](const MeshPart& a, const MeshPart& b) {
    return a.elements != b.elements ? a.elements > b.elements : a.nodes > b.nodes;
  });
  return out;
}

std::vector<std::string> MeshCheckWarnings(const Mesh& mesh, const MeshCheck& check, const std::string& file) {
  std::vector<std::string> out;
  if (check.parts.size() > 1) {
    std::ostringstream s;
    s << file << ": the model falls into " << check.parts.size()
      << " parts that no element, spring, rigid link or constraint joins:";
    int free_parts = 0;
    const size_t shown = std::min<size_t>(check.parts.size(), 6);
    for (size_t k = 0; k < check.parts.size(); ++k) {
      const MeshPart& part = check.parts[k];
      if (!part.supported) ++free_parts;
      if (k >= shown) continue;
      s << (k ? ";" : "") << " part " << k + 1 << ": ";
      if (part.first_element >= 0) {
        const Element& e = mesh.elements[part.first_element];
        s << part.elements << (part.elements == 1 ? " element" : " elements") << " and " << part.nodes
          << (part.nodes == 1 ? " node" : " nodes") << " from element " << e.id << At(e.origin);
      } else {
        s << "node " << mesh.nodes[part.first_node].id << (part.nodes > 1 ? " and others" : "")
          << " without elements (springs, links or a point mass only)";
      }
      if (part.supported) s << ", supported";
    }
    if (shown < check.parts.size()) s << "; and " << check.parts.size() - shown << " more";
    // one connected model has 6 rigid-body modes free-free, none once supported
    const bool any_support = free_parts < static_cast<int>(check.parts.size());
    s << ". A part held by no support moves as a rigid body: the model " << (any_support ? "with its supports" : "free-free")
      << " has up to " << 6 * free_parts << " rigid-body (zero-frequency) modes instead of " << (any_support ? 0 : 6)
      << "; join the parts (shared nodes, RBE2, a spring, *TIE) if they are one piece";
    out.push_back(s.str());
  }
  if (!check.unused_nodes.empty()) {
    std::ostringstream s;
    s << file << ": " << check.unused_nodes.size() << (check.unused_nodes.size() == 1 ? " node is" : " nodes are")
      << " used by no element, spring, link, constraint or mass (" << (check.unused_nodes.size() == 1 ? "id" : "ids");
    for (size_t k = 0; k < std::min<size_t>(check.unused_nodes.size(), 5); ++k)
      s << " " << mesh.nodes[check.unused_nodes[k]].id;
    s << (check.unused_nodes.size() > 5 ? " ..." : "")
      << "): they carry neither stiffness nor mass and have no degrees of freedom (e.g. orientation nodes)";
    out.push_back(s.str());
  }
  return out;
}

}  // namespace flexmb::fe
