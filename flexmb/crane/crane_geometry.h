#pragma once
/// \file crane_geometry.h
/// Where the crane template puts its parts at t = 0 (slew angle 0): the
/// boom from its luffing angle, the luffing cylinder between its pins, the
/// payload under the boom head, the rope's free length.

#include <string>

#include "flexmb/crane/crane_data.h"

namespace flexmb::crane {

/// The boom's points in its own axes and its mass, from the body file or the rigid boom's data.
struct BoomPoints {
  Vec3 foot_B = Vec3::Zero(), head_B = Vec3::Zero(), eye_B = Vec3::Zero();  ///< [m]
  double mass = 0;                                                            ///< [kg]
};

/// Reads the flexible boom's body file (`path`, resolved) and checks that the
/// foot, head and eye nodes are interface nodes of it; for a rigid boom the
/// data's points. Errors name the crane file's line (ctx) and the node.
BoomPoints ReadBoomPoints(const CraneData& d, const std::string& body_path, YamlContext& ctx);

/// The crane's placement at t = 0.
struct CraneGeometry {
  Mat3 R_WB = Mat3::Identity();  ///< boom axes in world
  Vec3 p_WB = Vec3::Zero();      ///< boom body origin [m]
  Vec3 head_W = Vec3::Zero(), eye_W = Vec3::Zero();
  Vec3 winch_exit_W = Vec3::Zero();  ///< where the rope leaves the drum (its top)
  double cylinder_length = 0;        ///< between the pins [m]
  double cylinder_pitch_deg = 0;     ///< cylinder axis below the horizontal [deg] (rpy pitch)
  Vec3 barrel_W = Vec3::Zero(), rod_W = Vec3::Zero();  ///< their centres [m]
  double bottom_z = 0;               ///< the payload's bottom [m] (below 0: pressed into its contacts)
  Vec3 load_W = Vec3::Zero(), part_W = Vec3::Zero();   ///< upper and lower payload bodies' centres
  Vec3 hook_L = Vec3::Zero();        ///< the hook in the (upper) load body's axes
  double upper_height = 0, lower_height = 0;  ///< heights of the payload bodies [m]
  double hook_drop = 0;              ///< boom head above the hook [m]
  double free_length = 0;            ///< rope from the drum to the hook, all falls [m]
  /// With the ANCF rope: the lead span's free length from the drum to the
  /// head, and the hanging span's (the falls as one) [m], each stretched by
  /// its static tension (the span by its mean: the load plus half its weight).
  double lead_free_length = 0, span_free_length = 0;
  double pad_penetration = 0;        ///< the pads' start into their contacts [m]
  double crane_mass = 0;             ///< without the payload [kg]
};

/// Cylinder length between the pins [m] with the boom at `luffing_deg`.
double CylinderLength(const CraneData& d, const BoomPoints& b, double luffing_deg);

/// The placement (t = 0) of the crane of `d` with boom points `b` under gravity g [m/s^2].
/// Throws (through ctx) if the cylinder's length is outside its stroke or
/// its pins are not in one x-z plane.
CraneGeometry PlaceCrane(const CraneData& d, const BoomPoints& b, double g, YamlContext& ctx);

}  // namespace flexmb::crane
