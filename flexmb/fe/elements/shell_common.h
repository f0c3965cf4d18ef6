#pragma once
/// \file shell_common.h
/// Pieces shared by the 3- and 4-node shells: input checks, the element's
/// local (mean-plane) frame, the membrane and plate material matrices, the
/// strain-displacement rows both elements build from shape functions
/// (membrane, curvature, covariant transverse shear, drilling), the scatter
/// of per-node sub-blocks into the 6-DOF element matrix, the lumped mass,
/// the transformation of local matrices to the basic frame, which carries
/// the warping projection and the normal offset as rigid links, and the
/// surface stress recovery.
/// Formulation notes: docs/design.md, "FE: shell elements".

#include <Eigen/Core>
#include <optional>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/elements/element_common.h"

namespace flexmb::fe::shell {

/// Drilling penalty (Hughes-Brezzi type): with omega = (dv/dx - du/dy) / 2
/// the in-plane rotation of the membrane, the drilling strain energy is
/// G t [alpha A (theta_z - omega)^2 at the centroid
///      + beta int (theta_z - omega)^2 dA with the full rule].
/// alpha ties the rotation to the membrane (one point: no in-plane locking);
/// beta only stabilizes the remaining drilling modes. alpha = 1 is Hughes and
/// Brezzi's gamma = G; the twisted beam of tests/validation/fe_shell_test.cc
/// needs it: with alpha = 1e-2 (1e-4) its tip deflections come out 2.4-3.0 %
/// (24-30 %) larger on every mesh, because the normal rotation of one facet
/// is a bending rotation of its twisted neighbour (docs/validation.md).
inline constexpr double kDrillingFactor = 1.0;
/// beta above.
inline constexpr double kDrillingStabilization = 1e-3;
/// Transverse shear correction factor of the Mindlin plate.
inline constexpr double kShearFactor = 5.0 / 6.0;
/// Largest accepted warping: |h| / sqrt(projected area), h the distance of
/// the corner nodes from the mean plane.
inline constexpr double kMaxWarpRatio = 0.1;

/// Local components that the plate part acts on: w, rx, ry.
inline constexpr int kPlateDofs[3] = {2, 3, 4};
/// Local components of the drilling part: u, v, rz.
inline constexpr int kDrillingDofs[3] = {0, 1, 5};
/// Local components of the membrane: u, v.
inline constexpr int kMembraneDofs[2] = {0, 1};

/// Material and section values of a shell, checked.
struct ShellData {
  double E = 0.0, nu = 0.0, G = 0.0;  ///< [Pa]
  double rho = 0.0;                   ///< [kg/m^3]
  double t = 0.0;                     ///< thickness [m]
  double nsm = 0.0;                   ///< non-structural mass [kg/m^2]
  double offset = 0.0;                ///< mid-surface offset along the normal [m]
  /// A laminated section in the element's local axes (e1 along the G1-G2
  /// edge): its A, D, S and mass replace those of E, nu, G, rho, t.
  std::optional<ShellLaminate> laminate;
};

/// Checks element, section and material of a shell with `n_nodes` nodes and
/// returns the values; throws InputError naming the element otherwise.
ShellData CheckShellInput(const ElementInput& in, int n_nodes);

/// Section constants both shells integrate with.
struct SectionConstants {
  Eigen::Matrix3d membrane;       ///< MembraneMatrix [N/m]
  Eigen::Matrix3d bending;        ///< BendingMatrix [N m]
  Eigen::Matrix3d coupling = Eigen::Matrix3d::Zero();  ///< membrane-bending B of a laminate [N]
  Eigen::Matrix2d shear;          ///< kShearFactor G t I, or a laminate's S [N/m]
  double drilling_tie = 0.0;      ///< kDrillingFactor G t (a laminate: A66) [N/m]
  double drilling_stabilization = 0.0;  ///< kDrillingStabilization G t (a laminate: A66) [N/m]
  double m0 = 0.0;                ///< translational mass rho t + nsm [kg/m^2]
  double m2 = 0.0;                ///< rotary inertia rho t^3 / 12 (a laminate: sum rho z^2 dz) [kg]
};

/// The constants of a checked section.
SectionConstants Constants(const ShellData& s);

/// Longest edge [m] of the closed polygon x[0..n-1]; throws InputError
/// "coincident nodes" (with `ctx`) if the shortest edge is below 1e-8 times
/// the longest.
double LongestEdge(const Vec3* x, int n, const ErrorContext& ctx);

/// Rotation basic-from-local with the columns e1, e3 x e1, e3 (e1 a unit
/// vector in the element plane, e3 the unit normal).
Eigen::Matrix3d FrameAxes(const Vec3& e1, const Vec3& e3);

/// Local frame of a (flat or slightly warped) shell: axes e1, e2 in the mean
/// plane and the normal e3 as columns of R (basic from local); the corner
/// nodes projected on the mean plane in local in-plane coordinates; and per
/// node the vector d from the node to its mid-surface point (projection plus
/// offset along the normal), basic frame.
template <int N>
struct LocalFrame {
  Eigen::Matrix3d R;
  Eigen::Matrix<double, N, 2> xy;
  Eigen::Matrix<double, 3, N> d;
};

/// The local frame of a 4-node element (shell, shear panel): e3 along (x3 -
/// x1) x (x4 - x2), e1 the edge from node 1 to node 2 projected on the mean
/// plane through the centroid, the nodes projected on that plane, and d the
/// vector to each node's mid-surface point at `offset` along e3. Throws
/// InputError naming the element for coincident nodes, zero area, a corner
/// farther than kMaxWarpRatio sqrt(area) off the mean plane, or a
/// non-convex or negatively ordered quad.
LocalFrame<4> QuadFrame(const ElementInput& in, double offset);

/// Plane-stress membrane stiffness A = E t / (1 - nu^2) [...] [N/m]
/// (a laminate: its A).
Eigen::Matrix3d MembraneMatrix(const ShellData& s);
/// Plate bending stiffness D = E t^3 / (12 (1 - nu^2)) [...] [N m] (a
/// laminate: its D).
Eigen::Matrix3d BendingMatrix(const ShellData& s);

/// Membrane strains (eps_xx, eps_yy, gamma_xy) over (u_i, v_i), node by
/// node, from the cartesian derivatives `dx` of the shape functions (rows
/// d/dx, d/dy) [1/m].
template <int N>
Eigen::Matrix<double, 3, 2 * N> MembraneStrain(const Eigen::Matrix<double, 2, N>& dx) {
  Eigen::Matrix<double, 3, 2 * N> b = Eigen::Matrix<double, 3, 2 * N>::Zero();
  for (int i = 0; i < N; ++i) {
    b(0, 2 * i) = dx(0, i);
    b(1, 2 * i + 1) = dx(1, i);
    b(2, 2 * i) = dx(1, i);
    b(2, 2 * i + 1) = dx(0, i);
  }
  return b;
}

/// Plate curvatures (k_xx, k_yy, 2 k_xy) of the section rotations
/// beta_x = ry, beta_y = -rx over (w_i, rx_i, ry_i), node by node [1/m].
template <int N>
Eigen::Matrix<double, 3, 3 * N> BendingStrain(const Eigen::Matrix<double, 2, N>& dx) {
  Eigen::Matrix<double, 3, 3 * N> b = Eigen::Matrix<double, 3, 3 * N>::Zero();
  for (int i = 0; i < N; ++i) {
    b(0, 3 * i + 2) = dx(0, i);
    b(1, 3 * i + 1) = -dx(1, i);
    b(2, 3 * i + 1) = -dx(0, i);
    b(2, 3 * i + 2) = dx(1, i);
  }
  return b;
}

/// Covariant transverse shear e = dw/ds + beta . dx/ds along the natural
/// direction `dir` (0 or 1) at a point with shape functions `n`, natural
/// derivatives `dn` (rows d/dxi, d/deta) and Jacobian `j` (rows dx/dxi,
/// dx/deta), over (w_i, rx_i, ry_i); beta_x = ry, beta_y = -rx. The MITC
/// elements tie it at their tying points.
template <int N>
Eigen::Matrix<double, 1, 3 * N> CovariantShear(const Eigen::Matrix<double, N, 1>& n,
                                               const Eigen::Matrix<double, 2, N>& dn,
                                               const Eigen::Matrix2d& j, int dir) {
  Eigen::Matrix<double, 1, 3 * N> row;
  for (int i = 0; i < N; ++i) {
    row(3 * i) = dn(dir, i);
    row(3 * i + 1) = -n(i) * j(dir, 1);
    row(3 * i + 2) = n(i) * j(dir, 0);
  }
  return row;
}

/// theta_z - omega, omega = (dv/dx - du/dy) / 2 the membrane's in-plane
/// rotation and theta_z interpolated with `n`, over (u_i, v_i, rz_i).
template <int N>
Eigen::Matrix<double, 1, 3 * N> DrillingStrain(const Eigen::Matrix<double, 2, N>& dx,
                                               const Eigen::Matrix<double, N, 1>& n) {
  Eigen::Matrix<double, 1, 3 * N> row;
  for (int i = 0; i < N; ++i) {
    row(3 * i) = 0.5 * dx(1, i);
    row(3 * i + 1) = -0.5 * dx(0, i);
    row(3 * i + 2) = n(i);
  }
  return row;
}

/// Adds `scale * sub` to the 6N x 6N local element matrix `out`, where `sub`
/// is ordered node by node over the C local components `comps` (e.g.
/// kPlateDofs).
template <int N, int C>
void AddNodal(const Eigen::Matrix<double, C * N, C * N>& sub, const int (&comps)[C], double scale,
              Eigen::Matrix<double, 6 * N, 6 * N>& out) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int a = 0; a < C; ++a)
        for (int b = 0; b < C; ++b)
          out(6 * i + comps[a], 6 * j + comps[b]) += scale * sub(C * i + a, C * j + b);
}

/// Adds `sub` (C1 N x C2 N, node by node over the local components `rows`
/// and `cols`) and its transpose to the 6N x 6N local element matrix `out`:
/// a symmetric coupling block (membrane-bending of a laminate).
template <int N, int C1, int C2>
void AddCoupling(const Eigen::Matrix<double, C1 * N, C2 * N>& sub, const int (&rows)[C1], const int (&cols)[C2],
                 Eigen::Matrix<double, 6 * N, 6 * N>& out) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int a = 0; a < C1; ++a)
        for (int b = 0; b < C2; ++b) {
          out(6 * i + rows[a], 6 * j + cols[b]) += sub(C1 * i + a, C2 * j + b);
          out(6 * j + cols[b], 6 * i + rows[a]) += sub(C1 * i + a, C2 * j + b);
        }
}

/// Adds the consistent translational (m0 = rho t + nsm [kg/m^2]) and
/// bending-rotation (m2 = rho t^3 / 12 [kg]) mass from `nn` = int N N^T dA.
template <int N>
void AddTranslationalAndRotaryMass(const Eigen::Matrix<double, N, N>& nn, double m0, double m2,
                                   Eigen::Matrix<double, 6 * N, 6 * N>& out) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      for (int a = 0; a < 3; ++a) out(6 * i + a, 6 * j + a) += m0 * nn(i, j);
      for (int a = 3; a < 5; ++a) out(6 * i + a, 6 * j + a) += m2 * nn(i, j);
    }
}

/// Diagonal lumped mass: per node its area share int N_i dA [m^2] times m0
/// on the translations, times m2 on the two bending rotations and times md
/// (the drilling inertia, shell_drilling.h) on rz.
template <int N>
Eigen::Matrix<double, 6 * N, 6 * N> LumpedMass(const Eigen::Matrix<double, N, 1>& share, double m0,
                                               double m2, double md) {
  Eigen::Matrix<double, 6 * N, 6 * N> m = Eigen::Matrix<double, 6 * N, 6 * N>::Zero();
  for (int i = 0; i < N; ++i) {
    for (int a = 0; a < 3; ++a) m(6 * i + a, 6 * i + a) = m0 * share(i);
    for (int a = 3; a < 5; ++a) m(6 * i + a, 6 * i + a) = m2 * share(i);
    m(6 * i + 5, 6 * i + 5) = md * share(i);
  }
  return m;
}

/// The map T from the element's nodal DOF (basic frame, at the nodes, node
/// by node ux uy uz rx ry rz) to its local DOF (u v w rx ry rz in the local
/// frame, at the mid-surface points): u_mid = R^T (u + theta x d),
/// theta_local = R^T theta; 6N x 6N.
template <int N>
Eigen::Matrix<double, 6 * N, 6 * N> LocalTransform(const LocalFrame<N>& frame);

/// Transforms a local element matrix (node by node u v w rx ry rz in the
/// local frame, at the mid-surface points) to the basic frame at the nodes:
/// out = T^T local T with T = LocalTransform(frame), symmetrized. Result in
/// `out` (resized).
template <int N>
void ToBasic(const LocalFrame<N>& frame, const Eigen::Matrix<double, 6 * N, 6 * N>& local,
             MatX& out);

/// Membrane stress resultants (Nxx, Nyy, Nxy) [N/m] in the local frame at a
/// point with shape function derivatives `dx` (rows d/dx, d/dy, local) for
/// the element's nodal DOF `u` (6N, basic frame, as K): MembraneMatrix times
/// the membrane strains of the mid-surface displacements (LocalTransform),
/// plus a laminate's B times the curvatures.
template <int N>
Eigen::Vector3d MembraneResultants(const LocalFrame<N>& frame, const ShellData& s,
                                   const Eigen::Matrix<double, 2, N>& dx,
                                   const Eigen::Matrix<double, 6 * N, 1>& u) {
  const Eigen::Matrix<double, 6 * N, 1> ul = LocalTransform<N>(frame) * u;
  Eigen::Matrix<double, 2 * N, 1> um;
  Eigen::Matrix<double, 3 * N, 1> ub;
  for (int i = 0; i < N; ++i) {
    um(2 * i) = ul(6 * i);
    um(2 * i + 1) = ul(6 * i + 1);
    for (int a = 0; a < 3; ++a) ub(3 * i + a) = ul(6 * i + kPlateDofs[a]);
  }
  Eigen::Vector3d n = MembraneMatrix(s) * (MembraneStrain<N>(dx) * um);
  if (s.laminate) n += s.laminate->B * (BendingStrain<N>(dx) * ub);  // N = A eps0 + B kappa
  return n;
}

/// Adds the membrane initial-stress (geometric) stiffness of one
/// integration point to the local element matrix `out`: on each of the local
/// translations u, v, w of nodes i and j, weight dN_i^T [Nxx Nxy; Nxy Nyy]
/// dN_j, the second variation of the membrane forces' work on the
/// Green-Lagrange membrane strains (grad u_a . grad u_a / 2 for a = u, v,
/// w); `dx` the shape function derivatives (rows d/dx, d/dy), `nres` the
/// resultants (Nxx, Nyy, Nxy) [N/m], `weight` the area weight [m^2].
template <int N>
void AddMembranePrestress(const Eigen::Matrix<double, 2, N>& dx, const Eigen::Vector3d& nres,
                          double weight, Eigen::Matrix<double, 6 * N, 6 * N>& out) {
  Eigen::Matrix2d t;
  t << nres(0), nres(2), nres(2), nres(1);
  const Eigen::Matrix<double, N, N> g = dx.transpose() * t * dx * weight;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int a = 0; a < 3; ++a) out(6 * i + a, 6 * j + a) += g(i, j);
}

/// Plane-stress elasticity E / (1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu) / 2]
/// [Pa], (sxx, syy, sxy) = C (eps_xx, eps_yy, gamma_xy).
Eigen::Matrix3d PlaneStressMatrix(const ShellData& s);

/// Stress recovery at one in-plane point of a shell whose shape function
/// derivatives there are `dx` (rows d/dx, d/dy in the local frame): the
/// 6 x 6N matrix from the element's nodal DOF (basic frame, as K) to the
/// in-plane stresses (sxx, syy, sxy) [Pa] in the local frame at the bottom
/// (rows 0-2, z = -t/2) and top (rows 3-5, z = +t/2) surfaces, z measured
/// from the (offset) mid-surface along e3: sigma(z) = C (eps0 + z kappa)
/// with the membrane strains eps0 (MembraneStrain) and the curvatures kappa
/// (BendingStrain) of the stiffness, C = PlaneStressMatrix. The membrane
/// stress is the mean of the two surfaces, the bending stress half their
/// difference. A laminate: the stresses of its bottom and top plies at its
/// outer surfaces (z_bottom, z_top), in the element's local axes.
template <int N>
Eigen::Matrix<double, 6, 6 * N> SurfaceStress(const LocalFrame<N>& frame, const ShellData& s,
                                              const Eigen::Matrix<double, 2, N>& dx);

}  // namespace flexmb::fe::shell
