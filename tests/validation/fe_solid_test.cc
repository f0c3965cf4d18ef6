// Solid elements as a free-free beam: a bar of 20 x 2 x 1 (length, width,
// depth in units of the depth h = 0.02 m), nu = 0, meshed with 8-node
// hexahedra (incompatible modes) and with 10-node tetrahedra (six per
// hexahedral cell), natural frequencies through fe::Assemble and
// fe::SolveModes on sequences of meshes. The first two bending modes across
// the depth and the first across the width, picked by the direction that
// carries their kinetic energy, against the Timoshenko beam with Cowper's
// shear coefficient of a rectangle, kappa = 10 (1 + nu) / (12 + 11 nu)
// (= 5/6 at nu = 0; with nu = 0 the section does not deform in its plane,
// as beam theory assumes). Sources: docs/validation.md, "FE: beams and
// solids".

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tests/validation/fe_beam_theory.h"
#include "tests/validation/fe_validation.h"

namespace flexmb::fe::validation {
namespace fe_solid_test {

constexpr double kH = 0.02, kW = 2.0 * kH, kL = 20.0 * kH;  // depth (z), width (y), length (x)
constexpr double kE = 2.1e11, kRho = 7850.0;

// box [0, L] x [-W/2, W/2] x [-H/2, H/2] of nx x ny x nz cubic cells; hex8,
// or tet10 with six tetrahedra per cell around the cell's main diagonal
// (the same in every cell, so faces match) and a node on every edge
Mesh BarMesh(int nz, bool tets) {
  const int nx = 20 * nz, ny = 2 * nz;
  Mesh mesh;
  const int mat = testing::AddMaterial(mesh, kE, 0.0, kRho);
  SolidSection sec;
  sec.material = mat;
  mesh.solid_sections.push_back(sec);
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        testing::AddNode(
            mesh, Vec3(kL * i / nx, kW * (double(j) / ny - 0.5), kH * (double(k) / nz - 0.5)));
  // corner c of a cell: bit 0 along x, bit 1 along y, bit 2 along z
  constexpr int kHexOrder[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  constexpr int kKuhn[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7},
                               {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
  constexpr int kEdge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  std::map<std::pair<int, int>, int> mid;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        int corner[8];
        for (int c = 0; c < 8; ++c)
          corner[c] = id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        if (!tets) {
          std::vector<int> hex;
          for (int c : kHexOrder) hex.push_back(corner[c]);
          testing::AddElement(mesh, ElementType::kHex8, 0, hex);
          continue;
        }
        for (const auto& t : kKuhn) {
          std::vector<int> e = {corner[t[0]], corner[t[1]], corner[t[2]], corner[t[3]]};
          const Vec3& x0 = mesh.nodes[e[0]].x;
          if ((mesh.nodes[e[1]].x - x0)
                  .cross(mesh.nodes[e[2]].x - x0)
                  .dot(mesh.nodes[e[3]].x - x0) < 0.0)
            std::swap(e[1], e[2]);
          for (const auto& edge : kEdge) {
            const int a = e[edge[0]], b = e[edge[1]];
            const std::pair<int, int> key(std::min(a, b), std::max(a, b));
            auto it = mid.find(key);
            if (it == mid.end())
              it = mid.emplace(key,
                               testing::AddNode(mesh, 0.5 * (mesh.nodes[a].x + mesh.nodes[b].x)))
                       .first;
            e.push_back(it->second);
          }
          testing::AddElement(mesh, ElementType::kTet10, 0, e);
        }
      }
  return mesh;
}

// Timoshenko beam of the bar bending across the depth (z) or the width (y)
BeamProperties Beam(bool across_depth) {
  const double d = across_depth ? kH : kW, w = across_depth ? kW : kH;  // bending depth, other side
  const double kappa = 10.0 / 12.0;                                     // Cowper, nu = 0
  BeamProperties p;
  p.EI = kE * w * d * d * d / 12.0;
  p.shear_compliance = 1.0 / (kappa * kE / 2.0 * w * d);
  p.rhoA = kRho * w * d;
  p.rhoI = kRho * w * d * d * d / 12.0;
  p.L = kL;
  return p;
}

// frequencies [Hz] of the first two bending modes across the depth and the
// first across the width
std::array<double, 3> BarBending(int nz, bool tets) {
  const Mesh mesh = BarMesh(nz, tets);
  AssembledModel model;
  const ModalResult r = SolveMeshModes(mesh, 12, MassForm::kConsistent, &model);
  std::vector<double> z, y;
  for (int k = 6; k < r.frequencies_hz.size(); ++k) {
    const Vec3 share = DirectionShares(mesh, model, r.modes.col(k));
    if (share.z() > 0.9) z.push_back(r.frequencies_hz[k]);
    if (share.y() > 0.9) y.push_back(r.frequencies_hz[k]);
  }
  EXPECT_GE(z.size(), 2u);
  EXPECT_GE(y.size(), 1u);
  z.resize(2, 0.0);
  y.resize(1, 0.0);
  return {z[0], z[1], y[0]};
}

void CheckBar(const char* name, bool tets, const std::vector<int>& meshes, double min_ratio) {
  std::vector<std::array<double, 3>> f;
  for (int nz : meshes) f.push_back(BarBending(nz, tets));
  const double ref[3] = {TimoshenkoOmega(Beam(true), BeamSupport::kFreeFree, 1) / (2 * kPi),
                         TimoshenkoOmega(Beam(true), BeamSupport::kFreeFree, 2) / (2 * kPi),
                         TimoshenkoOmega(Beam(false), BeamSupport::kFreeFree, 1) / (2 * kPi)};
  const char* label[3] = {" depth mode 1", " depth mode 2", " width mode 1"};
  // model error of the Timoshenko beam against 3D elasticity: it captures
  // the O((beta d)^2) correction to Euler-Bernoulli exactly, what remains is
  // of the next order, bounded here by that correction times (beta d)^2
  // (beta = beta_n / L from the Euler-Bernoulli eigenvalue, d the bending depth)
  const double beta_d[3] = {kFreeFreeBetaL[0] * kH / kL, kFreeFreeBetaL[1] * kH / kL,
                            kFreeFreeBetaL[0] * kW / kL};
  const BeamProperties beam[3] = {Beam(true), Beam(true), Beam(false)};
  const int mode[3] = {1, 2, 1};
  for (int k = 0; k < 3; ++k) {
    BeamProperties eb = beam[k];
    eb.shear_compliance = 0.0;
    eb.rhoI = 0.0;
    const double correction =
        1.0 - ref[k] * 2 * kPi / TimoshenkoOmega(eb, BeamSupport::kFreeFree, mode[k]);
    const double model_error = correction * beta_d[k] * beta_d[k];
    Convergence c{std::string(name) + label[k], {}, {}, ref[k]};
    for (size_t m = 0; m < meshes.size(); ++m) {
      c.meshes.push_back(20 * meshes[m]);
      c.values.push_back(f[m][k]);
    }
    c.Report();
    std::printf(
        "    reference Timoshenko %.3f Hz (Euler-Bernoulli higher by %.4f, model error bound "
        "%.5f)\n",
        ref[k], correction, model_error);
    c.ExpectErrorFallsBy(min_ratio);
    c.ExpectFinestWithinLastChange(model_error);
  }
}

// trilinear hexahedra (incompatible modes): frequency error O(h^2); we ask
// for at least O(h) per halving
TEST(FeSolidValidation, Hex8FreeFreeBar) { CheckBar("hex8 bar", false, {1, 2, 4}, 2.0); }

// quadratic tetrahedra: frequency error O(h^4); we ask for at least O(h^3)
TEST(FeSolidValidation, Tet10FreeFreeBar) { CheckBar("tet10 bar", true, {1, 2}, 8.0); }

}  // namespace fe_solid_test
}  // namespace flexmb::fe::validation
