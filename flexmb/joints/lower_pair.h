#pragma once
/// \file lower_pair.h
/// Lower-pair joints (fixed, revolute, prismatic, cylindrical, spherical,
/// universal, planar) are each a short list of the basic equations of
/// constraint_primitives.h between the axes of markers i and j. This base
/// class evaluates such a list, its Jacobian and its geometric stiffness, and
/// names its rows; a concrete joint only states its list and its
/// coordinates.

#include <array>
#include <initializer_list>

#include "flexmb/joints/joint.h"

namespace flexmb {

/// One basic equation of a lower pair, in terms of the marker axes
/// (0 = x, 1 = y, 2 = z).
struct PairEquation {
  enum class Kind {
    kOriginsCoincide,  ///< R_i^T (p_j - p_i) = 0 (three rows, along the axes of marker i)
    kPerpendicular,    ///< a_i . b_j = 0 (axis_i of marker i, axis_j of marker j)
    kPointInPlane,     ///< a_i . (p_j - p_i) = 0 (axis_i of marker i)
  };
  Kind kind = Kind::kOriginsCoincide;
  int axis_i = 0;
  int axis_j = 0;

  /// p_j - p_i = 0, stated along the axes of marker i rather than world
  /// axes: a row removed as redundant at the start (a closed loop) then stays
  /// the loop's redundant direction when the loop turns as a whole (a crane's
  /// luffing loop slewing by 90 degrees); in world axes it would turn into
  /// an essential one and the Newton matrix would become singular there.
  static constexpr PairEquation Coincide() { return {Kind::kOriginsCoincide, 0, 0}; }
  /// Axis a of marker i perpendicular to axis b of marker j.
  static constexpr PairEquation Perpendicular(int a, int b) { return {Kind::kPerpendicular, a, b}; }
  /// Origin j in the plane through origin i normal to axis a of marker i.
  static constexpr PairEquation InPlane(int a) { return {Kind::kPointInPlane, a, 0}; }
};

/// A joint made of PairEquations (at most six rows).
class LowerPairJoint : public Joint {
 public:
  int NumEquations() const final { return rows_; }
  std::string EquationName(int k) const final;
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const final;
  void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                             Mat12& H) const final;

 protected:
  LowerPairJoint(std::string name, std::initializer_list<PairEquation> equations);

 private:
  /// The equation that produces row k and the row's index within it.
  std::pair<const PairEquation*, int> EquationOfRow(int k) const;

  std::array<PairEquation, 6> equations_{};
  int count_ = 0;  ///< equations used
  int rows_ = 0;   ///< constraint rows (a coincidence counts three)
};

}  // namespace flexmb
