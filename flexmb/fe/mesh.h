#pragma once
/// \file mesh.h
/// A linear finite-element model of one part: nodes, elements, properties,
/// materials, sets, single-point constraints, rigid links, linear
/// multi-point constraints and concentrated
/// masses. Entities keep the ids of the file they came from; element and
/// link connectivity refers to node *indices* (positions in Mesh::nodes).
/// Units are whatever the source uses, consistently; flexmb's own models are
/// SI (m, kg, s, N, Pa).

#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/fe/laminate.h"

namespace flexmb::fe {

/// Names of the six DOF components of a node, in DOF order (translations
/// then rotations), for messages and file headers.
inline constexpr const char* kDofComponentNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

/// Corner nodes (local 0..3) at the ends of the edges that carry the
/// mid-edge nodes 4..9 of a 10-node tetrahedron, in that order.
inline constexpr int kTet10EdgeCorners[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
/// 6 x 6 matrix in a node's DOF order (ux uy uz rx ry rz).
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// Where an entity was defined, for messages ("frame.bdf:1234").
struct Origin {
  std::string file;
  int line = 0;
};

/// A grid point. Coordinates are in the basic (global) frame.
struct Node {
  int id = 0;        ///< id in the source file (> 0)
  Vec3 x = Vec3::Zero();  ///< position [m]
  Origin origin;
};

/// Isotropic linear elastic material (Nastran MAT1).
struct Material {
  int id = 0;
  std::string name;
  double E = 0.0;    ///< Young's modulus [Pa]
  double nu = 0.0;   ///< Poisson's ratio
  double G = 0.0;    ///< shear modulus [Pa]; E / (2 (1 + nu)) if not given
  double rho = 0.0;  ///< density [kg/m^3]
  Origin origin;
};

/// Element types, described by the rows of fe/element_traits.h; later types are ids declared with their element.
enum class ElementType {
  kQuad4,   ///< 4-node shell (CQUAD4, S4), 6 DOF per node
  kTria3,   ///< 3-node shell (CTRIA3, S3), 6 DOF per node
  kBeam2,   ///< 2-node Timoshenko beam (CBAR, CBEAM, B31), 6 DOF per node
  kTet4,    ///< 4-node tetrahedron (CTETRA, C3D4), 3 DOF per node
  kTet10,   ///< 10-node tetrahedron (CTETRA, C3D10), 3 DOF per node
  kHex8,    ///< 8-node hexahedron with incompatible modes (CHEXA, C3D8I), 3 DOF per node
};

/// Number of nodes of an element type.
int NodeCount(ElementType type);
/// Translational-only (3) or full (6) nodal DOF of an element type.
int DofsPerNode(ElementType type);
/// Name for messages ("CQUAD4-like shell").
const char* TypeName(ElementType type);

/// Shell section (PSHELL): thickness, material, non-structural mass.
struct ShellSection {
  int id = 0;
  int material = -1;          ///< index into Mesh::materials
  double thickness = 0.0;     ///< [m]
  double nsm = 0.0;           ///< non-structural mass per area [kg/m^2]
  /// A laminated or generalized section (PCOMP, PCOMPG; a PSHELL with a
  /// bending ratio, its own shear stiffness or a MID4 coupling; a membrane:
  /// a PSHELL without MID2, an Abaqus *MEMBRANE SECTION): the equivalent single layer
  /// in the section's material axes, used instead of `material` (-1 for
  /// plies) and `thickness` (the total); null for a plain shell.
  std::shared_ptr<const ShellLaminate> laminate;
  Origin origin;
};

/// Beam section (PBAR, PBARL, PBEAM at one station): properties in the
/// element frame (x along the axis, y from the orientation vector).
struct BeamSection {
  int id = 0;
  int material = -1;          ///< index into Mesh::materials
  double A = 0.0;             ///< area [m^2]
  double Iy = 0.0, Iz = 0.0;  ///< second moments about element y and z [m^4]
  double Iyz = 0.0;           ///< product of inertia [m^4]
  double J = 0.0;             ///< torsion constant [m^4]
  double ky = 0.0, kz = 0.0;  ///< shear factors (area ratio); 0 = no shear flexibility
  double nsm = 0.0;           ///< non-structural mass per length [kg/m]
  /// The neutral axis (y, z) from the beam's axis, element frame [m]
  /// (Nastran PBEAM N1, N2): the beam axis (the nodes' line plus end offsets)
  /// is the shear centre's; axial force and bending act about the neutral
  /// axis, which carries the structural mass; A, Iy, Iz, Iyz are about it.
  std::array<double, 2> neutral_axis{};
  /// The centre of the non-structural mass (y, z) from the beam's axis,
  /// element frame [m] (PBEAM M1, M2).
  std::array<double, 2> nsm_offset{};
  /// Polar moment of inertia of the non-structural mass about its centre,
  /// per length [kg m] (PBEAM NSI).
  double nsm_inertia = 0.0;
  /// True if the neutral axis or the non-structural mass lies off the beam
  /// axis, or the non-structural mass has an inertia of its own.
  bool HasAxisOffsets() const {
    return neutral_axis[0] != 0.0 || neutral_axis[1] != 0.0 || nsm_offset[0] != 0.0 || nsm_offset[1] != 0.0 ||
           nsm_inertia != 0.0;
  }
  /// Stress recovery points of the section, (y, z) in the element frame
  /// from the beam axis [m] (the centroid, unless `neutral_axis` is set:
  /// then the shear centre, as PBEAM gives them): Nastran's C, D, E, F of PBAR/PBEAM, the corners
  /// of a library shape (PBARL, Abaqus *BEAM SECTION), points on the outer
  /// circle of round shapes; empty when the source gives none. The normal
  /// stress of bending is largest at one of them (reduction/stress_modes.h).
  std::vector<std::array<double, 2>> stress_points;
  Origin origin;
};

/// Solid section (PSOLID): material only.
struct SolidSection {
  int id = 0;
  int material = -1;
  Origin origin;
};

/// One element. `property` indexes the section list of its family (shell,
/// beam or solid sections).
struct Element {
  int id = 0;
  ElementType type = ElementType::kQuad4;
  int property = -1;
  std::vector<int> nodes;             ///< node indices, in the source's order
  Vec3 orientation = Vec3::Zero();    ///< beams: vector in the x-y plane of the element frame
  Vec3 offset_a = Vec3::Zero();       ///< beams: offset of end A from its node, basic frame [m]
  Vec3 offset_b = Vec3::Zero();       ///< beams: offset of end B
  double shell_offset = 0.0;          ///< shells: offset of the mid-surface along the normal [m]
  double shell_theta = 0.0;           ///< shells: the material x axis from the G1-G2 edge [rad] (laminates)
  Origin origin;
};

/// Concentrated mass with inertia (CONM2): mass at an offset from its node;
/// inertia about the mass's own centre, basic axes. Or, if `general`, a
/// general symmetric 6 x 6 nodal mass matrix (CONM1) in `matrix`, basic
/// axes, DOF order ux uy uz rx ry rz [kg, kg m, kg m^2]; mass, offset and
/// inertia are then unused (zero).
struct PointMass {
  int id = 0;
  int node = -1;                  ///< node index
  double mass = 0.0;              ///< [kg]
  Vec3 offset = Vec3::Zero();     ///< from the node, basic frame [m]
  Mat3 inertia = Mat3::Zero();    ///< about the mass centre [kg m^2]
  bool general = false;           ///< the mass is `matrix` (CONM1)
  Mat6 matrix = Mat6::Zero();     ///< general nodal mass matrix, basic axes
  Origin origin;
};

/// Scalar spring (CELAS1, CELAS2): stiffness k between component
/// `component_a` of node `node_a` and component `component_b` of node
/// `node_b`, or to ground if node_b < 0. Components 0..5 are ux uy uz rx ry
/// rz in the basic frame. It adds k to K at (a, a) and (b, b) and -k at
/// (a, b) and (b, a); it has no mass and no mesh cell.
/// A `directional` spring acts instead on the generalized displacements
/// g_a = coef_a . u(node_a) and g_b = coef_b . u(node_b) (all six DOF of
/// each node, basic frame): energy k (g_a - g_b)^2 / 2, or k g_a^2 / 2 when
/// grounded; the components are then unused. Nastran CELAS along an axis of
/// a displacement system (GRID CD) and each of the six springs of a CBUSH.
struct ScalarSpring {
  int id = 0;
  int node_a = -1;                ///< node index
  int component_a = 0;            ///< 0..5
  int node_b = -1;                ///< node index, -1: grounded
  int component_b = 0;            ///< 0..5 (unused if grounded)
  double k = 0.0;                 ///< [N/m] for translations, [N m/rad] for rotations
  bool directional = false;       ///< use coef_a, coef_b instead of the components
  std::array<double, 6> coef_a{}; ///< g_a = coef_a . (ux uy uz rx ry rz of node_a) [1 or m]
  std::array<double, 6> coef_b{}; ///< g_b = coef_b . (DOF of node_b), unused if grounded
  Origin origin;
};

/// Rigid link (RBE2): the listed DOF (subset of 1..6, as a bit mask, bit k =
/// DOF k+1) of each dependent node follow the independent node rigidly.
struct RigidLink {
  int id = 0;
  int independent = -1;           ///< node index
  std::vector<int> dependent;     ///< node indices
  int dofs = 0b111111;            ///< component mask
  Origin origin;
};

/// One term of a linear constraint: coef * u(node, component).
struct MpcTerm {
  int node = -1;                  ///< node index
  int component = 0;              ///< 0..5 (ux uy uz rx ry rz, basic frame)
  double coef = 0.0;              ///< [m/m, m/rad, rad/m or rad/rad, as the components pair]
};

/// Linear multi-point constraint: the dependent DOF u(node, component) =
/// sum of the terms over independent DOF. One row of an RBE3
/// (fe/linear_constraint.h), Nastran MPC or Abaqus *EQUATION; it adds no
/// stiffness, it is eliminated master-slave like the rigid links.
struct LinearConstraint {
  int id = 0;                     ///< id of the card it came from (the RBE3's EID)
  std::string card = "MPC";       ///< card name, for messages ("RBE3")
  int node = -1;                  ///< dependent node index
  int component = 0;              ///< dependent component 0..5
  std::vector<MpcTerm> terms;     ///< independent DOF and coefficients
  Origin origin;
};

/// Single-point constraint: the masked DOF of a node are fixed at zero.
struct Constraint {
  int node = -1;                  ///< node index
  int dofs = 0b111111;            ///< component mask
  Origin origin;
};

/// A linear FE model of one part.
struct Mesh {
  std::string source;                       ///< file it was read from
  std::vector<Node> nodes;
  std::vector<Element> elements;
  std::vector<Material> materials;
  std::vector<ShellSection> shell_sections;
  std::vector<BeamSection> beam_sections;
  std::vector<SolidSection> solid_sections;
  std::vector<PointMass> point_masses;
  std::vector<ScalarSpring> springs;        ///< assembled into K with the elements
  std::vector<RigidLink> rigid_links;
  std::vector<LinearConstraint> linear_constraints;  ///< RBE3 rows and other MPC
  std::vector<Constraint> constraints;
  std::map<std::string, std::vector<int>> node_sets;     ///< name -> node indices
  std::map<std::string, std::vector<int>> element_sets;  ///< name -> element indices

  /// Index of the node with this id, or -1.
  int NodeIndex(int id) const;
  /// Rebuilds the id -> index map (call after adding nodes).
  void IndexNodes();

 private:
  std::map<int, int> node_index_;
};

}  // namespace flexmb::fe
