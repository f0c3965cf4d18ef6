#pragma once
/// \file model.h
/// The model: bodies, markers, joints, force elements and sensors.
///
/// A model is built by the Add* calls (the model file loader makes them) and
/// then frozen by Finalize(), which checks it, assigns each body its offsets in
/// q and v and each joint its offset in lambda. After Finalize() computation
/// only reads `const Model&`; all that changes lives in State and Workspace.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/bodies/body.h"
#include "flexmb/forces/force_element.h"
#include "flexmb/joints/joint.h"
#include "flexmb/model/settings.h"
#include "flexmb/model/state.h"
#include "flexmb/model/sensor.h"

namespace flexmb {

/// The multibody model. bodies[0] is the ground.
class Model {
 public:
  Model();
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  std::string name = "model";           ///< model name
  Vec3 gravity_W = Vec3(0, 0, -9.81);   ///< gravity in world [m/s^2]
  SolverSettings solver;                ///< integrator settings
  OutputSettings output;                ///< output settings
  std::string manoeuvre;                ///< the model file's manoeuvre it was loaded for ("" if none)

  /// Adds a body; returns its index. Throws InputError on a duplicate name.
  int AddBody(std::unique_ptr<Body> body);
  /// Adds a marker named "<body>.<name>" on body `body` with pose given in the
  /// user's body frame (converted to the body's internal frame, see Marker).
  /// Returns its index.
  int AddMarker(int body, const std::string& name, const Vec3& p_BM, const Mat3& R_BM, int node = -1);
  /// Adds a joint between markers i and j (indices); returns its index.
  int AddJoint(std::unique_ptr<Joint> joint, int marker_i, int marker_j);
  /// Adds a force element on markers i and (optionally, -1) j.
  int AddForce(std::unique_ptr<ForceElement> force, int marker_i, int marker_j);
  /// Adds a force element on markers[0] (i), markers[1] (j) and, for an
  /// element on more than two markers, the rest (ForceElement::more_markers).
  int AddForce(std::unique_ptr<ForceElement> force, const std::vector<int>& markers);
  /// Adds a sensor.
  int AddSensor(std::unique_ptr<Sensor> sensor);

  /// Checks the model and assigns offsets. Throws InputError naming the entity.
  void Finalize();
  /// True after Finalize().
  bool finalized() const { return finalized_; }

  /// Index of the named entity, or -1.
  int FindBody(const std::string& name) const;
  int FindMarker(const std::string& name) const;
  int FindJoint(const std::string& name) const;
  int FindForce(const std::string& name) const;

  /// Initial state from the bodies' initial coordinates (not yet assembled).
  State InitialState() const;

  std::vector<std::unique_ptr<Body>> bodies;
  std::vector<Marker> markers;
  std::vector<std::unique_ptr<Joint>> joints;
  std::vector<std::unique_ptr<ForceElement>> forces;
  std::vector<std::unique_ptr<Sensor>> sensors;

  int nq = 0;  ///< number of position coordinates
  int nv = 0;  ///< number of velocity coordinates (degrees of freedom before constraints)
  int nc = 0;  ///< number of constraint equations (before redundant ones are removed)

 private:
  bool finalized_ = false;
  std::map<std::string, int> body_index_, marker_index_, joint_index_, force_index_, sensor_index_;
};

}  // namespace flexmb
