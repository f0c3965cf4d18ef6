// Shell elements against the MacNeal-Harder / Belytschko obstacle course
// (Scordelis-Lo roof, pinched cylinder, pinched hemisphere, twisted beam)
// and plate frequencies (simply supported square plate, Leissa; cantilever
// strip, Euler-Bernoulli), each on a sequence of meshes. The small static
// and eigen problems are assembled and solved here (Eigen sparse LDL^T and
// inverse iteration) so the check depends on the element routines only.
// Reference values and sources: docs/validation.md, "FE: shells".

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "flexmb/fe/elements/shell_quad4.h"
#include "flexmb/fe/elements/shell_tria3.h"

namespace flexmb::fe {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A structured shell mesh on a parametric patch, with its constraints.
struct ShellModel {
  std::vector<Vec3> x;
  std::vector<std::vector<int>> elements;  // 4 nodes: quad, 3 nodes: tria
  double t = 0.0, E = 0.0, nu = 0.0, rho = 0.0;
  MassForm mass_form = MassForm::kConsistent;
  std::vector<bool> fixed;  // 6 per node
  int nu_nodes = 0, nv_nodes = 0;

  // nodes x(u, v) for u, v in [0, 1] on an nu x nv grid of quads (or each
  // quad split along its diagonal into two triangles)
  ShellModel(int nu_el, int nv_el, const std::function<Vec3(double, double)>& geometry,
             bool triangles = false)
      : nu_nodes(nu_el + 1), nv_nodes(nv_el + 1) {
    for (int j = 0; j <= nv_el; ++j)
      for (int i = 0; i <= nu_el; ++i) x.push_back(geometry(double(i) / nu_el, double(j) / nv_el));
    for (int j = 0; j < nv_el; ++j)
      for (int i = 0; i < nu_el; ++i) {
        const int a = Node(i, j), b = Node(i + 1, j), c = Node(i + 1, j + 1), d = Node(i, j + 1);
        if (triangles) {
          elements.push_back({a, b, c});
          elements.push_back({a, c, d});
        } else {
          elements.push_back({a, b, c, d});
        }
      }
    fixed.assign(6 * x.size(), false);
  }
  int Node(int i, int j) const { return j * nu_nodes + i; }
  // fixes the components (0..5) of all nodes satisfying pred(i, j)
  void Fix(const std::function<bool(int, int)>& pred, std::initializer_list<int> comps) {
    for (int j = 0; j < nv_nodes; ++j)
      for (int i = 0; i < nu_nodes; ++i)
        if (pred(i, j))
          for (int c : comps) fixed[6 * Node(i, j) + c] = true;
  }

  // free dof numbering and sparse K, M over the free dof
  std::vector<int> map;
  int n_free = 0;
  Eigen::SparseMatrix<double> K, M;
  void Assemble() {
    map.assign(fixed.size(), -1);
    n_free = 0;
    for (size_t k = 0; k < fixed.size(); ++k)
      if (!fixed[k]) map[k] = n_free++;
    Material mat;
    mat.E = E;
    mat.nu = nu;
    mat.rho = rho;
    ShellSection sec;
    sec.thickness = t;
    std::vector<Eigen::Triplet<double>> tk, tm;
    Element el;
    for (size_t e = 0; e < elements.size(); ++e) {
      const auto& conn = elements[e];
      el.id = static_cast<int>(e) + 1;
      el.type = conn.size() == 4 ? ElementType::kQuad4 : ElementType::kTria3;
      el.nodes = conn;
      Vec3 xe[4];
      for (size_t a = 0; a < conn.size(); ++a) xe[a] = x[conn[a]];
      ElementInput in;
      in.element = &el;
      in.x = xe;
      in.material = &mat;
      in.shell = &sec;
      in.mass_form = mass_form;
      MatX ke, me;
      if (conn.size() == 4)
        ShellQuad4Matrices(in, ke, me);
      else
        ShellTria3Matrices(in, ke, me);
      for (size_t a = 0; a < conn.size(); ++a)
        for (int p = 0; p < 6; ++p) {
          const int r = map[6 * conn[a] + p];
          if (r < 0) continue;
          for (size_t b = 0; b < conn.size(); ++b)
            for (int q = 0; q < 6; ++q) {
              const int c = map[6 * conn[b] + q];
              if (c < 0) continue;
              tk.emplace_back(r, c, ke(6 * a + p, 6 * b + q));
              tm.emplace_back(r, c, me(6 * a + p, 6 * b + q));
            }
        }
    }
    K.resize(n_free, n_free);
    M.resize(n_free, n_free);
    K.setFromTriplets(tk.begin(), tk.end());
    M.setFromTriplets(tm.begin(), tm.end());
  }

  // static solution for full-size load f (6 per node); returns full u
  Eigen::VectorXd Solve(const Eigen::VectorXd& f) {
    Assemble();
    Eigen::VectorXd fr = Eigen::VectorXd::Zero(n_free);
    for (size_t k = 0; k < fixed.size(); ++k)
      if (map[k] >= 0) fr(map[k]) = f(k);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
    EXPECT_EQ(ldlt.info(), Eigen::Success);
    const Eigen::VectorXd ur = ldlt.solve(fr);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(fixed.size());
    for (size_t k = 0; k < fixed.size(); ++k)
      if (map[k] >= 0) u(k) = ur(map[k]);
    return u;
  }

  // lowest circular frequency [rad/s] by inverse iteration from a random start
  double LowestOmega() {
    Assemble();
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
    EXPECT_EQ(ldlt.info(), Eigen::Success);
    std::srand(3);
    Eigen::VectorXd v = Eigen::VectorXd::Random(n_free);
    double lambda = 0.0;
    for (int it = 0; it < 200; ++it) {
      v = ldlt.solve(M * v);
      v /= std::sqrt(v.dot(M * v));
      const double next = v.dot(K * v);
      if (it > 10 && std::abs(next - lambda) < 1e-13 * next) break;
      lambda = next;
    }
    return std::sqrt(lambda);
  }

  // consistent nodal loads of a pressure q (per area) in direction dir
  Eigen::VectorXd SurfaceLoad(const Vec3& q) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(fixed.size());
    const double g = 1.0 / std::sqrt(3.0);
    const double xi[4] = {-g, g, g, -g}, eta[4] = {-g, -g, g, g};
    for (const auto& conn : elements) {
      const Vec3 &a = x[conn[0]], &b = x[conn[1]], &c = x[conn[2]], &d = x[conn[3]];
      for (int k = 0; k < 4; ++k) {
        const double n[4] = {0.25 * (1 - xi[k]) * (1 - eta[k]), 0.25 * (1 + xi[k]) * (1 - eta[k]),
                             0.25 * (1 + xi[k]) * (1 + eta[k]), 0.25 * (1 - xi[k]) * (1 + eta[k])};
        const Vec3 dxi = 0.25 * ((b - a) * (1 - eta[k]) + (c - d) * (1 + eta[k]));
        const Vec3 deta = 0.25 * ((d - a) * (1 - xi[k]) + (c - b) * (1 + xi[k]));
        const double da = dxi.cross(deta).norm();
        for (int p = 0; p < 4; ++p) f.segment<3>(6 * conn[p]) += n[p] * da * q;
      }
    }
    return f;
  }
};

void Report(const char* name, int n, double value, double ref) {
  std::printf("  %-28s mesh %3d: %.6g (normalized %.4f)\n", name, n, value, value / ref);
}

// Scordelis-Lo roof, quarter model: x along the axis (0 = midspan, L/2 =
// diaphragm), angle from the crown 0..40 degrees; gravity 90 per area.
double ScordelisLo(int n) {
  const double R = 25.0, L = 50.0, phi0 = 40.0 * kPi / 180.0;
  ShellModel m(n, n, [&](double u, double v) {
    const double phi = v * phi0;
    return Vec3(u * L / 2.0, R * std::sin(phi), R * std::cos(phi));
  });
  m.t = 0.25;
  m.E = 4.32e8;
  m.nu = 0.0;
  m.Fix([&](int i, int) { return i == n; }, {1, 2});        // diaphragm
  m.Fix([&](int i, int) { return i == 0; }, {0, 4, 5});     // symmetry x = 0
  m.Fix([&](int, int j) { return j == 0; }, {1, 3, 5});     // symmetry y = 0
  const Eigen::VectorXd u = m.Solve(m.SurfaceLoad(Vec3(0.0, 0.0, -90.0)));
  return -u(6 * m.Node(0, n) + 2);
}

// Pinched cylinder with end diaphragms, octant: x 0 (midspan) .. L/2,
// angle from the top 0..90 degrees; load P / 4 at the top of midspan.
double PinchedCylinder(int n) {
  const double R = 300.0, L = 600.0;
  ShellModel m(n, n, [&](double u, double v) {
    const double phi = v * kPi / 2.0;
    return Vec3(u * L / 2.0, R * std::sin(phi), R * std::cos(phi));
  });
  m.t = 3.0;
  m.E = 3e6;
  m.nu = 0.3;
  m.Fix([&](int i, int) { return i == n; }, {1, 2});
  m.Fix([&](int i, int) { return i == 0; }, {0, 4, 5});
  m.Fix([&](int, int j) { return j == 0; }, {1, 3, 5});
  m.Fix([&](int, int j) { return j == n; }, {2, 3, 4});
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * m.x.size());
  f(6 * m.Node(0, 0) + 2) = -0.25;
  const Eigen::VectorXd u = m.Solve(f);
  return -u(6 * m.Node(0, 0) + 2);
}

// Hemisphere with an 18 degree hole, quarter model; unit loads (half of the
// full model's 2) outward along x at (R, 0, 0) and inward along y at (0, R, 0).
double Hemisphere(int n) {
  const double R = 10.0, hole = 18.0 * kPi / 180.0;
  ShellModel m(n, n, [&](double u, double v) {
    const double theta = kPi / 2.0 - v * (kPi / 2.0 - hole);  // from the pole
    const double psi = u * kPi / 2.0;
    return Vec3(R * std::sin(theta) * std::cos(psi), R * std::sin(theta) * std::sin(psi),
                R * std::cos(theta));
  });
  m.t = 0.04;
  m.E = 6.825e7;
  m.nu = 0.3;
  m.Fix([&](int i, int) { return i == 0; }, {1, 3, 5});  // y = 0 plane
  m.Fix([&](int i, int) { return i == n; }, {0, 4, 5});  // x = 0 plane
  m.Fix([&](int i, int j) { return i == 0 && j == 0; }, {2});
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * m.x.size());
  f(6 * m.Node(0, 0) + 0) = 1.0;
  f(6 * m.Node(n, 0) + 1) = -1.0;
  const Eigen::VectorXd u = m.Solve(f);
  return u(6 * m.Node(0, 0) + 0);
}

// Twisted beam, clamped at x = 0, 90 degree twist, unit tip load along the
// tip's width (in-plane) or its normal (out-of-plane) spread along the tip
// edge; displacement of the tip centre in the load direction.
double TwistedBeam(int nl, int nw, bool in_plane) {
  const double L = 12.0, w = 1.1;
  ShellModel m(nl, nw, [&](double u, double v) {
    const double phi = u * kPi / 2.0, s = (v - 0.5) * w;
    return Vec3(u * L, s * std::cos(phi), s * std::sin(phi));
  });
  m.t = 0.32;
  m.E = 29e6;
  m.nu = 0.22;
  m.Fix([&](int i, int) { return i == 0; }, {0, 1, 2, 3, 4, 5});
  const Vec3 dir = in_plane ? Vec3(0.0, 0.0, 1.0) : Vec3(0.0, 1.0, 0.0);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * m.x.size());
  for (int j = 0; j <= nw; ++j)
    f.segment<3>(6 * m.Node(nl, j)) = dir * ((j == 0 || j == nw) ? 0.5 : 1.0) / nw;
  const Eigen::VectorXd u = m.Solve(f);
  return dir.dot(u.segment<3>(6 * m.Node(nl, nw / 2)));
}

TEST(FeShellValidation, ScordelisLoRoof) {
  const double ref = 0.3024;
  std::vector<double> r;
  for (int n : {4, 8, 16}) {
    r.push_back(ScordelisLo(n));
    Report("Scordelis-Lo roof", n, r.back(), ref);
  }
  EXPECT_NEAR(r[2] / ref, 1.0, 0.02);
  EXPECT_LT(std::abs(r[2] / ref - 1.0), std::abs(r[0] / ref - 1.0));
}

TEST(FeShellValidation, PinchedCylinder) {
  const double ref = 1.8248e-5;
  std::vector<double> r;
  for (int n : {4, 8, 16, 32}) {
    r.push_back(PinchedCylinder(n));
    Report("pinched cylinder", n, r.back(), ref);
  }
  for (size_t k = 1; k < r.size(); ++k) EXPECT_GT(r[k], r[k - 1]);
  EXPECT_NEAR(r.back() / ref, 1.0, 0.03);
}

TEST(FeShellValidation, PinchedHemisphere) {
  const double ref = 0.094;
  std::vector<double> r;
  for (int n : {4, 8, 16}) {
    r.push_back(Hemisphere(n));
    Report("pinched hemisphere", n, r.back(), ref);
  }
  EXPECT_NEAR(r.back() / ref, 1.0, 0.03);
}

TEST(FeShellValidation, TwistedBeam) {
  const double ref_in = 0.005424, ref_out = 0.001754;
  std::vector<double> in, out;
  for (int k : {1, 2, 4}) {
    in.push_back(TwistedBeam(12 * k, 2 * k, true));
    out.push_back(TwistedBeam(12 * k, 2 * k, false));
    Report("twisted beam in-plane", 12 * k, in.back(), ref_in);
    Report("twisted beam out-of-plane", 12 * k, out.back(), ref_out);
  }
  EXPECT_NEAR(in.back() / ref_in, 1.0, 0.02);
  EXPECT_NEAR(out.back() / ref_out, 1.0, 0.02);
}

// simply supported square plate (hard support: w and the tangential
// rotation fixed on the edges), lowest frequency against the thin-plate
// value omega_11 = 2 pi^2 / a^2 sqrt(D / (rho t)) (Leissa 1969)
double PlateOmega(int n, bool triangles, MassForm form) {
  const double a = 1.0;
  ShellModel m(n, n, [&](double u, double v) { return Vec3(u * a, v * a, 0.0); }, triangles);
  m.t = 0.01;
  m.E = 2e11;
  m.nu = 0.3;
  m.rho = 7850.0;
  m.mass_form = form;
  m.Fix([&](int i, int) { return i == 0 || i == n; }, {2, 3});
  m.Fix([&](int, int j) { return j == 0 || j == n; }, {2, 4});
  m.Fix([&](int i, int j) { return i == 0 && j == 0; }, {0, 1});
  m.Fix([&](int i, int j) { return i == n && j == 0; }, {1});
  return m.LowestOmega();
}

TEST(FeShellValidation, SimplySupportedPlateFrequency) {
  const double t = 0.01, D = 2e11 * t * t * t / (12.0 * (1.0 - 0.09));
  const double ref = 2.0 * kPi * kPi * std::sqrt(D / (7850.0 * t));
  std::vector<double> q;
  for (int n : {4, 8, 16}) {
    q.push_back(PlateOmega(n, false, MassForm::kConsistent));
    Report("SS plate quad4", n, q.back(), ref);
  }
  EXPECT_NEAR(q.back() / ref, 1.0, 0.005);
  for (size_t k = 1; k < q.size(); ++k)
    EXPECT_LT(std::abs(q[k] / ref - 1.0), std::abs(q[k - 1] / ref - 1.0));
  const double lumped = PlateOmega(16, false, MassForm::kLumped);
  Report("SS plate quad4 lumped", 16, lumped, ref);
  EXPECT_NEAR(lumped / ref, 1.0, 0.01);
  std::vector<double> tri;
  for (int n : {4, 8, 16}) {
    tri.push_back(PlateOmega(n, true, MassForm::kConsistent));
    Report("SS plate tria3", n, tri.back(), ref);
  }
  EXPECT_NEAR(tri.back() / ref, 1.0, 0.02);
}

// cantilever strip (nu = 0), first bending frequency against Euler-Bernoulli
// omega_1 = 1.8751^2 sqrt(E I / (rho A L^4))
double StripOmega(int nl, int nw, bool triangles) {
  ShellModel m(nl, nw, [&](double u, double v) { return Vec3(u * 1.0, v * 0.1, 0.0); }, triangles);
  m.t = 0.01;
  m.E = 2e11;
  m.nu = 0.0;
  m.rho = 7850.0;
  m.Fix([&](int i, int) { return i == 0; }, {0, 1, 2, 3, 4, 5});
  return m.LowestOmega();
}

TEST(FeShellValidation, CantileverStripFrequency) {
  const double b = 0.1, t = 0.01, beta = 1.875104068711961;
  const double ref = beta * beta * std::sqrt(2e11 * b * t * t * t / 12.0 / (7850.0 * b * t));
  std::vector<double> q;
  for (int k : {1, 2, 4}) {
    q.push_back(StripOmega(8 * k, k, false));
    Report("cantilever strip quad4", 8 * k, q.back(), ref);
  }
  EXPECT_NEAR(q.back() / ref, 1.0, 0.005);
  const double tri = StripOmega(32, 4, true);
  Report("cantilever strip tria3", 32, tri, ref);
  EXPECT_NEAR(tri / ref, 1.0, 0.01);
}

}  // namespace
}  // namespace flexmb::fe
