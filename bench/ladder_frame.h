#pragma once
/// \file ladder_frame.h
/// A generated truck ladder frame of 4-node shells for the benchmarks
/// (bench/fe_modes.cc, bench/reduce.cc) and the reduction tests: two C-channel rails along x (6 m,
/// web 0.3 m in the x-z plane at y = +-0.45 m, flanges 0.08 m pointing
/// inwards, t = 6 mm) joined by eight flat cross members (t = 5 mm) in y-z
/// planes sharing the rails' web nodes; steel, free-free. About 5,500 nodes
/// / 33,000 DOF at the default element size 0.04 m.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <limits>
#include <vector>

#include "flexmb/fe/mesh.h"
#include "flexmb/vehicle/ladder_frame.h"

namespace flexmb::bench {

/// The ladder frame with element size about h [m]: the library's
/// generator (flexmb/vehicle/ladder_frame.h) with the bench's dimensions,
/// steel only, no interface nodes.
inline fe::Mesh LadderFrame(double h) {
  vehicle::LadderFrameData d;
  d.front_x = 6.0;
  d.length = 6.0;
  d.half_spacing = 0.45;
  d.web_height = 0.3;
  d.flange_width = 0.08;
  d.thickness = 0.006;
  d.cross_member_thickness = 0.005;
  d.bottom_z = -0.15;
  d.element_size = h;
  d.cross_members.clear();
  for (int k = 0; k < 8; ++k) d.cross_members.push_back(0.25 + k * 5.5 / 7);
  fe::Mesh mesh = vehicle::GenerateLadderFrame(d, {}).mesh;
  mesh.source = "generated ladder frame";
  return mesh;
}

/// Interface nodes of the frame: `per_rail` stations evenly spaced along
/// each rail (x from 0 to 6 m), at mid-height of the web (z = 0), the
/// nearest node to each station; 2 * per_rail node indices (26 by default,
/// the seed truck's count).
inline std::vector<int> LadderFrameInterface(const fe::Mesh& mesh, int per_rail = 13) {
  std::vector<int> nodes;
  for (double y : {-0.45, 0.45}) {
    for (int k = 0; k < per_rail; ++k) {
      const fe::Vec3 target(per_rail > 1 ? 6.0 * k / (per_rail - 1) : 3.0, y, 0.0);
      int best = -1;
      double dmin = std::numeric_limits<double>::infinity();
      for (size_t n = 0; n < mesh.nodes.size(); ++n) {
        const double d = (mesh.nodes[n].x - target).squaredNorm();
        if (d < dmin) {
          dmin = d;
          best = static_cast<int>(n);
        }
      }
      nodes.push_back(best);
    }
  }
  return nodes;
}

/// Writes the frame as Nastran bulk data (free field: MAT1, PSHELL, GRID,
/// CQUAD4), so that the benchmarks can time reading a file users would
/// bring. Coordinates with 10 significant digits.
inline void WriteBulkData(const fe::Mesh& mesh, const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "$ %s\nBEGIN BULK\n", mesh.source.c_str());
  for (const fe::Material& m : mesh.materials) {
    std::fprintf(f, "MAT1,%d,%.10g,%.10g,%.10g,%.10g\n", m.id, m.E, m.G, m.nu, m.rho);
  }
  for (const fe::ShellSection& s : mesh.shell_sections) {
    const int mid = mesh.materials[static_cast<size_t>(s.material)].id;
    std::fprintf(f, "PSHELL,%d,%d,%.10g,%d,,%d\n", s.id, mid, s.thickness, mid, mid);
  }
  for (const fe::Node& n : mesh.nodes) {
    std::fprintf(f, "GRID,%d,,%.10g,%.10g,%.10g\n", n.id, n.x.x(), n.x.y(), n.x.z());
  }
  for (const fe::Element& e : mesh.elements) {
    const int pid = mesh.shell_sections[static_cast<size_t>(e.property)].id;
    std::fprintf(f, "CQUAD4,%d,%d", e.id, pid);
    for (int n : e.nodes) std::fprintf(f, ",%d", mesh.nodes[static_cast<size_t>(n)].id);
    std::fprintf(f, "\n");
  }
  std::fprintf(f, "ENDDATA\n");
  if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path);
}

}  // namespace flexmb::bench
