#pragma once
/// \file deformation_stiffness.h
/// Geometric stiffening of a reduced flexible body by the stress of its own
/// elastic deformation (docs/design.md, "Stiffening by the body's own
/// deformation"). The linear floating-frame body has the strain energy
/// 1/2 w^T K w; the quadratic part of the Green-Lagrange strain adds, to
/// the next order, the cubic energy
///
///   U3(w) = 1/2 u^T K_G(sigma(u)) u,  u = H w,
///
/// with sigma(u) the linear stress of the deformation and K_G the
/// element geometric stiffness under that stress (the same element
/// functions as the centrifugal stiffening, reduction/geometric_stiffness.h).
/// K_G is linear in the prestress displacement, so with one matrix per mode
///
///   G_j = H^T K_G(H e_j) H   (n x n, symmetric),   U3 = 1/2 sum_j w_j w^T G_j w.
///
/// This is the P-delta of a boom compressed by the forces at its pins, the
/// stiffening of a beam stretched between its supports, and the centrifugal
/// stiffening of a blade whose stretch the modes represent: it acts through
/// whatever stress the modal coordinates carry (the static modes of the
/// interface nodes carry the axial forces of the joints). References:
/// Wu and Haug 1988 ("Geometric non-linear substructuring for dynamics of
/// flexible mechanical systems", Int. J. Numer. Meth. Eng. 26, 2211-2226);
/// Mayo, Garcia-Vallejo and Dominguez 2004 ("Study of the geometric
/// stiffening effect: comparison of different formulations", Multibody
/// System Dynamics 11, 321-341), who keep the cubic and quartic terms.

#include <vector>

#include "flexmb/fe/mesh.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb::reduction {

/// The n matrices G_j = H^T K_G(H e_j) H of the file comment for the mode
/// shapes `modes` (6 rows per node of `mesh`, n columns, as
/// ReducedBody::modes), each symmetric n x n [units of the modal stiffness
/// per unit modal coordinate]. Element by element on the element's rows of
/// the modes; the modes are split among threads. Cost about
/// n_elements (d^2 n + d n^2) n for d element DOF. Throws InputError naming
/// an element with bad element data.
std::vector<MatX> ComputeDeformationStiffness(const fe::Mesh& mesh, const MatX& modes);

}  // namespace flexmb::reduction
