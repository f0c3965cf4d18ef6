#include <climits>
#include <map>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe_io/abaqus/abaqus_builder.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {
namespace {

using fe::ElementType;
using fe::Origin;
using fe::Vec3;

struct TypeInfo {
  Kind kind = Kind::kStructural;
  ElementType type = ElementType::kQuad4;
  bool euler_bernoulli = false;  // B33: no shear flexibility
  bool membrane = false;         // M3D4: a shell under a *MEMBRANE SECTION
  const char* note = nullptr;    // another formulation, read as `type`: the warning's text
  int nodes = 0;
};

// the element types of fe/element_traits.h by their Abaqus names, and the point masses
bool LookupType(const std::string& t, TypeInfo& info) {
  for (const fe::ElementTraits& row : fe::AllElementTraits())
    for (const fe::AbaqusName& a : row.abaqus)
      if (t == a.name) {
        info = {Kind::kStructural, row.type, a.variant == fe::AbaqusVariant::kEulerBernoulli,
                a.variant == fe::AbaqusVariant::kMembrane, a.variant == fe::AbaqusVariant::kOther ? a.note : nullptr,
                row.nodes};
        return true;
      }
  if (t == "MASS") info = {Kind::kMass, ElementType::kQuad4, false, false, nullptr, 1};
  if (t == "ROTARYI") info = {Kind::kRotaryInertia, ElementType::kQuad4, false, false, nullptr, 1};
  if (t == "SPRING1") info = {Kind::kSpring, ElementType::kQuad4, false, false, nullptr, 1};
  if (t == "SPRING2" || t == "SPRINGA") info = {Kind::kSpring, ElementType::kQuad4, false, false, nullptr, 2};
  return t == "MASS" || t == "ROTARYI" || t == "SPRING1" || t == "SPRING2" || t == "SPRINGA";
}

// the names LookupType knows, for messages
std::string SupportedTypes() {
  std::string s;
  for (const fe::ElementTraits& row : fe::AllElementTraits())
    for (const fe::AbaqusName& a : row.abaqus) s += std::string(a.name) + ", ";
  return s + "MASS, ROTARYI, SPRING1, SPRING2, SPRINGA";
}

}  // namespace

// *SYSTEM: the frame of the *NODE coordinates that follow (none: the global frame)
void Builder::System(const Card& c) {
  if (c.data.empty()) {
    sys_r_.setIdentity();
    sys_o_.setZero();
    return;
  }
  std::vector<double> v;
  for (const DataLine& d : c.data)
    for (size_t k = 0; k < d.fields.size(); ++k) v.push_back(RealOr(d, k, c.name, "coordinate", 0.0));
  const Origin& o = c.data.front().origin;
  if (v.size() != 3 && v.size() != 9) Fail(o, c.name, "expects 3 or 9 coordinates, got " + std::to_string(v.size()));
  sys_o_ = Vec3(v[0], v[1], v[2]);
  sys_r_.setIdentity();
  if (v.size() == 9) {
    const Vec3 b(v[3], v[4], v[5]), cc(v[6], v[7], v[8]);
    const Vec3 ex = b - sys_o_, in_plane = cc - sys_o_;
    const Vec3 ez = ex.cross(in_plane);
    if (!(ex.norm() > 0.0) || !(ez.norm() > 1e-12 * ex.norm() * in_plane.norm()))
      Fail(o, c.name, "the three points do not define a coordinate system");
    sys_r_.col(0) = ex.normalized();
    sys_r_.col(2) = ez.normalized();
    sys_r_.col(1) = sys_r_.col(2).cross(sys_r_.col(0));
  }
}

void Builder::Nodes(const Card& c) {
  const fe::Origin& co = c.origin;
  if (const Param* p = c.Find("SYSTEM"))
    if (Upper(p->value) != "R") Fail(co, c.name, "SYSTEM=" + p->value + " is not supported (only R)");
  NamedSet* set = nullptr;
  if (const Param* p = c.Find("NSET")) set = &NewSet(nsets_, p->value, co, c.name);
  for (const DataLine& d : c.data) {
    const int id = Integer(d, 0, c.name, "node id", 1, INT_MAX);
    const std::string entity = "node " + std::to_string(id);
    MaxFields(d, 7, entity);
    Vec3 x(RealOr(d, 1, entity, "x", 0.0), RealOr(d, 2, entity, "y", 0.0), RealOr(d, 3, entity, "z", 0.0));
    x = sys_o_ + sys_r_ * x;
    if (!x.allFinite()) Fail(d.origin, entity, "coordinates overflow");
    auto [it, fresh] = node_origin_.emplace(id, d.origin);
    if (!fresh) Fail(d.origin, entity, "duplicate node id (first defined at " + At(it->second) + ")");
    fe::Node n;
    n.id = id;
    n.x = x;
    n.origin = d.origin;
    mesh_.nodes.push_back(n);
    if (set) set->Add(static_cast<int>(mesh_.nodes.size()) - 1);
  }
}

int Builder::NodeIndex(const DataLine& d, size_t i, const std::string& entity) {
  const int id = Integer(d, i, entity, "node id", 1, INT_MAX);
  const int n = mesh_.NodeIndex(id);
  if (n < 0) Fail(d.origin, entity, "node " + std::to_string(id) + " does not exist");
  return n;
}

void Builder::Elements(const Card& c) {
  const Param* tp = c.Find("TYPE");
  if (tp == nullptr || tp->value.empty()) Fail(c.origin, c.name, "needs TYPE=");
  const std::string type = Upper(NoBlanks(tp->value));
  TypeInfo info;
  if (!LookupType(type, info))
    Fail(c.origin, c.name, "unknown or unsupported element type " + Printable(tp->value) +
                               " (supported: " + SupportedTypes() + ")");
  if (info.note) WarnOnce("type " + type, At(c.origin) + ": " + type + " elements are " + info.note);
  // C3D8: CalculiX's plain full integration, or Abaqus's selectively
  // reduced integration when Abaqus/CAE wrote the deck
  if (type == "C3D8") {
    if (abaqus_cae_) info.type = fe::kHex8Selective;
    WarnOnce("type C3D8",
             At(c.origin) + ": C3D8 elements are read as " +
                 (abaqus_cae_ ? "Abaqus's C3D8 (selectively reduced integration of the volumetric strain), since "
                                "Abaqus/CAE wrote the deck"
                              : "CalculiX's C3D8 (plain 2 x 2 x 2 integration); Abaqus's C3D8 (selectively reduced "
                                "integration, softer in bending) is used for decks with an '** Generated by: "
                                "Abaqus/CAE' line"));
  }
  NamedSet* set = nullptr;
  if (const Param* p = c.Find("ELSET")) set = &NewSet(elsets_, p->value, c.origin, c.name);
  const size_t want = static_cast<size_t>(info.nodes) + 1;
  for (size_t k = 0; k < c.data.size(); ++k) {
    // an element's line may continue on the next lines when it ends with a comma
    DataLine d = c.data[k];
    while (d.continued && d.fields.size() < want && k + 1 < c.data.size()) {
      const DataLine& next = c.data[++k];
      d.fields.insert(d.fields.end(), next.fields.begin(), next.fields.end());
      d.continued = next.continued;
    }
    const int id = Integer(d, 0, c.name, "element id", 1, INT_MAX);
    const std::string entity = type + " element " + std::to_string(id);
    if (d.fields.size() != want)
      Fail(d.origin, entity, "expected " + std::to_string(info.nodes) + " node ids, found " +
                                 std::to_string(d.fields.size() - 1));
    auto prev = element_origin_.find(id);
    if (prev != element_origin_.end())
      Fail(d.origin, entity, "duplicate element id (first defined at " + At(prev->second) + ")");
    element_origin_.emplace(id, d.origin);
    ElementRecord rec;
    if (info.kind == Kind::kStructural) {
      fe::Element e;
      e.id = id;
      e.type = info.type;
      e.origin = d.origin;
      for (int j = 0; j < info.nodes; ++j) e.nodes.push_back(NodeIndex(d, j + 1, entity));
      if (IsBeam(info.type)) e.orientation = Vec3(0.0, 0.0, -1.0);
      rec = {Kind::kStructural, static_cast<int>(mesh_.elements.size())};
      mesh_.elements.push_back(std::move(e));
      euler_.push_back(info.euler_bernoulli);
      membrane_.push_back(info.membrane);
      section_origin_.push_back(Origin{});
    } else {
      MassElement m;
      m.id = id;
      m.kind = info.kind;
      m.node = NodeIndex(d, 1, entity);
      if (info.nodes == 2) m.node_b = NodeIndex(d, 2, entity);
      if (m.node_b == m.node) Fail(d.origin, entity, "both nodes are the same");
      m.origin = d.origin;
      m.type = type;
      rec = {info.kind, static_cast<int>(masses_.size())};
      masses_.push_back(m);
    }
    elements_.emplace(id, rec);
    if (set) set->Add(id);
  }
}

// node index of a deck id, -1 if there is no such node
int Builder::NodeOfId(int64_t id) const {
  return id >= 1 && id <= INT_MAX ? mesh_.NodeIndex(static_cast<int>(id)) : -1;
}

std::string Builder::ElementName(int id) const {
  const ElementRecord& r = elements_.at(id);
  if (r.kind != Kind::kStructural) return masses_[r.index].type + " element " + std::to_string(id);
  return std::string(fe::TypeName(mesh_.elements[r.index].type)) + " element " + std::to_string(id);
}

}  // namespace flexmb::io::abaqus
