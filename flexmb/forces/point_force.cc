#include "flexmb/forces/point_force.h"

#include "flexmb/common/error.h"

namespace flexmb {

PointForce::PointForce(std::string name, std::array<std::shared_ptr<const ScalarFunction>, 3> components,
                       LoadFrame frame)
    : ForceElement(std::move(name)), f_(std::move(components)), frame_(frame) {
  for (const auto& f : f_)
    if (!f) throw InputError("force component function missing", {"", 0, "force '" + this->name() + "'"});
}

void PointForce::Evaluate(const MarkerState& mi, const MarkerState&, double t, ForceEval& e) const {
  const Vec3 F(f_[0]->Value(t), f_[1]->Value(t), f_[2]->Value(t));
  e.wrench.setZero();
  e.K.setZero();
  e.C.setZero();
  if (frame_ == LoadFrame::kWorld) {
    e.wrench.head<3>() = F;
  } else {
    const Vec3 f = mi.R_WM * F;
    e.wrench.head<3>() = f;
    e.K.block<3, 3>(0, 3) = -Skew(f);  // d(R F) = dth x (R F)
  }
}

}  // namespace flexmb
