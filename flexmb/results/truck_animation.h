#pragma once
/// \file truck_animation.h
/// ParaView animation of the truck in the lane-change test, written by the
/// engine's animation writer (results/vtk_animation.h, one binary .vtu per frame and a
/// .pvd collection flushed after every frame, so an interrupted run keeps
/// the frames written so far). The truck's rigid bodies get display shapes
/// (boxes and cylinders, SetTruckShapes), rods as lines; the frame is its FE shell mesh:
/// deformed and coloured by von Mises stress (cell data von_mises, point
/// data displacement) when elastic, undeformed when rigid; the corridor's
/// lines and the course centre line are drawn on the ground.

#include <memory>
#include <string>

#include "flexmb/results/vtk_animation.h"
#include "flexmb/vehicle/lane_change_course.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb {
struct State;
}

namespace flexmb::vehicle {

/// Animation settings (lane_change_test keys animation, animation_fps,
/// animation_deformation_scale; examples/truck_lane_change/README.md).
struct TruckAnimationData {
  double fps = 25.0;                ///< frames per second of simulated time [1/s], > 0
  double deformation_scale = 1.0;   ///< factor on the frame's elastic displacement in the frames (>= 0)
};

/// Sets the display shapes (Body::shape, vehicle frame, display only) of
/// the truck's rigid bodies found by name: cab 1.6 x 2.3 x 1.8 m,
/// powertrain 1.8 x 0.8 x 0.9 m and cargo 5.0 x 2.3 x 1.0 m boxes (the
/// README's mass-property boxes), axles as cylinders along y over the
/// track, wheels as cylinders of the tire's unloaded radius (0.28 m wide
/// per tire of the set), arms, knuckles and the pitman arm as small boxes;
/// each centred at its body's centre of mass. Further: the axle hubs of the
/// additional arms (front/rear_axle_hub) as 0.12 x 0.3 m boxes from the axle
/// centre up to the additional arm's end (extra_arm_height); the tires'
/// contact-patch bodies (wheel_xx_patch, tires with a relaxation length) as
/// flat 0.2 m x tire-set width x 0.02 m boxes on the road under the wheel
/// centre; the steering column as a 25 mm radius cylinder of column_length
/// along its axis (leaning rearwards by column_inclination). Bodies without
/// a rigid-body centre of mass or of another name are left alone.
void SetTruckShapes(const TruckData& d, Model& model);

/// The animation of one lane-change run.
class TruckAnimation {
 public:
  /// Sets the truck's shapes (SetTruckShapes) and model.output's
  /// deformation scale, creates the writer in `dir` (dir/anim.pvd,
  /// dir/frames/frame_NNNNN.vtu), adds the rigid frame's undeformed mesh
  /// (d.frame_mesh, when the frame body is rigid), the steering wheel (a
  /// disc of radius 0.25 m at the column's upper end, when there is a
  /// steering_column body), the distance joints drag_link, tie_rod and
  /// front/rear_extra_arm present in the model as lines between their
  /// markers (VtkAnimationWriter::AddLink), and the corridor. `model`
  /// must be finalized and outlive the animation. Throws InputError for
  /// fps <= 0, a negative scale or an unwritable directory.
  TruckAnimation(const std::string& dir, const TruckData& d, const TruckHandles& h, const LaneChangeCourse& course,
                 const TruckAnimationData& a, Model& model);

  /// Writes a frame if state.t has reached the next frame time k / fps
  /// (k = 0, 1, ...; after a frame at t the next k is the first with
  /// k / fps > t). Returns true if it wrote one.
  bool Update(const State& state);

  /// Frames written.
  int frames() const { return writer_->frames(); }
  /// The writer (paths of the .pvd and the frames).
  const VtkAnimationWriter& writer() const { return *writer_; }

 private:
  double fps_;
  long next_ = 0;  ///< index of the next frame time
  std::unique_ptr<VtkAnimationWriter> writer_;
};

}  // namespace flexmb::vehicle
