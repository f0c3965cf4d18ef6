#pragma once
/// \file abaqus_builder.h
/// The model layer of the Abaqus / CalculiX input deck reader (internal to
/// flexmb/io): turns the cards of abaqus_deck.h into an fe::Mesh. Its
/// members are defined by topic: abaqus_reader.cc (card order, final
/// checks), abaqus_mesh.cc (nodes, elements), abaqus_sets.cc (sets,
/// surfaces), abaqus_sections.cc (materials, sections, masses) and
/// abaqus_constraints.cc (boundary conditions, rigid bodies, couplings,
/// equations) and abaqus_tie.cc (tied surfaces).

#include <map>
#include <string>
#include <unordered_set>
#include <vector>

#include <Eigen/Dense>

#include "flexmb/fe/mesh.h"
#include "flexmb/fe_io/abaqus/abaqus_deck.h"

namespace flexmb::io::abaqus {

/// What an element line makes: a structural element, a point-mass part or a
/// spring (SPRING1, SPRING2, SPRINGA).
enum class Kind { kStructural, kMass, kRotaryInertia, kSpring };

/// Where an element id of the deck went.
struct ElementRecord {
  Kind kind;  ///< structural or mass part
  int index;  ///< into mesh.elements, or into the mass elements
};

/// A node or element set: items in the order first added, no repeats.
struct NamedSet {
  std::string name;  ///< spelling of the first definition
  std::vector<int> items;
  std::unordered_set<int> seen;
  /// Appends `v` unless it is already in the set.
  void Add(int v) {
    if (seen.insert(v).second) items.push_back(v);
  }
};

/// A MASS, ROTARYI or spring element, waiting for its *MASS / *ROTARY
/// INERTIA / *SPRING.
struct MassElement {
  int id = 0;
  Kind kind = Kind::kMass;
  int node = -1;
  int node_b = -1;                            ///< SPRING2, SPRINGA: the second node
  bool assigned = false;
  double mass = 0.0;                          ///< [kg]
  fe::Mat3 inertia = fe::Mat3::Zero();        ///< [kg m^2], basic frame
  double k = 0.0;                             ///< springs [N/m or N m/rad]
  int dof_a = 0, dof_b = 0;                   ///< SPRING1, SPRING2: components 0..5
  fe::Origin origin;
  std::string type;                           ///< "MASS", "ROTARYI", "SPRING1", "SPRING2" or "SPRINGA"
};

/// One face of an element-based surface: its element and its nodes (node
/// indices in Abaqus face order: corners, then mid-side nodes).
struct SurfaceFace {
  int element_id = 0;
  std::vector<int> nodes;
};

/// Builds the mesh of one deck; see ReadAbaqus for what it accepts.
class Builder {
 public:
  /// `path` becomes mesh.source.
  /// `abaqus_cae`: the deck was written by Abaqus/CAE, so its C3D8 are
  /// Abaqus's (selectively reduced integration), not CalculiX's.
  Builder(const std::string& path, bool abaqus_cae) : abaqus_cae_(abaqus_cae) { mesh_.source = path; }

  /// Interprets `cards` (sub-options get their parent set) in the order
  /// nodes, elements, sets, materials, sections, constraints; throws
  /// InputError naming file, line and entity on bad input.
  fe::Mesh Build(std::vector<Card>& cards);

 private:
  fe::Mesh mesh_;
  bool abaqus_cae_ = false;
  std::map<int, fe::Origin> node_origin_;           // id -> first definition
  std::map<int, fe::Origin> element_origin_;        // id -> first definition
  std::map<int, ElementRecord> elements_;           // id -> record
  std::vector<bool> euler_;                         // per mesh element: B33
  std::vector<bool> membrane_;                      // per mesh element: a membrane name (M3D4)
  std::vector<MassElement> masses_;
  std::map<std::string, NamedSet> nsets_, elsets_;  // upper-case name -> set
  std::map<std::string, std::vector<int>> surfaces_;
  std::map<std::string, std::vector<double>> surface_weights_;  // per surface node: area share (faces) or weight
  std::map<std::string, std::vector<SurfaceFace>> surface_faces_;  // element-based surfaces: their faces
  std::map<std::string, fe::Origin> ties_;          // upper-case *TIE name -> its card
  std::map<std::string, int> materials_;            // upper-case name -> index
  std::map<std::string, bool> warned_;
  std::vector<fe::Origin> section_origin_;          // per mesh element: where its section was assigned
  Eigen::Matrix3d sys_r_ = Eigen::Matrix3d::Identity();
  fe::Vec3 sys_o_ = fe::Vec3::Zero();
  std::map<int, int> constraint_of_node_;           // node index -> index in mesh.constraints
  int link_count_ = 0;

  // abaqus_reader.cc
  void WarnOnce(const std::string& key, const std::string& message);
  std::vector<int> Filter(std::vector<Card>& cards);
  void Finish();

  // abaqus_mesh.cc
  void System(const Card& c);
  void Nodes(const Card& c);
  int NodeIndex(const DataLine& d, size_t i, const std::string& entity);
  int NodeOfId(int64_t id) const;
  void Elements(const Card& c);
  std::string ElementName(int id) const;

  // abaqus_sets.cc (the template SetItems is defined and used there only)
  NamedSet& NewSet(std::map<std::string, NamedSet>& sets, const std::string& name, const fe::Origin& o,
                   const std::string& entity);
  NamedSet* FindSet(std::map<std::string, NamedSet>& sets, const std::string& name);
  NamedSet& NodeSetRef(const std::string& name, const fe::Origin& o, const std::string& entity);
  NamedSet& ElementSetRef(const std::string& name, const fe::Origin& o, const std::string& entity);
  void AddElementNodes(const NamedSet& es, NamedSet& out);
  std::vector<int> NodesOf(const std::string& f, const fe::Origin& o, const std::string& entity);
  template <class Exists, class Add, class Copy>
  void SetItems(const Card& c, const std::string& entity, const char* what, Exists&& exists, Add&& add,
                Copy&& copy_set);
  void NodeSet(const Card& c);
  void ElementSet(const Card& c);
  void Surface(const Card& c);

  // abaqus_sections.cc (the template AssignSection is defined and used there only)
  void MaterialCard(const std::vector<Card>& cards, const std::vector<int>& order, int i);
  int MaterialRef(const Card& c, const std::string& entity);
  const NamedSet& SectionSet(const Card& c, const std::string& entity);
  template <class Fits, class Assign>
  void AssignSection(const Card& c, const std::string& entity, const char* family, Fits&& fits, Assign&& assign);
  void SolidSection(const Card& c);
  void TrussSection(const Card& c, const std::string& entity);
  void ShellSection(const Card& c);
  void BeamSection(const std::vector<Card>& cards, const std::vector<int>& order, int i);
  int SameBeamSection(const fe::BeamSection& v) const;
  void MassCard(const Card& c);
  void SpringCard(const Card& c);

  // abaqus_constraints.cc
  void Boundary(const Card& c);
  int RefNode(const Card& c, const std::string& entity);
  void AddLink(int ref, const std::vector<int>& nodes, int mask, const fe::Origin& o, const std::string& entity);
  void RigidBody(const Card& c);
  void Coupling(const std::vector<Card>& cards, const std::vector<int>& order, int i);
  void Equation(const Card& c);

  // abaqus_tie.cc
  void Tie(const Card& c);
};

}  // namespace flexmb::io::abaqus
