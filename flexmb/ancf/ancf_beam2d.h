#pragma once
/// \file ancf_beam2d.h
/// Planar ANCF Euler-Bernoulli beam element (Shabana; Berzeri & Shabana 2000;
/// strain measures after Gerstmayr & Irschik 2008): nodal coordinates
/// (x, y, dx/ds, dy/ds) at each of its two nodes, cubic Hermite shape
/// functions, 8 coordinates. Axial strain |r'| - 1 (or Green-Lagrange,
/// AxialStrainMeasure) and bending strain (r' x r'') / |r'|^2 of the centre
/// line; see line_element.h.

#include <Eigen/Core>

#include "flexmb/ancf/line_element.h"

namespace flexmb::ancf {

/// Planar ANCF beam element in the x-y plane of its own coordinate system.
/// Coordinates e = (x0, y0, x0', y0', x1, y1, x1', y1') [m, -, m, -].
class AncfBeam2d : public LineElement<2> {
 public:
  /// Element of reference length `length` [m]; `curvature0` [1/m] is the
  /// stress-free curvature (positive: turning counter-clockwise along s).
  AncfBeam2d(double length, const BeamSection& section, double curvature0 = 0.0,
             const QuadratureOrder& order = {});

  /// Stress-free curvature [1/m].
  double curvature0() const { return kappa0_(0); }
};

}  // namespace flexmb::ancf
