// Imported matrices with what an FE model file adds to them: nodes, rigid
// links, point masses and constraints (fe::AssembleImported), and the
// geometric node selections of the FE model file.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>
#include <random>

#include "flexmb/fe/modal.h"
#include "flexmb/fe_io/exchange_set.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/fe_io/imported_matrices.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace imported_links_test {

using fe::AssembledModel;
using fe::AssemblyOptions;
using fe::FeModel;
using fe::Mesh;
using fe::Vec3;
using testing::FeData;
using testing::InputErrorOf;
using testing::ScratchPath;
using testing::WriteScratch;

double MaxAbs(const fe::SparseMat& a) { return Eigen::MatrixXd(a).cwiseAbs().maxCoeff(); }

// the same numbering, and matrices equal to round-off of the largest entry
void ExpectSameModel(const AssembledModel& a, const AssembledModel& b, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.dofs.n_full, b.dofs.n_full);
  EXPECT_EQ(a.dofs.n_free, b.dofs.n_free);
  EXPECT_EQ(a.dofs.full, b.dofs.full);
  EXPECT_EQ(a.dofs.free, b.dofs.free);
  for (auto [x, y, name] : {std::make_tuple(&a.K, &b.K, "K"), std::make_tuple(&a.M, &b.M, "M"),
                            std::make_tuple(&a.T, &b.T, "T"), std::make_tuple(&a.M_full, &b.M_full, "M_full")}) {
    ASSERT_EQ(x->rows(), y->rows()) << name;
    ASSERT_EQ(x->cols(), y->cols()) << name;
    EXPECT_LE(MaxAbs(*x - *y), 1e-13 * MaxAbs(*y)) << name;
  }
}

// the model's unconstrained assembly as another package would export it,
// its rows shuffled (a package numbers them its own way)
AssembledModel ExportedShuffled(const Mesh& mesh, unsigned seed) {
  AssemblyOptions none;
  none.apply_constraints = false;
  AssembledModel a = fe::Assemble(mesh, none);
  const int n = a.dofs.n_free;
  std::vector<int> perm(static_cast<size_t>(n));
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(Eigen::Map<Eigen::VectorXi>(perm.data(), n));
  fe::SparseMat K, M;
  K = a.K.twistedBy(P);
  M = a.M.twistedBy(P);
  for (auto* map : {&a.dofs.full, &a.dofs.free})
    for (auto& node : *map)
      for (int& r : node)
        if (r >= 0) r = perm[static_cast<size_t>(r)];
  a.K = K;
  a.M = M;
  a.M_full = M;
  a.T.resize(n, n);
  a.T.setIdentity();
  return a;
}

// adds a reference node, a rigid link from it to `dependent`, a point mass
// on it, and fixes it (or `fixed_dofs` of it)
void AddReference(Mesh& mesh, const Vec3& x, const std::vector<int>& dependent, int fixed_dofs) {
  fe::Node ref;
  ref.id = 900001;
  ref.x = x;
  mesh.nodes.push_back(ref);
  mesh.IndexNodes();
  const int r = static_cast<int>(mesh.nodes.size()) - 1;
  fe::RigidLink link;
  link.id = 1;
  link.independent = r;
  link.dependent = dependent;
  link.dofs = 0b111111;
  mesh.rigid_links.push_back(link);
  fe::PointMass pm;
  pm.id = 1;
  pm.node = r;
  pm.mass = 3.5;
  pm.offset = Vec3(0.01, 0.02, -0.03);
  pm.inertia = Vec3(1e-3, 2e-3, 3e-3).asDiagonal();
  mesh.point_masses.push_back(pm);
  if (fixed_dofs != 0) {
    fe::Constraint c;
    c.node = r;
    c.dofs = fixed_dofs;
    mesh.constraints.push_back(c);
  }
}

TEST(ImportedLinks, EqualAssemblingTheMeshWithTheSameAdditions) {
  // shells (6 DOF per node) and solids (3: the reference node gets its
  // rotations from the link alone); the imported rows shuffled
  FeModel strip = LoadFeModel(FeData("gmsh/strip.yaml"));
  strip.mesh.constraints.clear();
  const std::string common = "materials: {steel: {E: 2.1e11, nu: 0.3, rho: 7800}}\n";
  FeModel hex = LoadFeModel(WriteScratch(
      "links_hex.yaml", "mesh: " + FeData("gmsh/hex8_v41.msh") + "\n" + common +
                            "drop_elements: [bottom, group7]\nsections: [{elements: block, type: solid, material: steel}]\n"));
  for (FeModel* model : {&strip, &hex}) {
    Mesh& mesh = model->mesh;
    SCOPED_TRACE(mesh.source);
    std::vector<int> face;  // the nodes at x = 0
    for (size_t n = 0; n < mesh.nodes.size(); ++n)
      if (std::abs(mesh.nodes[n].x.x()) < 1e-12) face.push_back(static_cast<int>(n));
    ASSERT_GE(face.size(), 3u);
    int far = 0;  // a node away from the face, fixed through the options
    for (size_t n = 0; n < mesh.nodes.size(); ++n)
      if (mesh.nodes[n].x.x() > mesh.nodes[static_cast<size_t>(far)].x.x()) far = static_cast<int>(n);
    const Mesh plain = mesh;
    AddReference(mesh, Vec3(-0.1, 0.02, 0.01), face, 0b011011);  // ux uy rx ry fixed
    FeModel imported;
    imported.mesh = mesh;
    imported.mesh.elements.clear();  // display cells only: none here
    imported.imported = ExportedShuffled(plain, 7);
    for (bool constraints : {true, false}) {
      AssemblyOptions options;
      options.apply_constraints = constraints;
      options.extra_fixed_nodes = {far};
      ExpectSameModel(fe::BuildMatrices(imported, options), fe::Assemble(mesh, options),
                      constraints ? "constrained" : "free");
    }
    // the display cells of a geometry are not assembled
    imported.mesh.elements = plain.elements;
    ExpectSameModel(fe::BuildMatrices(imported, {}), fe::Assemble(mesh, {}), "with display cells");
    // the reference node's mass and the link: the mass properties of the free model
    AssemblyOptions none;
    none.apply_constraints = false;
    const fe::MassProperties p = fe::ComputeMassProperties(imported.mesh, fe::BuildMatrices(imported, none));
    const fe::MassProperties q = fe::ComputeMassProperties(plain, fe::Assemble(plain, none));
    EXPECT_NEAR(p.mass, q.mass + 3.5, 1e-12 * p.mass);
    const Vec3 c = (q.mass * q.center + 3.5 * Vec3(-0.09, 0.04, -0.02)) / (q.mass + 3.5);
    EXPECT_LT((p.center - c).norm(), 1e-12);
  }
}

TEST(ImportedLinks, AnImportedFaceTiedToAClampedNodeIsTheClampedModel) {
  // the free strip exported, then clamped through a reference node behind
  // its end, linked to the end's nodes (picked by a box) and fixed: the
  // modes of the strip clamped at those nodes
  const FeModel clamped = LoadFeModel(FeData("gmsh/strip.yaml"));
  FeModel free = clamped;
  free.mesh.constraints.clear();
  AssemblyOptions none;
  none.apply_constraints = false;
  WriteExchangeSet(free.mesh, fe::Assemble(free.mesh, none), ScratchPath("links_strip_set"));
  const std::string files =
      "matrices:\n  stiffness: links_strip_set/K_CCS.hb\n  mass: links_strip_set/M_CCS.hb\n"
      "  dof_map: links_strip_set/dof_map.txt\n  geometry: links_strip_set/geometry.vtk\n";
  const FeModel linked = LoadFeModel(WriteScratch(
      "links_strip.yaml", files +
                              "nodes: [{id: 900001, x: [-0.1, 0.025, 0]}]\n"
                              "rigid_links:\n  - {independent: 900001, dependent: {box: {min: [-1e-6, -1, -1], max: "
                              "[1e-6, 1, 1]}}}\nfixed: [900001]\n"));
  ASSERT_TRUE(linked.imported);
  ASSERT_EQ(linked.mesh.rigid_links.size(), 1u);
  EXPECT_EQ(linked.mesh.rigid_links[0].dependent.size(), 3u);
  fe::ModalOptions mo;
  mo.count = 4;
  const fe::ModalResult a = fe::SolveModes(fe::BuildMatrices(clamped, {}), mo);
  const fe::ModalResult b = fe::SolveModes(fe::BuildMatrices(linked, {}), mo);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(b.frequencies_hz[k], a.frequencies_hz[k], 1e-9 * a.frequencies_hz[k]);
  // a point mass on the reference node through the file: the free model gains it
  const FeModel massive = LoadFeModel(WriteScratch(
      "links_strip_mass.yaml", files + "nodes: [{id: 900001, x: [-0.1, 0.025, 0]}]\n"
                                       "point_masses: [{node: 900001, mass: 2.0}]\n"));
  const double m0 = fe::ComputeMassProperties(free.mesh, fe::Assemble(free.mesh, none)).mass;
  EXPECT_NEAR(fe::ComputeMassProperties(massive.mesh, fe::BuildMatrices(massive, none)).mass, m0 + 2.0, 1e-12);
}

TEST(ImportedLinks, TheGeometrysOwnConstraintsAreLeftOutWithAWarning) {
  // a deck as geometry: its SPC is not applied to the matrices, and says so
  FeModel strip = LoadFeModel(FeData("gmsh/strip.yaml"));
  AssemblyOptions none;
  none.apply_constraints = false;
  WriteExchangeSet(strip.mesh, fe::Assemble(strip.mesh, none), ScratchPath("links_warn_set"));
  const std::string deck = WriteScratch("links_warn_geometry.inp",
                                        "*NODE\n1, 0, 0, 0\n*BOUNDARY\n1, 1, 3\n");
  testing::WarningCapture warnings;
  try {
    ReadImportedMatrices({ScratchPath("links_warn_set/K_CCS.hb"), ScratchPath("links_warn_set/M_CCS.hb"),
                          ScratchPath("links_warn_set/dof_map.txt"), deck});
  } catch (const InputError&) {
    // the deck's one node does not carry the map's nodes: the warning comes first
  }
  EXPECT_EQ(warnings.Count("1 single-point constraints are not applied to the imported matrices"), 1);
  // AssembleImported takes matrices as read (every row free, T = I) only
  FeModel imported;
  imported.mesh = strip.mesh;
  imported.imported = fe::Assemble(strip.mesh, {});  // constrained: fewer free than full DOF
  testing::ExpectContains(InputErrorOf([&] { fe::AssembleImported(strip.mesh, *imported.imported, {}); }),
                          {"must come as read"}, "not as read");
}

TEST(ImportedLinks, ALinkOfRotationsOnSolidNodesIsAWarning) {
  // the nodes of solids have no rotations: a link of 456 alone does nothing
  const std::string common = "materials: {steel: {E: 2.1e11, nu: 0.3, rho: 7800}}\n";
  const FeModel hex = LoadFeModel(WriteScratch(
      "links_456.yaml", "mesh: " + FeData("gmsh/hex8_v41.msh") + "\n" + common +
                            "drop_elements: [bottom, group7]\nsections: [{elements: block, type: solid, material: steel}]\n"
                            "nodes: [{id: 900001, x: [-0.1, 0, 0]}]\n"
                            "rigid_links: [{independent: 900001, dependent: {box: {min: [-1, -1, -1], max: [0, 1, 1]}}, "
                            "dofs: 456}]\n"));
  testing::WarningCapture warnings;
  fe::Assemble(hex.mesh, {});
  EXPECT_EQ(warnings.Count("does nothing: none of its dependent nodes has a degree of freedom among the components 456"), 1);
}

TEST(ImportedLinks, NodeSelectionsPickByGeometry) {
  // strip nodes on a 0.025 m grid: a cylinder of radius 0.025 about the z
  // axis through (0, 0.025) passes through (0, 0), (0, 0.05) and (0.025, 0.025)
  const std::string head = "mesh: " + FeData("gmsh/strip_v41.msh") +
                           "\ndrop_elements: [clamp]\nmaterials: {steel: {E: 2.1e11, nu: 0.0, rho: 7850}}\n"
                           "sections: [{elements: strip, type: shell, material: steel, thickness: 0.005}]\n";
  const FeModel model = LoadFeModel(WriteScratch(
      "select_cylinder.yaml",
      head + "fixed: [{cylinder: {from: [0, 0.025, -1], to: [0, 0.025, 1], radius: 0.025, tolerance: 1e-6}}]\n"));
  std::vector<Vec3> picked;
  for (const fe::Constraint& c : model.mesh.constraints) picked.push_back(model.mesh.nodes[c.node].x);
  ASSERT_EQ(picked.size(), 3u);
  std::sort(picked.begin(), picked.end(), [](const Vec3& a, const Vec3& b) { return a.x() + 10 * a.y() < b.x() + 10 * b.y(); });
  EXPECT_LT((picked[0] - Vec3(0, 0, 0)).norm(), 1e-9);
  EXPECT_LT((picked[1] - Vec3(0.025, 0.025, 0)).norm(), 1e-9);
  EXPECT_LT((picked[2] - Vec3(0, 0.05, 0)).norm(), 1e-9);
  // a single selection as the whole of 'fixed'; a box grown by its tolerance;
  // the cylinder's default tolerance (1e-3 R) still picks the three
  const auto fixed_count = [&](const std::string& name, const std::string& fixed) {
    return LoadFeModel(WriteScratch(name, head + "fixed: " + fixed + "\n")).mesh.constraints.size();
  };
  EXPECT_EQ(fixed_count("select_map.yaml", "{box: {min: [-1, -1, -1], max: [0, 1, 1]}}"), 3u);
  EXPECT_EQ(fixed_count("select_tol0.yaml", "{box: {min: [-1, -1, 0], max: [0, 1, 1], tolerance: 0}}"), 3u);
  EXPECT_EQ(fixed_count("select_tol.yaml", "{box: {min: [-1, -1, 0.001], max: [0, 1, 1], tolerance: 0.0011}}"), 3u);
  EXPECT_EQ(fixed_count("select_default.yaml", "[{cylinder: {from: [0, 0.025, -1], to: [0, 0.025, 1], radius: 0.025}}]"), 3u);
  // the cylinder's length bounds it: from z = 0.001 on, nothing
  testing::ExpectBadFiles(
      {
          {"select_none.yaml",
           head + "fixed: [{cylinder: {from: [0, 0.025, 0.001], to: [0, 0.025, 1], radius: 0.025, tolerance: 1e-6}}]\n",
           ":5: fixed #1: the selection picks no node of strip_v41.msh: the nearest is node", {}},
          {"select_box_miss.yaml", head + "fixed: {box: {min: [-1, -1, 0.001], max: [1, 1, 1]}}\n",
           ":5: fixed #1: the selection picks no node of strip_v41.msh: the nearest is node", {"misses the box by 0.001", " at (0, "}},
          {"select_shape.yaml",
           head + "rigid_links: [{independent: 1, dependent: {sphere: {center: [0, 0, 0], radius: 1}}}]\n",
           ":5: rigid link #1: a node selection is {cylinder: {from, to, radius, tolerance}} or {box:", {}},
          {"select_typo.yaml",
           head + "rigid_links: [{independent: 1, dependent: {cylindre: {from: [0, 0, 0], to: [0, 0, 1], radius: 1}}}]\n",
           ":5: rigid link #1: a node selection is", {"got 'cylindre'"}},
          {"mesh_and_matrices.yaml", "matrices: {stiffness: a.hb, mass: b.hb, geometry: c.vtk}\nmesh: d.msh\n",
           ":2: 'mesh' and 'matrices' exclude each other", {}},
          {"fixed_typo.yaml", head + "fixed: [{node: 1, dofs: 123}]\n",
           ":5: fixed #1: unknown key 'node' (allowed: nodes, dofs)", {}},
          {"select_only_independent.yaml",
           head + "rigid_links: [{independent: 1, dependent: {box: {min: [-0.001, -0.001, -1], max: [0.001, 0.001, 1]}}}]\n",
           ":5: rigid link #1: the selection picks no node but the independent one", {}},
          {"select_box.yaml", head + "fixed: [{box: {min: [1, 0, 0], max: [0, 1, 1]}}]\n",
           ":5: fixed #1: the box's 'min' must not exceed its 'max'", {}},
          {"select_axis.yaml", head + "fixed: [{cylinder: {from: [0, 0, 0], to: [0, 0, 0], radius: 1}}]\n",
           ":5: fixed #1: the cylinder's 'from' and 'to' must differ", {}},
          {"node_twice.yaml", head + "nodes: [{id: 900001, x: [0, 0, 0]}, {id: 900001, x: [1, 0, 0]}]\n",
           ":5: node #2: node 900001 is listed twice in 'nodes'", {}},
          {"node_exists.yaml", head + "nodes: [{id: 1, x: [0, 0, 0]}]\n",
           ":5: node #1: node 1 already exists in strip_v41.msh", {}},
          {"node_position.yaml", head + "nodes: [{id: 900001}]\n", ":5: node #1: missing required key 'x'", {}},
      },
      [](const std::string& path) { LoadFeModel(path); });
}

}  // namespace imported_links_test
}  // namespace flexmb::io
