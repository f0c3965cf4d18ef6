#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include "flexmb/common/error.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"
#include "flexmb/fe_io/nastran/nastran_sections.h"

namespace flexmb::io::nastran {

namespace {
// C1 C2 D1 D2 E1 E2 F1 F2 in fields f .. f + 7 (PBAR, PBEAM): the section's
// stress recovery points (y, z) = (C1, C2), (D1, D2), ...; all blank or
// zero: none given (Nastran then recovers the axial stress only)
void ReadNastranStressPoints(const Entry& e, int f, fe::BeamSection& s) {
  double v[8];
  bool any = false;
  for (int k = 0; k < 8; ++k) {
    v[k] = e.Real(f + k, "stress recovery point", 0.0);
    any = any || v[k] != 0.0;
  }
  if (!any) return;
  for (int k = 0; k < 4; ++k) s.stress_points.push_back({v[2 * k], v[2 * k + 1]});
}
}  // namespace

void Builder::AddProperty(const Entry& e) {
  if (e.name() == "PELAS") return AddPelas(e);
  if (e.name() == "PMASS") return AddPmass(e);
  const int pid = e.Id(1, "PID");
  CheckNewId(property_origin_, e, pid, "property");
  const std::string& n = e.name();
  if (n == "PBUSH") return AddPbush(e, pid);
  int index = -1;
  if (n == "PSHELL") {
    index = AddPshell(e, pid);
  } else if (n == "PCOMP" || n == "PCOMPG") {
    index = AddPcomp(e, pid);
  } else if (n == "PSHEAR") {
    index = AddPshear(e, pid);
  } else if (n == "PSOLID") {
    fe::SolidSection s;
    s.id = pid;
    s.material = MaterialIndex(e, 2, e.Id(2, "MID"));
    e.Int(3, "CORDM", 0);
    const std::string& fctn = e.Text(7);
    if (!fctn.empty() && fctn != "SMECH")
      e.Fail(7, "FCTN = " + fctn + " (fluid elements) is not supported");
    s.origin = OriginOf(e);
    index = static_cast<int>(mesh_.solid_sections.size());
    mesh_.solid_sections.push_back(s);
  } else {
    fe::BeamSection s;
    s.id = pid;
    s.origin = OriginOf(e);
    if (n == "PBAR") ReadPbar(e, s);
    if (n == "PBARL" || n == "PBEAML") ReadBeamLibrary(e, s);
    if (n == "PBEAM") ReadPbeam(e, s);
    if (n == "PROD") ReadProd(e, s);
    if (n == "PTUBE") ReadPtube(e, s);
    index = static_cast<int>(mesh_.beam_sections.size());
    mesh_.beam_sections.push_back(s);
  }
  properties_[pid] = PropertyRef{n, index};
}

int Builder::AddPshell(const Entry& e, int pid) {
  fe::ShellSection s;
  s.id = pid;
  if (e.Blank(2)) e.Fail(2, "MID1 is blank: shells without membrane stiffness are not supported");
  const int mid1 = e.Id(2, "MID1");
  s.thickness = Positive(e, 3, "thickness T", e.Real(3, "T"));
  const double t = s.thickness;
  s.nsm = NonNegative(e, 8, "NSM", e.Real(8, "NSM", 0.0));
  e.Real(9, "Z1", 0.0);
  e.Real(10, "Z2", 0.0);
  s.origin = OriginOf(e);
  const ShellMaterial m1 = ShellMaterialOf(e, 2, mid1);
  if (m1.q.llt().info() != Eigen::Success || !m1.q.allFinite())
    e.Fail(2, "the plane-stress matrix of MID1 = " + std::to_string(mid1) + " is not positive definite");
  if (e.Blank(4)) {
    // a membrane: no bending, transverse shear or coupling (Nastran ignores
    // 12I/T**3 and TS/T then, read for their form; MID3 and MID4 must be blank)
    e.Real(5, "12I/T**3", 1.0);
    e.Real(7, "TS/T", 5.0 / 6.0);
    if (!e.Blank(6)) e.Fail(6, "MID3 is given but MID2 is blank (a membrane has no transverse shear)");
    if (!e.Blank(11)) e.Fail(11, "MID4 is given but MID2 is blank (a membrane has no bending)");
    s.laminate = std::make_shared<fe::ShellLaminate>(fe::MembraneLaminate(m1.q, m1.rho, t, "PSHELL " + std::to_string(pid)));
    mesh_.shell_sections.push_back(s);
    return static_cast<int>(mesh_.shell_sections.size()) - 1;
  }
  const int mid2 = e.Int(4, "MID2");
  if (mid2 <= 0)
    e.Fail(4, "MID2 = " + std::to_string(mid2) + " (plane strain or no bending) is not supported");
  const double ratio = Positive(e, 5, "12I/T**3", e.Real(5, "12I/T**3", 1.0));
  // blank MID3: Nastran neglects transverse shear flexibility; flexmb's
  // shells keep it (Mindlin, 5/6 T times the shear modulus of MID2), which
  // makes no difference for thin shells; a MID3 gives its shear times TS/T T
  const int mid3 = e.Blank(6) ? -1 : e.Id(6, "MID3");
  const double ts = Positive(e, 7, "TS/T", e.Real(7, "TS/T", 5.0 / 6.0));
  const int mid4 = e.Blank(11) ? -1 : e.Id(11, "MID4");
  const bool isotropic1 = materials_.count(mid1) != 0;
  if (isotropic1) s.material = MaterialIndex(e, 2, mid1);
  const bool plain = isotropic1 && mid2 == mid1 && std::abs(ratio - 1.0) <= 1e-6 && mid4 < 0 &&
                     (mid3 < 0 || (mid3 == mid1 && std::abs(ts - 5.0 / 6.0) <= 1e-4));
  if (!plain) {
    // MID1 and MID2 of other materials (MAT2, MAT8, another MAT1), a
    // bending ratio, another shear stiffness or a coupling: the section as
    // an equivalent single layer (fe/laminate.h), A = T q1, D = 12I/T^3 T^3
    // / 12 q2, S = TS/T T G3, B = T^2 q4 (Nastran's resultants: N = T G1
    // eps + T^2 G4 kappa, M = T^2 G4 eps + 12I/T^3 T^3/12 G2 kappa); mass
    // and rotary inertia of MID1's rho
    const ShellMaterial m2 = ShellMaterialOf(e, 4, mid2);
    // a MAT2's upper block is in-plane: without MID3, its G33 stands for the transverse shear
    Eigen::Matrix2d g3 = mat2_.count(mid2) != 0 ? Eigen::Matrix2d(Eigen::Matrix2d::Identity() * m2.q(2, 2)) : m2.shear;
    if (mid3 >= 0) g3 = ShellMaterialOf(e, 6, mid3).shear;
    if (m2.q.llt().info() != Eigen::Success || !m2.q.allFinite())
      e.Fail(4, "the plane-stress matrix of MID2 = " + std::to_string(mid2) + " is not positive definite");
    if (g3.llt().info() != Eigen::Success || !g3.allFinite())
      e.Fail(mid3 >= 0 ? 6 : 4, "the transverse shear stiffness of " +
                                    std::string(mid3 >= 0 ? "MID3 = " + std::to_string(mid3)
                                                          : "MID2 = " + std::to_string(mid2)) +
                                    " is not positive definite");
    auto l = std::make_shared<fe::ShellLaminate>();
    l->A = m1.q * t;
    l->D = m2.q * (ratio * t * t * t / 12.0);
    l->S = g3 * ((mid3 < 0 ? 5.0 / 6.0 : ts) * t);
    if (mid4 >= 0) {
      l->B = ShellMaterialOf(e, 11, mid4).q * (t * t);
      // the section's stiffness [A B; B D] must stay positive definite
      Eigen::Matrix<double, 6, 6> abd;
      abd << l->A, l->B, l->B, l->D;
      if (abd.llt().info() != Eigen::Success || !abd.allFinite())
        e.Fail(11, "the membrane-bending coupling of MID4 = " + std::to_string(mid4) +
                       " makes the section's stiffness [A B; B D] indefinite");
    }
    l->mass = m1.rho * t;
    l->rotary = m1.rho * t * t * t / 12.0;
    l->thickness = t;
    l->z_bottom = -0.5 * t;
    l->z_top = 0.5 * t;
    l->q_bottom = l->q_top = m1.q;
    l->qb_bottom = l->qb_top = m2.q;
    l->card = "PSHELL " + std::to_string(pid);
    s.laminate = std::move(l);
  }
  mesh_.shell_sections.push_back(s);
  return static_cast<int>(mesh_.shell_sections.size()) - 1;
}

// PSHEAR PID MID T NSM F1 F2: the shear panel's thickness, MAT1 and
// non-structural mass; the extensional effectiveness F1, F2 (rods along the
// edges) is not supported
int Builder::AddPshear(const Entry& e, int pid) {
  fe::ShellSection s;
  s.id = pid;
  s.material = MaterialIndex(e, 2, e.Id(2, "MID"));
  s.thickness = Positive(e, 3, "thickness T", e.Real(3, "T"));
  s.nsm = NonNegative(e, 4, "NSM", e.Real(4, "NSM", 0.0));
  for (int f : {5, 6})
    if (e.Real(f, f == 5 ? "F1" : "F2", 0.0) != 0.0)
      e.Fail(f, std::string(f == 5 ? "F1" : "F2") +
                    " != 0 (extensional stiffness of the panel's edges) is not supported: model the edge "
                    "members as CRODs");
  if (e.Size() > 7) e.Fail(7, "unexpected field");
  s.origin = OriginOf(e);
  mesh_.shell_sections.push_back(s);
  return static_cast<int>(mesh_.shell_sections.size()) - 1;
}

// Nastran I1 is int y^2 dA (bending in plane 1 = element x-y, about z) and
// I2 is int z^2 dA: I1 -> Iz, I2 -> Iy, I12 -> Iyz; K1, K2 (planes 1, 2,
// i.e. shear along y, z) -> ky, kz
void Builder::ReadPbar(const Entry& e, fe::BeamSection& s) {
  s.material = MaterialIndex(e, 2, e.Id(2, "MID"));
  s.A = e.Real(3, "A", 0.0);
  s.Iz = e.Real(4, "I1", 0.0);
  s.Iy = e.Real(5, "I2", 0.0);
  s.J = e.Real(6, "J", 0.0);
  s.nsm = e.Real(7, "NSM", 0.0);
  ReadNastranStressPoints(e, 9, s);
  // blank or 0 K1, K2: no shear flexibility; Nastran ignores them if I12 != 0
  s.ky = e.Real(17, "K1", 0.0);
  s.kz = e.Real(18, "K2", 0.0);
  s.Iyz = e.Real(19, "I12", 0.0);
  if (s.Iyz != 0.0) s.ky = s.kz = 0.0;
  if (e.Size() > 19) e.Fail(20, "unexpected field after I12");
  Positive(e, 3, "area A", s.A);
  Positive(e, 4, "I1", s.Iz);
  Positive(e, 5, "I2", s.Iy);
  Positive(e, 6, "torsion constant J", s.J);
  if (!(s.Iy * s.Iz > s.Iyz * s.Iyz)) e.Fail(19, "need I1 I2 > I12^2");
  NonNegative(e, 17, "K1", s.ky);
  NonNegative(e, 18, "K2", s.kz);
  NonNegative(e, 7, "NSM", s.nsm);
}

// PBARL, and PBEAML at a constant section (all stations equal)
void Builder::ReadBeamLibrary(const Entry& e, fe::BeamSection& s) {
  const int mid = e.Id(2, "MID");
  s.material = MaterialIndex(e, 2, mid);
  const std::string group = e.Blank(3) ? "MSCBML0" : e.Text(3);
  if (group != "MSCBML0") e.Fail(3, "GROUP " + group + " (user beam library) is not supported");
  const std::string& type = e.Text(4);
  if (type.empty()) e.Fail(4, "TYPE is required (field is blank)");
  const int n = nastran::ShapeDimensionCount(type);
  if (n == 0)
    e.Fail(4, "section TYPE " + type + " is not supported (supported: ROD, TUBE, BAR, BOX, I, CHAN, L, T, H)");
  std::vector<double> dims(n);
  for (int i = 0; i < n; ++i) {
    std::string what = "DIM";
    what += std::to_string(i + 1);
    dims[i] = e.Real(9 + i, what.c_str());
  }
  s.nsm = e.Real(9 + n, "NSM", 0.0);
  int f = 10 + n;
  if (e.name() == "PBEAML") {
    // further stations: SO, X/XB, DIM1..DIMn, NSM; blank values repeat end A
    while (f <= e.Size()) {
      const std::string& so = e.Text(f);
      if (!so.empty() && so != "YES" && so != "NO")
        e.Fail(f, "SO must be YES or NO, got '" + so + "'");
      const double x = e.Real(f + 1, "X/XB", 1.0);
      if (!(x > 0.0 && x <= 1.0)) e.Fail(f + 1, "X/XB must lie in (0, 1]");
      for (int i = 0; i <= n; ++i) {
        const double ref = i < n ? dims[i] : s.nsm;
        const double v = e.Real(f + 2 + i, i < n ? "DIM" : "NSM", ref);
        if (std::abs(v - ref) > 1e-9 * std::max(std::abs(ref), std::abs(v)))
          e.Fail(f + 2 + i, "tapered PBEAML (station values differ from end A) is not supported");
      }
      f += n + 3;
    }
  } else if (e.Size() >= f) {
    e.Fail(f, "unexpected field after NSM (TYPE " + type + " has " + std::to_string(n) + " dimensions)");
  }
  nastran::ShapeProperties p;
  const std::string err = nastran::ComputeShape(type, dims, mesh_.materials[s.material].nu, &p);
  if (!err.empty()) e.Fail(9, err);
  s.A = p.A;
  s.Iz = p.I1;
  s.Iy = p.I2;
  s.Iyz = p.I12;
  s.J = p.J;
  s.ky = p.K1;
  s.kz = p.K2;
  s.stress_points = p.points;
  for (double v : {s.A, s.Iz, s.Iy, s.J, s.ky, s.kz}) Positive(e, 9, "section constant from the dimensions", v);
  if (!(s.Iy * s.Iz > s.Iyz * s.Iyz) || !std::isfinite(s.Iyz)) e.Fail(9, "section constants out of range");
  NonNegative(e, 9 + n, "NSM", s.nsm);
}

void Builder::ReadPbeam(const Entry& e, fe::BeamSection& s) {
  s.material = MaterialIndex(e, 2, e.Id(2, "MID"));
  const double a[6] = {e.Real(3, "A(A)"),        e.Real(4, "I1(A)", 0.0), e.Real(5, "I2(A)", 0.0),
                       e.Real(6, "I12(A)", 0.0), e.Real(7, "J(A)", 0.0),  e.Real(8, "NSM(A)", 0.0)};
  auto is_so = [&](int f) { return e.Text(f) == "YES" || e.Text(f) == "YESA" || e.Text(f) == "NO"; };
  int f = 9;
  if (!is_so(9)) {
    ReadNastranStressPoints(e, 9, s);  // end A's; the section is constant
    f = 17;
  }
  // intermediate and end-B stations: only a constant section is supported
  while (is_so(f)) {
    const double x = e.Real(f + 1, "X/XB");
    if (!(x > 0.0 && x <= 1.0)) e.Fail(f + 1, "X/XB must lie in (0, 1]");
    for (int k = 0; k < 6; ++k) {
      const double v = e.Real(f + 2 + k, "station value", a[k]);
      if (std::abs(v - a[k]) > 1e-9 * std::max(std::abs(a[k]), std::abs(v)))
        e.Fail(f + 2 + k, "tapered PBEAM (station values differ from end A) is not supported");
    }
    if (e.Text(f) == "YES")
      for (int k = f + 8; k < f + 16; ++k) e.Real(k, "stress recovery point", 0.0);
    f += e.Text(f) == "YES" ? 16 : 8;
  }
  // footer: K1 K2 S1 S2 NSI(A) NSI(B) CW(A) CW(B), M1(A) M2(A) M1(B) M2(B) N1(A) N2(A) N1(B) N2(B)
  s.ky = e.Real(f, "K1", 1.0);
  s.kz = e.Real(f + 1, "K2", 1.0);
  e.Real(f + 2, "S1", 0.0);
  e.Real(f + 3, "S2", 0.0);
  e.Real(f + 6, "CW(A)", 0.0);  // warping needs SA/SB scalar points, rejected at CBEAM
  e.Real(f + 7, "CW(B)", 0.0);
  // end A's value of a field pair; end B's (blank: end A's) must equal it
  auto constant = [&](int field_a, int field_b, const char* name) {
    const double a_value = e.Real(field_a, (std::string(name) + "(A)").c_str(), 0.0);
    const double b_value = e.Real(field_b, (std::string(name) + "(B)").c_str(), a_value);
    if (std::abs(b_value - a_value) > 1e-9 * std::max(std::abs(a_value), std::abs(b_value)))
      e.Fail(field_b, std::string(name) + "(B) differs from " + name + "(A): a tapered PBEAM is not supported");
    return a_value;
  };
  s.nsm_inertia = constant(f + 4, f + 5, "NSI");
  s.nsm_offset = {constant(f + 8, f + 10, "M1"), constant(f + 9, f + 11, "M2")};
  s.neutral_axis = {constant(f + 12, f + 14, "N1"), constant(f + 13, f + 15, "N2")};
  if (e.Size() >= f + 16) e.Fail(f + 16, "unexpected field after the PBEAM footer");
  s.A = a[0];
  s.Iz = a[1];
  s.Iy = a[2];
  s.Iyz = a[3];
  s.J = a[4];
  s.nsm = a[5];
  Positive(e, 3, "area A(A)", s.A);
  Positive(e, 4, "I1(A)", s.Iz);
  Positive(e, 5, "I2(A)", s.Iy);
  Positive(e, 7, "torsion constant J(A)", s.J);
  if (!(s.Iy * s.Iz > s.Iyz * s.Iyz)) e.Fail(6, "need I1 I2 > I12^2");
  NonNegative(e, 8, "NSM(A)", s.nsm);
  NonNegative(e, f, "K1", s.ky);
  NonNegative(e, f + 1, "K2", s.kz);
  NonNegative(e, f + 4, "NSI(A)", s.nsm_inertia);
}

}  // namespace flexmb::io::nastran
