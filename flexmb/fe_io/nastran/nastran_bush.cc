#include <array>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

using fe::Mat3;
using fe::Vec3;

// PBUSH PID "K" K1..K6 / "B" B1..B6 / "GE" GE1.. / "RCV" SA ST EA ET / "M" M:
// each keyword starts a line (field 2 + 8 j), its values follow it
void Builder::AddPbush(const Entry& e, int pid) {
  BushProperty p;
  for (int f = 2; f <= e.Size(); f += 8) {
    const std::string& key = e.Text(f);
    if (key.empty()) continue;
    bool nonzero = false;
    auto values = [&](int count, const char* what) {
      for (int k = 1; k <= count; ++k) nonzero = e.Real(f + k, what, 0.0) != 0.0 || nonzero;
      for (int k = count + 1; k <= 6; ++k)
        if (!e.Blank(f + k)) e.Fail(f + k, "unexpected field after " + key);
    };
    if (key == "K") {
      for (int k = 0; k < 6; ++k) {
        p.k[k] = e.Real(f + 1 + k, "Ki", 0.0);
        if (!(p.k[k] >= 0.0) || !std::isfinite(p.k[k]))
          e.Fail(f + 1 + k, "stiffness K" + std::to_string(k + 1) + " must not be negative, got " + Str(p.k[k]));
        p.given[k] = !e.Blank(f + 1 + k);
      }
    } else if (key == "B") {
      values(6, "Bi");
      if (nonzero)
        Warn(e, "viscous damping B of PBUSH is ignored (flexmb's FE model has no damping matrix)", "PBUSH B");
    } else if (key == "GE") {
      values(6, "GEi");
      if (nonzero)
        Warn(e, "structural damping GE of PBUSH is ignored (flexmb's FE model has no damping matrix)", "PBUSH GE");
    } else if (key == "RCV") {
      values(4, "stress and strain recovery coefficient");  // output only
    } else if (key == "M") {
      values(1, "M");
      if (nonzero)
        e.Fail(f + 1, "mass M of PBUSH is not supported (it would change the mass matrix); model it with CONM2 "
                      "(unsupported)");
    } else {
      e.Fail(f, "PBUSH keyword '" + key + "' is not supported (K, B, GE, RCV, M)");
    }
  }
  properties_[pid] = PropertyRef{"PBUSH", static_cast<int>(pbush_.size())};
  pbush_.push_back(p);
}

// CBUSH EID PID GA GB G0/X1 X2 X3 CID / S OCID S1 S2 S3: six springs K1..K6
// along the axes of the element system, at the point P (S along GA-GB, or
// the offset S1-S3 from GA in OCID), P rigidly attached to GA and to GB
void Builder::AddCbush(const Entry& e) {
  const int id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, id, "element");
  const BushProperty& p = pbush_[PropertyIndex(e, 2, e.Int(2, "PID", id), {"PBUSH"})];
  const int ga = NodeIndex(e, 3, "GA");
  const bool grounded = e.Blank(4) || e.Text(4) == "0";
  const int gb = grounded ? -1 : NodeIndex(e, 4, "GB");
  if (gb == ga) e.Fail(4, "GB is the same grid point as GA");
  const Vec3& xa = mesh_.nodes[ga].x;
  const Vec3 xb = grounded ? xa : mesh_.nodes[gb].x;
  const bool has_cid = !e.Blank(8);
  const bool has_v = !(e.Blank(5) && e.Blank(6) && e.Blank(7));
  // Nastran's coincidence distance (QRG CBUSH, remark 6)
  const bool coincident = (xb - xa).norm() < 1e-4;
  Mat3 axes;  // columns: element x, y, z in basic
  if (has_cid) {
    // CID overrides G0 and X1-X3; a curvilinear CID is located at GA
    const int cid = e.Int(8, "CID");
    if (cid < 0) e.Fail(8, "CID must be 0 or a coordinate system id");
    axes = cid == 0 ? Mat3::Identity() : BasisAt(Coord(e, 8, cid), xa);
  } else {
    if (grounded || coincident)
      e.Fail(8, std::string(grounded ? "GB is blank (grounded)" : "GA and GB coincide (closer than 1e-4)") +
                    ": CID must be given (QRG CBUSH)");
    const Vec3 x = (xb - xa).normalized();
    if (!has_v) {
      // the line GA-GB alone orients only the axial (K1) and torsional (K4) springs
      for (int k : {1, 2, 4, 5})
        if (p.k[k] != 0.0)
          e.Fail(5, "neither CID nor an orientation vector (G0 or X1-X3) is given: Nastran then allows only K1 "
                    "and K4 on the PBUSH, but K" + std::to_string(k + 1) + " = " + Str(p.k[k]));
      const Vec3 helper = std::abs(x.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
      const Vec3 z = x.cross(helper).normalized();
      axes = Columns(x, z.cross(x), z);
    } else {
      Vec3 v;
      if (!nastran::LooksReal(e.Text(5)) && e.Blank(6) && e.Blank(7)) {
        const int g0 = NodeIndex(e, 5, "G0");
        if (g0 == ga || g0 == gb) e.Fail(5, "G0 must differ from GA and GB");
        v = mesh_.nodes[g0].x - xa;
      } else {
        // X1-X3 are in the displacement system of GA
        v = CdBasis(ga) * Vec3(e.Real(5, "X1", 0.0), e.Real(6, "X2", 0.0), e.Real(7, "X3", 0.0));
      }
      const Vec3 zr = x.cross(v);
      if (!(zr.norm() > 1e-9 * v.norm()) || !v.allFinite())
        e.Fail(5, "orientation vector is zero or parallel to GA-GB");
      const Vec3 z = zr.normalized();
      axes = Columns(x, z.cross(x), z);
    }
  }
  // the spring point P
  const int ocid = e.Int(10, "OCID", -1);
  if (ocid < -1) e.Fail(10, "OCID must be -1 or larger");
  Vec3 xp;
  if (ocid == -1) {
    const double s = e.Real(9, "S", 0.5);
    if (!(s >= 0.0 && s <= 1.0)) e.Fail(9, "S = " + Str(s) + " must be in [0, 1]");
    xp = xa + s * (xb - xa);
  } else {
    const Vec3 offset(e.Real(11, "S1", 0.0), e.Real(12, "S2", 0.0), e.Real(13, "S3", 0.0));
    xp = xa + (ocid == 0 ? Mat3::Identity() : BasisAt(Coord(e, 10, ocid), xa)) * offset;
  }
  if (e.Size() > 13) e.Fail(14, "unexpected field");
  // spring k: k (g_a - g_b)^2 / 2, g = e . (u + theta x r) = e . u + (r x e) . theta
  const Vec3 ra = xp - xa, rb = xp - xb;
  for (int k = 0; k < 6; ++k) {
    if (p.k[k] == 0.0) continue;
    const Vec3 axis = axes.col(k % 3);
    fe::ScalarSpring s;
    s.id = id;
    s.node_a = ga;
    s.node_b = gb;
    s.k = p.k[k];
    s.directional = true;
    const Vec3 ta = k < 3 ? axis : Vec3::Zero(), tb = k < 3 ? axis : Vec3::Zero();
    const Vec3 wa = k < 3 ? Vec3(ra.cross(axis)) : axis, wb = k < 3 ? Vec3(rb.cross(axis)) : axis;
    for (int j = 0; j < 3; ++j) {
      s.coef_a[j] = ta[j];
      s.coef_a[3 + j] = wa[j];
      s.coef_b[j] = grounded ? 0.0 : tb[j];
      s.coef_b[3 + j] = grounded ? 0.0 : wb[j];
    }
    s.origin = OriginOf(e);
    mesh_.springs.push_back(s);
  }
}

}  // namespace flexmb::io::nastran
