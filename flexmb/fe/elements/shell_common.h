#pragma once
/// \file shell_common.h
/// Pieces shared by the 3- and 4-node shells: input checks, the element's
/// local (mean-plane) frame, the membrane and plate material matrices, and
/// the transformation of local matrices to the basic frame, which carries
/// the warping projection and the normal offset as rigid links.
/// Formulation notes: docs/design.md, "FE: shell elements".

#include <Eigen/Core>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"

namespace flexmb::fe::shell {

/// Drilling penalty (Hughes-Brezzi type): with omega = (dv/dx - du/dy) / 2
/// the in-plane rotation of the membrane, the drilling strain energy is
/// G t [alpha A (theta_z - omega)^2 at the centroid
///      + beta int (theta_z - omega)^2 dA with the full rule].
/// alpha ties the rotation to the membrane (one point: no in-plane locking);
/// beta only stabilizes the remaining drilling modes.
inline constexpr double kDrillingFactor = 1.0;
/// beta above.
inline constexpr double kDrillingStabilization = 1e-3;
/// Transverse shear correction factor of the Mindlin plate.
inline constexpr double kShearFactor = 5.0 / 6.0;
/// Largest accepted warping: |h| / sqrt(projected area), h the distance of
/// the corner nodes from the mean plane.
inline constexpr double kMaxWarpRatio = 0.1;

/// Context naming the element for error messages ("4-node shell 17" at the
/// element's file:line).
ErrorContext Context(const Element& element);

/// Material and section values of a shell, checked.
struct ShellData {
  double E = 0.0, nu = 0.0, G = 0.0;  ///< [Pa]
  double rho = 0.0;                   ///< [kg/m^3]
  double t = 0.0;                     ///< thickness [m]
  double nsm = 0.0;                   ///< non-structural mass [kg/m^2]
  double offset = 0.0;                ///< mid-surface offset along the normal [m]
};

/// Checks element, section and material of a shell with `n_nodes` nodes and
/// returns the values; throws InputError naming the element otherwise.
ShellData CheckShellInput(const ElementInput& in, int n_nodes);

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

/// Plane-stress membrane stiffness A = E t / (1 - nu^2) [...] [N/m].
Eigen::Matrix3d MembraneMatrix(const ShellData& s);
/// Plate bending stiffness D = E t^3 / (12 (1 - nu^2)) [...] [N m].
Eigen::Matrix3d BendingMatrix(const ShellData& s);

/// Transforms a local element matrix (node by node u v w rx ry rz in the
/// local frame, at the mid-surface points) to the basic frame at the nodes:
/// u_mid = u + theta x d, then rotation by R. Result in `out` (resized).
template <int N>
void ToBasic(const LocalFrame<N>& frame, const Eigen::Matrix<double, 6 * N, 6 * N>& local,
             MatX& out);

}  // namespace flexmb::fe::shell
