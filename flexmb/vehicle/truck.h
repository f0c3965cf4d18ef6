#pragma once
/// \file truck.h
/// The two-axle (4x2) truck template: a ladder frame (rigid, or elastic by a
/// Craig-Bampton reduced body of the generated shell frame, ladder_frame.h)
/// with cab, powertrain and cargo on stiff mounts (bushings) at the frame's
/// interface points, rigid front and rear axles on
/// leaf-spring suspensions (vertical spring-dampers, a longitudinal arm,
/// a stabilizer as a roll spring), steered front knuckles, wheels on
/// revolute joints with tires, and a drive torque on the rear wheels.
/// Coordinates: the vehicle frame, x forward from the front-axle centre,
/// y to the left, z up from the road; at t = 0 it coincides with the world.

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "flexmb/math/scalar_function.h"
#include "flexmb/model/model.h"
#include "flexmb/reduction/reduced_body.h"
#include "flexmb/vehicle/ladder_frame.h"
#include "flexmb/vehicle/tire.h"

namespace flexmb {
class YamlContext;
}

namespace flexmb::vehicle {

/// Mass properties of one rigid part.
struct PartData {
  double mass = 1.0;              ///< [kg]
  Vec3 cg = Vec3::Zero();         ///< centre of mass, vehicle frame [m] (wheels, axles: only x used for axles)
  Vec3 inertia = Vec3::Ones();    ///< principal moments about the centre of mass, vehicle axes [kg m^2]
  /// Off-diagonal entries of the inertia tensor about the centre of mass
  /// (xy, xz, yz), vehicle axes [kg m^2]; 0 for principal axes along the
  /// vehicle axes.
  Vec3 products = Vec3::Zero();
};

/// Mounts of a rigid part (cab, powertrain, cargo) on the frame: one linear
/// bushing (translational stiffness and damping, vehicle axes) on each rail
/// at every station `x`, at the rail's top web-flange corner, preloaded by
/// the part's static weight shared by the lever rule.
struct MountData {
  std::vector<double> x;           ///< stations along the frame [m]
  Vec3 stiffness = Vec3::Constant(5e6);  ///< per mount [N/m]
  Vec3 damping = Vec3::Constant(2e4);    ///< per mount [N s/m]
};

/// One leaf-spring axle suspension.
struct SuspensionData {
  double spring_stiffness = 2e5;   ///< vertical rate per side [N/m]
  double spring_damping = 1e4;     ///< damper per side [N s/m]
  double spring_half_spacing = 0.45;  ///< lateral distance of each spring from the centre plane [m]
  double spring_length = 0.3;      ///< height of the spring's frame mount above the axle [m]
  double arm_length = 0.7;         ///< longitudinal arm: pivot on the frame ahead of the axle [m]
  double stabilizer_stiffness = 1e5;  ///< roll stiffness of the stabilizer [N m/rad]
  double stabilizer_damping = 0.0;    ///< roll damping [N m s/rad]
  /// Additional longitudinal arm (seed Fig. 3, rear): a rod of arm_length
  /// this far above the arm [m], from the frame (at the arm pivot's bracket)
  /// to a hub on which the axle rolls; the hub pitches on the arm, so arm,
  /// rod, frame and hub form a parallelogram holding the axle's pitch.
  /// 0: no additional arm (the axle rolls on the arm).
  double extra_arm_height = 0.0;
};

/// Mass of the hub between arm and axle of a suspension with the additional
/// arm [kg] (a small body carrying the axle's roll joint; counted with the
/// axle's unsprung mass).
inline constexpr double kAxleHubMass = 1.0;

/// All parameters of the truck (examples/truck_lane_change/README.md gives
/// the values and their sources).
struct TruckData {
  double wheelbase = 4.2;          ///< [m]; the rear axle is at x = -wheelbase
  double front_track = 2.0;        ///< [m]
  double rear_track = 1.85;        ///< centre of the twin tires [m]
  double kingpin_offset = 0.15;    ///< kingpin lateral distance inboard of the wheel centre [m]
  /// Sprung parts. The frame's mass properties are those of the generated
  /// shell frame (ShellMassProperties of `frame_mesh`, non-structural mass
  /// included), for the rigid and the elastic frame alike.
  PartData frame, cab, powertrain, cargo;
  LadderFrameData ladder;          ///< geometry and mass of the ladder frame
  MountData cab_mounts, powertrain_mounts, cargo_mounts;  ///< mounts of the parts on the frame
  std::shared_ptr<const fe::Mesh> frame_mesh;  ///< the generated frame (set by ParseTruck / SetFrameMesh)
  /// When set, the frame is a FlexibleBody of this reduced body (its basic
  /// frame is the vehicle frame; its interface nodes include the nodes
  /// nearest to FrameAttachments); otherwise a rigid body.
  std::shared_ptr<const reduction::ReducedBody> elastic_frame;
  /// The user's FE frame (truck file: frame.body), a body file made by
  /// `flexmb reduce` whose basic frame is the vehicle frame, in SI units;
  /// null: the generated ladder frame. The rigid frame takes its mass
  /// properties, the elastic frame is this body (truck_frame.h).
  std::shared_ptr<const reduction::ReducedBody> frame_body;
  std::string frame_body_file;                ///< its path, for messages
  std::map<std::string, int> frame_mounts;    ///< attachment name -> node id of frame_body
  /// Largest distance of a mount's node from its attachment point [m]; the
  /// offset between them is a rigid lever (a bracket idealized as rigid).
  double mount_tolerance = 0.1;
  PartData front_axle, rear_axle, knuckle, front_wheel, rear_wheel, arm;  ///< unsprung parts
  SuspensionData front, rear;      ///< suspensions
  double steering_stiffness = 4e5;  ///< knuckle servo stiffness about the kingpin [N m/rad]
  double steering_damping = 4e3;    ///< knuckle servo damping [N m s/rad]
  double steering_ratio = 20.0;    ///< steering-wheel / road-wheel angle [-]
  /// Steering linkage (seed Fig. 4): the servo turns a pitman arm on the
  /// frame, a drag link (distance rod) turns the left knuckle by an inboard
  /// steering arm, a one-piece tie rod (distance rod) between Ackermann
  /// trapezoid arms turns the right knuckle. False: each knuckle has its own
  /// servo to the commanded angle (kinematic parallel steer).
  bool steering_linkage = true;
  double pitman_arm_length = 0.25;  ///< pitman arm and steering arm length [m] (1:1 lever)
  double tie_rod_arm_length = 0.3;  ///< trapezoid arm length [m], pointing at the rear-axle centre
  /// Pitman arm (pivot and ball) this far ahead of the front axle [m], the
  /// horizontal drag link's length (truck.yaml: steering.pitman_x); the
  /// default equals the default front arm_length: the pitman ball then lies
  /// on the front arm's pivot axis.
  double drag_link_length = 0.7;
  double pitman_arm_mass = 5.0;     ///< [kg], centre of mass at x = drag_link_length
  /// Height of the steering arm's ball (the drag link's rear end) above the
  /// wheel centre [m]; the drag link is horizontal. The axle pitches with its
  /// arm about the arm pivot (at the wheel centre's height): a pitch phi
  /// (heave, brake wind-up) moves the ball by steering_arm_height * phi along
  /// the link and steers the wheels by -(steering_arm_height /
  /// pitman_arm_length) phi. 0 (the default): the link is level with the arm,
  /// no brake or roll steer to first order (examples/truck_lane_change/
  /// README.md, "Brake steer"); 0.15 was the first version's (truck.yaml:
  /// steering.steering_arm_height).
  double steering_arm_height = 0.0;
  /// Steering column (seed Fig. 4, with the linkage): steering wheel and
  /// column as one rotating body on a revolute on the frame at the steering
  /// gear, turned by the servo (gains steering_stiffness / ratio^2 and
  /// steering_damping / ratio^2, the same compliance seen at the pitman arm)
  /// to the steering-wheel angle and coupled to the pitman arm by a
  /// GearJoint of ratio -steering_ratio. False: the servo turns the pitman
  /// arm directly.
  bool steering_column = true;
  double column_mass = 12.0;         ///< steering wheel and column [kg]
  double column_inertia = 0.2;       ///< about the column axis [kg m^2]
  double column_length = 1.0;        ///< steering gear to steering wheel [m]; centre of mass at its middle
  double column_inclination = 0.35;  ///< column axis from the vertical, leaning rearwards [rad]
  TireData front_tire, rear_tire;  ///< tires (rear: a twin set per side)
  /// Front axle's share of the total brake torque [-], in [0, 1]; each axle's
  /// torque is split equally between its two wheels.
  double brake_front_share = 0.4;
  /// Smoothing spin omega_s of the wheel brakes [rad/s], > 0 (WheelBrake).
  double brake_smoothing_spin = 0.5;
  double gauge_width = 2.5;        ///< overall width of the vehicle for the gauge points [m]
};

/// Generates the ladder frame of `d.ladder` (ladder_frame.h), stores it in
/// d.frame_mesh and sets d.frame's mass properties from it.
void SetFrameMesh(TruckData& d);

/// The 26 named attachment points of the frame, vehicle frame [m]: spring
/// seats (4), arm pivots (2), steering gear (1), cab mounts (4 by default),
/// powertrain mounts (4), cargo mounts (10) and the rear tow hitch (1), at
/// the static ride height. The elastic frame's interface nodes are the mesh
/// nodes nearest to them (NearestNode).
std::vector<FrameAttachment> FrameAttachments(const TruckData& d, double g = 9.81);

/// Static axle loads [N] (front, rear) by the lever rule over all parts'
/// weights: the independent hand computation used to preload the springs
/// and by the static check.
std::array<double, 2> StaticAxleLoads(const TruckData& d, double g);

/// Indices of the entities of a built truck.
struct TruckHandles {
  int frame_body = -1;                 ///< the frame (RigidBody or FlexibleBody)
  bool elastic = false;                ///< the frame is a FlexibleBody
  int frame_ref = -1;                  ///< frame marker at the frame's centre of mass, vehicle axes
  int front_axle_ref = -1, rear_axle_ref = -1;  ///< frame markers above the axle centres at road level
  std::array<int, 4> gauge{};          ///< frame gauge markers: front-left, front-right, rear-left, rear-right
  std::array<int, 4> tire_force{};     ///< tire force elements: FL, FR, RL, RR
  std::array<int, 4> wheel_marker{};   ///< wheel-centre markers: FL, FR, RL, RR
  std::array<double, 2> wheel_centre_z{};  ///< static wheel-centre heights front, rear [m]
  std::array<int, 2> kingpin_joint{};  ///< kingpin revolutes: left, right
};

/// The truck's inputs as functions of time: the steering-wheel angle [rad],
/// the drive torque on the rear axle [N m] and, when not null, the total
/// brake torque on all wheels [N m] (WheelBrake on each wheel bearing,
/// shared by brake_front_share).
struct TruckInputs {
  std::shared_ptr<const ScalarFunction> steering_wheel;
  std::shared_ptr<const ScalarFunction> drive_torque;
  std::shared_ptr<const ScalarFunction> brake_torque;
};

/// Builds the truck into `model` (not finalized) moving forward at `speed`
/// [m/s] on a road with friction `mu`, its inputs the functions of
/// `inputs` (steering_wheel and drive_torque not null). Throws InputError
/// for bad data.
TruckHandles BuildTruck(const TruckData& d, double speed, double mu, const TruckInputs& inputs, Model& model);

/// Builds the truck into `model` (not finalized) moving forward at `speed`
/// [m/s] on a road with friction `mu`. The steering-wheel angle [rad], the
/// drive torque on the rear axle [N m] and, when not null, the total brake
/// torque on all wheels [N m] (WheelBrake on each wheel bearing, shared by
/// brake_front_share) are read from the shared values (zero-order hold,
/// CommandSignal). Throws InputError for bad data.
TruckHandles BuildTruck(const TruckData& d, double speed, double mu, std::shared_ptr<const double> steering_wheel,
                        std::shared_ptr<const double> drive_torque, Model& model,
                        std::shared_ptr<const double> brake_torque = nullptr);

/// Reads the truck's parameters from the "truck" map of a lane-change file;
/// tire data come from the YAML files named there, relative to `dir`.
TruckData ParseTruck(const YAML::Node& node, YamlContext& ctx, const std::string& dir);

/// Reads a tire data file: YAML (keys as the TireData members) or, for a
/// path ending in .tir, a Magic Formula property file (tir_file.h), whose
/// ignored coefficients are listed in one warning (LogWarning).
TireData LoadTireFile(const std::string& path);

/// Reads tire data from the map `t` (the keys of TireData; unknown keys are
/// errors) and checks them; errors through `ctx` name the file and line.
TireData ReadTireData(const YAML::Node& t, YamlContext& ctx);

}  // namespace flexmb::vehicle
