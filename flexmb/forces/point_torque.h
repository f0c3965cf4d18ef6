#pragma once
/// \file point_torque.h
/// Applied moment on one marker, given as three functions of time.

#include <array>
#include <memory>

#include "flexmb/forces/force_element.h"
#include "flexmb/forces/point_force.h"
#include "flexmb/math/scalar_function.h"

namespace flexmb {

/// Moment T(t) = (tx(t), ty(t), tz(t)) [N m] applied to marker i
/// (marker_j = -1). In LoadFrame::kMarker the world moment is R_i T(t).
class PointTorque final : public ForceElement {
 public:
  /// Throws InputError naming the element if a component function is null.
  PointTorque(std::string name, std::array<std::shared_ptr<const ScalarFunction>, 3> components,
              LoadFrame frame);
  const char* type() const override { return "point_torque"; }
  void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const override;
  /// Axes of the components.
  LoadFrame frame() const { return frame_; }

 private:
  std::array<std::shared_ptr<const ScalarFunction>, 3> f_;
  LoadFrame frame_;
};

}  // namespace flexmb
