#pragma once
/// \file crane_data.h
/// The data of the crane template (docs/crane-file.md): a mobile crane on
/// outriggers or a crane on a fixed base, with a slewing superstructure, a
/// luffing boom held by a hydraulic cylinder, a hoisting winch, a rope
/// reeved over the boom-head sheave onto a hook block, and the payload.
/// World axes at slew angle 0: x from the slewing axis towards the boom,
/// y to the left, z up; the ground is z = 0. Units SI.

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <vector>

#include "flexmb/math/rotation.h"
#include "flexmb/yaml/yaml_context.h"

namespace flexmb::crane {

/// Mass properties of a rigid part: mass [kg], centre of mass and principal
/// inertia about it [kg m^2] along the part's axes, and the user's `shape`
/// node (a model-file shape, may be undefined).
struct RigidPart {
  double mass = 0;
  Vec3 com = Vec3::Zero();
  Vec3 inertia = Vec3::Zero();
  YAML::Node shape{YAML::NodeType::Undefined};
};

/// One outrigger pad: its name and its place (x, y) [m] on the ground.
struct Pad {
  std::string name;
  double x = 0, y = 0;
};

/// A unilateral contact with the ground (model-file `plane_contact`).
struct GroundContact {
  double stiffness = 0;      ///< [N/m]
  double damping = 0;        ///< [N s/m]
  double friction = 0;       ///< Coulomb coefficient
  double slip_velocity = 0;  ///< [m/s] regularization of friction
};

/// The crane as read from the `crane` map of a model file.
struct CraneData {
  /// Height of the slewing ring above the ground [m]; the slewing axis is x = y = 0.
  double ring_height = 0;
  /// The carrier on its outriggers; absent (`has_carrier` false): the
  /// slewing ring stands on the ground (a fixed base).
  bool has_carrier = false;
  RigidPart carrier;                  ///< axes = world axes
  std::vector<Pad> pads;              ///< outrigger pads
  GroundContact pad_contact;          ///< pad on the ground
  RigidPart superstructure;           ///< platform with counterweight; axes = world at slew 0

  /// The boom: `flexible` (a body file) or `rigid`.
  std::string boom_type;
  YAML::Node boom_file{YAML::NodeType::Undefined};             ///< body file (flexible)
  int foot_node = 0, head_node = 0, eye_node = 0;  ///< interface nodes (flexible)
  RigidPart boom_rigid;               ///< mass properties in the boom's axes (rigid)
  Vec3 head_B = Vec3::Zero(), eye_B = Vec3::Zero();  ///< head and eye from the foot, boom axes (rigid)
  Vec3 foot_W = Vec3::Zero();         ///< foot pin at slew 0 [m]
  double luffing_deg = 0;             ///< boom axis above the horizontal [deg]
  double boom_damping_ratio = -1;     ///< modal damping ratio (flexible; < 0: the body file's)
  YAML::Node boom_options{YAML::NodeType::Undefined};          ///< the flexible body's stiffening switches, passed on
  std::vector<std::pair<std::string, int>> stresses;  ///< element_stress sensors (name, element id)

  /// The luffing cylinder between the platform and the boom's eye.
  Vec3 cylinder_base_W = Vec3::Zero();  ///< base pin at slew 0 [m]
  double stroke_min = 0, stroke_max = 0;  ///< length between the pins [m]
  RigidPart barrel, rod;                  ///< mass properties along the cylinder axis
  double barrel_length = 0, rod_length = 0, barrel_radius = 0, rod_radius = 0;

  /// The winch on the platform (drum axle along y).
  Vec3 winch_axle_W = Vec3::Zero();
  double drum_radius = 0;     ///< winding radius to the rope's centre line [m]
  double drum_mass = 0;       ///< [kg]
  Vec3 drum_inertia = Vec3::Zero();
  double drum_width = 0;      ///< [m], for the picture
  double rope_on_drum = -1;   ///< rope stored on the drum [m]; < 0: unlimited

  /// The hoisting rope.
  double rope_ea = 0;            ///< [N]
  double rope_damping_time = 0;  ///< [s]
  int falls = 1;
  double rope_slack = 0;         ///< rope beyond the taut length with the load on the ground [m]
  /// How the rope between the boom head and the hook is modelled: "massless"
  /// (the tension-only `rope` element all the way) or "ancf" (an
  /// `ancf_hoist_rope` span of `rope_elements` elements, the n falls as one
  /// span of n times the section, fed by the massless lead span from the drum).
  enum class RopeModel { kMassless, kAncf };
  RopeModel rope_model = RopeModel::kMassless;
  int rope_elements = 10;
  double rope_mass_per_length = 0;    ///< one fall [kg/m] (ancf)
  double rope_bending_stiffness = 0;  ///< one fall, EI [N m^2] (ancf)

  /// The payload: a box of `payload_size` [m] with the hook `hook_height`
  /// above its centre; standing on the ground (`clearance` 0) or hanging
  /// `clearance` [m] above it; `release_mass` [kg] of it below a grab
  /// that a manoeuvre may open (0: no grab).
  double payload_mass = 0;
  Vec3 payload_size = Vec3::Zero();
  double hook_height = 0;
  double clearance = 0;
  double release_mass = 0;
  GroundContact payload_contact;

  /// Lines of the crane file's sections, for errors found later ("boom" -> line).
  std::map<std::string, int> lines;
};

/// Reads and checks the `crane` map (its keys, signs and ranges); every
/// error names the file, the line and the part ("crane.boom ...").
CraneData ReadCraneData(const YAML::Node& crane, YamlContext& ctx);

}  // namespace flexmb::crane
