#pragma once
/// \file stress_modes.h
/// Stress modes of a reduced body (StressModes in reduced_body.h): per
/// element the recovery matrix of its stiffness formulation (shell surface
/// stresses, beam section forces, solid stresses; fe/elements/) times the
/// element's rows of the mode matrix, one dense product per element. Also
/// the von Mises stress of a recovered stress vector and the normal stress
/// at a point of a beam section.

#include <Eigen/Core>
#include <vector>

#include "flexmb/fe/mesh.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb::reduction {

/// Stress modes of every element of `mesh` for the mode shapes `modes`
/// (6 rows per node, ux uy uz rx ry rz in the basic frame, rotations unused
/// by solids; n columns, as ReducedBody::modes): shells (4- and 3-node) in
/// StressModes::shell, beams in ::beam, tetrahedra and hexahedra in
/// ::solid, each table's `modes` with n columns (0 rows if the mesh has no
/// element of that family). Throws InputError if `modes` does not have 6
/// rows per node, and InputError naming the element for a missing section
/// or material or a bad element (as the element routines of fe/elements/).
/// Beams whose section has stress recovery points also give
/// StressModes::beam_fibre; with `solid_corners`, solids also give
/// StressModes::solid_node (the stress at each corner node).
/// With `element_subset` (one flag per element of the mesh), only the
/// flagged elements are computed; the others keep their place in the
/// tables with zero rows and zero axes, so that the tables of a partition
/// of the elements sum, entry by entry, to the whole tables (a distributed
/// reduction, reduction/petsc/).
StressModes ComputeStressModes(const fe::Mesh& mesh, const MatX& modes, bool solid_corners = false,
                               const std::vector<char>* element_subset = nullptr);

/// Von Mises stress of a plane stress state (sxx, syy, sxy) (shell
/// components): sqrt(sxx^2 - sxx syy + syy^2 + 3 sxy^2).
double VonMises(const Eigen::Vector3d& s);

/// Von Mises stress of a 3-D stress state (sxx, syy, szz, sxy, syz, szx)
/// (solid components): sqrt(((sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2)
/// / 2 + 3 (sxy^2 + syz^2 + szx^2)).
double VonMises(const Eigen::Matrix<double, 6, 1>& s);

/// Von Mises stress of every recovery point of a shell or solid table from
/// its values v = table.modes * w (rows as table.modes): one entry per
/// point, element by element then location. Throws InputError for a table
/// whose points are not stress vectors (components "sxx" "syy" "sxy" or
/// "sxx" ... "szx"; beams: use BeamNormalStress), or if v has the wrong
/// size.
VecX PointVonMises(const StressTable& table, const VecX& v);

/// Largest von Mises stress of each element of a shell or solid table at
/// the modal coordinates w [Pa]: values = table.modes * w, then
/// von_mises(k) = max over the element's recovery points (shells: bottom
/// and top surface; solids: centroid) for the k-th of table.elements. The
/// one evaluation used by the animation (results/vtk_animation.h) and the truck's
/// stress hot spots (apps/flexmb/commands/lane_change.h). `values` and `von_mises`
/// are scratch and result, resized only when their size differs (no
/// allocation on repeated calls). Throws InputError naming the table if
/// its points are not stress vectors, if w.size() differs from
/// table.modes.cols() or table.modes has not elements * locations *
/// components rows.
void ElementVonMises(const StressTable& table, const Eigen::Ref<const VecX>& w, VecX& values, VecX& von_mises);

/// Element von Mises stresses as ElementVonMises, from given stress values
/// (rows as table.modes, e.g. one column of table.modes * W for a batch of
/// coordinate vectors W). Same checks of the table, and of values.size().
void ElementVonMisesOfValues(const StressTable& table, const Eigen::Ref<const VecX>& values, VecX& von_mises);

/// Normal stress sigma_xx [Pa] at the point (y, z) of a beam section
/// (element frame, from the section's centroid) from the section forces
/// f = (N, Vy, Vz, T, My, Mz) (StressModes::beam components), by
/// Euler-Bernoulli bending with the product of inertia Iyz = int y z dA:
/// sigma = N / A + z a - y b with [Iy -Iyz; -Iyz Iz] (a, b) = (My, Mz)
/// (a, b = E times the curvatures; the moment-curvature law of
/// fe/elements/beam2.h), i.e. N / A + My z / Iy - Mz y / Iz for Iyz = 0. Shear stresses of Vy, Vz and
/// T depend on the section's shape, which the mesh does not store. A rod
/// section (Iy = Iz = Iyz = 0, fe/elements/rod2.h) gives N / A. Throws
/// InputError if A <= 0 or Iy Iz <= Iyz^2 (other than a rod section). A
/// neutral axis off the beam axis (BeamSection::neutral_axis, e): y, z are
/// measured from the beam axis, the moments are taken about the neutral axis
/// (My - ez N, Mz + ey N) and y - ey, z - ez used above.
double BeamNormalStress(const Eigen::Matrix<double, 6, 1>& f, const fe::BeamSection& section,
                        double y, double z);

}  // namespace flexmb::reduction
