#pragma once
/// \file face_projection.h
/// The closest point of an element face to a point in space, and the face's
/// shape functions there: what a tied surface (Abaqus / CalculiX *TIE)
/// needs to make a node on one mesh follow the face of another. Faces are
/// given by their nodes in Abaqus face order (fe/element_traits.h): the
/// corners, then the mid-side nodes (edge 1-2, 2-3, ...).
///
/// Coordinates: a triangle (3 or 6 nodes) in area coordinates, N1 = 1 - xi
/// - eta, N2 = xi, N3 = eta; a quadrilateral (4 or 8 nodes) in xi, eta in
/// [-1, 1], corners at (-1,-1), (1,-1), (1,1), (-1,1); 8 nodes are the
/// serendipity face of the 20-node hexahedron and 15-node wedge.

#include <array>
#include <span>

#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

/// Shape functions of a face with `count` nodes (3, 4, 6 or 8) at (xi,
/// eta): values n[k] and derivatives dn[k] = (dN/dxi, dN/deta). Throws
/// std::invalid_argument for another count.
void FaceShapeFunctions(int count, double xi, double eta, std::array<double, 8>& n,
                        std::array<std::array<double, 2>, 8>& dn);

/// The projection of a point onto one face.
struct FaceProjection {
  double xi = 0.0, eta = 0.0;         ///< face coordinates of the closest point, inside the face
  std::array<double, 8> weights{};    ///< shape functions there (sum 1): the point is sum w_k x_k
  Vec3 point = Vec3::Zero();          ///< the closest point of the face [m]
  double normal_distance = 0.0;       ///< |distance| along the face normal at the foot point [m]
  double outside = 0.0;               ///< how far the foot point lies outside the face, in the face [m]; 0 inside
  bool converged = false;             ///< the foot-point iteration converged
};

/// Projects `p` onto the face with nodes `x` (3, 4, 6 or 8, Abaqus order):
/// the foot point of the normal through `p` on the face's surface extended
/// beyond its edges (Gauss-Newton on the face coordinates), then the face
/// coordinates clamped into the face. `normal_distance` is measured at the
/// foot point, `outside` from the foot point to the clamped point; `point`
/// and `weights` are those of the clamped point.
FaceProjection ProjectOntoFace(std::span<const Vec3> x, const Vec3& p);

}  // namespace flexmb::fe
