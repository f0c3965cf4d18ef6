// Matrices imported from CalculiX (*FREQUENCY, SOLVER=MATRIXSTORAGE) against
// CalculiX's own eigenvalue solution of the same deck, and against flexmb's
// element matrices of the same deck where the formulation is the same:
// C3D8 = flexmb's hex8 with full integration (stiffness and mass), C3D4
// stiffness = flexmb's tet4 (ccx integrates the C3D4 mass with one point,
// rho V / 16 per node pair, which the test reproduces). ccx (Debian
// calculix-ccx 2.20) is run by the test in a scratch directory; the test is
// skipped only if ccx is not installed. References: docs/validation.md,
// "FE: imported matrices and CalculiX matrix storage".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "ccx_runner.h"
#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"
#include "flexmb/fe_io/imported_matrices.h"

namespace flexmb {
namespace fe_calculix_matrices_test {

namespace fs = std::filesystem;

using flexmb::testing::CcxScratchDir;
using flexmb::testing::HaveCcx;
using flexmb::testing::ParseCcxFrequencies;
using flexmb::testing::RunCcx;

// a steel cantilever block 0.6 x 0.1 x 0.08 m clamped at x = 0 (SI units),
// nx x ny x nz cells of one C3D8 each or of six C3D4 (Kuhn split), then
// the given step
std::string CantileverDeck(const std::string& type, int nx, int ny, int nz, const std::string& step) {
  const double L = 0.6, W = 0.1, H = 0.08;
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  std::vector<Eigen::Vector3d> x((nx + 1) * (ny + 1) * (nz + 1) + 1);
  std::ostringstream d;
  d.precision(17);
  d << "** cantilever block for the flexmb / CalculiX matrix comparison\n*NODE\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        x[id(i, j, k)] = Eigen::Vector3d(L * i / nx, W * j / ny, H * k / nz);
        d << id(i, j, k) << ", " << x[id(i, j, k)].x() << ", " << x[id(i, j, k)].y() << ", " << x[id(i, j, k)].z()
          << "\n";
      }
  d << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n";
  int e = 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        // corner c = (bit 0: +x, bit 1: +y, bit 2: +z)
        std::array<int, 8> c;
        for (int b = 0; b < 8; ++b) c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        if (type == "C3D8") {
          d << e++ << ", " << c[0] << ", " << c[1] << ", " << c[3] << ", " << c[2] << ", " << c[4] << ", " << c[5]
            << ", " << c[7] << ", " << c[6] << "\n";
          continue;
        }
        // six tetrahedra along the paths 000 -> 111 (conforming between cells)
        const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
        for (const auto& p : paths) {
          std::array<int, 4> t = {c[0], c[p[0]], c[p[1]], c[7]};
          const double vol = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).dot(x[t[3]] - x[t[0]]);
          if (vol < 0) std::swap(t[1], t[2]);
          d << e++ << ", " << t[0] << ", " << t[1] << ", " << t[2] << ", " << t[3] << "\n";
        }
      }
  d << "*NSET, NSET=FIX\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j) d << id(0, j, k) << ",\n";
  d << "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n"
       "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*BOUNDARY\nFIX, 1, 3\n*STEP\n"
    << step << "\n*END STEP\n";
  return d.str();
}

fe::FeModel Import(const fs::path& dir) {
  return io::ReadImportedMatrices({(dir / "mat.sti").string(), (dir / "mat.mas").string(), "",
                                   (dir / "mat.inp").string()});
}

// a ccx run in its scratch directory and the matrices it wrote, imported
struct CcxImport {
  explicit CcxImport(const std::string& name) : dir(name) {}
  CcxScratchDir dir;
  fe::FeModel model;      // the imported matrices (model.imported) on the deck's nodes
  fe::ModalResult modes;  // their first frequencies
};

// runs ccx on the 6 x 2 x 2 cantilever of `type`: its eigenvalue solution
// ("freq", count modes) and its matrix storage ("mat"); imports the matrices
// and checks that their first `count` frequencies are ccx's own (7
// significant digits printed)
void SolveAndImport(CcxImport& run, const std::string& type, int count) {
  const fs::path& dir = run.dir.path;
  ASSERT_TRUE(RunCcx(dir, "freq", CantileverDeck(type, 6, 2, 2, "*FREQUENCY\n" + std::to_string(count))));
  ASSERT_TRUE(RunCcx(dir, "mat", CantileverDeck(type, 6, 2, 2, "*FREQUENCY, SOLVER=MATRIXSTORAGE")));
  const std::vector<double> ccx = ParseCcxFrequencies(dir / "freq.dat");
  ASSERT_EQ(static_cast<int>(ccx.size()), count);
  run.model = Import(dir);
  ASSERT_TRUE(run.model.imported.has_value());
  fe::ModalOptions o;
  o.count = count;
  run.modes = fe::SolveModes(*run.model.imported, o);
  for (int i = 0; i < count; ++i)
    EXPECT_NEAR(run.modes.frequencies_hz[i], ccx[i], 1e-6 * ccx[i]) << "mode " << i + 1;
}

// largest |A(r, s) - B(p[r], p[s])| over the rows of A (p empty: the identity)
double MaxMappedDifference(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const std::vector<int>& p = {}) {
  auto q = [&](int r) { return p.empty() ? r : p[r]; };
  double d = 0.0;
  for (int r = 0; r < A.rows(); ++r)
    for (int s = 0; s < A.cols(); ++s) d = std::max(d, std::fabs(A(r, s) - B(q(r), q(s))));
  return d;
}

// the frequencies of a dense K, M pair through fe::SolveModes
Eigen::VectorXd Frequencies(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M, int count) {
  fe::AssembledModel a;
  a.K = K.sparseView();
  a.M = M.sparseView();
  a.K.makeCompressed();
  a.M.makeCompressed();
  a.dofs.n_full = a.dofs.n_free = static_cast<int>(K.rows());
  fe::ModalOptions o;
  o.count = count;
  return fe::SolveModes(a, o).frequencies_hz;
}

TEST(FeCalculixMatrices, ImportedHexModelMatchesCcxAndFlexmbFullIntegrationHex8) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const int count = 8;
  CcxImport run("matrices_hex");
  ASSERT_NO_FATAL_FAILURE(SolveAndImport(run, "C3D8", count));
  const fe::FeModel& model = run.model;
  const fe::AssembledModel& imp = *model.imported;
  const int n = imp.dofs.n_free;
  EXPECT_EQ(n, 3 * 6 * 3 * 3);  // 7 x 3 x 3 nodes, the 3 x 3 of the x = 0 face fixed

  // flexmb's hex8 with full integration, element by element on the rows of
  // the imported matrices (the deck read by io::ReadAbaqus)
  const fe::Mesh mesh = io::ReadAbaqus((run.dir.path / "mat.inp").string());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
  for (const fe::Element& e : mesh.elements) {
    ASSERT_EQ(e.type, fe::kHex8Full);  // C3D8 of a deck not written by Abaqus/CAE: CalculiX's
    std::vector<fe::Vec3> x;
    std::vector<int> rows;
    for (int node : e.nodes) {
      x.push_back(mesh.nodes[node].x);
      const int k = model.mesh.NodeIndex(mesh.nodes[node].id);
      ASSERT_GE(k, 0);
      for (int c = 0; c < 3; ++c) rows.push_back(imp.dofs.free[k][c]);
    }
    fe::ElementInput in;
    in.element = &e;
    in.x = x.data();
    in.material = &mesh.materials[mesh.solid_sections[e.property].material];
    fe::MatX Ke, Me;
    fe::SolidHex8Matrices(in, Ke, Me, fe::Hex8Formulation::kFullIntegration);
    for (int a = 0; a < 24; ++a)
      for (int b = 0; b < 24; ++b) {
        if (rows[a] < 0 || rows[b] < 0) continue;
        K(rows[a], rows[b]) += Ke(a, b);
        M(rows[a], rows[b]) += Me(a, b);
      }
  }
  // ccx prints 14 significant digits
  EXPECT_LT(MaxMappedDifference(Eigen::MatrixXd(imp.K), K), 1e-12 * K.cwiseAbs().maxCoeff());
  EXPECT_LT(MaxMappedDifference(Eigen::MatrixXd(imp.M), M), 1e-12 * M.cwiseAbs().maxCoeff());
  const Eigen::VectorXd own = Frequencies(K, M, count);
  for (int i = 0; i < count; ++i) {
    EXPECT_NEAR(own[i], run.modes.frequencies_hz[i], 1e-9 * run.modes.frequencies_hz[i]) << "mode " << i + 1;
  }
}

TEST(FeCalculixMatrices, TetModelStiffnessEqualsFlexmbAssembly) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const int count = 6;
  CcxImport run("matrices_tet");
  ASSERT_NO_FATAL_FAILURE(SolveAndImport(run, "C3D4", count));
  const fe::FeModel& model = run.model;
  const fe::AssembledModel& imp = *model.imported;
  const int n = imp.dofs.n_free;

  // flexmb's assembly of the same deck (constant-strain tetrahedra, the
  // clamped face from *BOUNDARY); row r of the import is free DOF p[r]
  const fe::Mesh mesh = io::ReadAbaqus((run.dir.path / "mat.inp").string());
  const fe::AssembledModel own = fe::Assemble(mesh);
  ASSERT_EQ(own.dofs.n_free, n);
  std::vector<int> p(static_cast<size_t>(n), -1);
  for (size_t k = 0; k < model.mesh.nodes.size(); ++k) {
    const int m = mesh.NodeIndex(model.mesh.nodes[k].id);
    ASSERT_GE(m, 0);
    for (int c = 0; c < 6; ++c) {
      const int r = imp.dofs.free[k][c];
      if (r < 0) continue;
      ASSERT_GE(own.dofs.free[m][c], 0) << "node " << model.mesh.nodes[k].id << " component " << c + 1;
      p[static_cast<size_t>(r)] = own.dofs.free[m][c];
    }
  }
  const Eigen::MatrixXd Ko = Eigen::MatrixXd(own.K), Mo = Eigen::MatrixXd(own.M);
  EXPECT_LT(MaxMappedDifference(Eigen::MatrixXd(imp.K), Ko, p), 1e-12 * Ko.cwiseAbs().maxCoeff());

  // ccx's C3D4 mass: one integration point, rho V / 16 for every node pair
  // of a tetrahedron and direction
  const double rho = 7850.0;
  Eigen::MatrixXd M1 = Eigen::MatrixXd::Zero(n, n);
  for (const fe::Element& e : mesh.elements) {
    const fe::Vec3 &a = mesh.nodes[e.nodes[0]].x, &b = mesh.nodes[e.nodes[1]].x, &c = mesh.nodes[e.nodes[2]].x,
                   &d = mesh.nodes[e.nodes[3]].x;
    const double V = std::fabs((b - a).cross(c - a).dot(d - a)) / 6.0;
    for (int i : e.nodes)
      for (int j : e.nodes)
        for (int q = 0; q < 3; ++q) {
          const int r = imp.dofs.free[model.mesh.NodeIndex(mesh.nodes[i].id)][q];
          const int s = imp.dofs.free[model.mesh.NodeIndex(mesh.nodes[j].id)][q];
          if (r >= 0 && s >= 0) M1(r, s) += rho * V / 16.0;
        }
  }
  EXPECT_LT(MaxMappedDifference(Eigen::MatrixXd(imp.M), M1), 1e-12 * M1.cwiseAbs().maxCoeff());

  // the same stiffness in modal terms: imported K with flexmb's consistent
  // mass gives flexmb's frequencies
  Eigen::MatrixXd Mp(n, n);
  for (int r = 0; r < n; ++r)
    for (int s = 0; s < n; ++s) Mp(r, s) = Mo(p[r], p[s]);
  const Eigen::VectorXd mixed = Frequencies(Eigen::MatrixXd(imp.K), Mp, count);
  fe::ModalOptions o;
  o.count = count;
  const fe::ModalResult flexmb = fe::SolveModes(own, o);
  for (int i = 0; i < count; ++i) {
    EXPECT_NEAR(mixed[i], flexmb.frequencies_hz[i], 1e-9 * flexmb.frequencies_hz[i]) << "mode " << i + 1;
  }
}

TEST(FeCalculixMatrices, ShellExpansionIsRejectedWithAClearMessage) {
  // ccx expands S4 shells into bricks: job.dof repeats the shell nodes'
  // directions and names generated nodes; the import names the problem
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const CcxScratchDir scratch("matrices_shell");
  const fs::path& dir = scratch.path;
  ASSERT_TRUE(RunCcx(dir, "mat",
                     "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n4, 0, 1, 0\n5, 1, 1, 0\n6, 2, 1, 0\n"
                     "*ELEMENT, TYPE=S4, ELSET=EALL\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n"
                     "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1e11, 0.3\n*DENSITY\n7850.\n"
                     "*SHELL SECTION, ELSET=EALL, MATERIAL=STEEL\n0.01\n"
                     "*BOUNDARY\n1, 1, 6\n4, 1, 6\n*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n"));
  try {
    Import(dir);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find((dir / "mat.dof").string() + ":"), std::string::npos) << m;
    EXPECT_TRUE(m.find("is mapped twice") != std::string::npos ||
                m.find("does not exist in the geometry") != std::string::npos)
        << m;
  }
}

}  // namespace fe_calculix_matrices_test
}  // namespace flexmb
