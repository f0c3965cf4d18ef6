#pragma once
/// \file ladder_frame.h
/// A generated truck ladder frame of 4-node shells for the benchmarks
/// (bench/fe_modes.cc, bench/reduce.cc): two C-channel rails along x (6 m,
/// web 0.3 m in the x-z plane at y = +-0.45 m, flanges 0.08 m pointing
/// inwards, t = 6 mm) joined by eight flat cross members (t = 5 mm) in y-z
/// planes sharing the rails' web nodes; steel, free-free. About 5,500 nodes
/// / 33,000 DOF at the default element size 0.04 m.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include "flexmb/fe/mesh.h"

namespace flexmb::bench {

/// The ladder frame with element size about h [m].
inline fe::Mesh LadderFrame(double h) {
  using fe::Element;
  using fe::ElementType;
  using fe::Mesh;
  using fe::Vec3;
  const double length = 6.0, b = 0.9, web = 0.3, flange = 0.08;
  const int nx = std::max(1, static_cast<int>(std::lround(length / h)));
  const int nz = std::max(1, static_cast<int>(std::lround(web / h)));
  const int nf = std::max(1, static_cast<int>(std::lround(flange / h)));
  const int ny = std::max(2, static_cast<int>(std::lround(b / h)));
  Mesh mesh;
  mesh.source = "generated ladder frame";
  flexmb::fe::Material steel;
  steel.id = 1;
  steel.E = 2.1e11;
  steel.nu = 0.3;
  steel.G = steel.E / 2.6;
  steel.rho = 7850.0;
  mesh.materials.push_back(steel);
  for (double t : {0.006, 0.005}) {
    flexmb::fe::ShellSection s;
    s.id = static_cast<int>(mesh.shell_sections.size()) + 1;
    s.material = 0;
    s.thickness = t;
    mesh.shell_sections.push_back(s);
  }
  std::map<std::tuple<long, long, long>, int> index;
  auto node = [&](const Vec3& x) {
    const auto key = std::make_tuple(std::lround(x.x() * 1e6), std::lround(x.y() * 1e6), std::lround(x.z() * 1e6));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    flexmb::fe::Node n;
    n.id = static_cast<int>(mesh.nodes.size()) + 1;
    n.x = x;
    mesh.nodes.push_back(n);
    index[key] = n.id - 1;
    return n.id - 1;
  };
  auto quad = [&](int property, int a, int c, int d, int e) {
    Element el;
    el.id = static_cast<int>(mesh.elements.size()) + 1;
    el.type = ElementType::kQuad4;
    el.property = property;
    el.nodes = {a, c, d, e};
    mesh.elements.push_back(el);
  };
  // a structured patch p(u, v), u in [0, nu], v in [0, nv]
  auto patch = [&](int property, int nu, int nv, auto p) {
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        quad(property, node(p(i, j)), node(p(i + 1, j)), node(p(i + 1, j + 1)), node(p(i, j + 1)));
      }
  };
  const double dx = length / nx, dz = web / nz, df = flange / nf;
  for (double side : {-1.0, 1.0}) {
    const double y = side * b / 2;
    patch(0, nx, nz, [&](int i, int j) { return Vec3(i * dx, y, -web / 2 + j * dz); });
    for (double zf : {-web / 2, web / 2}) {
      patch(0, nx, nf, [&](int i, int j) { return Vec3(i * dx, y - side * j * df, zf); });
    }
  }
  const int n_cross = 8;
  const double dy = b / ny;
  for (int k = 0; k < n_cross; ++k) {
    const double x = std::round((0.25 + k * (length - 0.5) / (n_cross - 1)) / dx) * dx;
    patch(1, ny, nz, [&](int i, int j) { return Vec3(x, -b / 2 + i * dy, -web / 2 + j * dz); });
  }
  mesh.IndexNodes();
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
