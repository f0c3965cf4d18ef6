#pragma once
/// \file truck.h
/// The truck template: a ladder frame (rigid, or elastic by a Craig-Bampton
/// reduced body of the generated shell frame, ladder_frame.h, or of the
/// user's FE frame) with cab, powertrain and cargo on mounts (bushings) at
/// the frame's interface points, any number of rigid axles on leaf-spring
/// suspensions (vertical spring-dampers, a longitudinal arm, a stabilizer as
/// a roll spring), two of them optionally on a balancer bogie (6x4), the
/// first axle steered by knuckles and the steering linkage, wheels on
/// revolute joints with tires, a drive torque on the driven axles' wheels
/// and brakes on every wheel.
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
  /// Inter-leaf friction of each spring [N]: a Coulomb force against the
  /// spring's rate, smoothed over friction_velocity (ViscousCoulombFunction),
  /// in parallel with spring_damping: the leaf spring's hysteresis loop. 0:
  /// none.
  double friction_force = 0.0;
  double friction_velocity = 0.01;  ///< rate at which the friction reaches 0.76 of its force [m/s], > 0
};

/// Mass of the hub between arm and axle of a suspension with the additional
/// arm [kg] (a small body carrying the axle's roll joint; counted with the
/// axle's unsprung mass).
inline constexpr double kAxleHubMass = 1.0;

/// One axle: the rigid-axle template (a beam axle located by a longitudinal
/// arm, rolling on it against a stabilizer, on two vertical leaf springs),
/// with a wheel and tire set at each end; steered (knuckles on kingpins,
/// turned by the steering linkage), driven and braked as set here. Its
/// springs rest on the frame's spring seats, or with `bogie` on the ends of
/// that bogie's balancer beams.
struct AxleData {
  /// Names the axle's bodies, joints, forces and frame mounts ("front":
  /// front_axle, wheel_fl, spring_seat_front_left, arm_pivot_front; "rear":
  /// rear_axle, wheel_rl, ...; any other name n: n_axle, wheel_n_l, ...).
  std::string name;
  double x = 0.0;                  ///< axle centre along the vehicle's x [m]; the first axle at 0
  double track = 2.0;              ///< wheel-centre distance (twin tires: their centre) [m]
  /// Knuckles on kingpins, turned by the steering: the first axle, and
  /// optionally the second (8x4: a relay arm on the frame, turned by a rod
  /// from the pitman arm, drives its drag link; SteerRatio).
  bool steered = false;
  bool driven = false;             ///< the drive torque is shared equally by the wheels of all driven axles
  double brake_share = 0.5;        ///< this axle's share of the total brake torque [-]; the shares sum to 1
  PartData axle;                   ///< the axle beam (x of cg unused: at x)
  PartData wheel;                  ///< one wheel (a twin set: both rims)
  SuspensionData suspension;       ///< springs, arm, stabilizer
  TireData tire;                   ///< the tire set of one wheel
  int bogie = -1;                  ///< index into TruckData::bogies, -1: springs on the frame
};

/// A balancer (tandem) bogie: on each side a beam (the leaf spring of a
/// balancer suspension) pivots on a trunnion on the frame at `x` and rests
/// with its ends on the springs of the bogie's two axles, so that the
/// trunnion load is shared between them by the lever rule.
struct BogieData {
  std::string name;                ///< names the beams (bogie_<name>_left) and trunnions (trunnion_<name>_left)
  double x = 0.0;                  ///< trunnion axis along the vehicle's x [m], between the two axles
  PartData beam;                   ///< one beam; its centre of mass on the trunnion axis
};

/// All parameters of the truck (examples/truck_lane_change/README.md gives
/// the values and their sources).
struct TruckData {
  /// The axles from front to rear (the first at x = 0, steered); a truck
  /// file's front_*/rear_* keys make the two axles "front" and "rear".
  std::vector<AxleData> axles;
  std::vector<BogieData> bogies;   ///< balancer bogies of the axles (AxleData::bogie)
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
  PartData knuckle, arm;           ///< a knuckle of a steered axle, an axle's longitudinal arm
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
  /// Smoothing spin omega_s of the wheel brakes [rad/s], > 0 (WheelBrake).
  double brake_smoothing_spin = 0.5;
  double gauge_width = 2.5;        ///< overall width of the vehicle for the gauge points [m]
};

/// The name of the axle's wheel on side `side` (0 left, 1 right): wheel_fl,
/// wheel_fr for the axle "front", wheel_rl, wheel_rr for "rear", else
/// wheel_<name>_l, wheel_<name>_r.
std::string WheelName(const AxleData& a, int side);

/// Distance from the first axle to the rear axle group's centre [m]: to the
/// last axle, or to its bogie's trunnion (the effective wheelbase of the
/// single-track model and of the driver).
double Wheelbase(const TruckData& d);

/// Road-wheel angle of axle i per road-wheel angle of the first axle [-]:
/// 1 for the first axle, 0 for an unsteered one; a second steered axle (8x4)
/// turns about the same centre on the rear axle group's centre line,
/// (x_i + Wheelbase) / Wheelbase (the relay linkage's lever ratio).
double SteerRatio(const TruckData& d, size_t i);

/// Checks the axles and bogies of `d` (order, names, steering, shares, each
/// bogie with two axles around its trunnion); throws InputError naming the
/// axle or bogie.
void CheckAxles(const TruckData& d);

/// Generates the ladder frame of `d.ladder` (ladder_frame.h), stores it in
/// d.frame_mesh and sets d.frame's mass properties from it.
void SetFrameMesh(TruckData& d);

/// The named attachment points of the frame, vehicle frame [m], at the
/// static ride height: per axle its spring seats (2, not with a bogie) and
/// arm pivot (1), per bogie its trunnions (2), the steering gear (1), cab,
/// powertrain and cargo mounts (2 per station) and the rear tow hitch (1):
/// 26 for the example 4x2. The elastic frame's interface nodes are the mesh
/// nodes nearest to them (NearestNode).
std::vector<FrameAttachment> FrameAttachments(const TruckData& d, double g = 9.81);

/// Static axle loads [N], one per axle, the hand computation used to preload
/// the springs and by the static checks: each axle carries its unsprung
/// weight and half its arm's; the sprung weights go to the supports (an
/// axle's springs, a bogie's trunnions) by the lever rule with two
/// supports, else as on a rigid frame resting on the supports' springs and
/// tires in series; a bogie's load is shared by its axles by the lever rule.
std::vector<double> StaticAxleLoads(const TruckData& d, double g);

/// Indices of the entities of a built truck.
struct TruckHandles {
  int frame_body = -1;                 ///< the frame (RigidBody or FlexibleBody)
  bool elastic = false;                ///< the frame is a FlexibleBody
  int frame_ref = -1;                  ///< frame marker at the frame's centre of mass, vehicle axes
  /// Frame markers at road level above the first axle and the rear axle
  /// group's centre (at x = -Wheelbase).
  int front_axle_ref = -1, rear_axle_ref = -1;
  std::array<int, 4> gauge{};          ///< frame gauge markers: front-left, front-right, rear-left, rear-right
  std::vector<int> tire_force;         ///< tire force elements, per axle left then right (FL, FR, RL, RR, ...)
  std::vector<int> wheel_marker;       ///< wheel-centre markers, as tire_force
  std::vector<double> wheel_centre_z;  ///< static wheel-centre height per axle [m]
  std::array<int, 2> kingpin_joint{};  ///< the first axle's kingpin revolutes: left, right
  /// Per body of the model: the index of the axle whose unsprung part it is
  /// (its axle, arm, hub, wheels, contact patches, a steered axle's
  /// knuckles, a bogie's beams: its rear axle), -1 for the frame and the
  /// parts on it.
  std::vector<int> body_axle;
  int steered_axles = 1;               ///< the first axles that are steered: 1, or 2 (8x4)
};

/// The truck's inputs as functions of time: the steering-wheel angle [rad],
/// the drive torque on the driven axles [N m] and, when not null, the total
/// brake torque on all wheels [N m] (WheelBrake on each wheel bearing,
/// shared by the axles' brake_share).
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
/// drive torque on the driven axles [N m] and, when not null, the total brake
/// torque on all wheels [N m] (WheelBrake on each wheel bearing, shared by
/// the axles' brake_share) are read from the shared values (zero-order hold,
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
