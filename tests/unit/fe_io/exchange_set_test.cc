#include "flexmb/fe_io/exchange_set.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "../fe/fe_test_models.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/modal.h"
#include "matrix_test_util.h"

namespace flexmb::io {
namespace {

using fe::testing::AddMaterial;
using fe::testing::AddPointMass;
using fe::testing::AddRigidLink;
using testing::ExpectBitIdentical;
using testing::ExpectContains;
using testing::InputErrorOf;
using testing::ScratchPath;

// free-free steel plate 0.6 x 0.4 m, 6 x 4 CQUAD4-like shells 3 mm thick,
// node ids 1000 + 7 i, a point mass at a corner and a rigid link carrying a
// bracket node above the plate
fe::Mesh ShellPlate() {
  fe::Mesh mesh;
  const int steel = AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  fe::ShellSection s;
  s.id = 1;
  s.material = steel;
  s.thickness = 0.003;
  mesh.shell_sections.push_back(s);
  const int nx = 6, ny = 4;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      fe::Node n;
      n.id = 1000 + 7 * static_cast<int>(mesh.nodes.size());
      n.x = fe::Vec3(0.1 * i, 0.1 * j + 0.01 * i * i, 0.002 * i * j);
      mesh.nodes.push_back(n);
    }
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      fe::Element e;
      e.id = 1 + static_cast<int>(mesh.elements.size());
      e.type = fe::ElementType::kQuad4;
      e.property = 0;
      const int a = j * (nx + 1) + i;
      e.nodes = {a, a + 1, a + nx + 2, a + nx + 1};
      mesh.elements.push_back(e);
    }
  }
  fe::Node bracket;
  bracket.id = 5;
  bracket.x = fe::Vec3(0.3, 0.2, 0.05);
  mesh.nodes.push_back(bracket);
  mesh.IndexNodes();
  AddPointMass(mesh, static_cast<int>(mesh.nodes.size()) - 1, 0.8);
  AddRigidLink(mesh, 1, 2 * (nx + 1) + 3, {static_cast<int>(mesh.nodes.size()) - 1});
  AddPointMass(mesh, 0, 0.25);
  return mesh;
}

TEST(ExchangeSet, AssembledShellModelRoundTripsBitForBit) {
  const fe::Mesh mesh = ShellPlate();
  const fe::AssembledModel original = fe::Assemble(mesh);
  ASSERT_LT(original.dofs.n_free, original.dofs.n_full);  // the link removed the bracket's DOF

  const std::string dir = ScratchPath("exchange");
  std::filesystem::remove_all(dir);
  WriteExchangeSet(mesh, original, dir);
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"K_CCS.hb", "M_CCS.hb", "dof_map.txt", "geometry.vtk"}));

  const fe::FeModel read = ReadExchangeSet(dir);
  ASSERT_TRUE(read.imported.has_value());
  const fe::AssembledModel& imported = *read.imported;
  ExpectBitIdentical(imported.K, original.K);
  ExpectBitIdentical(imported.M, original.M);
  ASSERT_EQ(read.mesh.nodes.size(), mesh.nodes.size());
  for (size_t i = 0; i < mesh.nodes.size(); ++i) {
    const int k = read.mesh.NodeIndex(mesh.nodes[i].id);
    ASSERT_GE(k, 0);
    EXPECT_EQ(read.mesh.nodes[k].x, mesh.nodes[i].x);
    EXPECT_EQ(imported.dofs.free[k], original.dofs.free[i]) << "node " << mesh.nodes[i].id;
  }

  // the same modal problem: the same frequencies (6 rigid modes near 0, then elastic)
  fe::ModalOptions o;
  o.count = 12;
  const fe::ModalResult a = fe::SolveModes(original, o);
  const fe::ModalResult b = fe::SolveModes(imported, o);
  ASSERT_EQ(a.frequencies_hz.size(), 12);
  ASSERT_EQ(b.frequencies_hz.size(), 12);
  const double f_elastic = a.frequencies_hz[6];
  EXPECT_GT(f_elastic, 1.0);
  for (int i = 0; i < 12; ++i) {
    EXPECT_NEAR(b.frequencies_hz[i], a.frequencies_hz[i], 1e-9 * f_elastic) << "mode " << i;
  }
}

TEST(ExchangeSet, MissingDirectoryOrFileIsAnInputError) {
  const std::string dir = ScratchPath("no_such_exchange_set");
  ExpectContains(InputErrorOf([&] { ReadExchangeSet(dir); }),
                 {dir + ": exchange set: exchange set directory does not exist"}, "missing directory");

  const fe::Mesh mesh = ShellPlate();
  const std::string partial = ScratchPath("partial_exchange");
  WriteExchangeSet(mesh, fe::Assemble(mesh), partial);
  std::filesystem::remove(std::filesystem::path(partial) / "dof_map.txt");
  ExpectContains(InputErrorOf([&] { ReadExchangeSet(partial); }),
                 {"dof_map.txt: exchange set: file of the exchange set is missing"}, "missing file");
}

}  // namespace
}  // namespace flexmb::io
