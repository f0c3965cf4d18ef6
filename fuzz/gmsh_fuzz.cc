/// \file gmsh_fuzz.cc
/// libFuzzer target of the gmsh reader (io::ReadGmsh): any input must give
/// a mesh or a flexmb::Error, never a crash, hang or sanitizer report. A
/// mesh that reads must have valid node indices in its elements and sets.

#include <cstdlib>

#include "flexmb/fe_io/gmsh_reader.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".msh", [](const std::string& path) {
    const flexmb::fe::Mesh mesh = flexmb::io::ReadGmsh(path);
    const int nn = static_cast<int>(mesh.nodes.size());
    const int ne = static_cast<int>(mesh.elements.size());
    for (const flexmb::fe::Element& e : mesh.elements) {
      if (static_cast<int>(e.nodes.size()) != flexmb::fe::NodeCount(e.type)) std::abort();
      for (int n : e.nodes)
        if (n < 0 || n >= nn) std::abort();
    }
    for (const auto& [name, set] : mesh.node_sets)
      for (int n : set)
        if (n < 0 || n >= nn) std::abort();
    for (const auto& [name, set] : mesh.element_sets)
      for (int e : set)
        if (e < 0 || e >= ne) std::abort();
  });
  return 0;
}
