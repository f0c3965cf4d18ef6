// *TIE (tied contact) against CalculiX (ccx 2.20): a steel cantilever 1 m x
// 0.2 m x 0.2 m clamped at x = 0, made of two blocks meshed independently
// and tied at x = 0.5 m: the master block's face (2 x 2 faces) and the
// slave block's face (3 x 3 faces) do not match, and the slave block starts
// 0.1 mm beyond the interface, so that ccx and flexmb both move (adjust)
// the slave nodes onto the master surface. The same deck goes to ccx
// (*STATIC, loads on the free end's nodes) and to flexmb's reader; the
// displacements of the free end must agree to ccx's printed digits. Three
// master faces: 4-node quadrilaterals (C3D8I blocks), 3-node triangles
// (C3D4 blocks of six tetrahedra per cell against a C3D20 slave block) and
// 8-node quadrilaterals (C3D20 blocks), all elements whose stiffness equals
// ccx's (fe_calculix_test.cc, fe_hex20_calculix_test.cc); a static case,
// because ccx's frequencies of untied C3D4 and C3D8I blocks already differ
// from flexmb's (by 0.2 % and 0.1 % in the first one: the mass). The
// reader's rows themselves are checked by hand in
// tests/unit/fe_io/abaqus_tie_test.cc. A contrast run glues the slave
// nodes to their nearest master nodes instead: the displacements then
// differ clearly, so the comparison sees the interpolation.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ccx_compare.h"
#include "ccx_runner.h"
#include <Eigen/Dense>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe_io/abaqus/abaqus_reader.h"

namespace flexmb::fe {
namespace abaqus_tie_calculix_test {

using flexmb::testing::CcxScratchDir;
using flexmb::testing::HaveCcx;
using flexmb::testing::MaxRelDiffByNode;
using flexmb::testing::ParseCcxDisplacements;
using flexmb::testing::RunCcx;

// the deck's nodes and elements, written as text
struct DeckBuilder {
  std::ostringstream nodes, elements, tip;
  std::map<std::array<long, 4>, int> ids;  // (block, grid point) -> node id
  int next_node = 1, next_element = 1;

  int Node(int block, long i, long j, long k, const Vec3& x) {
    auto [it, fresh] = ids.emplace(std::array<long, 4>{block, i, j, k}, next_node);
    if (fresh) nodes << next_node++ << ", " << x.x() << ", " << x.y() << ", " << x.z() << "\n";
    return it->second;
  }
};

// one block x in [x0, x1] with n = (nx, ny, nz) cells of `type` (C3D8I,
// C3D20, or C3D4: six tetrahedra per cell);
// the element faces on the side x = x_face (x0 or x1) go to `face_lines`
void AddBlock(DeckBuilder& b, int block, const std::string& type, double x0, double x1, std::array<int, 3> n,
              bool face_at_x1, std::ostringstream& face_lines, std::ostringstream& root) {
  const int s = type == "C3D20" ? 2 : 1;  // grid points per cell edge
  auto node = [&](long i, long j, long k) {
    const Vec3 x(x0 + (x1 - x0) * i / (s * n[0]), 0.2 * j / (s * n[1]), 0.2 * k / (s * n[2]));
    const bool fresh = b.ids.count({block, i, j, k}) == 0;
    const int id = b.Node(block, i, j, k, x);
    if (fresh && block == 0 && i == 0) root << id << "\n";
    if (fresh && block == 1 && i == s * n[0]) b.tip << id << "\n";
    return id;
  };
  b.elements << "*ELEMENT, TYPE=" << type << ", ELSET=E" << block << "\n";
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const bool on_face = face_at_x1 ? i == n[0] - 1 : i == 0;
        if (type == "C3D4") {
          // the cell's six tetrahedra about its diagonal (0,0,0)-(1,1,1), one
          // per order of the axes (a conforming mesh: every cell alike)
          static const std::array<std::array<int, 3>, 6> kOrder = {
              {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
          for (const auto& o : kOrder) {
            std::array<std::array<int, 3>, 4> v{};
            for (int m = 1; m < 4; ++m) {
              v[m] = v[m - 1];
              v[m][o[m - 1]] = 1;
            }
            v[3] = {1, 1, 1};
            // positive volume: swap the last two if (v1 - v0) x (v2 - v0) . (v3 - v0) < 0
            auto d = [&](int a, int c) { return v[a][c] - v[0][c]; };
            const int vol = d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1)) -
                            d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0)) +
                            d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0));
            if (vol < 0) std::swap(v[2], v[3]);
            b.elements << b.next_element;
            for (const auto& p : v) b.elements << ", " << node(i + p[0], j + p[1], k + p[2]);
            b.elements << "\n";
            // the face on x = x1: faces S1 (1 2 3), S2 (1 4 2), S3 (2 4 3), S4 (3 4 1)
            static const std::array<std::array<int, 3>, 4> kFaces = {{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}}};
            for (int f = 0; f < 4 && on_face; ++f) {
              const auto& fc = kFaces[f];
              const int edge = face_at_x1 ? 1 : 0;
              if (v[fc[0]][0] == edge && v[fc[1]][0] == edge && v[fc[2]][0] == edge)
                face_lines << b.next_element << ", S" << f + 1 << "\n";
            }
            ++b.next_element;
          }
          continue;
        }
        // hexahedron corners and (C3D20) mid-side nodes on the doubled grid
        static const std::array<std::array<int, 3>, 8> kCorner = {
            {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
        static const std::array<std::array<int, 2>, 12> kEdge = {
            {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};
        b.elements << b.next_element;
        for (const auto& c : kCorner) b.elements << ", " << node(s * (i + c[0]), s * (j + c[1]), s * (k + c[2]));
        if (s == 2) {
          for (const auto& e : kEdge) {
            const auto &p = kCorner[e[0]], &q = kCorner[e[1]];
            b.elements << (e[0] == 4 && e[1] == 5 ? ",\n" : ", ")
                       << node(2 * i + p[0] + q[0], 2 * j + p[1] + q[1], 2 * k + p[2] + q[2]);
          }
        }
        b.elements << "\n";
        if (on_face) face_lines << b.next_element << ", " << (face_at_x1 ? "S4" : "S6") << "\n";
        ++b.next_element;
      }
}

// the cantilever deck: block 0 (master) x in [0, 0.5], block 1 (slave)
// x in [0.5 + gap, 1]; `tie` is the *TIE card (empty: none)
std::string CantileverDeck(const std::string& master_type, const std::string& slave_type, const std::string& tie) {
  DeckBuilder b;
  std::ostringstream master_faces, slave_faces, root, unused;
  AddBlock(b, 0, master_type, 0.0, 0.5, {3, 2, 2}, true, master_faces, root);
  AddBlock(b, 1, slave_type, 0.5001, 1.0, {4, 3, 3}, false, slave_faces, unused);
  std::ostringstream deck;
  deck << "*NODE\n" << b.nodes.str() << b.elements.str() << "*NSET, NSET=ROOT\n" << root.str()
       << "*SURFACE, NAME=MASTER, TYPE=ELEMENT\n" << master_faces.str() << "*SURFACE, NAME=SLAVE, TYPE=ELEMENT\n"
       << slave_faces.str() << tie << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << flexmb::testing::kCcxE << ", "
       << flexmb::testing::kCcxNu << "\n*DENSITY\n" << flexmb::testing::kCcxRho << "\n"
       << "*SOLID SECTION, ELSET=E0, MATERIAL=STEEL\n*SOLID SECTION, ELSET=E1, MATERIAL=STEEL\n"
       << "*NSET, NSET=TIP\n" << b.tip.str() << "*BOUNDARY\nROOT, 1, 3\n*STEP\n*STATIC\n*CLOAD\nTIP, 2, -300.\n"
       << "TIP, 3, 100.\n*NODE PRINT, NSET=TIP\nU\n*END STEP\n";
  return deck.str();
}

// the mesh with every tie row replaced by a tie to the nearest node of the
// row's master face (the contrast: a tie without interpolation)
Mesh NearestNodeTie(Mesh m) {
  for (LinearConstraint& row : m.linear_constraints) {
    const Vec3 x = m.nodes[row.node].x;
    MpcTerm nearest = row.terms.front();
    for (const MpcTerm& t : row.terms)
      if ((m.nodes[t.node].x - x).norm() < (m.nodes[nearest.node].x - x).norm()) nearest = t;
    nearest.coef = 1.0;
    row.terms = {nearest};
  }
  return m;
}

// flexmb's static displacements of the TIP nodes under the deck's loads
// (300 N in -y and 100 N in z on every tip node)
std::map<int, Vec3> TipDisplacements(const Mesh& m) {
  const AssembledModel a = Assemble(m);
  const std::vector<int>& tip = m.node_sets.at("TIP");
  Eigen::VectorXd f_full = Eigen::VectorXd::Zero(a.dofs.n_full);
  for (int n : tip) {
    f_full[a.dofs.full[n][1]] = -300.0;
    f_full[a.dofs.full[n][2]] = 100.0;
  }
  const Eigen::MatrixXd k(a.K);
  const Eigen::VectorXd u = a.T * k.ldlt().solve(a.T.transpose() * f_full);
  std::map<int, Vec3> out;
  for (int n : tip) out[m.nodes[n].id] = Vec3(u[a.dofs.full[n][0]], u[a.dofs.full[n][1]], u[a.dofs.full[n][2]]);
  return out;
}

struct Case {
  const char* master;
  const char* slave;
  const char* what;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.master << " master, " << c.slave << " slave"; }

class TieCalculix : public ::testing::TestWithParam<Case> {};

TEST_P(TieCalculix, TipDeflectionOfTheTiedCantileverEqualsCcx) {
  if (!HaveCcx()) GTEST_SKIP() << "ccx (CalculiX) is not installed";
  const Case& c = GetParam();
  CcxScratchDir dir(std::string("tie_") + c.master);
  const std::string deck = CantileverDeck(c.master, c.slave, "*TIE, NAME=GLUE\nSLAVE, MASTER\n");
  ASSERT_TRUE(RunCcx(dir.path, "job", deck));
  const std::map<int, Vec3> ccx = ParseCcxDisplacements(dir.path / "job.dat", "TIP");
  const Mesh mesh = io::ReadAbaqus((dir.path / "job.inp").string());
  ASSERT_EQ(ccx.size(), mesh.node_sets.at("TIP").size());
  const std::map<int, Vec3> ours = TipDisplacements(mesh), nearest = TipDisplacements(NearestNodeTie(mesh));
  const int probe = ccx.begin()->first;
  std::printf("  %s\n  tip node %d uy: ccx %.7e, flexmb %.7e, nearest master node %.7e\n", c.what, probe,
              ccx.at(probe).y(), ours.at(probe).y(), nearest.at(probe).y());
  std::printf("  max rel diff over the tip: *TIE %.2e, nearest node %.2e\n", MaxRelDiffByNode(ours, ccx), MaxRelDiffByNode(nearest, ccx));
  EXPECT_LT(MaxRelDiffByNode(ours, ccx), 2e-6);  // ccx prints 7 significant digits
  EXPECT_GT(MaxRelDiffByNode(nearest, ccx), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(
    Faces, TieCalculix,
    ::testing::Values(Case{"C3D8I", "C3D8I", "4-node quadrilateral master faces (C3D8I blocks)"},
                      Case{"C3D4", "C3D20", "3-node triangular master faces (C3D4 master, C3D20 slave block)"},
                      Case{"C3D20", "C3D20", "8-node quadrilateral master faces (C3D20 blocks)"}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.master); });

}  // namespace abaqus_tie_calculix_test
}  // namespace flexmb::fe
