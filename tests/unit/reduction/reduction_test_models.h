#pragma once
/// \file reduction_test_models.h
/// Shell and beam models built in code for the Craig-Bampton tests (unit and
/// validation), and small helpers to compare a reduced body with the full
/// FE model.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "bench/ladder_frame.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/reduction/reduced_body.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::reduction::testing {

/// Adds a flat steel plate parallel to the x-y plane at `corner`, a x b [m]
/// in nx x ny 4-node shells of thickness t [m] (node ids = index + 1).
/// Returns the node indices of its grid points, row-major, nx + 1 per row.
inline std::vector<int> AddPlate(fe::Mesh& mesh, int nx, int ny, double a, double b, double t,
                                 const fe::Vec3& corner = fe::Vec3::Zero()) {
  int steel = -1;
  for (size_t k = 0; k < mesh.materials.size(); ++k) {
    if (mesh.materials[k].E == 2.1e11) steel = static_cast<int>(k);
  }
  if (steel < 0) steel = fe::testing::AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  fe::ShellSection s;
  s.id = static_cast<int>(mesh.shell_sections.size()) + 1;
  s.material = steel;
  s.thickness = t;
  mesh.shell_sections.push_back(s);
  const int section = static_cast<int>(mesh.shell_sections.size()) - 1;
  std::vector<int> grid;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) grid.push_back(fe::testing::AddNode(mesh, corner + fe::Vec3(a * i / nx, b * j / ny, 0.0)));
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      fe::Element e;
      e.id = static_cast<int>(mesh.elements.size()) + 1;
      e.type = fe::ElementType::kQuad4;
      e.property = section;
      const int p = j * (nx + 1) + i;
      e.nodes = {grid[p], grid[p + 1], grid[p + nx + 2], grid[p + nx + 1]};
      e.origin = {"test.bdf", 5000 + e.id};
      mesh.elements.push_back(e);
    }
  }
  mesh.source = "test.bdf";
  return grid;
}

/// The bench's shell ladder frame at a coarse element size (about 1,000
/// nodes at h = 0.1 m) with its 2 x per_rail interface nodes.
struct Ladder {
  fe::Mesh mesh;
  std::vector<int> interface;
};
inline Ladder CoarseLadder(double h = 0.1, int per_rail = 4) {
  Ladder l;
  l.mesh = bench::LadderFrame(h);
  l.interface = bench::LadderFrameInterface(l.mesh, per_rail);
  return l;
}

/// The geometric rigid-body vectors of all active DOF (full numbering),
/// about the origin: n_full x 6, independent of the reduction code.
inline Eigen::MatrixXd FullRigidVectors(const fe::Mesh& mesh, const fe::DofMap& dofs) {
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(dofs.n_full, 6);
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    const fe::Vec3& x = mesh.nodes[n].x;
    for (int a = 0; a < 6; ++a) {
      fe::Vec3 u = fe::Vec3::Zero(), th = fe::Vec3::Zero();
      (a < 3 ? u : th)[a % 3] = 1.0;
      const fe::Vec3 ux = u + th.cross(x);
      for (int c = 0; c < 6; ++c) {
        const int f = dofs.full[n][c];
        if (f >= 0) r(f, a) = c < 3 ? ux[c] : th[c - 3];
      }
    }
  }
  return r;
}

/// Rows of ReducedBody::modes (6 per node) picked out for the free DOF of
/// an assembled model: n_free x n.
inline Eigen::MatrixXd FreeRows(const ReducedBody& body, const fe::DofMap& dofs) {
  Eigen::MatrixXd h(dofs.n_free, body.modes.cols());
  for (size_t n = 0; n < dofs.free.size(); ++n) {
    for (int c = 0; c < 6; ++c) {
      if (dofs.free[n][c] >= 0) h.row(dofs.free[n][c]) = body.modes.row(6 * static_cast<Eigen::Index>(n) + c);
    }
  }
  return h;
}

}  // namespace flexmb::reduction::testing
