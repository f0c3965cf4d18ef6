#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/rod2.h"
#include "flexmb/fe_io/nastran/nastran_builder.h"

namespace flexmb::io::nastran {

namespace {
// a rod's stress recovery point: Nastran's C at (C, 0) (the centroid if
// C = 0), so that every rod is in the beam_fibre stress table
void SetRodStressPoint(double c, fe::BeamSection& s) { s.stress_points = {{c, 0.0}}; }
}  // namespace

// PROD: PID MID A J C NSM
void Builder::ReadProd(const Entry& e, fe::BeamSection& s) {
  s.material = MaterialIndex(e, 2, e.Id(2, "MID"));
  s.A = Positive(e, 3, "area A", e.Real(3, "A"));
  s.J = NonNegative(e, 4, "torsion constant J", e.Real(4, "J", 0.0));
  SetRodStressPoint(e.Real(5, "C", 0.0), s);
  s.nsm = NonNegative(e, 6, "NSM", e.Real(6, "NSM", 0.0));
  if (e.Size() > 6) e.Fail(7, "unexpected field after NSM");
}

// PTUBE: PID MID OD T NSM OD2; T blank: a solid circle (T = OD / 2)
void Builder::ReadPtube(const Entry& e, fe::BeamSection& s) {
  s.material = MaterialIndex(e, 2, e.Id(2, "MID"));
  const double od = Positive(e, 3, "outer diameter OD", e.Real(3, "OD"));
  const double t = Positive(e, 4, "wall thickness T", e.Real(4, "T", od / 2.0));
  if (t > od / 2.0) e.Fail(4, "wall thickness T = " + Str(t) + " exceeds OD / 2 = " + Str(od / 2.0));
  s.nsm = NonNegative(e, 5, "NSM", e.Real(5, "NSM", 0.0));
  if (!e.Blank(6) && e.Real(6, "OD2") != od)
    e.Fail(6, "OD2 = " + e.Text(6) + " differs from OD: tapered tubes are not supported");
  if (e.Size() > 6) e.Fail(7, "unexpected field after OD2");
  const double di = od - 2.0 * t;
  s.A = std::numbers::pi / 4.0 * (od * od - di * di);
  s.J = std::numbers::pi / 32.0 * (std::pow(od, 4) - std::pow(di, 4));
  Positive(e, 3, "tube area", s.A);
  SetRodStressPoint(od / 2.0, s);
}

// CROD, CTUBE: EID PID G1 G2; CONROD: EID G1 G2 MID A J C NSM (its own section)
void Builder::AddRod(const Entry& e) {
  fe::Element el = NewElement(e, fe::kRod2);
  const bool conrod = e.name() == "CONROD";
  if (conrod) {
    ReadNodes(e, el, 2, 2);
    fe::BeamSection s;
    s.id = el.id;
    s.origin = OriginOf(e);
    s.material = MaterialIndex(e, 4, e.Id(4, "MID"));
    s.A = Positive(e, 5, "area A", e.Real(5, "A"));
    s.J = NonNegative(e, 6, "torsion constant J", e.Real(6, "J", 0.0));
    SetRodStressPoint(e.Real(7, "C", 0.0), s);
    s.nsm = NonNegative(e, 8, "NSM", e.Real(8, "NSM", 0.0));
    if (e.Size() > 8) e.Fail(9, "unexpected field after NSM");
    el.property = static_cast<int>(mesh_.beam_sections.size());
    mesh_.beam_sections.push_back(s);
  } else {
    const bool tube = e.name() == "CTUBE";
    const int pid = e.Int(2, "PID", el.id);
    el.property = PropertyIndex(e, 2, pid, {tube ? "PTUBE" : "PROD"});
    ReadNodes(e, el, 3, 2);
    if (e.Size() > 4) e.Fail(5, "unexpected field after G2");
  }
  const fe::Vec3 d = mesh_.nodes[el.nodes[1]].x - mesh_.nodes[el.nodes[0]].x;
  const double scale = std::max(mesh_.nodes[el.nodes[0]].x.norm(), mesh_.nodes[el.nodes[1]].x.norm());
  if (!(d.norm() > 1e-10 * scale) || !(d.norm() > 0.0))
    e.Fail(conrod ? 3 : 4, "zero length: nodes G1 and G2 are at the same position");
  mesh_.elements.push_back(std::move(el));
}

}  // namespace flexmb::io::nastran
