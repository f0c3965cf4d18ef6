#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/linear_constraint.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

namespace {

// a component field that may be blank or "0" (RBAR's CNA ... CMB): 0 then
int RigidOptionalMask(const Entry& e, int i) {
  const std::string& t = e.Text(i);
  return t.empty() || t == "0" ? 0 : -1;
}

bool RigidKeyword(const std::string& t) { return t == "UM" || t == "ALPHA" || t == "TREF"; }

}  // namespace

// RBAR  EID GA GB CNA CNB CMA CMB ALPHA; RBAR1  EID GA GB CB ALPHA. The
// form with all six independent DOF on one grid is a rigid link from that
// grid (docs/formats.md).
void Builder::AddRbar(const Entry& e) {
  fe::RigidLink link;
  link.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, link.id, "element");
  const int ga = NodeIndex(e, 2, "GA");
  const int gb = NodeIndex(e, 3, "GB");
  if (ga == gb) e.Fail(3, "GB is the same grid point as GA");
  link.origin = OriginOf(e);
  if (e.name() == "RBAR1") {
    // CB blank: GB moves with GA in all six components
    const int cb = RigidOptionalMask(e, 4) == 0 ? 0b111111 : Components(e, 4, "CB");
    if (AddCdRigid(e, link.id, ga, gb, cb)) return;
    link.independent = ga;
    link.dependent = {gb};
    link.dofs = cb;
    mesh_.rigid_links.push_back(std::move(link));
    return;
  }
  auto mask = [&](int i, const char* what) { return RigidOptionalMask(e, i) == 0 ? 0 : Components(e, i, what); };
  const int cna = mask(4, "CNA"), cnb = mask(5, "CNB"), cma = mask(6, "CMA"), cmb = mask(7, "CMB");
  auto describe = [&] {
    auto s = [&](int i) { return e.Blank(i) ? std::string("blank") : e.Text(i); };
    return "CNA = " + s(4) + ", CNB = " + s(5) + ", CMA = " + s(6) + ", CMB = " + s(7);
  };
  int independent = -1, dependent = -1, dep_mask = 0;
  if (cna == 0b111111 && cnb == 0 && cma == 0) {
    independent = ga, dependent = gb, dep_mask = cmb;
  } else if (cnb == 0b111111 && cna == 0 && cmb == 0) {
    independent = gb, dependent = ga, dep_mask = cma;
  } else {
    e.Fail(4, "independent DOF " + describe() +
                  ": flexmb supports the forms with all six independent DOF on one grid (CNA = 123456 with CNB "
                  "and CMA blank, or CNB = 123456 with CNA and CMB blank); independent DOF split across GA and GB "
                  "are not supported");
  }
  // CMA and CMB both blank: every DOF not independent is dependent (QRG)
  if (dep_mask == 0) dep_mask = 0b111111;
  if (AddCdRigid(e, link.id, independent, dependent, dep_mask)) return;
  link.independent = independent;
  link.dependent = {dependent};
  link.dofs = dep_mask;
  mesh_.rigid_links.push_back(std::move(link));
}

// RBE3  EID blank REFGRID REFC WT1 C1 G1,1 G1,2 ... WT2 C2 G2,1 ... ["UM" ...]
// ["ALPHA" a ["TREF" t]]: a weight starts a group (it is a real), the grids
// run to the next real or keyword; blanks are skipped
void Builder::AddRbe3(const Entry& e) {
  fe::Rbe3Spec spec;
  spec.id = e.Id(1, "EID");
  CheckNewId(element_ids_, e, spec.id, "element");
  spec.ref_node = NodeIndex(e, 3, "REFGRID");
  spec.ref_components = Components(e, 4, "REFC");
  CheckCd(e, 4, spec.ref_node, spec.ref_components);
  spec.origin = OriginOf(e);
  int f = 5;
  while (f <= e.Size()) {
    const std::string& t = e.Text(f);
    if (t.empty()) {
      ++f;
      continue;
    }
    if (t == "UM")
      e.Fail(f, "UM (dependent DOF moved from the reference grid to other grids) is not supported; flexmb makes "
                "the reference grid independent by itself where it is an interface node");
    if (t == "ALPHA" || t == "TREF") break;  // thermal expansion: no part of K and M
    if (!LooksReal(t)) e.Fail(f, "weight WTi expected (a real number), found '" + t + "'");
    fe::Rbe3Group g;
    g.weight = e.Real(f, "WTi");
    if (!(g.weight > 0.0)) e.Fail(f, "weight WTi = " + t + " must be > 0");
    g.components = Components(e, f + 1, "Ci");
    const int group_field = f;
    for (f += 2; f <= e.Size(); ++f) {
      const std::string& gt = e.Text(f);
      if (gt.empty()) continue;
      if (LooksReal(gt) || RigidKeyword(gt)) break;
      const int node = NodeIndex(e, f, "Gi,j");
      CheckCd(e, group_field + 1, node, g.components);
      g.nodes.push_back(node);
    }
    if (g.nodes.empty()) e.Fail(group_field, "weight WTi = " + t + " has no grid points Gi,j");
    spec.groups.push_back(std::move(g));
  }
  if (spec.groups.empty()) e.Fail(5, "no weight groups WTi Ci Gi,j");
  for (fe::LinearConstraint& row : fe::Rbe3Constraints(mesh_, spec)) mesh_.linear_constraints.push_back(std::move(row));
}

}  // namespace flexmb::io::nastran
