#pragma once
/// \file body.h
/// The interface every body type (ground, rigid, floating-frame flexible,
/// ANCF) gives the engine. A body addresses a slice of the global coordinates
/// q (nq entries) and velocities v (nv entries); it does not own them.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/kinematics/marker.h"

namespace flexmb {


/// Simple display shape for animation output, in the user's body frame.
struct Shape {
  enum class Type { kNone, kBox, kCylinder, kSphere };
  Type type = Type::kNone;
  Vec3 size = Vec3::Zero();   ///< box: edge lengths; cylinder: (radius, length, -); sphere: (radius, -, -) [m]
  Vec3 p_BS = Vec3::Zero();   ///< centre of the shape in the user's body frame [m]
  Mat3 R_BS = Mat3::Identity();  ///< orientation; a cylinder's axis is the shape's z axis
};

/// Abstract body. Coordinates are passed as pointers into the global vectors,
/// at the body's own offset.
class Body {
 public:
  virtual ~Body() = default;

  /// Unique name of the body.
  const std::string& name() const { return name_; }
  /// Number of position coordinates.
  virtual int nq() const = 0;
  /// Number of velocity coordinates (= dimension of the tangent space).
  virtual int nv() const = 0;

  /// Offsets into the global q and v (set when the model is finalized).
  int q_offset = 0;
  int v_offset = 0;

  /// Writes the initial coordinates (from the body's specification).
  virtual void InitialCoordinates(double* q, double* v) const = 0;

  /// q_out = q (+) dx: moves the coordinates by a tangent increment dx
  /// (nv entries, same components as v). Rotations use the exponential map.
  virtual void Retract(const double* q, const double* dx, double* q_out) const = 0;

  /// Mass matrix (nv x nv) at q.
  virtual void MassMatrix(const double* q, MatX& M) const = 0;
  /// True if the mass matrix does not depend on q (evaluated once).
  virtual bool HasConstantMass() const { return true; }
  /// Told by Model::Finalize which FE nodes (indices) the body's markers sit
  /// on (each once, ascending; markers without a node left out), so that a
  /// body can keep their data where the per-iteration marker evaluations
  /// read it fast. Nothing by default.
  virtual void UseMarkerNodes(const std::vector<int>& /*nodes*/) {}
  /// True if every marker's twist Jacobian can have rank 6 (all marker
  /// motions possible). Planar bodies return false, so that the equations of
  /// a joint holding them are checked for redundancy like those of a loop.
  virtual bool MarkerJacobianFullRank() const { return true; }

  /// Adds the body's own generalized forces (inertial velocity terms, elastic,
  /// gravity g_W [m/s^2]) to Q (nv) and the derivatives dQ/dx (tangent
  /// increments) and dQ/dv to dQdq, dQdv (nv x nv each).
  virtual void AddForces(const double* q, const double* v, const Vec3& g_W, Eigen::Ref<VecX> Q,
                         Eigen::Ref<MatX> dQdq, Eigen::Ref<MatX> dQdv) const = 0;

  /// Adds the generalized forces of AddForces to Q (nv) without their
  /// derivatives, for Newton iterations that keep an earlier iteration
  /// matrix (SolverSettings::jacobian_reuse), and returns true. The default
  /// adds nothing and returns false: the caller then uses AddForces (worth
  /// overriding where the derivatives cost more than the forces).
  virtual bool AddForceVector(const double* /*q*/, const double* /*v*/, const Vec3& /*g_W*/,
                              Eigen::Ref<VecX> /*Q*/) const {
    return false;
  }

  /// Adds scale * d(M(q) a)/dq to K (nv x nv; rows the velocity
  /// components, columns the tangent increments of Retract) for a fixed
  /// acceleration a (nv): the iteration-matrix term of a
  /// configuration-dependent mass. Called only when HasConstantMass() is
  /// false; the default adds nothing.
  virtual void AddMassTangent(const double* /*q*/, const double* /*a*/, double /*scale*/,
                              Eigen::Ref<MatX> /*K*/) const {}

  /// Sparsity of the body's own nv x nv blocks (mass matrix, and dQdq, dQdv
  /// of AddForces): appends the structurally non-zero (row, column) pairs, in
  /// the body's velocity indices, to `entries` (duplicates allowed) and
  /// returns true. Entries outside the pattern must stay zero in all three
  /// blocks: the assembler copies only the pattern into the sparse iteration
  /// matrix (and zeros only the pattern before AddForces). The default
  /// appends nothing and returns false: the blocks are dense. Called once,
  /// when the workspace is sized.
  virtual bool BlockPattern(std::vector<std::pair<int, int>>& entries) const {
    (void)entries;
    return false;
  }

  /// Velocity columns (first, count) of the body, in its own indices, that
  /// marker m depends on: its twist Jacobian J and MarkerTwistTangent are
  /// zero outside columns first..first+count-1, and AddMarkerWrenchTangent
  /// adds only to the rows and columns of that range. Default: all columns
  /// (0, nv()). Called once, when the workspace is sized.
  virtual std::pair<int, int> MarkerColumns(const Marker& m) const {
    (void)m;
    return {0, nv()};
  }

  /// Pose, twist and twist Jacobian of marker `m` attached to this body.
  virtual void EvaluateMarker(const double* q, const double* v, const Marker& m,
                              MarkerState& out) const = 0;

  /// Velocity-product part of the marker acceleration, (a; alpha) in world:
  /// [a_WM; alpha_WM] = J vdot + bias.
  virtual Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const = 0;

  /// Adds d(J^T w)/dx at fixed wrench w = (f_W, m_W at the marker origin) to
  /// dQdq (nv x nv): the part of a force tangent that comes from the marker
  /// Jacobian turning with the body.
  virtual void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& wrench_W,
                                      Eigen::Ref<MatX> dQdq) const = 0;

  /// Writes d(J v)/dx at fixed v (6 x nv) to `out`: how the marker twist
  /// changes when the body's coordinates move with its velocities held. It
  /// carries the velocity-dependent forces (dampers) into the stiffness.
  virtual void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                                  Eigen::Ref<MatX> out) const = 0;

  /// Kinetic energy [J].
  virtual double KineticEnergy(const double* q, const double* v) const = 0;
  /// Potential energy of gravity g_W, zero at the world origin [J].
  virtual double GravityPotential(const double* q, const Vec3& g_W) const = 0;
  /// Elastic (strain) energy stored in the body's deformation at q [J];
  /// 0 for bodies that cannot deform (the default).
  virtual double ElasticEnergy(const double* /*q*/) const { return 0.0; }
  /// Linear momentum [kg m/s] and angular momentum about the world origin
  /// [kg m^2/s], both in world components.
  virtual Vec6 Momentum(const double* q, const double* v) const = 0;

  /// Pose of the user's body frame in world (for output and animation).
  virtual void BodyFramePose(const double* q, Vec3& p_WB, Mat3& R_WB) const = 0;

  /// Number of points of the body's centre line (ANCF beams, cables and
  /// ropes), drawn as a polyline in animations; 0 (the default): none.
  virtual int CentreLinePoints() const { return 0; }
  /// World position [m] of centre-line point k in 0..CentreLinePoints()-1
  /// at q, in order along the line.
  virtual Vec3 CentreLinePoint(const double* /*q*/, int /*k*/) const { return Vec3::Zero(); }

  /// Position in the body's internal frame of a point given in the user's
  /// body frame (a rigid body's internal frame sits at its centre of mass).
  virtual Vec3 InternalPosition(const Vec3& p_B) const { return p_B; }

  /// Display shape (may be kNone).
  Shape shape;

 protected:
  explicit Body(std::string name) : name_(std::move(name)) {}

 private:
  std::string name_;
};

}  // namespace flexmb
