#pragma once
/// \file fe_validation.h
/// Helpers of the FE validation tests (tests/validation/fe_*_test.cc):
/// structured shell and hexahedral meshes built in code, a static solve and
/// a modal solve through flexmb's own assembly (fe::Assemble) and eigen
/// solver (fe::SolveModes), and the checks of a mesh-convergence sequence.
/// Reference numbers and their sources: docs/validation.md, sections
/// "FE: shells (obstacle course and plates)" and "FE: beams and solids".

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/SparseCholesky>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/nastran/nastran_reader.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::fe::validation {

constexpr double kPi = 3.14159265358979323846;

/// A structured shell mesh of one material and thickness on a parametric
/// patch x(u, v), u, v in [0, 1]: nu_el x nv_el quads, or each quad split
/// along its diagonal into two triangles. Node (i, j), i along u, has the
/// index j (nu_el + 1) + i.
struct ShellGrid {
  Mesh mesh;
  int nu_nodes = 0, nv_nodes = 0;

  ShellGrid(int nu_el, int nv_el, const std::function<Vec3(double, double)>& geometry, double t,
            double E, double nu, double rho, bool triangles = false)
      : nu_nodes(nu_el + 1), nv_nodes(nv_el + 1) {
    const int mat = testing::AddMaterial(mesh, E, nu, rho);
    ShellSection sec;
    sec.id = 1;
    sec.material = mat;
    sec.thickness = t;
    mesh.shell_sections.push_back(sec);
    for (int j = 0; j <= nv_el; ++j)
      for (int i = 0; i <= nu_el; ++i)
        testing::AddNode(mesh, geometry(double(i) / nu_el, double(j) / nv_el));
    for (int j = 0; j < nv_el; ++j)
      for (int i = 0; i < nu_el; ++i) {
        const int a = Node(i, j), b = Node(i + 1, j), c = Node(i + 1, j + 1), d = Node(i, j + 1);
        if (triangles) {
          testing::AddElement(mesh, ElementType::kTria3, 0, {a, b, c});
          testing::AddElement(mesh, ElementType::kTria3, 0, {a, c, d});
        } else {
          testing::AddElement(mesh, ElementType::kQuad4, 0, {a, b, c, d});
        }
      }
  }
  int Node(int i, int j) const { return j * nu_nodes + i; }
  /// Fixes the components `comps` (0..5 = ux..rz) of the nodes with pred(i, j).
  void Fix(const std::function<bool(int, int)>& pred, std::initializer_list<int> comps) {
    int mask = 0;
    for (int c : comps) mask |= 1 << c;
    for (int j = 0; j < nv_nodes; ++j)
      for (int i = 0; i < nu_nodes; ++i)
        if (pred(i, j)) testing::AddConstraint(mesh, Node(i, j), mask);
  }
  /// Consistent nodal forces (6 per node) of a constant load q per area on
  /// the quads (2 x 2 Gauss on the bilinear surface).
  Eigen::VectorXd SurfaceLoad(const Vec3& q) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * mesh.nodes.size());
    const double g = 1.0 / std::sqrt(3.0);
    const double xi[4] = {-g, g, g, -g}, eta[4] = {-g, -g, g, g};
    for (const Element& e : mesh.elements) {
      const Vec3 &a = mesh.nodes[e.nodes[0]].x, &b = mesh.nodes[e.nodes[1]].x;
      const Vec3 &c = mesh.nodes[e.nodes[2]].x, &d = mesh.nodes[e.nodes[3]].x;
      for (int k = 0; k < 4; ++k) {
        const double n[4] = {0.25 * (1 - xi[k]) * (1 - eta[k]), 0.25 * (1 + xi[k]) * (1 - eta[k]),
                             0.25 * (1 + xi[k]) * (1 + eta[k]), 0.25 * (1 - xi[k]) * (1 + eta[k])};
        const Vec3 dxi = 0.25 * ((b - a) * (1 - eta[k]) + (c - d) * (1 + eta[k]));
        const Vec3 deta = 0.25 * ((d - a) * (1 - xi[k]) + (c - b) * (1 + xi[k]));
        const double da = dxi.cross(deta).norm();
        for (int p = 0; p < 4; ++p) f.segment<3>(6 * e.nodes[p]) += n[p] * da * q;
      }
    }
    return f;
  }
};

/// The mesh of a deck given as text: written to a temporary file `name`
/// (unique per process), read as Nastran bulk data or, if `abaqus`, as an
/// Abaqus/CalculiX deck, and removed.
inline Mesh ReadDeckText(const std::string& text, const std::string& name, bool abaqus = false) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("flexmb_deck_" + std::to_string(getpid()) + "_" + name);
  std::ofstream(p) << text;
  Mesh m = abaqus ? io::ReadAbaqus(p.string()) : io::ReadNastran(p.string());
  std::filesystem::remove(p);
  return m;
}

/// Static solution of the mesh under nodal loads f (6 per node, basic
/// frame): fe::Assemble, then a sparse LDL^T solve on the free DOF. Returns
/// the displacements, 6 per node (0 where fixed or inactive).
inline Eigen::VectorXd SolveStatic(const Mesh& mesh, const Eigen::VectorXd& f) {
  const AssembledModel model = Assemble(mesh);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(model.dofs.n_free);
  for (size_t n = 0; n < mesh.nodes.size(); ++n)
    for (int c = 0; c < 6; ++c)
      if (model.dofs.free[n][c] >= 0) rhs(model.dofs.free[n][c]) = f(6 * n + c);
  Eigen::SimplicialLDLT<SparseMat> ldlt(model.K);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd u_free = ldlt.solve(rhs);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6 * mesh.nodes.size());
  for (size_t n = 0; n < mesh.nodes.size(); ++n)
    for (int c = 0; c < 6; ++c)
      if (model.dofs.free[n][c] >= 0) u(6 * n + c) = u_free(model.dofs.free[n][c]);
  return u;
}

/// The lowest `count` modes of the mesh through fe::Assemble and
/// fe::SolveModes (automatic negative shift, so free-free meshes work).
inline ModalResult SolveMeshModes(const Mesh& mesh, int count,
                                  MassForm form = MassForm::kConsistent,
                                  AssembledModel* assembled = nullptr) {
  AssemblyOptions options;
  options.mass_form = form;
  AssembledModel model = Assemble(mesh, options);
  ModalOptions modal;
  modal.count = count;
  ModalResult r = SolveModes(model, modal);
  if (assembled != nullptr) *assembled = std::move(model);
  return r;
}

/// Fractions of a mode's kinetic energy (phi^T M phi with M restricted to
/// the ux, uy, or uz DOF of all nodes) in the three translation directions.
inline Vec3 DirectionShares(const Mesh& mesh, const AssembledModel& model,
                            const Eigen::VectorXd& phi) {
  Vec3 share = Vec3::Zero();
  const Eigen::VectorXd mphi = model.M * phi;
  for (size_t n = 0; n < mesh.nodes.size(); ++n)
    for (int c = 0; c < 3; ++c) {
      const int f = model.dofs.free[n][c];
      if (f >= 0) share(c) += phi(f) * mphi(f);
    }
  return share / share.sum();
}

/// One mesh-convergence sequence: results on meshes refined by halving the
/// element size, against a reference value.
struct Convergence {
  std::string name;
  std::vector<int> meshes;     ///< a size parameter of each mesh, for the report
  std::vector<double> values;  ///< result on each mesh
  double reference = 0.0;

  /// Prints the table the docs quote: mesh, value, value / reference.
  void Report() const {
    std::printf("  %s, reference %.7g\n", name.c_str(), reference);
    for (size_t k = 0; k < values.size(); ++k)
      std::printf("  %-36s mesh %4d: %.7g (normalized %.5f)\n", name.c_str(), meshes[k], values[k],
                  values[k] / reference);
  }
  double Error(size_t k) const { return std::abs(values[k] / reference - 1.0); }
  double Change(size_t k) const {
    return std::abs(values[k] - values[k - 1]) / std::abs(reference);
  }

  /// The sequence converges: each refinement changes the result less than
  /// the one before.
  void ExpectConverges() const {
    for (size_t k = 2; k < values.size(); ++k)
      EXPECT_LT(Change(k), Change(k - 1))
          << name << ": refinement " << meshes[k - 1] << " -> " << meshes[k];
  }
  /// The relative error falls at each refinement by at least the factor
  /// `ratio` (2^p for order p in the element size h).
  void ExpectErrorFallsBy(double ratio) const {
    for (size_t k = 1; k < values.size(); ++k)
      EXPECT_GT(Error(k - 1), ratio * Error(k))
          << name << ": mesh " << meshes[k - 1] << " -> " << meshes[k];
  }
  /// The finest result lies within `reference_uncertainty` (relative) plus
  /// the last refinement's change of the reference: for a sequence that
  /// converges at least linearly in h, the error left after the finest mesh
  /// is at most that change (a Richardson-type bound, not fitted).
  void ExpectFinestWithinLastChange(double reference_uncertainty) const {
    const size_t n = values.size() - 1;
    EXPECT_LE(Error(n), Change(n) + reference_uncertainty)
        << name << ": finest mesh " << meshes[n] << ", error " << Error(n) << ", last change "
        << Change(n) << ", reference uncertainty " << reference_uncertainty;
  }
};

}  // namespace flexmb::fe::validation
