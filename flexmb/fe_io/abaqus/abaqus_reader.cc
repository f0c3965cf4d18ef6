#include "flexmb/fe_io/abaqus/abaqus_reader.h"

#include <set>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe_io/abaqus/abaqus_builder.h"
#include "flexmb/fe_io/abaqus/abaqus_deck.h"
#include "flexmb/fe_io/skipped_cards.h"

namespace flexmb::io {
namespace abaqus {
namespace {

void CheckData(const Card& c) {
  for (const DataLine& d : c.data)
    if (!d.error.empty()) Fail(d.origin, c.name, d.error);
}

}  // namespace

fe::Mesh Builder::Build(std::vector<Card>& cards) {
  std::vector<int> order = Filter(cards);
  for (int i : order) {
    const Card& c = cards[i];
    if (c.key == "SYSTEM") System(c);
    if (c.key == "NODE") Nodes(c);
  }
  mesh_.IndexNodes();
  for (int i : order)
    if (cards[i].key == "ELEMENT") Elements(cards[i]);
  for (int i : order) {
    const Card& c = cards[i];
    if (c.key == "NSET") NodeSet(c);
    if (c.key == "ELSET") ElementSet(c);
    if (c.key == "SURFACE") Surface(c);
  }
  for (int i : order)
    if (cards[i].key == "MATERIAL") MaterialCard(cards, order, i);
  for (int i : order) {
    const Card& c = cards[i];
    if (c.key == "SOLIDSECTION") SolidSection(c);
    if (c.key == "SHELLSECTION" || c.key == "MEMBRANESECTION") ShellSection(c);
    if (c.key == "BEAMSECTION" || c.key == "BEAMGENERALSECTION") BeamSection(cards, order, i);
    if (c.key == "MASS" || c.key == "ROTARYINERTIA") MassCard(c);
    if (c.key == "SPRING") SpringCard(c);
  }
  // ties first: they move (adjust) slave nodes onto the master surface
  for (int i : order)
    if (cards[i].key == "TIE") Tie(cards[i]);
  for (int i : order) {
    const Card& c = cards[i];
    if (c.key == "BOUNDARY") Boundary(c);
    if (c.key == "RIGIDBODY") RigidBody(c);
    if (c.key == "COUPLING") Coupling(cards, order, i);
    if (c.key == "EQUATION") Equation(c);
  }
  Finish();
  return std::move(mesh_);
}

void Builder::WarnOnce(const std::string& key, const std::string& message) {
  if (warned_.emplace(key, true).second) LogWarning(message);
}

// drops steps, checks keyword placement, attaches sub-options to parents
std::vector<int> Builder::Filter(std::vector<Card>& cards) {
  static const std::set<std::string> kModel = {
      "NODE", "ELEMENT", "NSET", "ELSET", "SURFACE", "MATERIAL", "SOLIDSECTION", "SHELLSECTION",
      "MEMBRANESECTION", "BEAMSECTION", "BEAMGENERALSECTION", "MASS", "ROTARYINERTIA", "BOUNDARY", "RIGIDBODY",
      "COUPLING", "SYSTEM", "EQUATION", "TIE", "SPRING"};
  static const std::set<std::string> kMaterialSub = {
      "ELASTIC", "DENSITY", "EXPANSION", "CONDUCTIVITY", "SPECIFICHEAT", "PLASTIC", "DAMPING", "CREEP"};
  static const std::set<std::string> kSilent = {
      "HEADING", "PREPRINT", "NODEFILE", "ELFILE", "NODEPRINT", "ELPRINT", "OUTPUT", "NODEOUTPUT",
      "ELEMENTOUTPUT", "CONTACTOUTPUT", "ENERGYPRINT", "RESTART", "FILEFORMAT", "SECTIONCONTROLS",
      "AMPLITUDE", "INITIALCONDITIONS", "PHYSICALCONSTANTS", "SECTIONPOINTS",
      "ENDPART", "ASSEMBLY", "ENDASSEMBLY", "ENDINSTANCE"};
  // keywords that would change the stiffness or mass: reading on without
  // them would give a different model (docs/formats.md)
  static const std::set<std::string> kUnsupported = {
      "MPC", "DASHPOT", "KINEMATICCOUPLING", "DISTRIBUTINGCOUPLING",
      "SHELLGENERALSECTION", "CONNECTORSECTION", "CONNECTORBEHAVIOR", "CONNECTORELASTICITY",
      "GAP", "TRANSFORM", "NONSTRUCTURALMASS", "EMBEDDEDELEMENT", "MATRIXINPUT", "MATRIXASSEMBLE",
      "SUBSTRUCTUREPROPERTY", "GASKETSECTION", "COHESIVESECTION", "FRAMESECTION", "USERELEMENT", "UELPROPERTY",
      "SHELLTOSOLIDCOUPLING", "PRETENSIONSECTION", "ELASTICFOUNDATION"};
  SkippedCards skipped;
  std::vector<int> out;
  int material = -1, section = -1, coupling = -1, parts = 0, instances = 0;
  for (size_t i = 0; i < cards.size(); ++i) {
    Card& c = cards[i];
    // a sub-option belongs to the card index `parent`, which must be set
    auto attach = [&](int parent, const char* missing) {
      if (parent < 0) Fail(c.origin, c.name, missing);
      c.parent = parent;
      CheckData(c);
      CheckParams(c);
      out.push_back(static_cast<int>(i));
    };
    if (c.key == "STEP") {
      const size_t start = i;
      for (++i; i < cards.size() && cards[i].key != "ENDSTEP"; ++i) {
        if (cards[i].key == "BOUNDARY")
          WarnOnce("step boundary", At(cards[i].origin) + ": *BOUNDARY inside a *STEP is ignored; flexmb "
                                                          "reads only model-level boundary conditions");
      }
      if (i >= cards.size()) Fail(cards[start].origin, "*STEP", "no *END STEP");
      material = section = coupling = -1;
      continue;
    }
    if (c.key == "ENDSTEP") Fail(c.origin, c.name, "*END STEP without *STEP");
    if (kMaterialSub.count(c.key)) {
      attach(material, "outside a *MATERIAL definition");
      continue;
    }
    if (c.key == "TRANSVERSESHEARSTIFFNESS") {
      attach(section, "must follow a *BEAM SECTION or *BEAM GENERAL SECTION");
      continue;
    }
    if (c.key == "KINEMATIC" || c.key == "DISTRIBUTING") {
      attach(coupling, "must follow a *COUPLING");
      continue;
    }
    material = section = coupling = -1;
    if (c.key == "MATERIAL") material = static_cast<int>(i);
    if (c.key == "BEAMSECTION" || c.key == "BEAMGENERALSECTION" || c.key == "SHELLSECTION")
      section = static_cast<int>(i);
    if (c.key == "COUPLING") coupling = static_cast<int>(i);
    if (c.key == "PART") {
      if (++parts > 1) Fail(c.origin, c.name, "more than one *PART: flexmb reads one part per deck");
      continue;
    }
    if (c.key == "INSTANCE") {
      if (++instances > 1) Fail(c.origin, c.name, "more than one *INSTANCE: flexmb reads one part per deck");
      CheckData(c);
      for (const DataLine& d : c.data)
        for (const std::string& f : d.fields)
          if (!f.empty() && Real(f, d.origin, c.name, "instance transformation") != 0.0)
            Fail(d.origin, c.name, "instance transformations are not supported");
      continue;
    }
    if (kModel.count(c.key)) {
      CheckData(c);
      CheckParams(c);
      out.push_back(static_cast<int>(i));
      continue;
    }
    if (kSilent.count(c.key)) continue;
    if (kUnsupported.count(c.key)) skipped.Unsupported(c.name, c.origin, c.name);
    else skipped.Ignored(c.name, c.origin);
  }
  skipped.Report("keyword", cards.empty() ? std::string() : cards.front().origin.file);
  return out;
}

// every element has its section, every mass element its values; mass
// elements become point masses, sets the mesh's sets
void Builder::Finish() {
  for (size_t k = 0; k < mesh_.elements.size(); ++k) {
    const fe::Element& e = mesh_.elements[k];
    if (e.property < 0) Fail(e.origin, ElementName(e.id), "no section is assigned to this element");
  }
  for (const MassElement& m : masses_) {
    if (!m.assigned)
      Fail(m.origin, m.type + " element " + std::to_string(m.id),
           m.kind == Kind::kMass            ? "no *MASS is assigned to this element"
           : m.kind == Kind::kSpring        ? "no *SPRING is assigned to this element"
                                            : "no *ROTARY INERTIA is assigned to this element");
  }
  // springs: a component pair, or (SPRINGA) along the line between the nodes
  for (const MassElement& m : masses_) {
    if (m.kind != Kind::kSpring) continue;
    fe::ScalarSpring s;
    s.id = m.id;
    s.node_a = m.node;
    s.component_a = m.dof_a;
    s.node_b = m.node_b;
    s.component_b = m.dof_b;
    s.k = m.k;
    s.origin = m.origin;
    if (m.type == "SPRINGA") {
      const fe::Vec3 d = mesh_.nodes[m.node_b].x - mesh_.nodes[m.node].x;
      if (!(d.norm() > 0.0)) Fail(m.origin, "SPRINGA element " + std::to_string(m.id), "its nodes coincide: no direction");
      const fe::Vec3 e = d.normalized();
      s.directional = true;
      for (int a = 0; a < 3; ++a) s.coef_a[a] = s.coef_b[a] = e[a];
    }
    mesh_.springs.push_back(s);
  }
  // a ROTARYI element joins the MASS element on the same node defined just before it
  for (const MassElement& m : masses_) {
    if (m.kind == Kind::kSpring) continue;
    if (m.kind == Kind::kRotaryInertia && !mesh_.point_masses.empty()) {
      fe::PointMass& last = mesh_.point_masses.back();
      if (last.node == m.node && last.inertia.isZero(0.0) && last.mass > 0.0) {
        last.inertia = m.inertia;
        continue;
      }
    }
    fe::PointMass pm;
    pm.id = m.id;
    pm.node = m.node;
    pm.mass = m.mass;
    pm.inertia = m.inertia;
    pm.origin = m.origin;
    mesh_.point_masses.push_back(pm);
  }
  for (auto& [key, set] : nsets_) mesh_.node_sets[set.name] = set.items;
  for (auto& [key, set] : elsets_) {
    std::vector<int>& out = mesh_.element_sets[set.name];
    for (int id : set.items) {
      const ElementRecord& r = elements_.at(id);
      if (r.kind == Kind::kStructural) out.push_back(r.index);
    }
  }
}

}  // namespace abaqus

fe::Mesh ReadAbaqus(const std::string& path) {
  std::vector<abaqus::Card> cards = abaqus::ReadCards(path);
  abaqus::Builder b(path, abaqus::WrittenByAbaqusCae(path));
  return b.Build(cards);
}

}  // namespace flexmb::io
