// Laminated shells: MAT8 (orthotropic plies), MAT2 (anisotropic shell
// materials of a PSHELL), PCOMP and PCOMPG (the ply
// stack), and the material angle (THETA or MCID) of the shell elements
// that use them. The section is the equivalent single layer of classical
// lamination theory (fe/laminate.h); what is approximated: docs/formats.md,
// "Nastran bulk data", and docs/design.md, "Laminated shells".

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/fe/laminate.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

namespace {
constexpr double kRadPerDegLaminate = 3.14159265358979323846 / 180.0;
}  // namespace

// MAT8: E1, E2, NU12, G12, G1Z, G2Z, RHO (thermal, strength and damping
// fields do not change K or M); blank G1Z, G2Z (Nastran: rigid in
// transverse shear) take G12
void Builder::AddMat8(const Entry& e, int id) {
  fe::LaminatePly p;
  const double e1 = Positive(e, 2, "E1", e.Real(2, "E1"));
  const double e2 = Positive(e, 3, "E2", e.Real(3, "E2"));
  const double nu12 = e.Real(4, "NU12");
  const double g12 = Positive(e, 5, "G12", e.Real(5, "G12"));
  if (!(1.0 - nu12 * nu12 * e2 / e1 > 0.0))
    e.Fail(4, "NU12 = " + Str(nu12) + " makes the ply unstable (1 - NU12^2 E2/E1 <= 0)");
  p.q = fe::OrthotropicPlaneStress(e1, e2, nu12, g12);
  p.g13 = e.Blank(6) ? g12 : Positive(e, 6, "G1Z", e.Real(6, "G1Z"));
  p.g23 = e.Blank(7) ? g12 : Positive(e, 7, "G2Z", e.Real(7, "G2Z"));
  if (e.Blank(6) || e.Blank(7))
    Warn(e, "blank G1Z or G2Z (Nastran: no transverse shear flexibility) taken as G12; flexmb's shells keep "
            "their shear flexibility",
         "MAT8 G1Z");
  p.rho = NonNegative(e, 8, "RHO", e.Real(8, "RHO", 0.0));
  for (int f = 9; f <= 19; ++f) e.Real(f, "a thermal, strength or damping value", 0.0);
  if (e.Size() > 19) e.Fail(20, "unexpected field");
  ply_materials_[id] = p;
  other_materials_[id] = "MAT8 (an orthotropic ply material: use it in a PCOMP or PCOMPG)";
}

// MAT2: G11 G12 G13 G22 G23 G33, RHO (thermal, stress limits and damping
// do not change K or M), MCSID blank or 0 (the element's material axis);
// the plane-stress matrix [G11 G12 G13; G12 G22 G23; G13 G23 G33] must be
// positive definite where a PSHELL uses it for membrane or bending, its
// upper 2 x 2 block [G11 G12; G12 G22] where it is MID3 (transverse shear)
void Builder::AddMat2(const Entry& e, int id) {
  ShellMaterial m;
  const int f[3][3] = {{2, 3, 4}, {3, 5, 6}, {4, 6, 7}};
  const char* names[3][3] = {{"G11", "G12", "G13"}, {"G12", "G22", "G23"}, {"G13", "G23", "G33"}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m.q(r, c) = e.Real(f[r][c], names[r][c], 0.0);
  m.shear = m.q.topLeftCorner<2, 2>();
  m.rho = NonNegative(e, 8, "RHO", e.Real(8, "RHO", 0.0));
  for (int k = 9; k <= 16; ++k) e.Real(k, "a thermal, stress limit or damping value", 0.0);
  if (e.Int(17, "MCSID", 0) != 0)
    e.Fail(17, "MCSID (a material coordinate system of its own) is not supported: leave it blank and give the "
               "material axis on the elements (THETA or MCID)");
  if (e.Size() > 17) e.Fail(18, "unexpected field");
  mat2_[id] = m;
  other_materials_[id] = "MAT2 (an anisotropic shell material: use it in a PSHELL)";
}

// MID `mid` (MAT1, MAT2 or MAT8, field i) as a shell section uses it
ShellMaterial Builder::ShellMaterialOf(const Entry& e, int i, int mid) {
  ShellMaterial m;
  if (const auto it = mat2_.find(mid); it != mat2_.end()) return it->second;
  if (const auto it = ply_materials_.find(mid); it != ply_materials_.end()) {
    m.q = it->second.q;
    m.shear = Eigen::Vector2d(it->second.g13, it->second.g23).asDiagonal();
    m.rho = it->second.rho;
    return m;
  }
  const fe::Material& iso = mesh_.materials[static_cast<size_t>(MaterialIndex(e, i, mid))];
  m.q = fe::IsotropicPlaneStress(iso.E, iso.nu);
  m.shear = Eigen::Matrix2d::Identity() * iso.G;
  m.rho = iso.rho;
  return m;
}

// the ply material of MAT1 or MAT8 `mid`, referred to from field i: its
// shell stiffness with the transverse shear moduli of a ply
fe::LaminatePly Builder::PlyMaterial(const Entry& e, int i, int mid) {
  if (mat2_.count(mid) != 0)
    e.Fail(i, "material " + std::to_string(mid) + " is a MAT2: not supported as a ply (it has no transverse "
              "shear moduli; give the ply as MAT8 or MAT1)");
  const ShellMaterial m = ShellMaterialOf(e, i, mid);
  fe::LaminatePly p;
  p.q = m.q;
  p.g13 = m.shear(0, 0);
  p.g23 = m.shear(1, 1);
  p.rho = m.rho;
  return p;
}

// PCOMP: PID Z0 NSM SB FT TREF GE LAM, then MID T THETA SOUT per ply (two
// on a line; a blank MID or T repeats the ply before). PCOMPG: the same
// head, then GPLYID MID T THETA SOUT on a line of its own per ply.
int Builder::AddPcomp(const Entry& e, int pid) {
  const bool global = e.name() == "PCOMPG";
  const int first = 9, stride = global ? 8 : 4, offset = global ? 1 : 0;
  std::vector<fe::LaminatePly> plies;
  int mid = -1;
  double t = 0.0;
  for (int f = first; f + offset <= e.Size(); f += stride) {
    const int fm = f + offset, ft = fm + 1, fth = fm + 2;
    if (!global && e.Blank(fm) && e.Blank(ft) && e.Blank(fth) && e.Blank(fm + 3)) continue;  // a blank slot
    if (global) e.Id(f, "GPLYID");
    if (!e.Blank(fm) || mid < 0) mid = e.Id(fm, "MID");
    if (!e.Blank(ft) || !(t > 0.0)) t = Positive(e, ft, "ply thickness T", e.Real(ft, "T"));
    fe::LaminatePly p = PlyMaterial(e, fm, mid);
    p.t = t;
    p.theta = e.Real(fth, "THETA", 0.0) * kRadPerDegLaminate;
    const std::string& sout = e.Text(fm + 3);
    if (!sout.empty() && sout != "YES" && sout != "NO") e.Fail(fm + 3, "SOUT must be YES or NO");
    if (global)
      for (int k = f + 5; k < f + 8; ++k)
        if (!e.Blank(k)) e.Fail(k, "unexpected field");
    plies.push_back(p);
  }
  if (plies.empty()) e.Fail(first, "no plies");
  const std::string lam = e.Text(8);
  if (lam == "SYM") {
    for (int k = static_cast<int>(plies.size()) - 1; k >= 0; --k) plies.push_back(plies[static_cast<size_t>(k)]);
  } else if (!lam.empty()) {
    e.Fail(8, "LAM = " + lam + " is not supported (blank or SYM): flexmb reads the full membrane and bending "
              "stiffness of the plies");
  }
  double total = 0.0;
  for (const fe::LaminatePly& p : plies) total += p.t;
  const double z0 = e.Real(2, "Z0", -0.5 * total);
  fe::ShellLaminate l = fe::StackPlies(plies, z0);
  l.card = e.name() + " " + std::to_string(pid);
  for (int f : {4, 6, 7}) e.Real(f, "SB, TREF or GE", 0.0);
  if (!e.Blank(5) && e.Text(5) != "HILL" && e.Text(5) != "HOFF" && e.Text(5) != "TSAI" && e.Text(5) != "STRN")
    e.Fail(5, "FT must be HILL, HOFF, TSAI or STRN");
  fe::ShellSection s;
  s.id = pid;
  s.thickness = total;
  s.nsm = NonNegative(e, 3, "NSM", e.Real(3, "NSM", 0.0));
  s.laminate = std::make_shared<const fe::ShellLaminate>(std::move(l));
  s.origin = OriginOf(e);
  mesh_.shell_sections.push_back(s);
  return static_cast<int>(mesh_.shell_sections.size()) - 1;
}

// THETA (degrees from the G1-G2 edge) or MCID (the x axis of a rectangular
// system projected onto the element) of a shell with a laminated property
// into el.shell_theta; for other properties the field is checked only
void Builder::ReadShellMaterialAngle(const Entry& e, int i, fe::Element& el) {
  const bool laminate = mesh_.shell_sections[static_cast<size_t>(el.property)].laminate != nullptr;
  if (e.Blank(i)) return;
  if (LooksReal(e.Text(i))) {
    el.shell_theta = e.Real(i, "THETA") * kRadPerDegLaminate;
    return;
  }
  const int mcid = e.Int(i, "MCID", 0);
  if (!laminate) return;
  if (mcid < 0) e.Fail(i, "MCID must not be negative");
  fe::Vec3 axis = fe::Vec3::UnitX();  // MCID 0: the basic system
  if (mcid > 0) {
    const CoordSys& cs = Coord(e, i, mcid);
    if (cs.kind != 'R') e.Fail(i, "MCID " + std::to_string(mcid) + " is not a rectangular system (unsupported)");
    axis = cs.R.col(0);
  }
  const auto x = [&](int k) { return mesh_.nodes[el.nodes[static_cast<size_t>(k)]].x; };
  const bool quad = el.nodes.size() == 4 || el.nodes.size() == 8;  // the corners' diagonals (as the elements)
  const fe::Vec3 normal = quad ? fe::Vec3((x(2) - x(0)).cross(x(3) - x(1)))
                                               : fe::Vec3((x(1) - x(0)).cross(x(2) - x(0)));
  const fe::Vec3 n = normal.normalized();
  const fe::Vec3 e1 = (x(1) - x(0) - n * n.dot(x(1) - x(0))).normalized(), e2 = n.cross(e1);
  const fe::Vec3 m = axis - n * n.dot(axis);
  if (!(m.norm() > 1e-6)) e.Fail(i, "the x axis of MCID " + std::to_string(mcid) + " is normal to the element");
  el.shell_theta = std::atan2(m.dot(e2), m.dot(e1));
}

}  // namespace flexmb::io::nastran
