#pragma once
/// \file mesh_io_test_util.h
/// Helpers for the file reader tests (meshes, matrices, model files): test
/// data paths, scratch files, texts edited for bad-input cases, the message
/// of an expected InputError, table-driven bad-file checks, captured
/// warnings and the comparison of two meshes.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::io::testing {

/// Path of a file under tests/data/fe/.
inline std::string FeData(const std::string& relative) {
  return std::string(FLEXMB_SOURCE_DIR) + "/tests/data/fe/" + relative;
}

/// A per-process scratch directory (created on first use).
inline std::filesystem::path ScratchDir() {
  const auto dir = std::filesystem::temp_directory_path() / ("flexmb_mesh_io_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

/// Removes the scratch directory when the test program ends.
struct ScratchCleanup {
  ~ScratchCleanup() {
    std::error_code ec;
    std::filesystem::remove_all(
        std::filesystem::temp_directory_path(ec) / ("flexmb_mesh_io_test_" + std::to_string(getpid())), ec);
  }
};
inline ScratchCleanup scratch_cleanup;

/// Path of the scratch file `name` (not created).
inline std::string ScratchPath(const std::string& name) { return (ScratchDir() / name).string(); }

/// Writes `text` to the scratch file `name` (which may name a subdirectory)
/// and returns its path.
inline std::string WriteScratch(const std::string& name, const std::string& text) {
  const std::filesystem::path path = ScratchDir() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  return path.string();
}

/// Mass [kg] of one element with nodes at x and density rho (the sum of the
/// x-direction block of its consistent mass, E = 2e11 Pa, nu = 0.3): rho V
/// for an element read in the right node order.
inline double ElementTotalMass(const fe::Element& e, const std::vector<fe::Vec3>& x, double rho) {
  fe::Material mat;
  mat.E = 2.0e11;
  mat.nu = 0.3;
  mat.rho = rho;
  fe::ElementInput in;
  in.element = &e;
  in.x = x.data();
  in.material = &mat;
  fe::MatX K, M;
  fe::ElementMatrices(in, K, M);
  double total = 0.0;
  for (int i = 0; i < M.rows(); i += 3)
    for (int j = 0; j < M.cols(); j += 3) total += M(i, j);
  return total;
}

/// The whole content of a file ("" if it cannot be read).
inline std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with the first occurrence of `from` (which must be there) replaced by `to`.
inline std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t p = text.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  if (p != std::string::npos) text.replace(p, from.size(), to);
  return text;
}

/// Runs `f`, expecting an InputError; returns its full message ("" if none).
/// Another exception is a test failure.
template <class F>
std::string InputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected an InputError, got: " << e.what();
    return std::string("unexpected exception: ") + e.what();
  }
  return "";
}

/// Expects `message` to contain each of `parts`; a failure names `label`.
inline void ExpectContains(const std::string& message, const std::vector<std::string>& parts,
                           const std::string& label) {
  for (const std::string& part : parts)
    EXPECT_NE(message.find(part), std::string::npos)
        << label << ":\n  message: " << message << "\n  expected: " << part;
}

/// One case of a table-driven bad-input test.
struct BadFile {
  std::string name;                // scratch file name
  std::string text;                // its content
  std::string where;               // expected right after the file's path (":LINE: ENTITY: ");
                                   // empty: the message need not name this file
  std::vector<std::string> parts;  // further parts of the message
};

/// Writes each case to its scratch file, runs `read(path)` and expects an
/// InputError whose message holds the path followed by `where`, and `parts`.
template <class Read>
void ExpectBadFiles(const std::vector<BadFile>& cases, Read&& read) {
  for (const BadFile& c : cases) {
    const std::string path = WriteScratch(c.name, c.text);
    const std::string message = InputErrorOf([&] { read(path); });
    std::vector<std::string> parts = c.parts;
    if (!c.where.empty()) parts.insert(parts.begin(), path + c.where);
    ExpectContains(message, parts, c.name);
  }
}

/// Collects the warnings issued while alive.
struct WarningCapture {
  std::vector<std::string> messages;
  LogSink previous;
  WarningCapture() {
    previous = SetWarningSink([this](const std::string& m) { messages.push_back(m); });
  }
  ~WarningCapture() { SetWarningSink(previous); }
  /// Number of warnings containing `part`.
  int Count(const std::string& part) const {
    int n = 0;
    for (const std::string& m : messages) n += m.find(part) != std::string::npos;
    return n;
  }
};

/// Expects equal vectors: within `tol` (Euclidean norm) if tol > 0, else bit for bit.
inline void ExpectSameVec3(const fe::Vec3& a, const fe::Vec3& b, double tol, const std::string& what) {
  if (tol > 0.0)
    EXPECT_LT((a - b).norm(), tol) << what;
  else
    EXPECT_EQ(std::memcmp(a.data(), b.data(), 3 * sizeof(double)), 0)
        << what << ": (" << a.transpose() << ") vs (" << b.transpose() << ")";
}

/// Expects equal numbers: within `tol` if tol > 0, else equal.
inline void ExpectSameValue(double a, double b, double tol, const std::string& what) {
  if (tol > 0.0)
    EXPECT_NEAR(a, b, tol) << what;
  else
    EXPECT_EQ(a, b) << what;
}

/// The same nodes in the same order: ids, and positions within `tol` [m] (0: bit for bit).
inline void ExpectSameNodes(const fe::Mesh& a, const fe::Mesh& b, double tol = 0.0) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (size_t k = 0; k < a.nodes.size(); ++k) {
    EXPECT_EQ(a.nodes[k].id, b.nodes[k].id);
    ExpectSameVec3(a.nodes[k].x, b.nodes[k].x, tol, "node " + std::to_string(a.nodes[k].id));
  }
}

/// The same elements in the same order: types and node indices, and ids if `ids`.
inline void ExpectSameConnectivity(const fe::Mesh& a, const fe::Mesh& b, bool ids = true) {
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (size_t k = 0; k < a.elements.size(); ++k) {
    if (ids) EXPECT_EQ(a.elements[k].id, b.elements[k].id);
    EXPECT_EQ(a.elements[k].type, b.elements[k].type) << "element " << a.elements[k].id;
    EXPECT_EQ(a.elements[k].nodes, b.elements[k].nodes) << "element " << a.elements[k].id;
  }
}

/// Tolerances of ExpectSameMesh (0: equal; node positions and offsets: bit for bit).
struct MeshMatch {
  double position = 0.0;      ///< node positions and point mass offsets [m]
  double shell_offset = 0.0;  ///< element shell offsets [m]
  double shear = 0.0;         ///< beam shear factors ky, kz
  std::string writer_sets;    ///< prefix of the sets b may hold beyond a's (a writer's own); empty: equal sets
};

/// Everything a mesh file carries is the same in a and b: nodes, elements
/// (with orientations and offsets), materials, sections, point masses,
/// rigid links, constraints and sets.
inline void ExpectSameMesh(const fe::Mesh& a, const fe::Mesh& b, const MeshMatch& tol = {}) {
  ExpectSameNodes(a, b, tol.position);
  ExpectSameConnectivity(a, b);
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (size_t k = 0; k < a.elements.size(); ++k) {
    const fe::Element &x = a.elements[k], &y = b.elements[k];
    const std::string what = "element " + std::to_string(x.id);
    EXPECT_EQ(x.property, y.property) << what;
    EXPECT_EQ(x.orientation, y.orientation) << what;
    EXPECT_EQ(x.offset_a, y.offset_a) << what;
    EXPECT_EQ(x.offset_b, y.offset_b) << what;
    ExpectSameValue(x.shell_offset, y.shell_offset, tol.shell_offset, what);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (size_t k = 0; k < a.materials.size(); ++k) {
    const fe::Material &x = a.materials[k], &y = b.materials[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.E, y.E) << x.name;
    EXPECT_EQ(x.nu, y.nu) << x.name;
    EXPECT_EQ(x.G, y.G) << x.name;
    EXPECT_EQ(x.rho, y.rho) << x.name;
  }
  ASSERT_EQ(a.shell_sections.size(), b.shell_sections.size());
  for (size_t k = 0; k < a.shell_sections.size(); ++k) {
    EXPECT_EQ(a.shell_sections[k].material, b.shell_sections[k].material);
    EXPECT_EQ(a.shell_sections[k].thickness, b.shell_sections[k].thickness);
    EXPECT_EQ(a.shell_sections[k].nsm, b.shell_sections[k].nsm);
  }
  ASSERT_EQ(a.beam_sections.size(), b.beam_sections.size());
  for (size_t k = 0; k < a.beam_sections.size(); ++k) {
    const fe::BeamSection &x = a.beam_sections[k], &y = b.beam_sections[k];
    const std::string what = "beam section " + std::to_string(x.id);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.material, y.material) << what;
    EXPECT_EQ(x.A, y.A) << what;
    EXPECT_EQ(x.Iy, y.Iy) << what;
    EXPECT_EQ(x.Iz, y.Iz) << what;
    EXPECT_EQ(x.Iyz, y.Iyz) << what;
    EXPECT_EQ(x.J, y.J) << what;
    ExpectSameValue(x.ky, y.ky, tol.shear, what);
    ExpectSameValue(x.kz, y.kz, tol.shear, what);
    EXPECT_EQ(x.nsm, y.nsm) << what;
  }
  ASSERT_EQ(a.solid_sections.size(), b.solid_sections.size());
  for (size_t k = 0; k < a.solid_sections.size(); ++k)
    EXPECT_EQ(a.solid_sections[k].material, b.solid_sections[k].material);
  ASSERT_EQ(a.point_masses.size(), b.point_masses.size());
  for (size_t k = 0; k < a.point_masses.size(); ++k) {
    const fe::PointMass &x = a.point_masses[k], &y = b.point_masses[k];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.node, y.node);
    EXPECT_EQ(x.mass, y.mass);
    ExpectSameVec3(x.offset, y.offset, tol.position, "point mass " + std::to_string(x.id) + " offset");
    EXPECT_EQ(x.inertia, y.inertia);
  }
  ASSERT_EQ(a.rigid_links.size(), b.rigid_links.size());
  for (size_t k = 0; k < a.rigid_links.size(); ++k) {
    EXPECT_EQ(a.rigid_links[k].id, b.rigid_links[k].id);
    EXPECT_EQ(a.rigid_links[k].independent, b.rigid_links[k].independent);
    EXPECT_EQ(a.rigid_links[k].dependent, b.rigid_links[k].dependent);
    EXPECT_EQ(a.rigid_links[k].dofs, b.rigid_links[k].dofs);
  }
  ASSERT_EQ(a.constraints.size(), b.constraints.size());
  for (size_t k = 0; k < a.constraints.size(); ++k) {
    EXPECT_EQ(a.constraints[k].node, b.constraints[k].node);
    EXPECT_EQ(a.constraints[k].dofs, b.constraints[k].dofs);
  }
  // every set of a is in b; b may add its writer's own sets
  auto expect_same_sets = [&](const std::map<std::string, std::vector<int>>& x,
                              const std::map<std::string, std::vector<int>>& y, const char* what) {
    if (tol.writer_sets.empty()) {
      EXPECT_EQ(x, y) << what;
      return;
    }
    for (const auto& [name, members] : x) {
      ASSERT_TRUE(y.count(name)) << what << " " << name;
      EXPECT_EQ(members, y.at(name)) << what << " " << name;
    }
    for (const auto& [name, members] : y)
      EXPECT_TRUE(x.count(name) || name.rfind(tol.writer_sets, 0) == 0) << what << " " << name;
  };
  expect_same_sets(a.node_sets, b.node_sets, "node set");
  expect_same_sets(a.element_sets, b.element_sets, "element set");
}

}  // namespace flexmb::io::testing
