#include "flexmb/fe_io/fe_model_file.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexmb/fe/mesh_checks.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe_io/exchange_set.h"
#include "flexmb/fe_io/gmsh_reader.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using fe::AssembledModel;
using fe::AssemblyOptions;
using fe::FeModel;
using fe::Mesh;
using fe::Vec3;
using testing::FeData;
using testing::InputErrorOf;
using testing::ScratchPath;
using testing::WriteScratch;

// Euler-Bernoulli cantilever: beta_k L (roots of 1 + cos b cosh b = 0)
constexpr double kCantilever[] = {1.8751040687119611, 4.6940911329741746, 7.8547574382376126};
// clamped-clamped beam: roots of cos b cosh b = 1
constexpr double kClampedClamped[] = {4.7300407448627040, 7.8532046240958376};

// f = (beta L)^2 / (2 pi L^2) sqrt(E I / (rho A))
double BeamHz(double betaL, double L, double E, double I, double rho, double A) {
  return betaL * betaL / (2.0 * M_PI * L * L) * std::sqrt(E * I / (rho * A));
}

fe::ModalResult Modes(const FeModel& model, int count, const AssemblyOptions& options = {}) {
  fe::ModalOptions mo;
  mo.count = count;
  return fe::SolveModes(fe::BuildMatrices(model, options), mo);
}

TEST(FeModelFile, ShellStripFirstBendingMatchesEulerBernoulli) {
  const FeModel model = LoadFeModel(FeData("gmsh/strip.yaml"));
  EXPECT_FALSE(model.imported);
  ASSERT_EQ(model.mesh.elements.size(), 80u);  // the clamp's line elements are dropped
  EXPECT_EQ(model.mesh.constraints.size(), 3u);
  const double E = 2.1e11, rho = 7850, b = 0.05, t = 0.005, L = 1.0;
  const double f1 = BeamHz(kCantilever[0], L, E, b * t * t * t / 12.0, rho, b * t);
  const fe::ModalResult r = Modes(model, 2);
  // 40 x 2 MITC4 shells, nu = 0: bilinear shells converge as h^2, 40 elements
  // along the length give well below 0.1 % on the first mode, 0.5 % on the second
  EXPECT_NEAR(r.frequencies_hz[0], f1, 1e-3 * f1) << "f1 = " << r.frequencies_hz[0] << " Hz, EB " << f1 << " Hz";
  // the second mode is out-of-plane bending again (the in-plane one is (b / t) = 10 times higher)
  const double f2 = BeamHz(kCantilever[1], L, E, b * t * t * t / 12.0, rho, b * t);
  EXPECT_NEAR(r.frequencies_hz[1], f2, 5e-3 * f2);
}

// int_0^1 w'^2 dx / int_0^1 w^2 dx of the Euler-Bernoulli cantilever mode with
// root beta (L = 1): w = cosh bx - cos bx - s (sinh bx - sin bx), by Simpson's rule
double SlopeRatio(double b) {
  const double s = (std::cosh(b) + std::cos(b)) / (std::sinh(b) + std::sin(b));
  const int n = 4000;
  double w2 = 0.0, d2 = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double x = static_cast<double>(i) / n, c = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    const double w = std::cosh(b * x) - std::cos(b * x) - s * (std::sinh(b * x) - std::sin(b * x));
    const double d = b * (std::sinh(b * x) + std::sin(b * x) - s * (std::cosh(b * x) - std::cos(b * x)));
    w2 += c * w * w;
    d2 += c * d * d;
  }
  return d2 / w2;
}

TEST(FeModelFile, BeamCantileverMatchesEulerBernoulli) {
  const FeModel model = LoadFeModel(FeData("gmsh/beam.yaml"));
  ASSERT_EQ(model.mesh.elements.size(), 20u);
  for (const fe::Element& e : model.mesh.elements) EXPECT_EQ(e.orientation, Vec3(0, 0, 1));
  const double E = 7.0e10, rho = 2700, A = 1.0e-4, Iy = 0.02 * std::pow(0.005, 3) / 12.0,
               Iz = 0.005 * std::pow(0.02, 3) / 12.0, h = 1.0 / 20;
  // first four: bending about y (modes 1, 2 and 3 of that plane) and about z (mode 1).
  // The element carries the rotary inertia rho I, which lowers f by the Rayleigh
  // factor 1 - (I / A) R / 2 to first order, R = int w'^2 / int w^2; cubic Hermite
  // elements with consistent mass raise it by about (beta h)^4 / 1440.
  struct Ref {
    double f, tol;
  };
  std::vector<Ref> ref;
  for (auto [k, I] : {std::pair{0, Iy}, {1, Iy}, {2, Iy}, {0, Iz}}) {
    const double b = kCantilever[k];
    const double f = BeamHz(b, 1, E, I, rho, A) * (1.0 - 0.5 * (I / A) * SlopeRatio(b));
    ref.push_back({f, std::pow(b * h, 4) / 1000.0 + 1e-6});
  }
  std::sort(ref.begin(), ref.end(), [](const Ref& a, const Ref& b) { return a.f < b.f; });
  const fe::ModalResult r = Modes(model, 4);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(r.frequencies_hz[k], ref[k].f, ref[k].tol * ref[k].f) << "mode " << k + 1;
}

// beam.yaml with extra lines (absolute mesh path, so the scratch file can live anywhere)
std::string BeamYaml(const std::string& extra) {
  return "mesh: " + FeData("gmsh/beam_v41.msh") +
         "\n"
         "materials:\n"
         "  alu: {E: 7.0e10, nu: 0.33, rho: 2700}\n"
         "sections:\n"
         "  - {elements: all, type: beam, material: alu, A: 1.0e-4, Iy: 2.0833333333333333e-10,\n"
         "     Iz: 3.3333333333333333e-9, J: 7.0e-10, orientation: [0, 0, 1]}\n" +
         extra;
}

TEST(FeModelFile, RigidLinkMakesTheCantileverClampedClamped) {
  // the tip follows the root rigidly in all six DOF; the root is clamped
  const FeModel model = LoadFeModel(WriteScratch(
      "cc.yaml", BeamYaml("fixed: root\nrigid_links:\n  - {independent: root, dependent: [tip], dofs: 123456}\n")));
  ASSERT_EQ(model.mesh.rigid_links.size(), 1u);
  const double E = 7.0e10, rho = 2700, A = 1.0e-4, Iy = 0.02 * std::pow(0.005, 3) / 12.0;
  const fe::ModalResult r = Modes(model, 2);
  // rotary inertia (about -(I / A) beta^2 / 2 ~ -6e-5 on mode 2) and discretization
  // ((beta h)^4 / 1440 ~ 2e-5) stay below 1e-4
  for (int k = 0; k < 2; ++k) {
    const double ref = BeamHz(kClampedClamped[k], 1, E, Iy, rho, A);
    EXPECT_NEAR(r.frequencies_hz[k], ref, 1e-4 * ref) << "mode " << k + 1;
  }
}

TEST(FeModelFile, PointMassAddsToTheMassProperties) {
  const FeModel model = LoadFeModel(WriteScratch(
      "pm.yaml", BeamYaml("point_masses:\n  - {node: tip, mass: 0.27, offset: [0, 0, 0.1], inertia: [1e-3, 2e-3, 3e-3]}\n"
                          "  - {node: 12, mass: 0.54}\n")));
  AssemblyOptions free;
  free.apply_constraints = false;
  const AssembledModel a = fe::BuildMatrices(model, free);
  const fe::MassProperties p = fe::ComputeMassProperties(model.mesh, a);
  // bar 2700 * 1e-4 * 1 = 0.27 kg centred at x = 0.5; masses at (1, 0, 0.1) and node 12 (x = 0.5)
  const double m = 0.27 + 0.27 + 0.54;
  EXPECT_NEAR(p.mass, m, 1e-12 * m);
  const Vec3 x12 = model.mesh.nodes[model.mesh.NodeIndex(12)].x;
  EXPECT_LT((x12 - Vec3(0.5, 0, 0)).norm(), 1e-9);  // as gmsh placed it
  const Vec3 c = (0.27 * Vec3(0.5, 0, 0) + 0.27 * Vec3(1, 0, 0.1) + 0.54 * x12) / m;
  EXPECT_LT((p.center - c).norm(), 1e-12);
  EXPECT_EQ(model.mesh.point_masses[1].node, model.mesh.NodeIndex(12));
}

TEST(FeModelFile, SolidsGetTheirMassFromTheSections) {
  // hex8: the faces are dropped; tet10: the faces are no elements at all
  const std::string common = "materials: {steel: {E: 2.1e11, nu: 0.3, rho: 7800}}\n";
  const FeModel hex = LoadFeModel(WriteScratch(
      "hex.yaml", "mesh: " + FeData("gmsh/hex8_v41.msh") + "\n" + common +
                      "drop_elements: [bottom, group7]\nsections: [{elements: block, type: solid, material: steel}]\n"));
  const FeModel tet = LoadFeModel(WriteScratch(
      "tet.yaml", "mesh: " + FeData("gmsh/tet10_v22.msh") + "\n" + common +
                      "sections: [{elements: all, type: solid, material: steel}]\nfixed: [base]\n"));
  AssemblyOptions free;
  free.apply_constraints = false;
  const fe::MassProperties ph = fe::ComputeMassProperties(hex.mesh, fe::BuildMatrices(hex, free));
  EXPECT_NEAR(ph.mass, 7800 * 0.3 * 0.2 * 0.1, 1e-10);
  EXPECT_LT((ph.center - Vec3(0.15, 0.1, 0.05)).norm(), 1e-12);
  const fe::MassProperties pt = fe::ComputeMassProperties(tet.mesh, fe::BuildMatrices(tet, free));
  EXPECT_NEAR(pt.mass, 7800 * 0.4 * 0.2 * 0.1, 1e-10);
  EXPECT_LT((pt.center - Vec3(0.2, 0.1, 0.05)).norm(), 1e-12);
  // the base node set: every node at z = 0, fixed
  for (const fe::Constraint& c : tet.mesh.constraints) EXPECT_EQ(tet.mesh.nodes[c.node].x.z(), 0.0);
  EXPECT_GT(tet.mesh.constraints.size(), 9u);
}

void ExpectSameMatrix(const fe::SparseMat& a, const fe::SparseMat& b) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  EXPECT_EQ((Eigen::MatrixXd(a) - Eigen::MatrixXd(b)).cwiseAbs().maxCoeff(), 0.0);
}

void ExpectSameModel(const AssembledModel& a, const AssembledModel& b) {
  EXPECT_EQ(a.dofs.n_full, b.dofs.n_full);
  EXPECT_EQ(a.dofs.n_free, b.dofs.n_free);
  EXPECT_EQ(a.dofs.full, b.dofs.full);
  EXPECT_EQ(a.dofs.free, b.dofs.free);
  ExpectSameMatrix(a.K, b.K);
  ExpectSameMatrix(a.M, b.M);
  ExpectSameMatrix(a.T, b.T);
  ExpectSameMatrix(a.M_full, b.M_full);
}

TEST(FeModel, FixNodesEqualsAssemblingWithFixedNodes) {
  // a beam with a rigid link (so T is not the identity) and a shell strip
  const FeModel beam = LoadFeModel(WriteScratch(
      "fix.yaml", BeamYaml("rigid_links:\n  - {independent: 5, dependent: [6, 7], dofs: 1234}\n")));
  const FeModel strip = LoadFeModel(FeData("gmsh/strip.yaml"));
  for (const FeModel* model : {&beam, &strip}) {
    const Mesh& mesh = model->mesh;
    const std::vector<int> nodes = {mesh.NodeIndex(1), mesh.NodeIndex(5), mesh.NodeIndex(12), mesh.NodeIndex(2)};
    AssemblyOptions fixed;
    fixed.extra_fixed_nodes = nodes;
    const AssembledModel reference = fe::Assemble(mesh, fixed);
    const AssembledModel fixed_later = fe::FixNodes(fe::Assemble(mesh), nodes);
    ExpectSameModel(fixed_later, reference);
    EXPECT_LT(reference.dofs.n_free, fe::Assemble(mesh).dofs.n_free);
    // in two steps, and through BuildMatrices
    ExpectSameModel(fe::FixNodes(fe::FixNodes(fe::Assemble(mesh), {nodes[0], nodes[1]}), {nodes[2], nodes[3]}),
                    reference);
    ExpectSameModel(fe::BuildMatrices(*model, fixed), reference);
  }
  // a dependent node cannot be fixed afterwards
  const std::string msg = InputErrorOf([&] { fe::FixNodes(fe::Assemble(beam.mesh), {beam.mesh.NodeIndex(6)}); });
  EXPECT_NE(msg.find("dependent on a rigid link"), std::string::npos) << msg;
  EXPECT_NE(InputErrorOf([&] { fe::FixNodes(fe::Assemble(beam.mesh), {99}); }).find("index 99"), std::string::npos);
}

TEST(FeModel, ImportedMatricesHonourConstraintsAndFixedNodes) {
  // "import" the unconstrained assembly of the strip (T = identity) and
  // constrain it afterwards: the same as assembling with the constraints
  FeModel model = LoadFeModel(FeData("gmsh/strip.yaml"));
  Mesh& mesh = model.mesh;
  fe::Constraint partial;
  partial.node = mesh.NodeIndex(60);
  partial.dofs = 0b100101;  // ux, rx, rz
  mesh.constraints.push_back(partial);
  AssemblyOptions options;
  options.extra_fixed_nodes = {mesh.NodeIndex(2)};
  const AssembledModel reference = fe::BuildMatrices(model, options);
  FeModel imported;
  imported.mesh = mesh;
  AssemblyOptions none;
  none.apply_constraints = false;
  imported.imported = fe::Assemble(mesh, none);
  ASSERT_EQ(imported.imported->dofs.n_free, imported.imported->dofs.n_full);
  ExpectSameModel(fe::BuildMatrices(imported, options), reference);
  // without the mesh's constraints only the extra node is fixed
  options.apply_constraints = false;
  EXPECT_EQ(fe::BuildMatrices(imported, options).dofs.n_free, imported.imported->dofs.n_free - 6);
}

TEST(FeModelFile, ImportedMatricesFromAnFeModelFile) {
  // the free strip written as an exchange set, read back through 'matrices'
  // and clamped through 'fixed' by node ids: the modes of the strip model
  const FeModel strip = LoadFeModel(FeData("gmsh/strip.yaml"));
  AssemblyOptions none;
  none.apply_constraints = false;
  WriteExchangeSet(strip.mesh, fe::Assemble(strip.mesh, none), ScratchPath("strip_set"));
  std::string ids;
  for (int n : strip.mesh.node_sets.at("clamp")) ids += (ids.empty() ? "" : ", ") + std::to_string(strip.mesh.nodes[n].id);
  const FeModel imported = LoadFeModel(WriteScratch(
      "imported.yaml", "matrices:\n  stiffness: strip_set/K_CCS.hb\n  mass: strip_set/M_CCS.hb\n"
                       "  dof_map: strip_set/dof_map.txt\n  geometry: strip_set/geometry.vtk\nfixed: [" + ids + "]\n"));
  ASSERT_TRUE(imported.imported);
  EXPECT_EQ(imported.mesh.constraints.size(), 3u);
  const fe::ModalResult a = Modes(strip, 3), b = Modes(imported, 3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.frequencies_hz[k], a.frequencies_hz[k], 1e-9 * a.frequencies_hz[k]);
  // 'matrices' takes no materials or sections
  const std::string msg = InputErrorOf([] {
    LoadFeModel(WriteScratch("imported_bad.yaml", "matrices: {stiffness: a, mass: b}\nmaterials: {}\n"));
  });
  EXPECT_NE(msg.find("imported_bad.yaml:2: unknown key 'materials' (allowed: matrices, nodes, fixed, point_masses, rigid_links)"), std::string::npos)
      << msg;
}

TEST(FeModelFile, ImportedMatricesGetNoMeshConnectivityWarnings) {
  // an exchange set's geometry holds display cells only: a node with degrees
  // of freedom in the matrices but in no cell (a lumped mass here; the
  // condensed master nodes of an RBE2 in bench/peers/rotor) is not unused,
  // and the cells do not tell the parts apart: no mesh check warnings
  FeModel strip = LoadFeModel(FeData("gmsh/strip.yaml"));
  fe::Node extra;
  extra.id = 900001;
  extra.x = Vec3(0.0, 0.5, 0.0);
  strip.mesh.nodes.push_back(extra);
  fe::PointMass pm;
  pm.id = 1;
  pm.node = static_cast<int>(strip.mesh.nodes.size()) - 1;
  pm.mass = 2.0;
  strip.mesh.point_masses.push_back(pm);
  AssemblyOptions none;
  none.apply_constraints = false;
  WriteExchangeSet(strip.mesh, fe::Assemble(strip.mesh, none), ScratchPath("strip_extra_set"));
  testing::WarningCapture warnings;
  const FeModel imported = LoadFeModel(WriteScratch(
      "imported_extra.yaml", "matrices:\n  stiffness: strip_extra_set/K_CCS.hb\n  mass: strip_extra_set/M_CCS.hb\n"
                             "  dof_map: strip_extra_set/dof_map.txt\n  geometry: strip_extra_set/geometry.vtk\n"));
  ASSERT_TRUE(imported.imported);
  EXPECT_EQ(warnings.Count("used by no element"), 0);
  EXPECT_EQ(warnings.Count("parts that no element"), 0);
  // the same mesh read as elements does warn about the lone mass node
  EXPECT_EQ(fe::MeshCheckWarnings(strip.mesh, fe::CheckMesh(strip.mesh), "strip").size(), 1u);
}

TEST(FeModelFile, LoadFeModelByExtension) {
  const FeModel msh = LoadFeModel(FeData("gmsh/beam_v22.msh"));
  EXPECT_EQ(msh.mesh.elements.size(), 20u);
  EXPECT_EQ(msh.mesh.elements[0].property, -1);
  const FeModel vtk = LoadFeModel(FeData("vtk/all_cells_v3.vtk"));
  EXPECT_EQ(vtk.mesh.elements.size(), 6u);
  const std::string msg = InputErrorOf([] { LoadFeModel(FeData("gmsh/beam.geo")); });
  EXPECT_NE(msg.find("beam.geo: unknown FE model file type '.geo'"), std::string::npos) << msg;
}

TEST(FeModelFile, ResolveNodeList) {
  const Mesh mesh = ReadGmsh(FeData("gmsh/strip_v41.msh"));
  EXPECT_EQ(ResolveNodeList(mesh, "clamp"), mesh.node_sets.at("clamp"));
  EXPECT_EQ(ResolveNodeList(mesh, "12,13, 40,12"),
            (std::vector<int>{mesh.NodeIndex(12), mesh.NodeIndex(13), mesh.NodeIndex(40)}));
  const std::pair<const char*, const char*> bad[] = {
      {"12,999", "strip_v41.msh: node 999: does not exist"},
      {"clmap", "strip_v41.msh: node set 'clmap': there is no node set named 'clmap' (node sets: clamp, strip, tip)"},
      {"12,,13", "empty entry"},
      {"0", "bad node id '0'"},
  };
  for (const auto& [list_text, expected] : bad) {
    const char* list = list_text;  // clang 14 cannot capture a structured binding
    testing::ExpectContains(InputErrorOf([&] { ResolveNodeList(mesh, list); }), {expected}, list);
  }
}

// each case: file, ":line: entity: message" after its path (or, for an
// error in the mesh, the message naming the mesh file)
TEST(FeModelFile, BadInputNamesFileLineAndEntity) {
  const std::string strip = FeData("gmsh/strip_v41.msh");
  const std::string head = "mesh: " + strip + "\nmaterials:\n  steel: {E: 2.1e11, nu: 0.3, rho: 7850}\n";  // lines 1-3
  testing::ExpectBadFiles(
      {
          {"unknown_key.yaml", head + "matrial: {}\n", ":4: unknown key 'matrial' (allowed: mesh, matrices", {}},
          {"missing_mesh.yaml", "mesh: nothere.msh\n", ":1: mesh: file 'nothere.msh' does not exist", {}},
          {"unknown_set.yaml",
           head + "sections:\n  - {elements: stirp, type: shell, material: steel, thickness: 0.01}\n",
           ":5: section #1: there is no element set named 'stirp' in strip_v41.msh (element sets: clamp, strip)", {}},
          {"no_property.yaml",
           head + "sections:\n  - {elements: strip, type: shell, material: steel, thickness: 0.01}\n", "",
           {"strip_v41.msh:285: 2-node beam element 2: has no section: no entry of 'sections' in no_property.yaml "
            "covers it (element sets: 'clamp')"}},
          {"bad_node.yaml",
           head + "drop_elements: clamp\nsections: [{elements: all, type: shell, material: steel, thickness: 1}]\n"
                  "fixed: [1, 999]\n",
           ":6: fixed #2: node 999 does not exist in strip_v41.msh", {}},
          {"wrong_family.yaml",
           head + "sections:\n  - {elements: clamp, type: shell, material: steel, thickness: 0.01}\n",
           ":5: section #1: element set 'clamp' holds 2-node beam element 2", {}},
          {"material.yaml", head + "sections:\n  - {elements: strip, type: shell, material: stel, thickness: 0.01}\n",
           ":5: section #1: there is no material named 'stel' in 'materials' (materials: steel)", {}},
          {"negative.yaml", head + "sections:\n  - {elements: strip, type: shell, material: steel, thickness: -1}\n",
           ":5: section #1: 'thickness' must be positive", {}},
          {"beam_key.yaml",
           head + "sections:\n  - {elements: strip, type: shell, material: steel, thickness: 1, Iy: 2}\n",
           ":5: section #1: unknown key 'Iy' (allowed: elements, type, material, thickness, nsm)", {}},
          {"nu.yaml", "mesh: " + strip + "\nmaterials:\n  steel: {E: 2.1e11, nu: 0.5, rho: 7850}\n",
           ":3: material 'steel': 'nu' must be in (-1, 0.5)", {}},
          {"dofs.yaml",
           head + "drop_elements: clamp\nsections: [{elements: all, type: shell, material: steel, thickness: 1}]\n"
                  "fixed: [{nodes: clamp, dofs: 1237}]\n",
           ":6: fixed #1: 'dofs' must be distinct digits 1 to 6", {}},
          {"syntax.yaml", "mesh: [a\n", ":2: YAML syntax error", {}},
          {"bad_extension.yaml", "mesh: " + FeData("gmsh/beam.geo") + "\n", ":1: mesh: 'mesh' file", {}},
          {"point_mass_set.yaml",
           head + "drop_elements: clamp\nsections: [{elements: all, type: shell, material: steel, "
                  "thickness: 1}]\npoint_masses: [{node: clamp, mass: 1}]\n",
           ":6: point mass #1: 'node' must name exactly one node, got 3", {}},
      },
      [](const std::string& path) { LoadFeModel(path); });
  // errors inside the mesh file name the mesh file
  const std::string bad_mesh = WriteScratch("bad_mesh.msh", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n");
  const std::string uses_bad_mesh = WriteScratch("uses_bad_mesh.yaml", "mesh: bad_mesh.msh\n");
  testing::ExpectContains(InputErrorOf([&] { LoadFeModel(uses_bad_mesh); }),
                          {bad_mesh + ":2: binary .msh not supported"}, "uses_bad_mesh.yaml");
}

TEST(FeModelFile, ADeckWithoutNodesIsAnErrorNamingTheFile) {
  // found on the first try of `fe info` on an empty .bdf: 0 nodes, exit 0
  for (const auto& [name, text] : {std::pair<const char*, const char*>{"empty.bdf", ""},
                                   {"bulk_only.bdf", "BEGIN BULK\nENDDATA\n"},
                                   {"materials_only.inp", "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n"}}) {
    const std::string path = WriteScratch(name, text);
    try {
      LoadFeModel(path);
      ADD_FAILURE() << name << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.context().file, path);
      EXPECT_NE(std::string(e.what()).find("defines no nodes"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace flexmb::io
