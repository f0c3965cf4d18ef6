#pragma once
/// \file ladder_frame.h
/// A parametric truck ladder frame of 4-node shells: two C-channel rails
/// along x (web in an x-z plane, flanges pointing inwards), joined by flat
/// cross members (plates in y-z planes sharing the rails' web nodes),
/// steel, free-free; named interface nodes placed on existing mesh nodes
/// nearest to given attachment points. Coordinates: the vehicle frame (x
/// forward, y left, z up) [m]. The values of the truck are in
/// examples/truck_lane_change/README.md.

#include <string>
#include <vector>

#include "flexmb/fe/mesh.h"

namespace flexmb::vehicle {

/// Largest number of shells a generated ladder frame may have (the
/// example's 0.04 m mesh has 5,478, a 6 mm mesh would have about 245,000,
/// far more than the frame's reduction needs); GenerateLadderFrame refuses
/// an element size that makes more.
inline constexpr int kMaxLadderFrameShells = 200000;

/// The steel structure of a flatbed platform on the frame (the seed's FE
/// model was "the frame and the platform"), of shells like the frame: two
/// longitudinal sills (C channels, flanges inwards) above the rails, cross
/// bearers (a web in a y-z plane and a top flange into the platform, as
/// deep as the sills) across the whole width at most `bearer_spacing`
/// apart (plus the rounding to the element grid), and a side rail (a web in an x-z plane with a bottom flange
/// inwards) along each edge; they share their nodes where they meet. The
/// sills rest on a spacer strip (wood, much softer than the steel: not
/// modelled, as the seed leaves out the wooden deck and the attachments)
/// and are joined to the rails only by brackets: shear plates in the webs'
/// planes bridging the spacer gap over `bracket_length`, sharing the nodes
/// of the rail's web top edge and of the sill's web bottom edge. The deck,
/// sides and fittings are the non-structural mass `mass` minus the steel,
/// smeared over the sills and cross bearers (on the thin side rails' webs
/// it makes a cluster of nearly equal local modes that a kept-mode count
/// would cut through). All in the vehicle frame [m].
struct PlatformData {
  bool present = false;              ///< whether the frame carries the platform
  double length = 0.0;               ///< platform length [m]
  double front_x = 0.0;              ///< x of the platform's front end (runs to front_x - length) [m]
  double width = 2.5;                ///< outer width (side rails at +-width / 2) [m]
  double spacer = 0.02;              ///< gap between the rails' top flanges and the sills' bottom flanges [m]
  double sill_height = 0.12;         ///< depth of the sills, cross bearers and side rails [m]
  double sill_flange_width = 0.06;   ///< sill flange width, from the web inwards [m]
  double sill_thickness = 0.005;     ///< [m]
  double bearer_spacing = 0.6;       ///< largest spacing of the cross bearers (one at each end) [m]
  double bearer_thickness = 0.004;   ///< [m]
  double side_rail_thickness = 0.004;  ///< [m]
  std::vector<double> brackets;      ///< x of the brackets' centres, on both sides [m]; at least two
  double bracket_length = 0.2;       ///< bracket (shear plate) length along x [m]
  double bracket_thickness = 0.01;   ///< [m]
  double bearer_flange_width = 0.05;  ///< cross bearer top flange width along x [m]
  double side_rail_flange_width = 0.05;  ///< side rail bottom flange width, inwards [m]
  double mass = 0.0;                 ///< total platform mass: steel, deck, sides, fittings [kg]; not below the steel
};

/// Geometry, material and mass of the ladder frame.
struct LadderFrameData {
  double front_x = 1.2;            ///< x of the rails' front end [m]
  double length = 8.0;             ///< rail length (rails run from front_x to front_x - length) [m]
  double half_spacing = 0.43;      ///< y of the rails' web mid-surfaces, +-half_spacing [m]
  double web_height = 0.27;        ///< channel web height (mid-surface of the flanges) [m]
  double flange_width = 0.085;     ///< channel flange width, from the web inwards [m]
  double thickness = 0.007;        ///< rail plate thickness [m]
  double bottom_z = 0.8;           ///< z of the bottom flange [m]
  std::vector<double> cross_members = {1.2, 0.7, -0.8, -2.2, -3.5, -5.2, -6.8};  ///< x of the cross members [m]
  double cross_member_thickness = 0.006;  ///< [m]
  double element_size = 0.04;      ///< target element edge length [m]
  double E = 2.1e11;               ///< Young's modulus [Pa]
  double nu = 0.3;                 ///< Poisson's ratio
  double rho = 7850.0;             ///< density [kg/m^3]
  /// Total mass of the rails and cross members [kg] including
  /// non-structural mass (brackets, fuel tank, batteries...; a platform
  /// without its own `platform` map) smeared on the rails as a
  /// non-structural mass per area; 0: steel only. Must not be below their
  /// steel mass. A `platform` brings its own mass.
  double total_mass = 0.0;
  /// Radius of the rigid spiders (RBE2) that spread each interface node's
  /// load over the nodes around it, as a bracket does [m] (AddSpiders).
  double spider_radius = 0.1;
  /// A flatbed platform on the frame (when platform.present).
  PlatformData platform;
};

/// Section indices of a generated frame's shells (fe::Mesh::shell_sections).
enum LadderSection : int {
  kRailSection = 0,        ///< the rails' channels
  kCrossMemberSection,     ///< the frame's cross members
  kSillSection,            ///< the platform's sills
  kBearerSection,          ///< the platform's cross bearers
  kSideRailSection,        ///< the platform's side rails
  kBracketSection,         ///< the platform's brackets on the rails
};

/// z of the platform's top (the sills' top flanges), where cargo rests [m].
double PlatformTopZ(const LadderFrameData& data);

/// A wanted attachment point of the frame.
struct FrameAttachment {
  std::string name;               ///< e.g. "spring_seat_front_left"
  fe::Vec3 point = fe::Vec3::Zero();  ///< attachment coordinates, vehicle frame [m]
};

/// The generated frame.
struct LadderFrame {
  fe::Mesh mesh;                   ///< shells, one steel material; sections in the order of LadderSection
  std::vector<std::string> names;  ///< interface names, in the order of the attachments
  std::vector<int> nodes;          ///< interface node index per name (the node nearest to the point)
  double steel_mass = 0.0;         ///< mass of the frame's steel alone (rails, cross members) [kg]
  double nsm = 0.0;                ///< non-structural mass per area of the rails [kg/m^2]
  double platform_steel_mass = 0.0;  ///< steel of the platform and its brackets [kg]
  double platform_nsm = 0.0;       ///< non-structural mass per area of the sills and cross bearers [kg/m^2]
};

/// Mass properties of a body: total mass, centre of mass and the inertia
/// tensor about it, vehicle axes.
struct MassProperties3 {
  double mass = 0.0;                  ///< [kg]
  fe::Vec3 cg = fe::Vec3::Zero();     ///< [m]
  fe::Mat3 inertia = fe::Mat3::Zero();  ///< about cg [kg m^2]
};

/// Generates the frame and places the interface nodes: each attachment
/// point gets the mesh node nearest to it (a node may serve several
/// attachments). Throws InputError for non-positive dimensions, an element
/// size that leaves fewer than one element across the flange, a cross
/// member outside the rails, a total mass below the steel mass, or a
/// platform that does not fit the frame (narrower than the rails, ahead of
/// the rails' front end, sill flanges reaching the centre plane, a gap
/// between its plates under 1 mm, fewer than two brackets, a bracket off the
/// rails or the sills, overlapping brackets, too short for its bearers'
/// flanges, a mass below its steel).
LadderFrame GenerateLadderFrame(const LadderFrameData& data, const std::vector<FrameAttachment>& attachments);

/// Index of the mesh node nearest to `point` (the first of equals).
int NearestNode(const fe::Mesh& mesh, const fe::Vec3& point);

/// Adds a rigid link (RBE2, all six DOF) from each of `nodes` to every other
/// node within `radius` of it [m], so that the loads of an attachment are
/// spread over a patch instead of one shell node (a point load on a shell
/// is singular). A node already dependent, or itself in `nodes`, is left
/// out. With `part` (one entry per node) only nodes of the independent
/// node's part are taken: a spider on a rail must not reach the platform's
/// sills above it (they meet only at the brackets). No mass is added.
void AddSpiders(fe::Mesh& mesh, const std::vector<int>& nodes, double radius, const std::vector<int>* part = nullptr);

/// The part of each node of a generated frame's mesh: 1 for the platform's
/// sills, bearers and side rails, 0 for the rest (rails, cross members; a
/// bracket's nodes are on the rail's or the sill's edge).
std::vector<int> FramePartOfNodes(const fe::Mesh& mesh);

/// Adds a rigid bracket (RBE2, all six DOF) from `node` to the nodes within
/// `radius` of each of `points` [m] and of the node itself (nodes already
/// dependent are left out): an attachment whose loads reach the frame at
/// several places, e.g. an axle-arm pivot on a cross member whose loads the
/// springs take to both rails.
void AddBracket(fe::Mesh& mesh, int node, const std::vector<fe::Vec3>& points, double radius);

/// Mass, centre of mass and inertia of a mesh of flat 4-node shells (steel
/// and non-structural mass) by 2 x 2 Gauss quadrature over each element's
/// bilinear surface (exact for the mass, first and second moments of flat
/// elements); the thickness's own rotary inertia (order t^2) is neglected.
MassProperties3 ShellMassProperties(const fe::Mesh& mesh);

}  // namespace flexmb::vehicle
