#pragma once
/// \file force_element.h
/// The interface of a force element acting on one or two markers.
///
/// A force element returns the wrenches it applies to its markers,
/// w = (f_i, m_i, f_j, m_j): forces [N] and moments [N m] in world components,
/// moments about the marker origins, and their analytic derivatives with
/// respect to the marker pose variations x = (dp_i, dth_i, dp_j, dth_j) and
/// the marker twists (v_i, w_i, v_j, w_j), see MarkerState.

#include <string>

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Workspace of one force element.
struct ForceEval {
  Vec12 wrench = Vec12::Zero();  ///< (f_i, m_i, f_j, m_j) world [N, N m]
  Mat12 K = Mat12::Zero();       ///< d wrench / d x
  Mat12 C = Mat12::Zero();       ///< d wrench / d twist
  /// Set by the caller: false when only the wrench is needed (a residual
  /// evaluation with a kept iteration matrix); an element whose tangents
  /// are costly (e.g. finite differences) may then leave K and C as they are.
  bool tangents = true;
};

/// Abstract force element. Single-marker elements have marker_j = -1 and
/// leave the j parts zero.
class ForceElement {
 public:
  virtual ~ForceElement() = default;
  /// Unique name.
  const std::string& name() const { return name_; }
  /// Type name as in the model file.
  virtual const char* type() const = 0;
  /// Fills e (all entries are overwritten) at time t [s]. For single-marker
  /// elements `mj` is a default MarkerState and must be ignored.
  virtual void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, ForceEval& e) const = 0;
  /// Stored potential energy [J] (0 for non-conservative elements).
  virtual double PotentialEnergy(const MarkerState&, const MarkerState&, double) const { return 0.0; }

  /// Markers (indices into Model::markers); marker_j = -1 for one marker.
  int marker_i = -1, marker_j = -1;

 protected:
  explicit ForceElement(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

}  // namespace flexmb
