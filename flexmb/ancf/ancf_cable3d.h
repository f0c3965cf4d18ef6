#pragma once
/// \file ancf_cable3d.h
/// 3D ANCF cable element (Gerstmayr & Shabana 2006): position r and slope r'
/// at each of two nodes, cubic Hermite shape functions, 12 coordinates. Axial
/// strain |r'| - 1 (or Green-Lagrange, AxialStrainMeasure) and bending
/// strain vector (r' x r'') / |r'|^2 with energy 1/2 EI |kappa|^2 (isotropic
/// section, straight in the reference state, no torsion); see line_element.h.

#include <Eigen/Core>

#include "flexmb/ancf/line_element.h"

namespace flexmb::ancf {

/// 3D ANCF cable element. Coordinates e = (r_0, r'_0, r_1, r'_1) in world
/// components [m, -, m, -].
class AncfCable3d : public LineElement<3> {
 public:
  /// Element of reference length `length` [m], straight when unstressed.
  AncfCable3d(double length, const BeamSection& section, const QuadratureOrder& order = {});
};

}  // namespace flexmb::ancf
