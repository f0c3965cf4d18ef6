#include "flexmb/fe_io/imported_matrices.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>

#include "flexmb/fe_io/dof_map.h"
#include "flexmb/fe_io/format_registry.h"
#include "flexmb/fe_io/harwell_boeing.h"
#include "flexmb/fe_io/matrix_market.h"
#include "flexmb/fe_io/vtk_mesh.h"
#include "mesh_io_test_util.h"

namespace flexmb::io {
namespace {

using testing::FeData;
using testing::InputErrorOf;
using testing::ScratchPath;
using testing::WriteScratch;

// nodes 10, 20, 30 on the x axis; matrix rows 10 ux, 20 ux, 20 uy, 30 uz
struct Fixture {
  std::string geometry, dof_map, k_hb, m_hb;
  fe::SparseMat K, M;

  Fixture() {
    fe::Mesh mesh;
    for (int i = 0; i < 3; ++i) {
      fe::Node n;
      n.id = 10 * (i + 1);
      n.x = fe::Vec3(i * 0.5, 0.0, 0.0);
      mesh.nodes.push_back(n);
    }
    mesh.IndexNodes();
    geometry = ScratchPath("imp_geometry.vtk");
    WriteVtk(mesh, geometry);
    dof_map = WriteScratch("imp_dof_map.txt", "1 10 1\n2 20 1\n3 20 2\n4 30 3\n");
    Eigen::Matrix4d k;
    k << 3e5, -1e5, 0, 0, -1e5, 2e5, 1.0 / 3.0, 0, 0, 1.0 / 3.0, 5e4, -2e4, 0, 0, -2e4, 2e4;
    K = k.sparseView();
    K.makeCompressed();
    M.resize(4, 4);
    for (int i = 0; i < 4; ++i) M.insert(i, i) = 0.1 * (i + 1);
    M.makeCompressed();
    k_hb = ScratchPath("imp_K.hb");
    m_hb = ScratchPath("imp_M.hb");
    WriteHarwellBoeing(K, k_hb);
    WriteHarwellBoeing(M, m_hb);
  }

  ImportedMatricesSpec Spec() const { return {k_hb, m_hb, dof_map, geometry}; }
};

TEST(ImportedMatrices, BuildsAnFeModelFromMatricesDofMapAndGeometry) {
  const Fixture f;
  const fe::FeModel model = ReadImportedMatrices(f.Spec());
  ASSERT_TRUE(model.imported.has_value());
  const fe::AssembledModel& a = *model.imported;
  ASSERT_EQ(model.mesh.nodes.size(), 3u);
  EXPECT_TRUE(model.mesh.elements.empty());
  EXPECT_EQ(a.dofs.n_full, 4);
  EXPECT_EQ(a.dofs.n_free, 4);
  const int n10 = model.mesh.NodeIndex(10), n20 = model.mesh.NodeIndex(20), n30 = model.mesh.NodeIndex(30);
  ASSERT_GE(n10, 0);
  ASSERT_GE(n20, 0);
  ASSERT_GE(n30, 0);
  EXPECT_EQ(a.dofs.full[n10], (std::array<int, 6>{0, -1, -1, -1, -1, -1}));
  EXPECT_EQ(a.dofs.full[n20], (std::array<int, 6>{1, 2, -1, -1, -1, -1}));
  EXPECT_EQ(a.dofs.full[n30], (std::array<int, 6>{-1, -1, 3, -1, -1, -1}));
  EXPECT_EQ(a.dofs.free, a.dofs.full);
  EXPECT_EQ(Eigen::MatrixXd(a.T), Eigen::MatrixXd::Identity(4, 4));
  EXPECT_EQ(Eigen::MatrixXd(a.K), Eigen::MatrixXd(f.K));
  EXPECT_EQ(Eigen::MatrixXd(a.M), Eigen::MatrixXd(f.M));
  EXPECT_EQ(Eigen::MatrixXd(a.M_full), Eigen::MatrixXd(f.M));
}

TEST(ImportedMatrices, ReadsMatrixMarketAndMixedFormats) {
  const Fixture f;
  const std::string k_mtx = ScratchPath("imp_K.mtx");
  WriteMatrixMarket(f.K, k_mtx);
  const fe::FeModel model = ReadImportedMatrices({k_mtx, f.m_hb, f.dof_map, f.geometry});
  EXPECT_EQ(Eigen::MatrixXd(model.imported->K), Eigen::MatrixXd(f.K));
}

TEST(ImportedMatrices, CalculixMatrixStorageWithItsDofFile) {
  // job.dof next to job.sti; geometry from the deck
  const fe::FeModel model = ReadImportedMatrices(
      {FeData("calculix/tiny.sti"), FeData("calculix/tiny.mas"), "", FeData("calculix/tiny.inp")});
  ASSERT_TRUE(model.imported.has_value());
  EXPECT_EQ(model.imported->dofs.full[model.mesh.NodeIndex(10)][1], 1);
  EXPECT_EQ(model.imported->dofs.full[model.mesh.NodeIndex(20)][0], 2);
  EXPECT_EQ(model.imported->K.coeff(1, 2), -500.0);
}

// Abaqus's *MATRIX OUTPUT, FORMAT=COORDINATE (.mtx without a Matrix Market
// banner): "ROW COLUMN VALUE" lines, both triangles or one (mirrored)
TEST(ImportedMatrices, ReadsAbaqusCoordinateMatrices) {
  const Fixture f;
  const Eigen::MatrixXd k(f.K);
  std::string both = "** written as Abaqus does\n", lower;
  char b[120];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (k(i, j) == 0.0) continue;
      std::snprintf(b, sizeof b, "%d %d  %.17g\n", i + 1, j + 1, k(i, j));
      both += b;
      if (i >= j) lower += b;
    }
  const std::string kb = WriteScratch("abq_STIF1.mtx", both), kl = WriteScratch("abq_lower_STIF1.mtx", lower);
  EXPECT_EQ(Eigen::MatrixXd(ReadImportedMatrices({kb, f.m_hb, f.dof_map, f.geometry}).imported->K), k);
  EXPECT_EQ(Eigen::MatrixXd(ReadImportedMatrices({kl, f.m_hb, f.dof_map, f.geometry}).imported->K), k);
  // errors name the file, line and entry
  const std::string twice = WriteScratch("abq_twice.mtx", "1 1 2.\n2 2 3.\n1 1 4.\n");
  testing::ExpectContains(InputErrorOf([&] { ReadImportedMatrices({twice, f.m_hb, f.dof_map, f.geometry}); }),
                          {twice + ":3: entry (1, 1)", "given twice (also line 1)"}, "twice");
  const std::string fields = WriteScratch("abq_fields.mtx", "1 1 2.\n2 2\n");
  testing::ExpectContains(InputErrorOf([&] { ReadImportedMatrices({fields, f.m_hb, f.dof_map, f.geometry}); }),
                          {fields + ":2: entry 2", "ROW COLUMN VALUE"}, "fields");
  // neither format: the Matrix Market message
  const std::string neither = WriteScratch("abq_neither.mtx", "hello world\n");
  testing::ExpectContains(InputErrorOf([&] { ReadImportedMatrices({neither, f.m_hb, f.dof_map, f.geometry}); }),
                          {neither + ":1: banner", "not a Matrix Market file"}, "neither");
}

struct BadCase {
  const char* name;
  ImportedMatricesSpec spec;
  std::string where;   // file (and line, entity) expected in the message
  const char* what;
};

// Abaqus's default FORMAT=MATRIX INPUT: "NODE, DOF, NODE, DOF, VALUE"; the
// rows are the (node, DOF) pairs named, in node and DOF order
TEST(ImportedMatrices, ReadsAbaqusLabelledMatrices) {
  const Fixture f;  // rows 10 ux, 20 ux, 20 uy, 30 uz
  const int node[4] = {10, 20, 20, 30}, dof[4] = {1, 1, 2, 3};
  const Eigen::MatrixXd k(f.K), m(f.M);
  // K: one triangle, half its entries written (j, i) (another equation
  // order); M: both triangles, the file's lines in reverse order
  std::string kt = "** STIFFNESS MATRIX\n", mt;
  char b[160];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j <= i; ++j) {
      if (k(i, j) == 0.0) continue;
      const bool swap = (i + j) % 2 == 1;
      const int r = swap ? j : i, c = swap ? i : j;
      std::snprintf(b, sizeof b, "%d,%d, %d,%d, %.17g\n", node[r], dof[r], node[c], dof[c], k(r, c));
      kt += b;
    }
  for (int i = 3; i >= 0; --i)
    for (int j = 3; j >= 0; --j) {
      if (m(i, j) == 0.0) continue;
      std::snprintf(b, sizeof b, "%d,%d, %d,%d, %.17g\n", node[i], dof[i], node[j], dof[j], m(i, j));
      mt += b;
    }
  const std::string kl = WriteScratch("abq_lab_STIF1.mtx", kt), ml = WriteScratch("abq_lab_MASS1.mtx", mt);
  const fe::FeModel model = ReadImportedMatrices({kl, ml, "", f.geometry});
  ASSERT_TRUE(model.imported);
  EXPECT_EQ(Eigen::MatrixXd(model.imported->K), k);
  EXPECT_EQ(Eigen::MatrixXd(model.imported->M), m);
  EXPECT_EQ(model.imported->dofs.full[static_cast<size_t>(model.mesh.NodeIndex(20))],
            (std::array<int, 6>{1, 2, -1, -1, -1, -1}));
  // a DOF only M names is a row too (K's column and row of zeros)
  const std::string m5 = WriteScratch("abq_lab_m5.mtx", mt + "30,1, 30,1, 0.5\n");
  const fe::FeModel wider = ReadImportedMatrices({kl, m5, "", f.geometry});
  EXPECT_EQ(wider.imported->dofs.n_free, 5);
  EXPECT_EQ(wider.imported->dofs.full[static_cast<size_t>(wider.mesh.NodeIndex(30))],
            (std::array<int, 6>{3, -1, 4, -1, -1, -1}));
  EXPECT_EQ(Eigen::MatrixXd(wider.imported->K).row(3).norm(), 0.0);
  // instance-qualified labels of one instance; a file that mixes one-sided
  // and paired off-diagonal entries
  std::string inst = kt;
  for (const char* n : {"10,", "20,", "30,"}) {
    for (size_t p = inst.find(std::string("\n") + n); p != std::string::npos; p = inst.find(std::string("\n") + n, p + 1))
      inst.insert(p + 1, "PART-1-1.");
    for (size_t p = inst.find(std::string(" ") + n); p != std::string::npos; p = inst.find(std::string(" ") + n, p + 10))
      inst.insert(p + 1, "PART-1-1.");
  }
  ASSERT_NE(inst.find("PART-1-1.20,1, PART-1-1."), std::string::npos) << inst;
  const std::string ki = WriteScratch("abq_lab_inst.mtx", inst);
  EXPECT_EQ(Eigen::MatrixXd(ReadImportedMatrices({ki, ml, "", f.geometry}).imported->K), k);
  std::snprintf(b, sizeof b, "%d,%d, %d,%d, %.17g\n", node[3], dof[3], node[2], dof[2], k(3, 2));
  const std::string mixed = WriteScratch("abq_lab_mixed.mtx", kt + b);  // (30 uz, 20 uy) now both ways
  EXPECT_EQ(Eigen::MatrixXd(ReadImportedMatrices({mixed, ml, "", f.geometry}).imported->K), k);
  const std::vector<BadCase> cases = {
      {"two instances", {WriteScratch("abq_lab_two.mtx", "A.10,1, A.10,1, 1.\nB.20,1, A.10,1, 2.\n"), ml, "", f.geometry},
       "abq_lab_two.mtx:2: entry 2", "node labels of two instances ('A' and 'B')"},
      {"decimal label", {WriteScratch("abq_lab_decimal.mtx", "10,1, 10,1, 1.\n10.0,1, 10,1, 2.\n"), ml, "", f.geometry},
       "abq_lab_decimal.mtx:2: entry 2", "node labels and DOF must be integers, got '10.0'"},
      {"keyword line", {WriteScratch("abq_lab_keyword.mtx", "10,1, 10,1, 1.\n*MATRIX INPUT, NAME=K\n"), ml, "", f.geometry},
       "abq_lab_keyword.mtx:2: entry 2", "a keyword line"},
      {"penalty", {WriteScratch("abq_lab_penalty.mtx", "10,1, 10,1, 1.\n20,1, 20,1, 1.0e+36\n"), ml, "", f.geometry},
       "abq_lab_penalty.mtx:2: entry 2", "is a penalty"},
      {"internal node", {WriteScratch("abq_lab_internal.mtx", "10,1, 10,1, 1.\n-3,1, 10,1, 2.\n"), ml, "", f.geometry},
       "abq_lab_internal.mtx:2: entry 2", "node label -3 is an Abaqus internal node"},
      {"DOF 8", {WriteScratch("abq_lab_dof.mtx", "10,1, 10,1, 1.\n20,8, 20,8, 2.\n"), ml, "", f.geometry},
       "abq_lab_dof.mtx:2: entry 2", "DOF 8 of node 20 is not a displacement or rotation"},
      {"twice", {WriteScratch("abq_lab_twice.mtx", "10,1, 10,1, 1.\n20,1, 10,1, 2.\n10,1, 10,1, 3.\n"), ml, "", f.geometry},
       "abq_lab_twice.mtx:3: entry (10 1, 10 1)", "given twice (also line 1)"},
      {"fields", {WriteScratch("abq_lab_fields.mtx", "10,1, 10,1, 1.\n20,1, 10,1\n"), ml, "", f.geometry},
       "abq_lab_fields.mtx:2: entry 2", "'NODE, DOF, NODE, DOF, VALUE'"},
      {"mixed formats", {kl, f.m_hb, "", f.geometry}, kl + ": K: ", "labelled format (FORMAT=MATRIX INPUT) but"},
      {"DOF map given", {kl, ml, f.dof_map, f.geometry}, f.dof_map + ": dof_map: ", "leave out the DOF map"},
      {"node not in geometry", {WriteScratch("abq_lab_ghost.mtx", "10,1, 10,1, 1.\n99,1, 99,1, 2.\n"), ml, "", f.geometry},
       "abq_lab_ghost.mtx", "node 99 does not exist in the geometry"},
  };
  for (const BadCase& c : cases)
    testing::ExpectContains(InputErrorOf([&] { ReadImportedMatrices(c.spec); }), {c.where, c.what}, c.name);
  // one labelled matrix alone has no rows to go by
  testing::ExpectContains(InputErrorOf([&] { FindMatrixFormat(kl)->read_matrix(kl, "K", 0); }),
                          {kl + ": K: ", "read only as a stiffness and mass pair"}, "alone");
}

// no DOF map: 3 or 6 rows per node of the geometry, in its node order, with
// a warning that says so
TEST(ImportedMatrices, WithoutADofMapRowsAreThreeOrSixPerNodeInNodeOrder) {
  const Fixture f;  // its geometry: nodes 10, 20, 30
  for (int per_node : {3, 6}) {
    const int n = 3 * per_node;
    Eigen::MatrixXd k = Eigen::MatrixXd::Identity(n, n) * 2e5;
    k(0, 1) = k(1, 0) = -1e4;
    const fe::SparseMat K = k.sparseView(), M = Eigen::MatrixXd(Eigen::MatrixXd::Identity(n, n)).sparseView();
    const std::string kp = ScratchPath("imp_default_K.mtx"), mp = ScratchPath("imp_default_M.mtx");
    WriteMatrixMarket(K, kp);
    WriteMatrixMarket(M, mp);
    testing::WarningCapture w;
    const fe::FeModel model = ReadImportedMatrices({kp, mp, "", f.geometry});
    EXPECT_EQ(w.Count("no DOF map given"), 1);
    EXPECT_EQ(w.Count(std::to_string(per_node) + " DOF per node"), 1);
    const fe::AssembledModel& a = *model.imported;
    EXPECT_EQ(a.dofs.n_full, n);
    for (int node = 0; node < 3; ++node)
      for (int c = 0; c < 6; ++c)
        EXPECT_EQ(a.dofs.full[model.mesh.NodeIndex(10 * (node + 1))][c], c < per_node ? per_node * node + c : -1);
    EXPECT_EQ(Eigen::MatrixXd(a.K), k);
  }
}

TEST(ImportedMatrices, SymmetrizesRoundOffAsymmetry) {
  const Fixture f;
  const std::string k_mtx = WriteScratch("imp_roundoff.mtx",
                                         "%%MatrixMarket matrix coordinate real general\n4 4 6\n"
                                         "1 1 2\n2 2 2\n3 3 2\n4 4 2\n1 2 0.3\n2 1 0.30000000000000004\n");
  const fe::FeModel model = ReadImportedMatrices({k_mtx, f.m_hb, f.dof_map, f.geometry});
  const fe::SparseMat& K = model.imported->K;
  EXPECT_EQ(K.coeff(0, 1), K.coeff(1, 0));
  EXPECT_NEAR(K.coeff(0, 1), 0.3, 1e-16);
}


TEST(ImportedMatrices, BadInputNamesFileAndEntity) {
  const Fixture f;
  const std::string asym = WriteScratch("imp_asym.mtx",
                                        "%%MatrixMarket matrix coordinate real general\n4 4 6\n"
                                        "1 1 2\n2 2 2\n3 3 2\n4 4 2\n2 3 1\n3 2 1.5\n");
  const std::string nonfinite = WriteScratch("imp_nan.mtx",
                                             "%%MatrixMarket matrix coordinate real symmetric\n4 4 4\n"
                                             "1 1 2\n2 2 2\n3 3 inf\n4 4 2\n");
  const std::string m3 = ScratchPath("imp_M3.hb");
  {
    fe::SparseMat M(3, 3);
    for (int i = 0; i < 3; ++i) M.insert(i, i) = 0.5;
    WriteHarwellBoeing(M, m3);
  }
  const std::string short_map = WriteScratch("imp_short_map.txt", "1 10 1\n2 20 1\n3 20 2\n");
  const std::string long_map = WriteScratch("imp_long_map.txt", "1 10 1\n2 20 1\n3 20 2\n4 30 3\n5 30 1\n");
  const std::string ghost_map = WriteScratch("imp_ghost_map.txt", "1 10 1\n2 20 1\n3 20 2\n4 99 3\n");
  const std::string twice_map = WriteScratch("imp_twice_map.txt", "1 10 1\n2 20 1\n3 20 2\n4 10 1\n");
  const std::string truncated = WriteScratch("imp_truncated.hb", [&] {
    std::string text = testing::ReadText(f.k_hb);
    return text.substr(0, text.size() - 30);
  }());
  const std::string banner = WriteScratch("imp_banner.mtx", "%%MatrixMarket matrix coordinate pattern general\n4 4 1\n1 1\n");
  const std::vector<BadCase> cases = {
      {"asymmetric", {asym, f.m_hb, f.dof_map, f.geometry}, asym + ": K: ",
       "worst entry K(3,2) = 1.5 but K(2,3) = 1"},
      {"asymmetric names nodes", {asym, f.m_hb, f.dof_map, f.geometry}, asym,
       "(row 3 = node 20 uy, column 2 = node 20 ux)"},
      {"non-finite", {nonfinite, f.m_hb, f.dof_map, f.geometry}, nonfinite + ":5: entry 3 (row 3, column 3)",
       "not finite"},
      {"size K vs M", {f.k_hb, m3, f.dof_map, f.geometry}, m3 + ": M: ", "M is 3 x 3 but K"},
      {"row not mapped", {f.k_hb, f.m_hb, short_map, f.geometry}, short_map + ": row 4: ",
       "row 4 of the 4 x 4 matrices"},
      {"too many rows", {f.k_hb, f.m_hb, long_map, f.geometry}, long_map + ":5: row 5: ",
       "the DOF map has 5 rows but the matrices"},
      {"node not in geometry", {f.k_hb, f.m_hb, ghost_map, f.geometry}, ghost_map + ":4: row 4: ",
       "node 99 does not exist in the geometry"},
      {"node twice", {f.k_hb, f.m_hb, twice_map, f.geometry}, twice_map + ":4: row 4: ",
       "node 10 ux is mapped twice (rows 1 and 4)"},
      {"truncated", {truncated, f.m_hb, f.dof_map, f.geometry}, truncated + ":", "file ends early"},
      {"wrong banner", {banner, f.m_hb, f.dof_map, f.geometry}, banner + ":1: banner", "pattern matrices"},
      {"extension", {f.dof_map, f.m_hb, f.dof_map, f.geometry}, f.dof_map + ": K: ", "unknown matrix file type"},
      {"no dof map", {f.k_hb, f.m_hb, "", f.geometry}, f.k_hb + ": K: ", "4 rows of the matrices are not 3 or 6 per node of the 3 nodes"},
  };
  for (const BadCase& c : cases)
    testing::ExpectContains(InputErrorOf([&] { ReadImportedMatrices(c.spec); }), {c.where, c.what}, c.name);
}

}  // namespace
}  // namespace flexmb::io
