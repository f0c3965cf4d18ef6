#pragma once
/// \file fe_test_models.h
/// Small meshes built in code for the FE assembly and modal tests.

#include <string>

#include "flexmb/fe/mesh.h"

namespace flexmb::fe::testing {

/// Adds a node with id = index + 1 and returns its index.
inline int AddNode(Mesh& mesh, const Vec3& x) {
  Node n;
  n.id = static_cast<int>(mesh.nodes.size()) + 1;
  n.x = x;
  n.origin = {"test.bdf", 100 + n.id};
  mesh.nodes.push_back(n);
  mesh.IndexNodes();
  return static_cast<int>(mesh.nodes.size()) - 1;
}

/// Adds a material and returns its index (G from E and nu).
inline int AddMaterial(Mesh& mesh, double E, double nu, double rho) {
  Material m;
  m.id = static_cast<int>(mesh.materials.size()) + 1;
  m.E = E;
  m.nu = nu;
  m.G = E / (2.0 * (1.0 + nu));
  m.rho = rho;
  mesh.materials.push_back(m);
  return static_cast<int>(mesh.materials.size()) - 1;
}

/// Adds a beam section of a solid circular bar of radius r.
inline int AddRoundBar(Mesh& mesh, int material, double r) {
  BeamSection s;
  s.id = static_cast<int>(mesh.beam_sections.size()) + 1;
  s.material = material;
  s.A = M_PI * r * r;
  s.Iy = s.Iz = M_PI * r * r * r * r / 4.0;
  s.J = 2.0 * s.Iy;
  mesh.beam_sections.push_back(s);
  return static_cast<int>(mesh.beam_sections.size()) - 1;
}

/// Adds a 2-node beam between node indices a and b.
inline int AddBeam(Mesh& mesh, int section, int a, int b, const Vec3& orientation) {
  Element e;
  e.id = static_cast<int>(mesh.elements.size()) + 1;
  e.type = ElementType::kBeam2;
  e.property = section;
  e.nodes = {a, b};
  e.orientation = orientation;
  e.origin = {"test.bdf", 1000 + e.id};
  mesh.elements.push_back(e);
  return static_cast<int>(mesh.elements.size()) - 1;
}

/// Adds a point mass without inertia at node index n.
inline void AddPointMass(Mesh& mesh, int n, double m, const Vec3& offset = Vec3::Zero(),
                         const Mat3& inertia = Mat3::Zero()) {
  PointMass pm;
  pm.id = static_cast<int>(mesh.point_masses.size()) + 1;
  pm.node = n;
  pm.mass = m;
  pm.offset = offset;
  pm.inertia = inertia;
  pm.origin = {"test.bdf", 2000 + pm.id};
  mesh.point_masses.push_back(pm);
}

/// Adds a rigid link and returns its index.
inline int AddRigidLink(Mesh& mesh, int id, int independent, std::vector<int> dependent, int dofs = 0b111111) {
  RigidLink l;
  l.id = id;
  l.independent = independent;
  l.dependent = std::move(dependent);
  l.dofs = dofs;
  l.origin = {"test.bdf", 3000 + id};
  mesh.rigid_links.push_back(l);
  return static_cast<int>(mesh.rigid_links.size()) - 1;
}

/// Adds a single-point constraint.
inline void AddConstraint(Mesh& mesh, int n, int dofs) {
  Constraint c;
  c.node = n;
  c.dofs = dofs;
  c.origin = {"test.bdf", 4000 + static_cast<int>(mesh.constraints.size())};
  mesh.constraints.push_back(c);
}

/// Chain of n_mass point masses m on massless axial bars of stiffness
/// k = E A / L along x, node 0 clamped, every other node free in ux only.
inline Mesh SpringChain(int n_mass, double k, double m, double length = 0.5) {
  Mesh mesh;
  const int mat = AddMaterial(mesh, 2.0e11, 0.3, 0.0);
  const int sec = AddRoundBar(mesh, mat, 0.01);
  mesh.materials[mat].E = k * length / mesh.beam_sections[sec].A;
  mesh.materials[mat].G = mesh.materials[mat].E / 2.6;
  for (int i = 0; i <= n_mass; ++i) AddNode(mesh, Vec3(i * length, 0.0, 0.0));
  for (int i = 0; i < n_mass; ++i) AddBeam(mesh, sec, i, i + 1, Vec3(0.0, 1.0, 0.0));
  for (int i = 1; i <= n_mass; ++i) AddPointMass(mesh, i, m);
  AddConstraint(mesh, 0, 0b111111);
  for (int i = 1; i <= n_mass; ++i) AddConstraint(mesh, i, 0b111110);
  return mesh;
}

/// Free-free 3D frame: nx x ny x nz grid of nodes with spacing h joined by
/// steel bars along the grid lines, optional diagonals in every face.
inline Mesh Lattice(int nx, int ny, int nz, double h, bool diagonals = true) {
  Mesh mesh;
  const int mat = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  const int sec = AddRoundBar(mesh, mat, 0.05 * h);
  auto id = [&](int i, int j, int k) { return (k * ny + j) * nx + i; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) AddNode(mesh, Vec3(i * h, j * h, k * h));
  const Vec3 ex(1, 0, 0), ey(0, 1, 0), ez(0, 0, 1);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        if (i + 1 < nx) AddBeam(mesh, sec, id(i, j, k), id(i + 1, j, k), ey);
        if (j + 1 < ny) AddBeam(mesh, sec, id(i, j, k), id(i, j + 1, k), ez);
        if (k + 1 < nz) AddBeam(mesh, sec, id(i, j, k), id(i, j, k + 1), ex);
        if (diagonals && i + 1 < nx && j + 1 < ny) AddBeam(mesh, sec, id(i, j, k), id(i + 1, j + 1, k), ez);
      }
  return mesh;
}

}  // namespace flexmb::fe::testing
