#pragma once
/// \file contact_patch_joint.h
/// Joint of a tire's contact-patch body on the wheel carrier when the tire
/// relaxes laterally and longitudinally (flexmb/vehicle/tire.h).

#include "flexmb/joints/lower_pair.h"

namespace flexmb::vehicle {

/// Planar translation: the orientations of markers i and j are equal and
/// origin j lies in the x-z plane of marker i (the plane normal to y_i);
/// j slides along x_i and z_i without rotating (four rows). For a tire's
/// contact patch, marker i on the carrier has z along the spin axis and x
/// forward, so the patch moves laterally and longitudinally.
class ContactPatchJoint final : public LowerPairJoint {
 public:
  explicit ContactPatchJoint(std::string name)
      : LowerPairJoint(std::move(name), {PairEquation::Perpendicular(2, 0), PairEquation::Perpendicular(2, 1),
                                          PairEquation::Perpendicular(0, 1), PairEquation::InPlane(1)}) {}
  const char* type() const override { return "contact_patch"; }
};

}  // namespace flexmb::vehicle
