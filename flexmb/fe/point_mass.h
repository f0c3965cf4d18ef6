#pragma once
/// \file point_mass.h
/// The 6 x 6 nodal mass matrix of a concentrated mass with inertia (CONM2)
/// or of a general nodal mass matrix (CONM1).

#include <Eigen/Core>

#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

/// Mass matrix at the node of a general point mass (pm.general): pm.matrix,
/// checked to be finite, symmetric and positive semi-definite. Otherwise the
/// mass matrix at the node of a mass `pm.mass` [kg] whose centre sits at
/// `pm.offset` [m] from the node, with inertia `pm.inertia` [kg m^2] about
/// that centre (basic axes): with d = offset,
///   M = [[m I, -m skew(d)], [m skew(d), I_c - m skew(d)^2]],
/// so that 1/2 (v, w)^T M (v, w) is the kinetic energy of the rigid mass when
/// the node moves with velocity v and angular velocity w. Throws InputError
/// naming the mass (id, file, line) for a negative or non-finite mass or an
/// inertia that is not symmetric positive semi-definite.
Mat6 PointMassMatrix(const PointMass& pm);

}  // namespace flexmb::fe
