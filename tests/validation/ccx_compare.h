#pragma once
/// \file ccx_compare.h
/// Pieces shared by the tests that compare flexmb's FE elements with
/// CalculiX (fe_calculix_test.cc, fe_wedge_calculix_test.cc,
/// fe_hex20_calculix_test.cc): ccx's matrix storage files, the deck of a
/// mesh with a *FREQUENCY step, a steel material, flexmb's frequencies of
/// an assembled model and the relative differences the tests report.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe_io/abaqus/abaqus_writer.h"

namespace flexmb::testing {

/// Steel of the CalculiX comparisons: E [Pa], nu, rho [kg/m^3].
inline constexpr double kCcxE = 2.1e11, kCcxNu = 0.3, kCcxRho = 7850.0;

/// The whole text of a file ("" if it cannot be read).
inline std::string CcxReadText(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A matrix ccx writes with SOLVER=MATRIXSTORAGE (job.sti, job.mas): one
/// "row column value" line per entry of the upper triangle, 1-based.
inline Eigen::MatrixXd ParseCcxMatrix(const std::filesystem::path& file, int n) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  std::ifstream in(file);
  int i = 0, j = 0;
  double v = 0.0;
  while (in >> i >> j >> v) {
    a(i - 1, j - 1) = v;
    a(j - 1, i - 1) = v;
  }
  return a;
}

/// The deck of `mesh` (io::WriteAbaqus into dir/model.inp) with `type_from`
/// element types renamed to `type_to` (empty: none) and a *FREQUENCY step
/// for `count` modes, or the matrix storage step if count == 0.
inline std::string CcxDeck(const fe::Mesh& mesh, const std::filesystem::path& dir, int count,
                           const std::string& type_from = "", const std::string& type_to = "") {
  io::WriteAbaqus(mesh, (dir / "model.inp").string());
  std::string deck = CcxReadText(dir / "model.inp");
  if (!type_from.empty()) {
    const std::string from = "TYPE=" + type_from + ",", to = "TYPE=" + type_to + ",";
    for (size_t p = deck.find(from); p != std::string::npos; p = deck.find(from, p + to.size()))
      deck.replace(p, from.size(), to);
  }
  if (count > 0)
    deck += "*STEP\n*FREQUENCY\n" + std::to_string(count) + "\n*END STEP\n";
  else
    deck += "*STEP\n*FREQUENCY, SOLVER=MATRIXSTORAGE\n*END STEP\n";
  return deck;
}

/// A mesh holding only the steel material (id 1, "STEEL").
inline fe::Mesh CcxSteelMesh() {
  fe::Mesh m;
  fe::Material mat;
  mat.id = 1;
  mat.name = "STEEL";
  mat.E = kCcxE;
  mat.nu = kCcxNu;
  mat.G = kCcxE / (2.0 * (1.0 + kCcxNu));
  mat.rho = kCcxRho;
  m.materials.push_back(mat);
  return m;
}

/// Adds nodes to a mesh by position: a node at x is merged with an
/// existing one at the same place (to 1e-9 m); returns its index.
struct MeshNodeIndexer {
  fe::Mesh& m;
  std::map<std::array<long, 3>, int> index;
  int operator()(const fe::Vec3& x) {
    const std::array<long, 3> key = {std::lround(x.x() * 1e9), std::lround(x.y() * 1e9), std::lround(x.z() * 1e9)};
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    fe::Node n;
    n.id = static_cast<int>(m.nodes.size()) + 1;
    n.x = x;
    m.nodes.push_back(n);
    index.emplace(key, static_cast<int>(m.nodes.size()) - 1);
    return static_cast<int>(m.nodes.size()) - 1;
  }
};

/// The lowest `count` natural frequencies [Hz] of an assembled model.
inline std::vector<double> FlexmbFrequencies(const fe::AssembledModel& model, int count) {
  fe::ModalOptions o;
  o.count = count;
  const fe::ModalResult r = fe::SolveModes(model, o);
  return std::vector<double>(r.frequencies_hz.data(), r.frequencies_hz.data() + r.frequencies_hz.size());
}

/// max_k |a_k - b_k| / |b_k| (and a failure if the sizes differ).
inline double MaxRelDiff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) d = std::max(d, std::abs(a[k] - b[k]) / std::abs(b[k]));
  return d;
}

/// Largest entry of |a - b| over the largest of |b|.
inline double MatrixRelDiff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// Displacements [m] by node id from the table ccx writes to job.dat for
/// "*NODE PRINT, NSET=set" + "U": after the line "displacements
/// (vx,vy,vz) for set SET", one "id ux uy uz" row per node.
inline std::map<int, fe::Vec3> ParseCcxDisplacements(const std::filesystem::path& dat, const std::string& set) {
  std::istringstream in(CcxReadText(dat));
  std::string line;
  std::map<int, fe::Vec3> u;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.find("displacements (vx,vy,vz) for set " + set) != std::string::npos) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    std::istringstream row(line);
    int id = 0;
    fe::Vec3 v;
    if (row >> id >> v.x() >> v.y() >> v.z()) {
      u[id] = v;
    } else if (!u.empty()) {
      break;
    }
  }
  return u;
}

/// max |a - b| over the nodes of `b` (each must be in `a`), relative to
/// the largest displacement component of `b`.
inline double MaxRelDiffByNode(const std::map<int, fe::Vec3>& a, const std::map<int, fe::Vec3>& b) {
  double d = 0.0, scale = 0.0;
  for (const auto& [id, v] : b) {
    scale = std::max(scale, v.cwiseAbs().maxCoeff());
    d = std::max(d, (a.at(id) - v).cwiseAbs().maxCoeff());
  }
  return d / scale;
}

/// Prints a row of frequencies for the test log.
inline void PrintFrequencies(const char* what, const std::vector<double>& f) {
  std::printf("  %-36s", what);
  for (double v : f) std::printf(" %13.8g", v);
  std::printf("\n");
}

}  // namespace flexmb::testing
