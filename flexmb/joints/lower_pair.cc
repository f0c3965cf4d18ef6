#include "flexmb/joints/lower_pair.h"

#include <cassert>

#include "flexmb/joints/constraint_primitives.h"

namespace flexmb {

using namespace primitives;

namespace {
constexpr const char* kAxis[] = {"x", "y", "z"};
}  // namespace

LowerPairJoint::LowerPairJoint(std::string name, std::initializer_list<PairEquation> equations)
    : Joint(std::move(name)) {
  assert(equations.size() <= equations_.size());
  for (const PairEquation& eq : equations) {
    equations_[count_++] = eq;
    rows_ += eq.kind == PairEquation::Kind::kOriginsCoincide ? 3 : 1;
  }
  assert(rows_ <= 6);
}

std::pair<const PairEquation*, int> LowerPairJoint::EquationOfRow(int k) const {
  int row = 0;
  for (int q = 0; q < count_; ++q) {
    const int n = equations_[q].kind == PairEquation::Kind::kOriginsCoincide ? 3 : 1;
    if (k < row + n) return {&equations_[q], k - row};
    row += n;
  }
  return {nullptr, 0};
}

std::string LowerPairJoint::EquationName(int k) const {
  const auto [eq, sub] = EquationOfRow(k);
  if (!eq) return "?";
  switch (eq->kind) {
    case PairEquation::Kind::kOriginsCoincide:
      return std::string(kAxis[sub]) + "_i . (p_j - p_i) = 0 (origins coincide)";
    case PairEquation::Kind::kPerpendicular:
      return std::string(kAxis[eq->axis_i]) + "_i . " + kAxis[eq->axis_j] + "_j = 0";
    case PairEquation::Kind::kPointInPlane:
      return std::string(kAxis[eq->axis_i]) + "_i . (p_j - p_i) = 0";
  }
  return "?";
}

void LowerPairJoint::Evaluate(const MarkerState& mi, const MarkerState& mj, double, JointEval& e) const {
  const Vec3 d = mj.p_WM - mi.p_WM;
  int row = 0;
  for (int q = 0; q < count_; ++q) {
    const PairEquation& eq = equations_[q];
    switch (eq.kind) {
      case PairEquation::Kind::kOriginsCoincide:  // along the axes of marker i
        for (int k = 0; k < 3; ++k) PointInPlane(mi.R_WM.col(k), d, e, row++);
        break;
      case PairEquation::Kind::kPerpendicular:
        Perpendicular(mi.R_WM.col(eq.axis_i), mj.R_WM.col(eq.axis_j), e, row++);
        break;
      case PairEquation::Kind::kPointInPlane:
        PointInPlane(mi.R_WM.col(eq.axis_i), d, e, row++);
        break;
    }
  }
}

void LowerPairJoint::AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj, const double* lambda,
                                           Mat12& H) const {
  const Vec3 d = mj.p_WM - mi.p_WM;
  int row = 0;
  for (int q = 0; q < count_; ++q) {
    const PairEquation& eq = equations_[q];
    switch (eq.kind) {
      case PairEquation::Kind::kOriginsCoincide:
        for (int k = 0; k < 3; ++k) PointInPlaneStiffness(mi.R_WM.col(k), d, lambda[row++], H);
        break;
      case PairEquation::Kind::kPerpendicular:
        PerpendicularStiffness(mi.R_WM.col(eq.axis_i), mj.R_WM.col(eq.axis_j), lambda[row++], H);
        break;
      case PairEquation::Kind::kPointInPlane:
        PointInPlaneStiffness(mi.R_WM.col(eq.axis_i), d, lambda[row++], H);
        break;
    }
  }
}

}  // namespace flexmb
