#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

using fe::Mat3;
using fe::Vec3;

namespace {

// local rectangular coordinates of a point given in a system's own coordinates
Vec3 LocalRect(char kind, const Vec3& c) {
  const double deg = M_PI / 180.0;
  if (kind == 'C') return Vec3(c[0] * std::cos(c[1] * deg), c[0] * std::sin(c[1] * deg), c[2]);
  if (kind == 'S')
    return Vec3(c[0] * std::sin(c[1] * deg) * std::cos(c[2] * deg),
                c[0] * std::sin(c[1] * deg) * std::sin(c[2] * deg), c[0] * std::cos(c[1] * deg));
  return c;
}

}  // namespace

Mat3 Columns(const Vec3& c0, const Vec3& c1, const Vec3& c2) {
  Mat3 m;
  m.col(0) = c0;
  m.col(1) = c1;
  m.col(2) = c2;
  return m;
}

Vec3 ToBasic(const CoordSys& cs, const Vec3& coords) { return cs.origin + cs.R * LocalRect(cs.kind, coords); }

// the system's unit axes at a point (basic position): R for rectangular,
// (e_r, e_theta, e_z) for cylindrical, (e_r, e_theta, e_phi) for spherical
Mat3 BasisAt(const CoordSys& cs, const Vec3& x) {
  const Vec3 l = cs.R.transpose() * (x - cs.origin);
  if (cs.kind == 'C') {
    const double t = std::atan2(l.y(), l.x());
    return cs.R * Columns(Vec3(std::cos(t), std::sin(t), 0.0), Vec3(-std::sin(t), std::cos(t), 0.0),
                           Vec3::UnitZ());
  }
  if (cs.kind == 'S') {
    const double p = std::atan2(l.y(), l.x());
    const double t = std::atan2(std::hypot(l.x(), l.y()), l.z());
    return cs.R * Columns(Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)),
                           Vec3(std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), -std::sin(t)),
                           Vec3(-std::sin(p), std::cos(p), 0.0));
  }
  return cs.R;
}

void Builder::AddDefaults(const Entry& e) {
  const Card** slot = e.name() == "GRDSET" ? &grdset_ : e.name() == "BAROR" ? &baror_ : &beamor_;
  if (*slot) e.Fail("only one " + e.name() + " card is allowed (first at " +
                    deck_.files[(*slot)->file] + ":" + std::to_string((*slot)->line) + ")");
  *slot = &e.card();
}

void Builder::AddCoord(const Entry& e) {
  const int id = e.Id(1, "CID");
  if (coords_.count(id)) {
    const Card* first = coords_[id].card;
    e.Fail(1, "duplicate coordinate system id " + std::to_string(id) + " (first defined at " +
                  deck_.files[first->file] + ":" + std::to_string(first->line) + ")");
  }
  CoordSys cs;
  cs.card = &e.card();
  if (e.name().rfind("CORD2", 0) != 0) {
    cs.kind = 0;  // recorded so that a reference to it gets a clear message
    coords_[id] = cs;
    return;
  }
  cs.kind = e.name()[5];
  cs.rid = e.Int(2, "RID", 0);
  if (cs.rid < 0) e.Fail(2, "RID must not be negative");
  cs.a = Vec3(e.Real(3, "A1", 0.0), e.Real(4, "A2", 0.0), e.Real(5, "A3", 0.0));
  cs.b = Vec3(e.Real(6, "B1", 0.0), e.Real(7, "B2", 0.0), e.Real(8, "B3", 0.0));
  cs.c = Vec3(e.Real(9, "C1", 0.0), e.Real(10, "C2", 0.0), e.Real(11, "C3", 0.0));
  coords_[id] = cs;
}

// resolves a system and the chain of systems it refers to (iteratively)
void Builder::Resolve(CoordSys& target) {
  std::vector<CoordSys*> chain{&target};
  while (true) {
    CoordSys& cs = *chain.back();
    if (cs.state == 2 || cs.kind == 0) break;
    if (cs.state == 1) {
      const Entry e(*cs.card, deck_);
      e.Fail(2, "coordinate systems refer to each other in a cycle (RID " + std::to_string(cs.rid) + ")");
    }
    cs.state = 1;
    if (cs.rid == 0) break;
    const Entry e(*cs.card, deck_);
    Coord(e, 2, cs.rid);  // exists and is supported
    chain.push_back(&coords_.at(cs.rid));
  }
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    CoordSys& cs = **it;
    if (cs.state == 2 || cs.kind == 0) continue;
    CoordSys basic;
    const CoordSys& ref = cs.rid == 0 ? basic : coords_.at(cs.rid);
    const Vec3 a = ToBasic(ref, cs.a), b = ToBasic(ref, cs.b), c = ToBasic(ref, cs.c);
    const Entry e(*cs.card, deck_);
    const double scale = std::max({a.norm(), b.norm(), c.norm(), 1e-300});
    if (!a.allFinite() || !b.allFinite() || !c.allFinite()) e.Fail("defining points are not finite");
    const Vec3 ez = b - a;
    if (!(ez.norm() > 1e-12 * scale)) e.Fail(6, "points A and B coincide: no z axis");
    const Vec3 z = ez.normalized();
    const Vec3 xr = (c - a) - z * z.dot(c - a);
    if (!(xr.norm() > 1e-9 * std::max((c - a).norm(), 1e-300)) || !((c - a).norm() > 1e-12 * scale))
      e.Fail(9, "point C lies on the z axis (line A-B): no x-z plane");
    const Vec3 x = xr.normalized();
    cs.origin = a;
    cs.R = Columns(x, z.cross(x), z);
    cs.state = 2;
  }
}

void Builder::AddMaterial(const Entry& e) {
  const int id = e.Id(1, "MID");
  CheckNewId(material_origin_, e, id, "material");
  if (e.name() == "MAT8") return AddMat8(e, id);
  if (e.name() == "MAT2") return AddMat2(e, id);
  if (e.name() != "MAT1") {
    other_materials_[id] = e.name();
    return;
  }
  // Nastran's rule (QRG MAT1, remark 3): one missing of E, G, NU follows
  // from E = 2 (1 + NU) G; E alone or G alone sets the other two to 0
  const bool has_e = !e.Blank(2), has_g = !e.Blank(3), has_nu = !e.Blank(4);
  double E = e.Real(2, "E", 0.0), G = e.Real(3, "G", 0.0), nu = e.Real(4, "NU", 0.0);
  if (!has_e && !has_g) e.Fail(2, "E and G are both blank");
  if (has_e && !has_g && !has_nu)
    e.Fail(2, "only E is given: Nastran then sets G = NU = 0 (no shear stiffness), which flexmb's "
              "elements do not support (unsupported); give NU or G as well");
  if (!has_e && has_g && !has_nu)
    e.Fail(3, "only G is given: Nastran then sets E = NU = 0, which flexmb's elements do not support "
              "(unsupported); give E or NU as well");
  Positive(e, has_e ? 2 : 3, has_e ? "E" : "G", has_e ? E : G);
  if (has_g) Positive(e, 3, "G", G);
  if (!has_nu) nu = E / (2.0 * G) - 1.0;
  if (!has_g) G = E / (2.0 * (1.0 + nu));
  if (!has_e) E = 2.0 * (1.0 + nu) * G;
  if (!(nu > -1.0 && nu < 0.5))
    e.Fail(4, "Poisson's ratio NU = " + Str(nu) + " is outside (-1, 0.5)" +
                  (has_nu ? "" : " (computed from E and G)"));
  Positive(e, 2, "E", E);
  Positive(e, 3, "G", G);
  if (has_e && has_g && has_nu && std::abs(E / (2.0 * (1.0 + nu) * G) - 1.0) > 0.01)
    Warn(e, "E, G and NU do not satisfy E = 2 (1 + NU) G within 1%; used as given", "MAT1 E G NU");
  fe::Material m;
  m.id = id;
  m.E = E;
  m.G = G;
  m.nu = nu;
  m.rho = NonNegative(e, 5, "RHO", e.Real(5, "RHO", 0.0));
  for (int f = 6; f <= 8; ++f) e.Real(f, "A, TREF or GE", 0.0);
  m.origin = OriginOf(e);
  materials_[id] = static_cast<int>(mesh_.materials.size());
  mesh_.materials.push_back(m);
}

void Builder::AddGrid(const Entry& e) {
  const Entry* defaults = nullptr;
  std::optional<Entry> grdset;
  if (grdset_) defaults = &grdset.emplace(*grdset_, deck_);
  const int id = e.Id(1, "ID");
  // blank CP, CD and PS take the GRDSET values
  const int cp = e.Blank(2) && defaults ? defaults->Int(2, "CP", 0) : e.Int(2, "CP", 0);
  const int cd = e.Blank(6) && defaults ? defaults->Int(6, "CD", 0) : e.Int(6, "CD", 0);
  if (cp < 0) e.Fail(2, "CP must not be negative");
  if (cd < 0) e.Fail(6, "CD = " + std::to_string(cd) + " (fluid grid points) is not supported");
  const Vec3 x(e.Real(3, "X1", 0.0), e.Real(4, "X2", 0.0), e.Real(5, "X3", 0.0));
  fe::Node node;
  node.id = id;
  node.x = cp == 0 ? x : ToBasic(Coord(e, 2, cp), x);
  if (!node.x.allFinite()) e.Fail(3, "position is not finite");
  if (cd > 0) Coord(e, 6, cd);
  node.origin = OriginOf(e);
  const auto [it, inserted] = nodes_.emplace(id, static_cast<int>(mesh_.nodes.size()));
  if (!inserted)
    e.Fail(1, "duplicate GRID id " + std::to_string(id) + " (first defined at " +
                  Where(mesh_.nodes[it->second].origin) + ")");
  mesh_.nodes.push_back(node);
  node_cd_.push_back(cd);
  // PS: permanent single-point constraints
  const Entry& ps = e.Blank(7) && defaults ? *defaults : e;
  if (!ps.Blank(7)) {
    const int mask = Components(ps, 7, "PS");
    AddFixed(e, it->second, mask);
  }
  e.Int(8, "SEID", 0);
}

}  // namespace flexmb::io::nastran
