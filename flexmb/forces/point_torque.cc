#include "flexmb/forces/point_torque.h"

#include "flexmb/common/error.h"

namespace flexmb {

PointTorque::PointTorque(std::string name, std::array<std::shared_ptr<const ScalarFunction>, 3> components,
                         LoadFrame frame)
    : ForceElement(std::move(name)), f_(std::move(components)), frame_(frame) {
  for (const auto& f : f_)
    if (!f) throw InputError("torque component function missing", {"", 0, "force '" + this->name() + "'"});
}

void PointTorque::Evaluate(const MarkerState& mi, const MarkerState&, double t, ForceEval& e) const {
  const Vec3 T(f_[0]->Value(t), f_[1]->Value(t), f_[2]->Value(t));
  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  if (frame_ == LoadFrame::kWorld) {
    e.wrench.segment<3>(3) = T;
  } else {
    const Vec3 m = mi.R_WM * T;
    e.wrench.segment<3>(3) = m;
    e.K.block<3, 3>(3, 3) = -Skew(m);  // d(R T) = dth x (R T)
  }
}

}  // namespace flexmb
