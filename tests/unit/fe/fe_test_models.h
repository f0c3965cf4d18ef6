#pragma once
/// \file fe_test_models.h
/// Helpers shared by the FE tests (unit and validation): small meshes built
/// in code, rigid-body modes and their checks, a dense solve with prescribed
/// DOF, and the check of an InputError's message.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <array>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::fe::testing {

/// Cross-product matrix: Skew(v) w = v x w.
inline Mat3 Skew(const Vec3& v) {
  Mat3 s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

/// A pseudo-random proper rotation, reproducible from its seed.
inline Mat3 RandomRotation(unsigned seed) {
  std::srand(seed);
  return Eigen::Quaterniond(Eigen::Vector4d::Random().normalized()).toRotationMatrix();
}

/// The six rigid-body modes of nodes at x with 3 (ux uy uz) or 6 (ux uy uz
/// rx ry rz) DOF per node, node by node: columns are the translations along
/// x, y, z and the rotations about the origin's x, y, z axes.
inline MatX RigidModes(const std::vector<Vec3>& x, int dofs_per_node) {
  const int n = static_cast<int>(x.size());
  MatX r = MatX::Zero(dofs_per_node * n, 6);
  for (int i = 0; i < n; ++i) {
    r.block<3, 3>(dofs_per_node * i, 0).setIdentity();
    r.block<3, 3>(dofs_per_node * i, 3) = -Skew(x[i]);
    if (dofs_per_node == 6) r.block<3, 3>(6 * i + 3, 3).setIdentity();
  }
  return r;
}

/// Checks an element or model stiffness K with nodes at x: symmetric, the
/// six rigid-body modes store no energy (R^T K R = 0 to round-off), exactly
/// six eigenvalues at round-off level and the others above `positive` times
/// the largest (no spurious zero-energy mode).
inline void ExpectSixRigidModes(const MatX& K, const std::vector<Vec3>& x, int dofs_per_node,
                                double positive = 1e-9) {
  EXPECT_LT((K - K.transpose()).norm(), 1e-13 * K.norm());
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<MatX>(K).eigenvalues();
  const double top = ev.cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev(i)), 1e-11 * top) << "eigenvalue " << i;
  for (int i = 6; i < ev.size(); ++i) EXPECT_GT(ev(i), positive * top) << "eigenvalue " << i;
  const MatX r = RigidModes(x, dofs_per_node);
  EXPECT_LT((r.transpose() * K * r).norm(), 1e-11 * top);
}

/// Analytic rigid-body mass (6 x 6, as RigidModes' columns) of a body made of
/// tetrahedra (corner lists), density rho: int x x^T dV = V / 20 (sum x_i
/// x_i^T + s s^T), s = sum x_i.
inline Eigen::Matrix<double, 6, 6> TetsRigidMass(const std::vector<std::array<Vec3, 4>>& tets, double rho) {
  double m = 0.0;
  Vec3 s1 = Vec3::Zero();
  Mat3 s2 = Mat3::Zero();
  for (const auto& t : tets) {
    const double v = std::abs((t[1] - t[0]).cross(t[2] - t[0]).dot(t[3] - t[0])) / 6.0;
    const Vec3 s = t[0] + t[1] + t[2] + t[3];
    Mat3 q = s * s.transpose();
    for (const Vec3& p : t) q += p * p.transpose();
    m += rho * v;
    s1 += rho * v * s / 4.0;
    s2 += rho * v / 20.0 * q;
  }
  Eigen::Matrix<double, 6, 6> out;
  out << m * Mat3::Identity(), -Skew(s1), Skew(s1), s2.trace() * Mat3::Identity() - s2;
  return out;
}

/// One solid element on nodes 0 .. n-1 with E = 2e11 Pa, nu = 0.3, rho = 7800
/// kg/m^3, for element tests; Compute goes through the traits table, as the
/// assembler does.
struct OneSolid {
  Element element;
  Material material;
  std::vector<Vec3> x;

  OneSolid(ElementType type, std::vector<Vec3> nodes, int id, Origin origin) {
    element.id = id;
    element.type = type;
    element.origin = std::move(origin);
    for (size_t i = 0; i < nodes.size(); ++i) element.nodes.push_back(static_cast<int>(i));
    material.E = 2.0e11;
    material.nu = 0.3;
    material.rho = 7800.0;
    x = std::move(nodes);
  }
  ElementInput Input(MassForm form = MassForm::kConsistent) const {
    ElementInput in;
    in.element = &element;
    in.x = x.data();
    in.material = &material;
    in.mass_form = form;
    return in;
  }
  void Compute(MatX& K, MatX& M, MassForm form = MassForm::kConsistent) const { ElementMatrices(Input(form), K, M); }
};

/// Solves K u = 0 for the DOF not marked `fixed`, the fixed ones taking their
/// values from `u_fixed`; returns the whole u.
inline Eigen::VectorXd SolvePrescribed(const MatX& k, const std::vector<bool>& fixed,
                                       const Eigen::VectorXd& u_fixed) {
  const int n = static_cast<int>(k.rows());
  std::vector<int> f, p;
  for (int i = 0; i < n; ++i) (fixed[i] ? p : f).push_back(i);
  MatX kff(f.size(), f.size()), kfp(f.size(), p.size());
  for (size_t a = 0; a < f.size(); ++a) {
    for (size_t b = 0; b < f.size(); ++b) kff(a, b) = k(f[a], f[b]);
    for (size_t b = 0; b < p.size(); ++b) kfp(a, b) = k(f[a], p[b]);
  }
  Eigen::VectorXd up(p.size());
  for (size_t b = 0; b < p.size(); ++b) up(b) = u_fixed(p[b]);
  const Eigen::VectorXd uf = kff.ldlt().solve(-kfp * up);
  Eigen::VectorXd u = u_fixed;
  for (size_t a = 0; a < f.size(); ++a) u(f[a]) = uf(a);
  return u;
}

/// Dense assembly of the stiffness of `elements` (lists of node indices)
/// on n_nodes nodes with dofs_per_node DOF each; `stiffness(conn)` returns
/// the element matrix of the element on the nodes conn, node by node.
template <class F>
MatX DenseStiffness(int n_nodes, int dofs_per_node, const std::vector<std::vector<int>>& elements,
                    F&& stiffness) {
  const int d = dofs_per_node;
  MatX k = MatX::Zero(d * n_nodes, d * n_nodes);
  for (const std::vector<int>& conn : elements) {
    const MatX ke = stiffness(conn);
    for (size_t a = 0; a < conn.size(); ++a)
      for (size_t b = 0; b < conn.size(); ++b)
        k.block(d * conn[a], d * conn[b], d, d) += ke.block(d * a, d * b, d, d);
  }
  return k;
}

/// Patch test on nodes x (3 DOF each) with `elements` (node lists) whose
/// stiffness `element_stiffness(coordinates)` gives: the field u0 + A x
/// (fixed u0, A; plus 1e-3 x^2 in ux with `quadratic`) prescribed on the
/// nodes not `interior`; returns the largest error of the solved interior
/// DOF against the field.
template <class F>
double PatchTestError(const std::vector<Vec3>& x, const std::vector<std::vector<int>>& elements,
                      const std::vector<bool>& interior, F&& element_stiffness, bool quadratic = false) {
  const MatX k = DenseStiffness(static_cast<int>(x.size()), 3, elements, [&](const std::vector<int>& conn) {
    std::vector<Vec3> xe;
    for (int i : conn) xe.push_back(x[static_cast<size_t>(i)]);
    return MatX(element_stiffness(xe));
  });
  Mat3 A;
  A << 1.0e-3, 2.0e-4, -3.0e-4, 5.0e-4, -2.0e-3, 1.0e-4, -4.0e-4, 6.0e-4, 1.5e-3;
  const Vec3 u0(1.0e-3, -2.0e-3, 5.0e-4);
  std::vector<bool> fixed(3 * x.size());
  Eigen::VectorXd exact(3 * x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    exact.segment<3>(3 * i) = u0 + A * x[i];
    if (quadratic) exact(3 * i) += 1e-3 * x[i].x() * x[i].x();
    for (int d = 0; d < 3; ++d) fixed[3 * i + d] = !interior[i];
  }
  return (SolvePrescribed(k, fixed, exact) - exact).cwiseAbs().maxCoeff();
}

/// Runs `f` and expects an InputError whose message contains every one of
/// `parts` (file:line, entity, the complaint).
template <class F>
void ExpectInputErrorWith(F&& f, std::initializer_list<std::string> parts) {
  try {
    f();
    ADD_FAILURE() << "no InputError; expected one mentioning " << *parts.begin();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    for (const std::string& part : parts) EXPECT_NE(msg.find(part), std::string::npos) << msg;
  }
}

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

/// Adds an element of any type on the node indices `nodes` with the section
/// `property` of its family; id = position + 1, origin test.bdf:1000 + id.
inline int AddElement(Mesh& mesh, ElementType type, int property, std::vector<int> nodes) {
  Element e;
  e.id = static_cast<int>(mesh.elements.size()) + 1;
  e.type = type;
  e.property = property;
  e.nodes = std::move(nodes);
  e.origin = {"test.bdf", 1000 + e.id};
  mesh.elements.push_back(e);
  return static_cast<int>(mesh.elements.size()) - 1;
}

/// Adds a 2-node beam between node indices a and b.
inline int AddBeam(Mesh& mesh, int section, int a, int b, const Vec3& orientation) {
  const int e = AddElement(mesh, ElementType::kBeam2, section, {a, b});
  mesh.elements[e].orientation = orientation;
  return e;
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
