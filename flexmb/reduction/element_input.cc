#include "flexmb/reduction/element_input.h"

#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/element_common.h"

namespace flexmb::reduction {

fe::ElementInput ResolveElementInput(const fe::Mesh& mesh, const fe::Element& e, std::vector<fe::Vec3>& x) {
  const ErrorContext ctx = fe::ElementContext(e);
  if (static_cast<int>(e.nodes.size()) != fe::NodeCount(e.type))
    throw InputError("has " + std::to_string(e.nodes.size()) + " nodes, expected " +
                         std::to_string(fe::NodeCount(e.type)),
                     ctx);
  x.clear();
  for (int node : e.nodes) {
    if (node < 0 || node >= static_cast<int>(mesh.nodes.size()))
      throw InputError("refers to a node that does not exist (index " + std::to_string(node) + ")", ctx);
    x.push_back(mesh.nodes[node].x);
  }
  fe::ElementInput in;
  in.element = &e;
  in.x = x.data();
  // the element's section in the list of its family, checked
  auto section = [&](const auto& list, const char* family) {
    if (e.property < 0 || e.property >= static_cast<int>(list.size()))
      throw InputError(std::string("has no ") + family + " section", ctx);
    return &list[e.property];
  };
  int material = -1;
  switch (fe::Traits(e.type).family) {
    case fe::ElementFamily::kShell:
      in.shell = section(mesh.shell_sections, "shell");
      material = in.shell->material;
      break;
    case fe::ElementFamily::kBeam:
      in.beam = section(mesh.beam_sections, "beam");
      material = in.beam->material;
      break;
    case fe::ElementFamily::kSolid: material = section(mesh.solid_sections, "solid")->material; break;
  }
  if (in.shell != nullptr && in.shell->laminate && material < 0) return in;  // the plies carry the material
  if (material < 0 || material >= static_cast<int>(mesh.materials.size()))
    throw InputError("its section has no material (a mesh read back from a body file has none for laminated "
                     "shells, membranes and beams with PBEAM axis offsets: assemble the FE model itself)",
                     ctx);
  in.material = &mesh.materials[material];
  return in;
}

}  // namespace flexmb::reduction
