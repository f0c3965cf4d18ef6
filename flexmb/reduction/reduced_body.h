#pragma once
/// \file reduced_body.h
/// A flexible body reduced by Craig-Bampton: everything the multibody engine
/// needs to simulate it by the floating frame of reference (THEORY sections
/// 3 to 5) and everything needed to display it and recover its stresses.
/// The body frame is the FE model's basic frame; lengths, masses and times
/// are in the FE model's units (recorded in `units`), SI for flexmb's own
/// models.

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "flexmb/fe/mesh.h"

namespace flexmb::reduction {

using MatX = Eigen::MatrixXd;
using VecX = Eigen::VectorXd;
using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;

/// Inertia invariants: the coefficients of the mass matrix M(w) of THEORY
/// section 4, for n modal coordinates w. With L_k(w) = L0_k + sum_i w_i L1_k,i
/// (only the omega columns of L depend on w), every block is
///
///   M_vv          = mvv
///   M_vo(w)       = mvo0 + sum_i w_i mvo1[i]
///   M_vw          = mvw
///   M_oo(w)       = moo0 + sum_i w_i moo1[i] + sum_ij w_i w_j moo2[i n + j]
///   M_ow(w)       = mow0 + sum_i w_i mow1[i]
///   M_ww          = mww
///
/// exactly (no term dropped), for the consistent mass matrix in general form
/// (translational and rotational 6 x 6 node blocks); the lower blocks are
/// the transposes (M_ov = M_vo^T, ...). Stacked over all nodes, the columns
/// of L(w) are E (3 columns: I on every node's translations), Omega(w) =
/// Omega0 + sum_i w_i Omega1_i (3 columns; Omega0: -skew(rho_k) on the
/// translations and I on the rotations of node k; Omega1_i: -skew(h_k,i) on
/// the translations, 0 on the rotations) and H (the n modes). With
/// M = M_FEM (reduction/inertia_invariants.h computes them):
///
///   mvv = E^T M E          mvo0 = E^T M Omega0        mvo1[i] = E^T M Omega1_i
///   mvw = E^T M H          moo0 = Omega0^T M Omega0   mow0 = Omega0^T M H
///   moo1[i] = Omega0^T M Omega1_i + Omega1_i^T M Omega0
///   moo2[i n + j] = Omega1_i^T M Omega1_j              mow1[i] = Omega1_i^T M H
///   mww = H^T M H
///
/// Units below for SI models and dimensionless w (modes in m and rad per
/// unit w); mass-normalized modes give w the unit sqrt(kg) m.
struct InertiaInvariants {
  int n = 0;                   ///< modal coordinates
  Mat3 mvv = Mat3::Zero();     ///< sum of the translational mass blocks (= m I) [kg]
  Mat3 mvo0 = Mat3::Zero();    ///< first moment, -m skew(c) for the centre of mass c [kg m]
  std::vector<Mat3> mvo1;      ///< n [kg m]
  MatX mvw;                    ///< 3 x n [kg m]
  Mat3 moo0 = Mat3::Zero();    ///< inertia about the body-frame origin [kg m^2]
  std::vector<Mat3> moo1;      ///< n, symmetric [kg m^2]
  std::vector<Mat3> moo2;      ///< n * n, index i * n + j; moo2[j n + i] = moo2[i n + j]^T [kg m^2]
  MatX mow0;                   ///< 3 x n [kg m^2]
  std::vector<MatX> mow1;      ///< n, each 3 x n [kg m^2]
  MatX mww;                    ///< n x n [kg m^2] (identity for an orthonormal basis)
};

/// One table of stress modes: the recovery values of one element family
/// (shells, beams or solids) for a unit value of each modal coordinate. At
/// modal coordinates w the values are `modes * w` (stress(t) = sum_j
/// modes.col(j) w_j(t)); they are linear in w, so von Mises and other
/// invariants are formed after the sum (reduction/stress_modes.h). Every
/// element of the table has the same recovery points (`locations`), every
/// point the same `components`. Stresses are in force / length^2 of the
/// model's units (Pa for SI), section forces in force and force * length.
/// For the body file: all fields are stored as they are (`axes` as an
/// elements x 3 x 3 array, axes[k](i, j) at [k][i][j]); a table without
/// elements has empty vectors and modes 0 x n.
struct StressTable {
  /// Family name, also the table's name in the body file: "shell", "beam"
  /// or "solid".
  std::string name;
  /// Component names of one recovery point, in row order (see StressModes).
  std::vector<std::string> components;
  /// Names of the recovery points of one element, in row order (see
  /// StressModes).
  std::vector<std::string> locations;
  /// Element indices (positions in ReducedBody::mesh.elements) of the
  /// table's elements, ascending.
  std::vector<int> elements;
  /// Per element of `elements`: the frame its components are expressed in,
  /// as a rotation basic-from-element (columns e1 e2 e3 in the basic
  /// frame); the identity for solids (basic frame).
  std::vector<Mat3> axes;
  /// (elements * locations * components) x n: row Row(k, l, c) holds
  /// component c at location l of element k (the k-th of `elements`).
  MatX modes;

  /// Components per point.
  int Components() const { return static_cast<int>(components.size()); }
  /// Locations per element.
  int Locations() const { return static_cast<int>(locations.size()); }
  /// Row of `modes` of element k (position in `elements`), location l,
  /// component c: (k * Locations() + l) * Components() + c.
  Eigen::Index Row(int k, int l, int c) const {
    return (static_cast<Eigen::Index>(k) * Locations() + l) * Components() + c;
  }
};

/// Stress modes of a reduced body: one table per element family
/// (reduction/stress_modes.h ComputeStressModes fills them).
struct StressModes {
  /// 4- and 3-node shells. Locations "bottom", "top": the centroid of the
  /// surfaces z = -t/2 and +t/2 from the (offset) mid-surface along the
  /// element normal e3. Components "sxx", "syy", "sxy": in-plane stresses in
  /// the element frame (fe/elements/shell_quad4.h, shell_tria3.h). The
  /// membrane stress is (top + bottom) / 2, the bending stress (top -
  /// bottom) / 2 at the top surface.
  StressTable shell;
  /// 2-node beams. Locations "end_a", "end_b". Components "N", "Vy", "Vz",
  /// "T", "My", "Mz": section forces in the element frame (x from end A to
  /// end B; fe/elements/beam2.h), resultants on the cut face with outward
  /// normal +x, N > 0 in tension; the moments about the beam axis (the
  /// shear centre's line where a PBEAM gives a neutral axis off it).
  StressTable beam;
  /// 2-node beams whose section has stress recovery points
  /// (fe::BeamSection::stress_points): the normal stress of the axial force
  /// and the bending moments (reduction/stress_modes.h BeamNormalStress) at
  /// each point at both ends. Locations "end_a_p1" .. "end_a_pK", then
  /// "end_b_p1" .. "end_b_pK" (K the most points any section has; a section
  /// with fewer repeats its last one). Component "sxx" [Pa]. The shear
  /// stresses of Vy, Vz and T are left out (Euler-Bernoulli fibre stress,
  /// as Nastran's CBAR/CBEAM stress output). Empty in body files written
  /// before it existed.
  StressTable beam_fibre;
  /// Tetrahedra and hexahedra. Location "centroid". Components "sxx",
  /// "syy", "szz", "sxy", "syz", "szx": stresses in the basic frame.
  StressTable solid;
  /// Solids at their corner nodes, when asked for (reduce
  /// --solid-corner-stress; else empty): locations "n1" .. "n8" (the
  /// element's corner nodes in node order; tetrahedra and wedges repeat
  /// their last corner), components as `solid`. The strain field of the
  /// element evaluated at the node, not averaged over the elements around
  /// it.
  StressTable solid_node;
};

/// The reduced flexible body.
struct ReducedBody {
  static constexpr int kFormatVersion = 1;

  fe::Mesh mesh;                      ///< nodes and elements (display, stress); properties kept
  std::vector<int> interface_nodes;   ///< node indices of the interface (exact markers)
  /// Mode shapes, 6 rows per node (ux uy uz rx ry rz, rotations 0 where a
  /// node has none), n columns: u_node = rho_node + modes.block(6k, 0, 3, n) w.
  MatX modes;
  VecX frequencies_hz;                ///< flexible free-free (or constrained) frequencies, ascending
  MatX mass;                          ///< reduced n x n (identity when orthonormal)
  MatX stiffness;                     ///< reduced n x n (diag(omega^2) when orthonormal)
  MatX damping;                       ///< reduced n x n
  InertiaInvariants invariants;
  StressModes stress;
  /// Geometric stiffness of the centrifugal load cases
  /// (reduction/geometric_stiffness.h): empty (no geometric stiffening) or
  /// six symmetric n x n matrices Kg_c [units of `stiffness` per
  /// (rad/s)^2], in the order of kCentrifugalCaseNames
  /// (wx*wx, wy*wy, wz*wz, wx*wy, wy*wz, wz*wx); the modal force is
  /// -(sum_c p_c(om) Kg_c) w for the products p_c of the angular velocity.
  std::vector<MatX> geometric_stiffness;
  /// Geometric stiffness of the body's own deformation
  /// (reduction/deformation_stiffness.h): empty (none) or n symmetric
  /// n x n matrices G_j = H^T K_G(H e_j) H [units of `stiffness` per unit
  /// modal coordinate]; the strain energy gains 1/2 sum_j w_j w^T G_j w.
  std::vector<MatX> deformation_stiffness;
  std::string units = "SI (m, kg, s, N, Pa)";
  /// Provenance: source file, options, counts, flexmb version, date.
  std::vector<std::pair<std::string, std::string>> provenance;
  int static_modes = 0;               ///< static (constraint) modes in the Craig-Bampton basis
  int normal_modes = 0;               ///< fixed-interface normal modes in the basis
  int rigid_modes_removed = 0;        ///< rigid-body modes detected and removed
};

}  // namespace flexmb::reduction
