/// \file vtk_fuzz.cc
/// libFuzzer target of the legacy VTK reader (io::ReadVtk): any input must
/// give a mesh or a flexmb::Error, never a crash, hang or sanitizer report.
/// A mesh that reads is written back (io::WriteVtk) and read again, which
/// must give the same nodes (bit for bit) and elements.

#include <cstdlib>
#include <cstring>

#include "flexmb/fe_io/vtk_mesh.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  flexmb::fuzz::ReadScratchFile(data, size, ".vtk", [](const std::string& path) {
    const flexmb::fe::Mesh mesh = flexmb::io::ReadVtk(path);
    const std::string copy = path + ".out.vtk";
    flexmb::io::WriteVtk(mesh, copy);
    const flexmb::fe::Mesh again = flexmb::io::ReadVtk(copy);
    if (again.nodes.size() != mesh.nodes.size() || again.elements.size() != mesh.elements.size()) std::abort();
    for (size_t k = 0; k < mesh.nodes.size(); ++k)
      if (again.nodes[k].id != mesh.nodes[k].id ||
          std::memcmp(again.nodes[k].x.data(), mesh.nodes[k].x.data(), 3 * sizeof(double)) != 0)
        std::abort();
    for (size_t k = 0; k < mesh.elements.size(); ++k)
      if (again.elements[k].id != mesh.elements[k].id || again.elements[k].type != mesh.elements[k].type ||
          again.elements[k].nodes != mesh.elements[k].nodes)
        std::abort();
  });
  return 0;
}
