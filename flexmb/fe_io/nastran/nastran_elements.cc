#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

using fe::Mat3;
using fe::Vec3;

namespace {

// the rows of fe/element_traits.h read from Nastran card `card`
std::vector<const fe::ElementTraits*> NastranRows(const std::string& card) {
  std::vector<const fe::ElementTraits*> rows;
  for (const fe::ElementTraits& t : fe::AllElementTraits())
    for (const char* c : t.nastran_cards)
      if (card == c) rows.push_back(&t);
  return rows;
}

}  // namespace

fe::Element Builder::NewElement(const Entry& e, fe::ElementType type) {
  fe::Element el;
  el.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, el.id, "element");
  el.type = type;
  el.origin = OriginOf(e);
  return el;
}

void Builder::ReadNodes(const Entry& e, fe::Element& el, int first, int count) {
  for (int k = 0; k < count; ++k) {
    std::string what = "G";
    what += std::to_string(k + 1);
    const int n = NodeIndex(e, first + k, what.c_str());
    for (int m : el.nodes)
      if (m == n) e.Fail(first + k, "node " + e.Text(first + k) + " appears twice");
    el.nodes.push_back(n);
  }
}

void Builder::AddShell(const Entry& e) {
  const fe::ElementTraits& row = *NastranRows(e.name()).front();
  // CQUADR, CTRIAR: Nastran's shells with a drilling DOF of their own
  // formulation; flexmb's shells carry a drilling stiffness as well
  if (e.name() == "CQUADR" || e.name() == "CTRIAR")
    Warn(e,
         e.name() + " elements are read as flexmb's " + row.description +
             " (membrane, bending and shear as CQUAD4 / CTRIA3; the drilling stiffness differs from Nastran's)",
         e.name());
  fe::Element el = NewElement(e, row.type);
  const int nn = row.nodes;
  const int pid = e.Int(2, "PID", el.id);
  el.property = PropertyIndex(e, 2, pid, {"PSHELL", "PCOMP", "PCOMPG"});
  // fields after the grid points (QRG): CQUAD4, CTRIA3: THETA, ZOFFS, -, -,
  // TFLAG, T1..; CQUAD8: T1-T4, THETA, ZOFFS, TFLAG; CTRIA6: THETA, ZOFFS,
  // T1-T3, TFLAG
  struct Fields {
    int theta, zoffs, tflag, t1, last;
  };
  const int corners = row.corners;
  const Fields f = nn == 8   ? Fields{15, 16, 17, 11, 17}
                   : nn == 6 ? Fields{9, 10, 14, 11, 14}
                             : Fields{3 + nn, 4 + nn, 10, 11, 10 + nn};
  for (int k = corners; k < nn; ++k)
    if (e.Blank(3 + k))
      e.Fail(3 + k, "mid-side grid point G" + std::to_string(k + 1) +
                        " is blank: elements without some mid-side nodes are not supported");
  ReadNodes(e, el, 3, nn);
  // THETA or MCID: the material axis, for laminates (isotropic MAT1: no effect)
  ReadShellMaterialAngle(e, f.theta, el);
  el.shell_offset = e.Real(f.zoffs, "ZOFFS", 0.0);
  const int tflag = e.Int(f.tflag, "TFLAG", 0);
  if (tflag != 0 && tflag != 1) e.Fail(f.tflag, "TFLAG must be 0 or 1");
  const double t = mesh_.shell_sections[el.property].thickness;
  for (int k = 0; k < corners; ++k) {
    if (e.Blank(f.t1 + k)) continue;
    std::string what = "T";
    what += std::to_string(k + 1);
    const double ti = e.Real(f.t1 + k, what.c_str());
    const double expected = tflag == 1 ? 1.0 : t;
    if (std::abs(ti - expected) > 1e-6 * expected)
      e.Fail(f.t1 + k, "corner thicknesses T1-T" + std::to_string(corners) +
                           " different from the PSHELL thickness are not supported");
  }
  if (e.Size() > f.last) e.Fail(f.last + 1, "unexpected field");
  mesh_.elements.push_back(std::move(el));
}

// CSHEAR EID PID G1 G2 G3 G4 on a PSHEAR (fe/elements/shear4.h); a panel
// that is not a parallelogram gets one warning: flexmb's panel is exact
// for parallelograms, Nastran's formulation differs for other shapes
void Builder::AddShear(const Entry& e) {
  fe::Element el = NewElement(e, NastranRows(e.name()).front()->type);
  el.property = PropertyIndex(e, 2, e.Int(2, "PID", el.id), {"PSHEAR"});
  ReadNodes(e, el, 3, 4);
  if (e.Size() > 7) e.Fail(7, "unexpected field");
  const Vec3 &a = mesh_.nodes[el.nodes[0]].x, &b = mesh_.nodes[el.nodes[1]].x, &c = mesh_.nodes[el.nodes[2]].x,
             &d = mesh_.nodes[el.nodes[3]].x;
  const double size = std::max((c - a).norm(), (d - b).norm());
  if ((a - b + c - d).norm() > 1e-3 * size)
    Warn(e,
         "CSHEAR panels that are not parallelograms are read with flexmb's shear panel (uniform shear along the "
         "mean directions of the edge pairs, exact for parallelograms); Nastran's formulation differs for such "
         "shapes",
         "CSHEAR shape");
  mesh_.elements.push_back(std::move(el));
}

// a solid card is the row whose node count it gives; its grid points in the
// row's Nastran order
void Builder::AddSolid(const Entry& e) {
  const std::vector<const fe::ElementTraits*> rows = NastranRows(e.name());
  const int max_nodes = rows.front()->nastran_card_grids;
  int given = 0;
  for (int k = 0; k < max_nodes; ++k) given += e.Blank(3 + k) ? 0 : 1;
  const fe::ElementTraits* row = nullptr;
  std::string counts;
  for (const fe::ElementTraits* t : rows) {
    if (t->nodes == given) row = t;
    if (!counts.empty()) counts += " or ";
    counts += std::to_string(t->nodes);
  }
  if (row == nullptr)
    e.Fail(e.name() + " with " + std::to_string(given) + " grid points: only " + counts + " are supported (" +
           std::to_string(given) + "-node " + e.name() + " is unsupported)");
  if (e.Size() > 2 + max_nodes) e.Fail(3 + max_nodes, "unexpected field");
  fe::Element el = NewElement(e, row->type);
  el.property = PropertyIndex(e, 2, e.Id(2, "PID"), {"PSOLID"});
  ReadNodes(e, el, 3, row->nodes);
  if (!row->nastran_order.empty()) {
    const std::vector<int> card = el.nodes;
    for (int k = 0; k < row->nodes; ++k) el.nodes[k] = card[fe::FormatNode(row->nastran_order, k)];
  }
  mesh_.elements.push_back(std::move(el));
}

void Builder::AddBeam(const Entry& e) {
  const bool bar = e.name() == "CBAR";
  fe::Element el = NewElement(e, NastranRows(e.name()).front()->type);
  const Card* def_card = bar ? baror_ : beamor_;
  std::optional<Entry> defaults;
  if (def_card) defaults.emplace(*def_card, deck_);
  // PID, orientation and OFFT default to the BAROR / BEAMOR values
  const int pid = !e.Blank(2) ? e.Id(2, "PID") : defaults && !defaults->Blank(2) ? defaults->Id(2, "PID") : el.id;
  el.property = PropertyIndex(e, 2, pid, bar ? std::initializer_list<const char*>{"PBAR", "PBARL"}
                                             : std::initializer_list<const char*>{"PBEAM", "PBEAML"});
  ReadNodes(e, el, 3, 2);
  const int ga = el.nodes[0], gb = el.nodes[1];
  const Vec3& xa = mesh_.nodes[ga].x;
  const Vec3& xb = mesh_.nodes[gb].x;

  const bool own_v = !(e.Blank(5) && e.Blank(6) && e.Blank(7));
  if (!own_v && !(defaults && !(defaults->Blank(5) && defaults->Blank(6) && defaults->Blank(7))))
    e.Fail(5, "orientation vector X1-X3 or G0 is missing (and no " + std::string(bar ? "BAROR" : "BEAMOR") +
                  " default)");
  const Entry& ve = own_v ? e : *defaults;
  // CBEAM field 9 may hold BIT (a real, p-elements only): then OFFT is the default
  const bool own_offt = !e.Blank(8) && (bar || !nastran::LooksReal(e.Text(8)));
  const bool def_offt = !own_offt && defaults && !defaults->Blank(8) &&
                        (bar || !nastran::LooksReal(defaults->Text(8)));
  const std::string offt = own_offt ? e.Text(8) : def_offt ? defaults->Text(8) : "GGG";
  const Entry& oe = def_offt ? *defaults : e;
  if (offt.size() != 3 || (offt[0] != 'G' && offt[0] != 'B') || (offt[1] != 'G' && offt[1] != 'O') ||
      (offt[2] != 'G' && offt[2] != 'O'))
    oe.Fail(8, "OFFT '" + offt + "' is not one of GGG, BGG, GGO, BGO, GOG, BOG, GOO, BOO");

  Vec3 v;
  if (!ve.Blank(5) && !nastran::LooksReal(ve.Text(5)) && ve.Blank(6) && ve.Blank(7)) {
    const int g0 = NodeIndex(ve, 5, "G0");
    if (g0 == ga || g0 == gb) ve.Fail(5, "G0 must differ from GA and GB");
    v = mesh_.nodes[g0].x - xa;
  } else {
    v = Vec3(ve.Real(5, "X1", 0.0), ve.Real(6, "X2", 0.0), ve.Real(7, "X3", 0.0));
    if (offt[0] == 'G' && node_cd_[ga] != 0) v = BasisAt(Coord(e, 3, node_cd_[ga]), xa) * v;
  }
  if (!(v.norm() > 0.0) || !v.allFinite()) ve.Fail(5, "orientation vector is zero or not finite");
  el.orientation = v;

  for (int f : {9, 10})
    if (!e.Blank(f) && e.Text(f) != "0") e.Fail(f, "pin flags PA/PB are not supported");
  if (!bar)
    for (int f : {17, 18})
      if (!e.Blank(f) && e.Text(f) != "0") e.Fail(f, "warping scalar points SA/SB are not supported");
  if (e.Size() > (bar ? 16 : 18)) e.Fail(bar ? 17 : 19, "unexpected field");

  const Vec3 wa(e.Real(11, "W1A", 0.0), e.Real(12, "W2A", 0.0), e.Real(13, "W3A", 0.0));
  const Vec3 wb(e.Real(14, "W1B", 0.0), e.Real(15, "W2B", 0.0), e.Real(16, "W3B", 0.0));
  el.offset_a = Offset(e, offt[1], wa, ga, xa, xb, v, 11);
  el.offset_b = Offset(e, offt[2], wb, gb, xa, xb, v, 14);
  if (!el.offset_a.allFinite() || !el.offset_b.allFinite()) e.Fail(11, "offsets are not finite");
  mesh_.elements.push_back(std::move(el));
}

// end offset in basic: 'G' in the node's displacement system, 'O' in the
// offset system (x from GA to GB, y in the plane of x and v)
Vec3 Builder::Offset(const Entry& e, char how, const Vec3& w, int node, const Vec3& xa, const Vec3& xb,
                     const Vec3& v, int field) {
  if (w.isZero(0.0)) return w;
  if (how == 'G') {
    const int cd = node_cd_[node];
    return cd == 0 ? w : Vec3(BasisAt(Coord(e, field, cd), mesh_.nodes[node].x) * w);
  }
  const Vec3 d = xb - xa;
  if (!(d.norm() > 0.0)) e.Fail(field, "offset system (OFFT 'O') undefined: GA and GB coincide");
  const Vec3 ex = d.normalized();
  const Vec3 zr = ex.cross(v);
  if (!(zr.norm() > 1e-8 * v.norm())) e.Fail(field, "offset system (OFFT 'O') undefined: v is parallel to GA-GB");
  const Vec3 ez = zr.normalized();
  return Columns(ex, ez.cross(ex), ez) * w;
}

void Builder::AddConm2(const Entry& e) {
  fe::PointMass pm;
  pm.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, pm.id, "element");
  pm.node = NodeIndex(e, 2, "G");
  const int cid = e.Int(3, "CID", 0);
  if (cid < -1) e.Fail(3, "CID must be -1 or larger");
  pm.mass = NonNegative(e, 4, "mass M", e.Real(4, "M"));
  const Vec3 x(e.Real(5, "X1", 0.0), e.Real(6, "X2", 0.0), e.Real(7, "X3", 0.0));
  const double i11 = e.Real(9, "I11", 0.0), i21 = e.Real(10, "I21", 0.0), i22 = e.Real(11, "I22", 0.0);
  const double i31 = e.Real(12, "I31", 0.0), i32 = e.Real(13, "I32", 0.0), i33 = e.Real(14, "I33", 0.0);
  NonNegative(e, 9, "I11", i11);
  NonNegative(e, 11, "I22", i22);
  NonNegative(e, 14, "I33", i33);
  if (e.Size() > 14) e.Fail(15, "unexpected field");
  // Nastran supplies the minus signs of the off-diagonal terms (QRG CONM2):
  // I21 = int x2 x1 dm etc. are products of inertia
  Mat3 inertia;
  inertia << i11, -i21, -i31, -i21, i22, -i32, -i31, -i32, i33;
  const Vec3& xn = mesh_.nodes[pm.node].x;
  Mat3 basis = Mat3::Identity();
  if (cid > 0) basis = BasisAt(Coord(e, 3, cid), xn);
  pm.offset = cid == -1 ? Vec3(x - xn) : Vec3(basis * x);
  pm.inertia = basis * inertia * basis.transpose();
  if (!pm.offset.allFinite() || !pm.inertia.allFinite()) e.Fail(5, "offset or inertia is not finite");
  pm.origin = OriginOf(e);
  mesh_.point_masses.push_back(pm);
}

// the lower triangle of the 6 x 6 matrix row by row from field 4 (M11, M21,
// M22, M31, ...), in the system CID at the grid, turned to basic axes
void Builder::AddConm1(const Entry& e) {
  fe::PointMass pm;
  pm.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, pm.id, "element");
  pm.node = NodeIndex(e, 2, "G");
  const int cid = e.Int(3, "CID", 0);
  if (cid < 0) e.Fail(3, "CID must be 0 or a coordinate system id");
  if (e.Size() > 24) e.Fail(25, "unexpected field");
  fe::Mat6 m = fe::Mat6::Zero();
  int field = 4;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j <= i; ++j, ++field) {
      const std::string what = "M" + std::to_string(i + 1) + std::to_string(j + 1);
      m(i, j) = m(j, i) = e.Real(field, what.c_str(), 0.0);
    }
  for (int i = 0; i < 6; ++i) {
    const std::string what = "M" + std::to_string(i + 1) + std::to_string(i + 1);
    NonNegative(e, 4 + i * (i + 3) / 2, what.c_str(), m(i, i));
  }
  if (cid > 0) {
    const Mat3 b = BasisAt(Coord(e, 3, cid), mesh_.nodes[pm.node].x);
    fe::Mat6 t = fe::Mat6::Zero();
    t.topLeftCorner<3, 3>() = b;
    t.bottomRightCorner<3, 3>() = b;
    m = t * m * t.transpose();
  }
  if (!m.allFinite()) e.Fail(4, "mass matrix is not finite");
  pm.general = true;
  pm.matrix = m;
  pm.origin = OriginOf(e);
  mesh_.point_masses.push_back(pm);
}

}  // namespace flexmb::io::nastran
