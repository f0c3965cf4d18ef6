#pragma once
/// \file joint.h
/// The interface of a joint: position-level constraint equations Phi = 0
/// between two markers i and j, with analytic Jacobians.
///
/// Jacobians are taken with respect to the marker pose variations
/// x = (dp_i, dtheta_i, dp_j, dtheta_j), all in world components (12 columns),
/// see MarkerState. The engine chains them with the marker twist Jacobians, so
/// a joint never sees body coordinates and works on every body type.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "flexmb/kinematics/marker.h"

namespace flexmb {

using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using RowMat12 = Eigen::Matrix<double, Eigen::Dynamic, 12, Eigen::RowMajor>;

/// Workspace of one joint: constraint values and derivatives at the current
/// marker states. Sized once at model finalization.
struct JointEval {
  VecX phi;   ///< constraint values (n) [m or dimensionless]
  VecX phi_t; ///< partial time derivative (n), non-zero for driven joints
  RowMat12 D; ///< n x 12 derivative with respect to the marker variations
};

/// Abstract joint between markers i and j. Joint coordinates (an angle or a
/// translation, where the joint has them) are what drivers, motors and
/// sensors use.
class Joint {
 public:
  virtual ~Joint() = default;
  /// Unique name.
  const std::string& name() const { return name_; }
  /// Type name as in the model file ("revolute", ...).
  virtual const char* type() const = 0;
  /// Number of constraint equations.
  virtual int NumEquations() const = 0;
  /// Short description of equation k, for messages about redundant rows.
  virtual std::string EquationName(int k) const = 0;

  /// Evaluates phi, phi_t and D at time t [s].
  virtual void Evaluate(const MarkerState& mi, const MarkerState& mj, double t, JointEval& e) const = 0;

  /// Adds sum_k lambda_k d(D_k^T)/dx (12 x 12) to H: the geometric stiffness of
  /// the constraint forces at fixed multipliers.
  virtual void AddGeometricStiffness(const MarkerState& mi, const MarkerState& mj,
                                     const double* lambda, Mat12& H) const = 0;

  /// Number of joint coordinates (0, 1 or 2).
  virtual int NumCoordinates() const { return 0; }
  /// Name of joint coordinate k ("angle", "translation").
  virtual const char* CoordinateName(int k) const;
  /// Joint coordinate k [rad or m] (angles wrapped to (-pi, pi]) and its
  /// derivative with respect to the marker variations (12).
  virtual double Coordinate(int k, const MarkerState& mi, const MarkerState& mj, Vec12* dq) const;
  /// Whether coordinate k is an angle (wraps at +-pi).
  virtual bool CoordinateIsAngle(int k) const { return false; }
  /// Axis of coordinate k in world: the direction along which (translation)
  /// or about which (angle) a motor acts; marker i's axis.
  virtual Vec3 CoordinateAxis(int k, const MarkerState& mi) const;

  /// Markers (indices into Model::markers).
  int marker_i = -1, marker_j = -1;
  /// Offset of this joint's equations in the global multiplier vector.
  int lambda_offset = 0;
  /// Time [s] at which the joint lets go: the simulator ends a step there
  /// and from then on the joint's equations are dropped and its multipliers
  /// (reaction forces) held at zero (Workspace::joint_released), e.g. the
  /// sudden release of part of a payload (EN 13001-2's phi_3).
  /// +infinity: never.
  double release_time = std::numeric_limits<double>::infinity();
  /// Limits of joint coordinate 0 [m or rad] (a hydraulic cylinder's
  /// stroke, an end stop): a run whose coordinate leaves them stops with an
  /// error naming the joint (Simulator). Unlimited by default.
  double coordinate_min = -std::numeric_limits<double>::infinity();
  double coordinate_max = std::numeric_limits<double>::infinity();

 protected:
  explicit Joint(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

}  // namespace flexmb
