#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/abaqus/abaqus_builder.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {
namespace {

using fe::Vec3;

constexpr double kPi = 3.14159265358979323846;

// St. Venant torsion constant of a solid rectangle (series solution)
double RectangleTorsion(double a, double b) {
  const double l = std::max(a, b), s = std::min(a, b);
  double sum = 0.0;
  for (int n = 1; n < 200; n += 2) sum += std::tanh(n * kPi * l / (2.0 * s)) / std::pow(n, 5);
  return l * s * s * s * (1.0 / 3.0 - 64.0 / std::pow(kPi, 5) * (s / l) * sum);
}

// Cowper (1966) shear factor of a thin-walled box for shear parallel to the
// webs: h web depth, t web thickness, b flange width, t1 flange thickness
double CowperBox(double h, double t, double b, double t1, double nu) {
  const double m = b * t1 / (h * t), n = b / h;
  return 10.0 * (1.0 + nu) * (1.0 + 3.0 * m) * (1.0 + 3.0 * m) /
         ((12.0 + 72.0 * m + 150.0 * m * m + 90.0 * m * m * m) +
          nu * (11.0 + 66.0 * m + 135.0 * m * m + 90.0 * m * m * m) + 10.0 * n * n * ((3.0 + nu) * m + 3.0 * m * m));
}

// stress recovery points of a rectangle a (section 1-axis, element y) by
// b (2-axis, element z): its corners, (y, z) from the centroid
std::vector<std::array<double, 2>> AbaqusRectanglePoints(double a, double b) {
  return {{0.5 * a, 0.5 * b}, {-0.5 * a, 0.5 * b}, {-0.5 * a, -0.5 * b}, {0.5 * a, -0.5 * b}};
}

// 8 points on the outer circle of radius r at 45 degree steps from +y
std::vector<std::array<double, 2>> AbaqusCirclePoints(double r) {
  std::vector<std::array<double, 2>> pts;
  for (int k = 0; k < 8; ++k) pts.push_back({r * std::cos(k * kPi / 4.0), r * std::sin(k * kPi / 4.0)});
  return pts;
}

// properties of a library shape; Iy = I11 (about the section 1-axis, n1),
// Iz = I22; shear factors after Cowper (1966)
void ShapeSection(const std::string& shape, const DataLine& d, double nu, const std::string& entity,
                  fe::BeamSection& s) {
  if (shape == "RECT") {
    MaxFields(d, 2, entity);
    const double a = Positive(d, 0, entity, "width a"), b = Positive(d, 1, entity, "height b");
    s.A = a * b;
    s.Iy = a * b * b * b / 12.0;
    s.Iz = b * a * a * a / 12.0;
    s.J = RectangleTorsion(a, b);
    s.ky = s.kz = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
    s.stress_points = AbaqusRectanglePoints(a, b);
  } else if (shape == "CIRC") {
    if (d.fields.size() > 1)
      Fail(d.origin, entity, "SECTION=CIRC with two values (CalculiX's elliptical section, by its two diameters) is "
                             "not supported; Abaqus's CIRC takes one radius");
    MaxFields(d, 1, entity);
    const double r = Positive(d, 0, entity, "radius r");
    s.A = kPi * r * r;
    s.Iy = s.Iz = kPi * r * r * r * r / 4.0;
    s.J = 2.0 * s.Iy;
    s.ky = s.kz = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    s.stress_points = AbaqusCirclePoints(r);
  } else if (shape == "PIPE" || shape == "THICKPIPE") {
    MaxFields(d, 2, entity);
    const double r = Positive(d, 0, entity, "outer radius r"), t = Positive(d, 1, entity, "wall thickness t");
    if (!(t <= r)) Fail(d.origin, entity, "wall thickness t larger than the radius r");
    const double ri = r - t, m = ri / r, m2 = (1.0 + m * m) * (1.0 + m * m);
    s.A = kPi * (r * r - ri * ri);
    s.Iy = s.Iz = kPi * (r * r * r * r - ri * ri * ri * ri) / 4.0;
    s.J = 2.0 * s.Iy;
    s.ky = s.kz = 6.0 * (1.0 + nu) * m2 / ((7.0 + 6.0 * nu) * m2 + (20.0 + 12.0 * nu) * m * m);
    s.stress_points = AbaqusCirclePoints(r);
  } else if (shape == "BOX") {
    MaxFields(d, 6, entity);
    const double a = Positive(d, 0, entity, "width a"), b = Positive(d, 1, entity, "height b");
    const double t1 = Positive(d, 2, entity, "wall t1"), t2 = Positive(d, 3, entity, "wall t2");
    const double t3 = Positive(d, 4, entity, "wall t3"), t4 = Positive(d, 5, entity, "wall t4");
    if (t1 != t3 || t2 != t4)
      Fail(d.origin, entity, "BOX with unequal opposite walls (t1 != t3 or t2 != t4) is not supported: its "
                             "centroid is off the section origin");
    const double tw = t1, tf = t2;
    if (!(2.0 * tw < a) || !(2.0 * tf < b)) Fail(d.origin, entity, "BOX walls thicker than half the width or height");
    const double ai = a - 2.0 * tw, bi = b - 2.0 * tf;
    s.A = a * b - ai * bi;
    s.Iy = (a * b * b * b - ai * bi * bi * bi) / 12.0;
    s.Iz = (b * a * a * a - bi * ai * ai * ai) / 12.0;
    const double am = a - tw, bm = b - tf;
    s.J = 2.0 * tw * tf * am * am * bm * bm / (am * tw + bm * tf);
    s.ky = CowperBox(am, tf, bm, tw, nu);  // shear along 1: webs are the walls t2, t4
    s.kz = CowperBox(bm, tw, am, tf, nu);  // shear along 2: webs are the walls t1, t3
    s.stress_points = AbaqusRectanglePoints(a, b);
  } else {
    Fail(d.origin, entity, "unsupported section shape SECTION=" + shape + " (supported: RECT, CIRC, PIPE, BOX, GENERAL)");
  }
}

// "*CARD (ELSET=name)": the entity named in messages about a section card
std::string SectionEntity(const Card& c) {
  const Param* p = c.Find("ELSET");
  return c.name + " (ELSET=" + (p ? p->value : std::string()) + ")";
}

}  // namespace

void Builder::MaterialCard(const std::vector<Card>& cards, const std::vector<int>& order, int i) {
  const Card& c = cards[i];
  const Param* p = c.Find("NAME");
  if (p == nullptr || p->value.empty()) Fail(c.origin, c.name, "needs NAME=");
  const std::string entity = "material " + p->value;
  fe::Material m;
  m.id = static_cast<int>(mesh_.materials.size()) + 1;
  m.name = p->value;
  m.origin = c.origin;
  bool elastic = false;
  for (int j : order) {
    const Card& s = cards[j];
    if (s.parent != i) continue;
    if (s.key == "ELASTIC") {
      if (const Param* t = s.Find("TYPE"))
        if (Upper(t->value) != "ISOTROPIC" && Upper(t->value) != "ISO")
          Fail(s.origin, entity, "*ELASTIC, TYPE=" + t->value + " is not supported (isotropic only)");
      if (s.data.size() != 1)
        Fail(s.origin, entity, "*ELASTIC needs exactly one data line (temperature-dependent data is not supported)");
      const DataLine& d = s.data[0];
      MaxFields(d, 3, entity);
      m.E = Positive(d, 0, entity, "Young's modulus");
      m.nu = RealOr(d, 1, entity, "Poisson's ratio", 0.0);
      if (!(m.nu > -1.0 && m.nu < 0.5)) Fail(d.origin, entity, "Poisson's ratio must be in (-1, 0.5)");
      m.G = m.E / (2.0 * (1.0 + m.nu));
      elastic = true;
    } else if (s.key == "DENSITY") {
      if (s.data.size() != 1)
        Fail(s.origin, entity, "*DENSITY needs exactly one data line (temperature-dependent data is not supported)");
      MaxFields(s.data[0], 2, entity);
      m.rho = RealReq(s.data[0], 0, entity, "density");
      if (m.rho < 0.0) Fail(s.data[0].origin, entity, "density must not be negative");
    }
  }
  if (!elastic) m.E = 0.0;  // checked when a section uses it
  auto [it, fresh] = materials_.emplace(Upper(m.name), static_cast<int>(mesh_.materials.size()));
  if (!fresh) Fail(c.origin, entity, "defined twice (first at " + At(mesh_.materials[it->second].origin) + ")");
  mesh_.materials.push_back(m);
}

int Builder::MaterialRef(const Card& c, const std::string& entity) {
  const Param* p = c.Find("MATERIAL");
  if (p == nullptr || p->value.empty()) Fail(c.origin, entity, "needs MATERIAL=");
  auto it = materials_.find(Upper(p->value));
  if (it == materials_.end()) Fail(c.origin, entity, "material '" + Printable(p->value) + "' is not defined");
  if (!(mesh_.materials[it->second].E > 0.0))
    Fail(c.origin, entity, "material '" + p->value + "' has no *ELASTIC data");
  return it->second;
}

const NamedSet& Builder::SectionSet(const Card& c, const std::string& entity) {
  const Param* p = c.Find("ELSET");
  if (p == nullptr || p->value.empty()) Fail(c.origin, entity, "needs ELSET=");
  return ElementSetRef(p->value, c.origin, entity);
}

// sets the section of every element of the set; `fits` says whether the family matches
template <class Fits, class Assign>
void Builder::AssignSection(const Card& c, const std::string& entity, const char* family, Fits&& fits,
                            Assign&& assign) {
  const NamedSet& set = SectionSet(c, entity);
  for (int id : set.items) {
    const ElementRecord& r = elements_.at(id);
    if (r.kind != Kind::kStructural || !fits(mesh_.elements[r.index].type))
      Fail(c.origin, entity, ElementName(id) + " is not a " + family + " element");
    fe::Element& e = mesh_.elements[r.index];
    if (e.property >= 0)
      Fail(c.origin, entity, ElementName(id) + " already has a section (from " + At(section_origin_[r.index]) + ")");
    section_origin_[r.index] = c.origin;
    assign(e, r.index);
  }
}

// rods (T3D2) of a *SOLID SECTION: a rod section with the area of the data line
static bool AbaqusIsRod(fe::ElementType t) { return fe::Traits(t).translations_only; }

void Builder::TrussSection(const Card& c, const std::string& entity) {
  fe::BeamSection s;
  s.material = MaterialRef(c, entity);
  s.origin = c.origin;
  if (c.data.empty()) Fail(c.origin, entity, "truss elements need the cross-section area on the next line");
  MaxFields(c.data[0], 1, entity);
  s.A = Positive(c.data[0], 0, entity, "cross-section area");
  s.stress_points = {{0.0, 0.0}};
  s.id = static_cast<int>(mesh_.beam_sections.size()) + 1;
  int index = SameBeamSection(s);
  if (index < 0) {
    index = static_cast<int>(mesh_.beam_sections.size());
    mesh_.beam_sections.push_back(s);
  }
  AssignSection(c, entity, "truss", AbaqusIsRod, [&](fe::Element& e, int) { e.property = index; });
}

void Builder::SolidSection(const Card& c) {
  const std::string entity = SectionEntity(c);
  for (int id : SectionSet(c, entity).items) {
    const ElementRecord& r = elements_.at(id);
    if (r.kind == Kind::kStructural && AbaqusIsRod(mesh_.elements[r.index].type)) return TrussSection(c, entity);
  }
  fe::SolidSection s;
  s.id = static_cast<int>(mesh_.solid_sections.size()) + 1;
  s.material = MaterialRef(c, entity);
  s.origin = c.origin;
  int index = 0;
  while (index < static_cast<int>(mesh_.solid_sections.size()) && mesh_.solid_sections[index].material != s.material)
    ++index;
  if (index == static_cast<int>(mesh_.solid_sections.size())) mesh_.solid_sections.push_back(s);
  AssignSection(c, entity, "solid", IsSolid, [&](fe::Element& e, int) { e.property = index; });
}

// *SHELL SECTION, and *MEMBRANE SECTION (the same syntax) for the membrane
// elements (M3D4): a membrane section has no bending (ShellLaminate::membrane_only)
void Builder::ShellSection(const Card& c) {
  const std::string entity = SectionEntity(c);
  const bool membrane = c.key == "MEMBRANESECTION";
  for (const char* unsupported : {"COMPOSITE", "NODALTHICKNESS", "ORIENTATION"})
    if (c.Find(unsupported)) Fail(c.origin, entity, std::string(unsupported) + " is not supported");
  for (int id : SectionSet(c, entity).items) {
    const ElementRecord& r = elements_.at(id);
    if (r.kind != Kind::kStructural || !IsShell(mesh_.elements[r.index].type) || membrane_[r.index] == membrane)
      continue;
    Fail(c.origin, entity,
         ElementName(id) + (membrane ? " is a shell, not a membrane element (M3D3, M3D4, M3D4R): give it a "
                                       "*SHELL SECTION"
                                     : " is a membrane element: give it a *MEMBRANE SECTION"));
  }
  fe::ShellSection s;
  s.id = static_cast<int>(mesh_.shell_sections.size()) + 1;
  s.material = MaterialRef(c, entity);
  s.origin = c.origin;
  if (c.data.empty()) Fail(c.origin, entity, "needs the thickness on the next line");
  MaxFields(c.data[0], 2, entity);
  s.thickness = Positive(c.data[0], 0, entity, "thickness");
  double offset = 0.0;  // reference surface from the mid-surface, fraction of the thickness
  if (const Param* p = c.Find("OFFSET")) {
    const std::string v = Upper(p->value);
    if (v == "SPOS") {
      offset = 0.5;
    } else if (v == "SNEG") {
      offset = -0.5;
    } else if (v == "MIDSURFACE") {
      offset = 0.0;
    } else {
      offset = Real(p->value, c.origin, entity, "OFFSET");
    }
  }
  if (membrane) {
    if (offset != 0.0) Fail(c.origin, entity, "OFFSET must be 0 (a membrane has no bending to offset)");
    const fe::Material& m = mesh_.materials[s.material];
    s.laminate = std::make_shared<fe::ShellLaminate>(fe::MembraneLaminate(
        fe::IsotropicPlaneStress(m.E, m.nu), m.rho, s.thickness, "*MEMBRANE SECTION at " + At(c.origin)));
  }
  int index = 0;
  for (; index < static_cast<int>(mesh_.shell_sections.size()); ++index) {
    const fe::ShellSection& o = mesh_.shell_sections[index];
    if (o.material == s.material && o.thickness == s.thickness && (o.laminate != nullptr) == membrane) break;
  }
  if (index == static_cast<int>(mesh_.shell_sections.size())) mesh_.shell_sections.push_back(s);
  AssignSection(c, entity, "shell", IsShell, [&](fe::Element& e, int) {
    e.property = index;
    e.shell_offset = -offset * s.thickness;
  });
}

void Builder::BeamSection(const std::vector<Card>& cards, const std::vector<int>& order, int i) {
  const Card& c = cards[i];
  const std::string entity = SectionEntity(c);
  const bool general = c.key == "BEAMGENERALSECTION";
  const Param* sp = c.Find("SECTION");
  const std::string shape = sp ? Upper(NoBlanks(sp->value)) : (general ? "GENERAL" : "");
  if (shape.empty()) Fail(c.origin, entity, "needs SECTION=");
  if (c.data.empty()) Fail(c.origin, entity, "needs the section data on the next line");
  int material = -1;
  if (!general || c.Find("MATERIAL")) {
    if (general && c.Find("DENSITY")) Fail(c.origin, entity, "give either MATERIAL= or DENSITY=, not both");
    material = MaterialRef(c, entity);
    if (general && c.data.size() > 2)
      Fail(c.data[2].origin, entity, "with MATERIAL= the third data line (E, G) is not used; remove it");
  } else {
    // material from the third data line (E, G) and DENSITY=
    if (c.data.size() < 3) Fail(c.origin, entity, "needs E and G on the third data line (or MATERIAL=)");
    const DataLine& d = c.data[2];
    fe::Material m;
    m.id = static_cast<int>(mesh_.materials.size()) + 1;
    m.name = "general section " + (c.Find("ELSET") ? c.Find("ELSET")->value : std::string());
    m.E = Positive(d, 0, entity, "Young's modulus E");
    m.G = Positive(d, 1, entity, "shear modulus G");
    m.nu = m.E / (2.0 * m.G) - 1.0;
    m.rho = 0.0;
    if (const Param* dp = c.Find("DENSITY")) m.rho = Real(dp->value, c.origin, entity, "DENSITY");
    if (m.rho < 0.0) Fail(c.origin, entity, "DENSITY must not be negative");
    m.origin = d.origin;
    material = static_cast<int>(mesh_.materials.size());
    mesh_.materials.push_back(m);
  }
  if (c.data.size() > 3) Fail(c.data[3].origin, entity, "too many data lines");
  const fe::Material& mat = mesh_.materials[material];
  fe::BeamSection s;
  s.material = material;
  s.origin = c.origin;
  const DataLine& d0 = c.data[0];
  if (shape == "GENERAL") {
    if (!general) Fail(c.origin, entity, "SECTION=GENERAL needs *BEAM GENERAL SECTION");
    MaxFields(d0, 7, entity);
    s.A = Positive(d0, 0, entity, "area A");
    s.Iy = Positive(d0, 1, entity, "I11");
    s.Iyz = RealOr(d0, 2, entity, "I12", 0.0);
    s.Iz = Positive(d0, 3, entity, "I22");
    s.J = Positive(d0, 4, entity, "torsion constant J");
    s.ky = s.kz = 1.0;
  } else {
    ShapeSection(shape, d0, mat.nu, entity, s);
    if (shape == "CIRC")
      WarnOnce("CIRC", At(c.origin) + ": " + entity + ": SECTION=CIRC " + d0.fields[0] +
                           " is read as the radius (Abaqus); CalculiX reads it as the diameter, so a CalculiX deck's "
                           "round beam would come out 16 times stiffer in bending: there give it as SECTION=PIPE "
                           "with the radius and a wall as thick as the radius (reported once)");
  }
  // OFFSET1, OFFSET2 (CalculiX): the beam's axis lies -OFFSETk times the
  // section's extent along local k from the node line (OFFSET2 = 0.5: the
  // nodes on the top surface)
  const double offset[2] = {c.Find("OFFSET1") ? Real(c.Find("OFFSET1")->value, c.origin, entity, "OFFSET1") : 0.0,
                            c.Find("OFFSET2") ? Real(c.Find("OFFSET2")->value, c.origin, entity, "OFFSET2") : 0.0};
  const bool offsets = offset[0] != 0.0 || offset[1] != 0.0;
  double extent[2] = {0.0, 0.0};  // the section's size along local 1 and 2
  if (offsets) {
    if (shape == "RECT" || shape == "BOX") {
      extent[0] = Positive(d0, 0, entity, "width a");
      extent[1] = Positive(d0, 1, entity, "height b");
    } else if (shape == "PIPE" || shape == "THICKPIPE") {
      extent[0] = extent[1] = 2.0 * Positive(d0, 0, entity, "radius r");
    } else if (shape == "CIRC") {
      Fail(c.origin, entity, "OFFSET1 / OFFSET2 (CalculiX) with SECTION=CIRC: CalculiX's CIRC value is a diameter, "
                             "Abaqus's a radius; give the section as SECTION=PIPE (radius, wall as thick as the "
                             "radius)");
    } else {
      Fail(c.origin, entity, "OFFSET1 / OFFSET2 need a section with a size (RECT, CIRC, PIPE, BOX), not " + shape);
    }
  }
  Vec3 n1(0.0, 0.0, -1.0);
  if (c.data.size() > 1) {
    const DataLine& d1 = c.data[1];
    MaxFields(d1, 3, entity);
    n1 = Vec3(RealOr(d1, 0, entity, "n1 x", 0.0), RealOr(d1, 1, entity, "n1 y", 0.0),
              RealOr(d1, 2, entity, "n1 z", 0.0));
    if (!(n1.norm() > 0.0)) Fail(d1.origin, entity, "zero orientation vector n1");
  }
  for (int j : order) {
    const Card& t = cards[j];
    if (t.parent != i || t.key != "TRANSVERSESHEARSTIFFNESS") continue;
    if (t.data.empty()) Fail(t.origin, entity, "*TRANSVERSE SHEAR STIFFNESS needs K23, K13");
    const DataLine& d = t.data[0];
    MaxFields(d, 3, entity);
    const double G = mat.G > 0.0 ? mat.G : mat.E / (2.0 * (1.0 + mat.nu));
    s.kz = Positive(d, 0, entity, "K23") / (G * s.A);
    s.ky = Positive(d, 1, entity, "K13") / (G * s.A);
  }
  // one section for the shear-flexible (B31) and one for the Euler-Bernoulli (B33) elements
  int index[2] = {-1, -1};
  AssignSection(c, entity, "beam", [](fe::ElementType t) { return IsBeam(t) && !AbaqusIsRod(t); },
                [&](fe::Element& e, int k) {
                  const int eb = euler_[k] ? 1 : 0;
                  if (index[eb] < 0) {
                    fe::BeamSection v = s;
                    if (eb) v.ky = v.kz = 0.0;
                    v.id = static_cast<int>(mesh_.beam_sections.size()) + 1;
                    index[eb] = SameBeamSection(v);
                    if (index[eb] < 0) {
                      index[eb] = static_cast<int>(mesh_.beam_sections.size());
                      mesh_.beam_sections.push_back(v);
                    }
                  }
                  e.property = index[eb];
                  e.orientation = n1;
                  if (offsets) {
                    const Vec3 axis = mesh_.nodes[e.nodes.back()].x - mesh_.nodes[e.nodes.front()].x;
                    const Vec3 t = axis.normalized(), n1p = n1 - t * t.dot(n1);
                    if (!(axis.norm() > 0.0) || !(n1p.norm() > 1e-8 * n1.norm()))
                      Fail(c.origin, entity, ElementName(e.id) + ": no local axes for OFFSET1 / OFFSET2 (zero length, "
                                                                 "or n1 along the beam)");
                    const Vec3 e1 = n1p.normalized(), e2 = t.cross(e1);
                    e.offset_a = e.offset_b = -(offset[0] * extent[0] * e1 + offset[1] * extent[1] * e2);
                  }
                });
}

// index of an identical beam section, or -1
int Builder::SameBeamSection(const fe::BeamSection& v) const {
  for (size_t k = 0; k < mesh_.beam_sections.size(); ++k) {
    const fe::BeamSection& o = mesh_.beam_sections[k];
    if (o.material == v.material && o.A == v.A && o.Iy == v.Iy && o.Iz == v.Iz && o.Iyz == v.Iyz && o.J == v.J &&
        o.ky == v.ky && o.kz == v.kz && o.nsm == v.nsm)
      return static_cast<int>(k);
  }
  return -1;
}

void Builder::MassCard(const Card& c) {
  const std::string entity = SectionEntity(c);
  const bool rotary = c.key == "ROTARYINERTIA";
  if (c.Find("ORIENTATION")) Fail(c.origin, entity, "ORIENTATION is not supported");
  if (c.data.empty()) Fail(c.origin, entity, "needs its values on the next line");
  const DataLine& d = c.data[0];
  double mass = 0.0;
  fe::Mat3 inertia = fe::Mat3::Zero();
  if (rotary) {
    MaxFields(d, 6, entity);
    const double i11 = RealReq(d, 0, entity, "I11"), i22 = RealReq(d, 1, entity, "I22");
    const double i33 = RealReq(d, 2, entity, "I33"), i12 = RealOr(d, 3, entity, "I12", 0.0);
    const double i13 = RealOr(d, 4, entity, "I13", 0.0), i23 = RealOr(d, 5, entity, "I23", 0.0);
    inertia << i11, i12, i13, i12, i22, i23, i13, i23, i33;
  } else {
    MaxFields(d, 1, entity);
    mass = RealReq(d, 0, entity, "mass");
    if (mass < 0.0) Fail(d.origin, entity, "mass must not be negative");
  }
  const NamedSet& set = SectionSet(c, entity);
  for (int id : set.items) {
    const ElementRecord& r = elements_.at(id);
    if (r.kind != (rotary ? Kind::kRotaryInertia : Kind::kMass))
      Fail(c.origin, entity, ElementName(id) + " is not a " + (rotary ? "ROTARYI" : "MASS") + " element");
    MassElement& m = masses_[r.index];
    if (m.assigned) Fail(c.origin, entity, ElementName(id) + " already has its values");
    m.assigned = true;
    m.mass = mass;
    m.inertia = inertia;
  }
}

// *SPRING (linear): SPRING1 and SPRING2 take their DOF on the first data
// line (integers, as CalculiX tells it from the stiffness line, the blank
// line Abaqus writes for SPRINGA being dropped), then the stiffness
void Builder::SpringCard(const Card& c) {
  const std::string entity = SectionEntity(c);
  if (c.Find("NONLINEAR")) Fail(c.origin, entity, "NONLINEAR springs are not supported (linear springs only)");
  if (c.Find("ORIENTATION")) Fail(c.origin, entity, "ORIENTATION is not supported (springs act in basic axes)");
  if (c.data.empty()) Fail(c.origin, entity, "needs its stiffness on the next line");
  auto integers = [](const DataLine& d) {
    for (const std::string& f : d.fields)
      if (f.find_first_of(".eEdD") != std::string::npos) return false;
    return !d.fields.empty();
  };
  const bool with_dofs = integers(c.data[0]);
  const size_t first = with_dofs ? 1 : 0;
  if (c.data.size() != first + 1)
    Fail(c.origin, entity, c.data.size() <= first ? "needs its stiffness after the degrees of freedom"
                                                  : "needs exactly one stiffness line (temperature-dependent springs are not supported)");
  const DataLine& kd = c.data[first];
  MaxFields(kd, 3, entity);
  const double k = RealReq(kd, 0, entity, "spring stiffness");
  if (!(k >= 0.0)) Fail(kd.origin, entity, "spring stiffness must not be negative");
  const NamedSet& set = SectionSet(c, entity);
  for (int id : set.items) {
    const ElementRecord& r = elements_.at(id);
    if (r.kind != Kind::kSpring) Fail(c.origin, entity, ElementName(id) + " is not a spring element");
    MassElement& m = masses_[r.index];
    if (m.assigned) Fail(c.origin, entity, ElementName(id) + " already has its stiffness");
    const int want = m.type == "SPRINGA" ? 0 : m.type == "SPRING1" ? 1 : 2;
    const int got = with_dofs ? static_cast<int>(c.data[0].fields.size()) : 0;
    if (got != want)
      Fail(with_dofs ? c.data[0].origin : c.origin, entity,
           ElementName(id) + " needs " + std::to_string(want) + " degree(s) of freedom on the line after *SPRING, got " +
               std::to_string(got));
    if (want >= 1) m.dof_a = Integer(c.data[0], 0, entity, "degree of freedom", 1, 6) - 1;
    if (want == 2) m.dof_b = Integer(c.data[0], 1, entity, "degree of freedom", 1, 6) - 1;
    m.k = k;
    m.assigned = true;
  }
}

}  // namespace flexmb::io::abaqus
