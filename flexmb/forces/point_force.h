#pragma once
/// \file point_force.h
/// Applied force on one marker, given as three functions of time.

#include <array>
#include <memory>

#include "flexmb/forces/force_element.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Axes in which the components of an applied load are given.
enum class LoadFrame {
  kWorld,   ///< world axes: the load keeps its direction
  kMarker,  ///< axes of the marker: the load turns with the marker (follower load)
};

/// Force F(t) = (fx(t), fy(t), fz(t)) [N] applied at the origin of marker i
/// (marker_j = -1). In LoadFrame::kMarker the world force is R_i F(t).
class PointForce final : public ForceElement {
 public:
  /// Throws InputError naming the element if a component function is null.
  PointForce(std::string name, std::array<std::shared_ptr<const ScalarFunction>, 3> components,
             LoadFrame frame);
  const char* type() const override { return "point_force"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// Axes of the components.
  LoadFrame frame() const { return frame_; }

 private:
  std::array<std::shared_ptr<const ScalarFunction>, 3> f_;
  LoadFrame frame_;
};

}  // namespace flexmb
