#pragma once
/// \file beam3.h
/// 3-node straight Timoshenko beam (Abaqus/CalculiX B32 and B32R, gmsh
/// type 8, VTK_QUADRATIC_EDGE), 6 DOF per node. Node order as Abaqus: end
/// A, the mid node, end B (gmsh and VTK list the mid node last; their
/// readers reorder). The element is two exact 2-node Timoshenko beams
/// (beam2.h), A to the mid node and the mid node to B, sharing the
/// section, the material and the orientation vector: on a straight
/// prismatic beam this gives the exact nodal displacements under nodal
/// loads, which Abaqus's quadratic interpolation approaches as the mesh is
/// refined, so the two codes agree to the B32 element's discretization
/// error. Only straight elements are read: a mid node off the chord A-B by
/// more than 1e-4 of its length, or closer than 1 % of the length to an
/// end, is an error (an arc is meshed with straight elements instead); the
/// two halves then share one element frame. An offset of the beam's axis
/// from its nodes (offset_a = offset_b, e.g. Abaqus OFFSET1/OFFSET2) is a
/// rigid link at all three nodes. Details: docs/design.md, "FE:
/// 3-node beam".

#include <Eigen/Core>

#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe {

/// Type id of the 3-node beam (its row: fe/element_traits.cc).
inline constexpr ElementType kBeam3{11};

/// Fills K [N/m, N, N m] and M [kg, kg m, kg m^2] (18 x 18, basic frame,
/// node by node ux uy uz rx ry rz, nodes A, mid, B) of a 3-node beam: the
/// sum of its two halves' beam2 matrices (Beam2Matrices, with the mass form
/// of `in`). Throws InputError naming the element (type, id, file:line) for
/// a curved element or a mid node near an end (see the file comment),
/// different offsets at its ends, and everything Beam2Matrices refuses.
void Beam3Matrices(const ElementInput& in, MatX& K, MatX& M);

/// Section forces of a 3-node beam at its ends, as Beam2SectionForces: S
/// (12 x 18) maps the element DOF to (N, Vy, Vz, T, My, Mz) [N, N m] at end
/// A (rows 0-5, from the first half) and end B (rows 6-11, from the second
/// half), in the element frame `axes` (x from A to B, y from the
/// orientation vector). Throws InputError as Beam3Matrices.
void Beam3SectionForces(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes);

/// Geometric stiffness of a 3-node beam under its element displacements
/// `u` (18): each half's beam2 geometric stiffness under that half's mean
/// axial force; *axial_force (if not null) is the mean of the two [N].
/// Throws InputError as Beam3Matrices.
void Beam3GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG,
                             double* axial_force);

}  // namespace flexmb::fe
