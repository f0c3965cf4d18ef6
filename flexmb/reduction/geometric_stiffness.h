#pragma once
/// \file geometric_stiffness.h
/// Geometric stiffening of a reduced flexible body (the SID standard's
/// "geometric stiffness" of Wallrapp 1994; docs/design.md "Geometric
/// stiffening"). The inertial loads of the floating frame's motion stress
/// the body; the stress stiffens it. For the centrifugal loads this is what
/// keeps a fast rotating beam stable (Simo and Vu-Quoc's spin-up), which the
/// linear floating-frame model alone misses.
///
/// For each of the six centrifugal load cases c (the products of the body's
/// angular velocity components, CentrifugalProducts) the FE model, held at
/// its support nodes, is loaded by the inertial (d'Alembert) forces
/// f_c = -M_full a_c of the rigid acceleration field a_c(x) per unit product
/// (om x (om x x) = sum_c p_c(om) a_c(x)); the static solution
/// K u_c = f_c gives the element stresses (beams: axial force; shells:
/// membrane resultants; solids: stress tensor), each element its geometric
/// stiffness K_G(u_c), and the projection onto the modes
/// Kg_c = H^T K_G(u_c) H (n x n, symmetric). At run time the body adds the
/// modal force -(sum_c p_c(om) Kg_c) w (bodies/geometric_stiffening.h).
/// Every element type has a geometric stiffness: beams from their axial
/// force (Beam2GeometricStiffness), shells from their membrane stress
/// resultants (ShellQuad4/ShellTria3GeometricStiffness), solids from their
/// stress tensor (SolidHex8/Tet4/Tet10GeometricStiffness). Only the six
/// centrifugal load cases are built: the translational (gravity, frame
/// acceleration) and angular-acceleration cases of the SID standard are
/// not (docs/design.md, "Geometric stiffening").

#include <array>
#include <vector>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/mesh.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb::reduction {

/// Number of centrifugal load cases.
inline constexpr int kCentrifugalCases = 6;

/// Names of the load cases, in order: "wx*wx", "wy*wy", "wz*wz", "wx*wy",
/// "wy*wz", "wz*wx".
extern const std::array<const char*, kCentrifugalCases> kCentrifugalCaseNames;

/// The products p_c(om) of the angular velocity components om (body axes,
/// rad/s), in the order of kCentrifugalCaseNames [rad^2/s^2].
inline std::array<double, kCentrifugalCases> CentrifugalProducts(const Vec3& om) {
  return {om.x() * om.x(), om.y() * om.y(), om.z() * om.z(),
          om.x() * om.y(), om.y() * om.z(), om.z() * om.x()};
}

/// Rigid acceleration per unit product of case c at the point x (body
/// frame): a_c(x) with om x (om x x) = sum_c p_c(om) a_c(x) [m per rad^2].
Vec3 CentrifugalAcceleration(int c, const Vec3& x);

/// Details of a geometric stiffness computation (for reports and tests).
struct GeometricStiffnessInfo {
  std::vector<int> support_nodes;  ///< node indices held in the static load cases
  /// Axial force [N] of every element (mesh order) per unit product of each
  /// case: axial_force[c][e] (mean of the element's two ends; 0 for shells
  /// and solids).
  std::array<std::vector<double>, kCentrifugalCases> axial_force;
};

/// Geometric (initial-stress) stiffness of one element under the prestress
/// of its nodal displacements `u` (element order, DofsPerNode per node,
/// basic frame, as K): fills KG (as K) by the element's own function. For a
/// beam `axial_force` (if not null) receives the force N [N] it used (mean
/// of the two ends, > 0 tension); for other elements it is set to 0. Throws
/// InputError naming the element for bad element data.
void ElementGeometricStiffness(const fe::ElementInput& in, const Eigen::VectorXd& u, MatX& KG,
                               double* axial_force = nullptr);

/// Assembled geometric stiffness (n_full x n_full, DofMap::full numbering
/// of `dofs`, both triangles stored) of all elements of `mesh` under the
/// prestress of the displacements `u_full` (n_full, e.g. T times a static
/// solution on the free DOF). Free-DOF form: T^T KG T. Throws InputError
/// naming an element with bad data.
fe::SparseMat AssembleGeometricStiffness(const fe::Mesh& mesh, const fe::DofMap& dofs,
                                         const Eigen::VectorXd& u_full);

/// Computes the six matrices Kg_c (n x n each; see the file comment) for
/// the mode shapes `modes` (6 rows per node of `mesh`, n columns, as
/// ReducedBody::modes). The static load cases hold the nodes
/// `support_nodes` (all 6 DOF) and the mesh's own single-point
/// constraints; the reduction passes its fixed nodes, or without them the
/// interface nodes (exact for a body attached through one interface node,
/// e.g. a cantilever on a hub; with several interface nodes the body is
/// over-constrained in the load cases, an approximation). `mass_form` is
/// the mass of the inertial loads. Throws InputError for bad element data
/// (naming the element) or no support at all, NumericalError if the held
/// model is still a mechanism.
std::vector<MatX> ComputeGeometricStiffness(const fe::Mesh& mesh, const MatX& modes,
                                            const std::vector<int>& support_nodes,
                                            fe::MassForm mass_form = fe::MassForm::kConsistent,
                                            GeometricStiffnessInfo* info = nullptr);

}  // namespace flexmb::reduction
