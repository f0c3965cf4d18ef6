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
#include <vector>

#include "flexmb/joints/joint.h"

namespace flexmb {

/// Most markers a force element may act on (Model::Finalize checks it).
constexpr int kMaxForceMarkers = 16;

/// Workspace of one force element.
struct ForceEval {
  Vec12 wrench = Vec12::Zero();  ///< (f_i, m_i, f_j, m_j) world [N, N m]
  Mat12 K = Mat12::Zero();       ///< d wrench / d x
  Mat12 C = Mat12::Zero();       ///< d wrench / d twist
  /// Set by the caller: false when only the wrench is needed (a residual
  /// evaluation with a kept iteration matrix); an element whose tangents
  /// are costly (e.g. finite differences) may then leave K and C as they are.
  bool tangents = true;
  /// Elements on n > 2 markers (ForceElement::more_markers) only: the
  /// wrenches of all markers in their order (6 n) and their derivatives
  /// (6 n x 6 n), as `wrench`, K and C above, which they leave unused. Sized
  /// once by the workspace.
  VecX wrench_n;
  MatX K_n, C_n;
};

/// Wrench (force, moment; world [N, N m]) that a force element on n
/// markers applies to its marker a < n, from its evaluation e.
inline Eigen::Ref<const Vec6> MarkerWrench(const ForceEval& e, int n, int a) {
  if (n <= 2) return e.wrench.segment<6>(6 * a);
  return e.wrench_n.segment<6>(6 * a);
}

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

  /// Elements on n > 2 markers: fills e.wrench_n, e.K_n and e.C_n (all
  /// entries) from the states m[0..n) of markers i, j, more_markers... at
  /// time t [s]. Evaluate is then not called. The default throws: an element
  /// that lists more markers must override it.
  virtual void EvaluateMarkers(const MarkerState* const* m, double t, ForceEval& e) const;
  /// Stored potential energy [J] of an element on n > 2 markers (0 unless
  /// overridden).
  virtual double PotentialEnergyMarkers(const MarkerState* const*, double) const { return 0.0; }

  /// Number of markers the element acts on: 1, 2, or 2 + more_markers.
  int NumMarkers() const { return marker_j < 0 ? 1 : 2 + static_cast<int>(more_markers.size()); }
  /// Index (into Model::markers) of the element's marker a < NumMarkers().
  int MarkerAt(int a) const { return a == 0 ? marker_i : a == 1 ? marker_j : more_markers[a - 2]; }

  /// Markers (indices into Model::markers); marker_j = -1 for one marker.
  int marker_i = -1, marker_j = -1;
  /// Markers after i and j of an element on more than two (empty for most).
  std::vector<int> more_markers;

 protected:
  explicit ForceElement(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

}  // namespace flexmb
