// *TIE: tied contact of two surfaces, as CalculiX documents it. Every node
// of the slave surface whose orthogonal distance from a face of the master
// surface is within the position tolerance, and whose foot point lies in
// that face or not farther outside it than the tolerance, follows the face:
// u_s = sum_k N_k(xi, eta) u_k over the face's nodes, with the face's own
// shape functions at the slave node's projection (fe/face_projection.h).
// Rows for the translations; for the rotations too where the slave node and
// every node of the face carry rotations (shells and beams) and NO ROTATION
// is not given, as Abaqus does. Tied slave nodes are moved onto the master
// surface unless ADJUST=NO. docs/formats.md, "Tied surfaces".

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/log.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/face_projection.h"
#include "flexmb/fe/linear_constraint.h"
#include "flexmb/fe_io/abaqus/abaqus_builder.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io::abaqus {
namespace {

using fe::Vec3;

std::string TieNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// the mean corner-to-corner edge length of the faces: CalculiX's "typical
// element size" for the default position tolerance
double TieTypicalSize(const fe::Mesh& mesh, const std::vector<SurfaceFace>& faces) {
  double sum = 0.0;
  int count = 0;
  for (const SurfaceFace& f : faces) {
    const int corners = f.nodes.size() == 3 || f.nodes.size() == 6 ? 3 : 4;
    for (int k = 0; k < corners; ++k) {
      sum += (mesh.nodes[f.nodes[(k + 1) % corners]].x - mesh.nodes[f.nodes[k]].x).norm();
      ++count;
    }
  }
  return count > 0 ? sum / count : 0.0;
}

// the faces by the cells of a uniform grid (cell size at least the largest
// face's extent plus the tolerance) that their boxes, grown by the
// tolerance, overlap: a point's candidates are those of its cell
class TieFaceGrid {
 public:
  TieFaceGrid(const fe::Mesh& mesh, const std::vector<SurfaceFace>& faces, double tol) {
    std::vector<std::pair<Vec3, Vec3>> boxes;
    for (const SurfaceFace& f : faces) {
      Vec3 lo = mesh.nodes[f.nodes[0]].x, hi = lo;
      for (int n : f.nodes) {
        lo = lo.cwiseMin(mesh.nodes[n].x);
        hi = hi.cwiseMax(mesh.nodes[n].x);
      }
      lo.array() -= tol;
      hi.array() += tol;
      cell_ = std::max(cell_, (hi - lo).maxCoeff());
      boxes.emplace_back(lo, hi);
    }
    if (!(cell_ > 0.0)) cell_ = 1.0;
    for (size_t f = 0; f < boxes.size(); ++f) {
      const Key a = KeyOf(boxes[f].first), b = KeyOf(boxes[f].second);
      for (long i = a[0]; i <= b[0]; ++i)
        for (long j = a[1]; j <= b[1]; ++j)
          for (long k = a[2]; k <= b[2]; ++k) cells_[{i, j, k}].push_back(static_cast<int>(f));
    }
  }
  const std::vector<int>& Candidates(const Vec3& p) const {
    static const std::vector<int> kNone;
    auto it = cells_.find(KeyOf(p));
    return it == cells_.end() ? kNone : it->second;
  }

 private:
  using Key = std::array<long, 3>;
  Key KeyOf(const Vec3& p) const {
    return {std::lround(std::floor(p.x() / cell_)), std::lround(std::floor(p.y() / cell_)),
            std::lround(std::floor(p.z() / cell_))};
  }
  double cell_ = 0.0;
  std::map<Key, std::vector<int>> cells_;
};

}  // namespace

void Builder::Tie(const Card& c) {
  static const std::pair<const char*, const char*> kUnsupported[] = {{"CYCLICSYMMETRY", "CYCLIC SYMMETRY"},
                                                                     {"MULTISTAGE", "MULTISTAGE"},
                                                                     {"FLUIDCOUPLING", "FLUID COUPLING"},
                                                                     {"THERMAL", "THERMAL"},
                                                                     {"CONSTRAINTRATIO", "CONSTRAINT RATIO"}};
  for (const auto& [key, spelled] : kUnsupported)
    if (c.Find(key)) Fail(c.origin, c.name, std::string(spelled) + " is not supported (flexmb reads tied contact)");
  const Param* np = c.Find("NAME");
  if (np == nullptr || np->value.empty()) Fail(c.origin, c.name, "needs NAME=");
  const std::string entity = c.name + " " + Printable(np->value);
  if (auto [it, fresh] = ties_.emplace(Upper(np->value), c.origin); !fresh)
    Fail(c.origin, entity, "a *TIE of this name is already defined at " + At(it->second));
  bool adjust = true;
  if (const Param* p = c.Find("ADJUST")) {
    const std::string v = Upper(p->value);
    if (v != "YES" && v != "NO") Fail(c.origin, entity, "ADJUST=" + Printable(p->value) + ": expected YES or NO");
    adjust = v == "YES";
  }
  if (const Param* p = c.Find("TYPE")) {
    const std::string v = NoBlanks(Upper(p->value));
    if (v != "NODETOSURFACE" && v != "SURFACETOSURFACE")
      Fail(c.origin, entity, "TYPE=" + Printable(p->value) + ": expected NODE TO SURFACE or SURFACE TO SURFACE");
    if (v == "SURFACETOSURFACE")
      WarnOnce("tie surface to surface", At(c.origin) + ": " + entity +
                                             ": TYPE=SURFACE TO SURFACE is read as node to surface (each slave "
                                             "node follows the master face it projects onto)");
  }
  const bool rotations = c.Find("NOROTATION") == nullptr;
  if (c.data.size() != 1) Fail(c.origin, entity, "needs exactly one data line: slave surface, master surface");
  const DataLine& d = c.data.front();
  MaxFields(d, 2, entity);
  if (d.fields.size() < 2 || d.fields[0].empty() || d.fields[1].empty())
    Fail(d.origin, entity, "needs the slave and the master surface");
  auto slave_it = surfaces_.find(Upper(d.fields[0]));
  if (slave_it == surfaces_.end()) Fail(d.origin, entity, "unknown slave surface '" + Printable(d.fields[0]) + "'");
  auto master_it = surface_faces_.find(Upper(d.fields[1]));
  if (master_it == surface_faces_.end())
    Fail(d.origin, entity, "unknown master surface '" + Printable(d.fields[1]) + "'");
  const std::vector<SurfaceFace>& faces = master_it->second;
  if (faces.empty())
    Fail(d.origin, entity, "master surface '" + Printable(d.fields[1]) + "' has no element faces (a master "
                                                                      "surface must be element-based)");
  double tol = 0.0;
  if (const Param* p = c.Find("POSITIONTOLERANCE")) tol = Real(p->value, c.origin, entity, "POSITION TOLERANCE");
  if (tol < 0.0) Fail(c.origin, entity, "POSITION TOLERANCE must not be negative");
  if (tol < 1e-10) tol = 0.025 * TieTypicalSize(mesh_, faces);  // CalculiX's default

  // which nodes carry rotations (used by a shell or beam element that acts
  // on rotations: not a truss or a membrane)
  std::vector<bool> rotational(mesh_.nodes.size(), false);
  for (const fe::Element& e : mesh_.elements)
    if (fe::Traits(e.type).DofsPerNode() == 6 && !fe::ActsOnTranslationsOnly(mesh_, e))
      for (int n : e.nodes) rotational[n] = true;
  std::set<int> master_nodes;
  for (const SurfaceFace& f : faces) master_nodes.insert(f.nodes.begin(), f.nodes.end());

  const TieFaceGrid grid(mesh_, faces, tol);
  std::vector<int> untied;
  int tied = 0;
  for (int s : slave_it->second) {
    if (master_nodes.count(s)) continue;  // a node of both surfaces is joined already
    const Vec3 p = mesh_.nodes[s].x;
    int best = -1;
    double best_score = 0.0;
    fe::FaceProjection best_proj;
    for (int f : grid.Candidates(p)) {
      std::vector<Vec3> x;
      for (int n : faces[f].nodes) x.push_back(mesh_.nodes[n].x);
      const fe::FaceProjection r = fe::ProjectOntoFace(x, p);
      if (!r.converged || r.normal_distance > tol || r.outside > tol) continue;
      const double score = std::hypot(r.normal_distance, r.outside);
      if (best < 0 || score < best_score) {
        best = f;
        best_score = score;
        best_proj = r;
      }
    }
    if (best < 0) {
      untied.push_back(mesh_.nodes[s].id);
      continue;
    }
    ++tied;
    const SurfaceFace& face = faces[best];
    bool with_rotations = rotations && rotational[s];
    for (int n : face.nodes) with_rotations = with_rotations && rotational[n];
    for (int comp = 0; comp < (with_rotations ? 6 : 3); ++comp) {
      fe::LinearConstraint row;
      row.id = ++link_count_;
      row.card = entity;
      row.node = s;
      row.component = comp;
      row.origin = c.origin;
      for (size_t k = 0; k < face.nodes.size(); ++k)
        if (std::abs(best_proj.weights[k]) > 1e-14) row.terms.push_back({face.nodes[k], comp, best_proj.weights[k]});
      mesh_.linear_constraints.push_back(std::move(row));
    }
    if (adjust) mesh_.nodes[s].x = best_proj.point;
  }
  if (tied == 0)
    Fail(c.origin, entity, "no node of the slave surface '" + Printable(d.fields[0]) + "' lies within the position "
                           "tolerance " + TieNumber(tol) + " of the master surface '" + Printable(d.fields[1]) +
                           "': check the surfaces or give POSITION TOLERANCE=");
  if (!untied.empty()) {
    std::string ids;
    for (size_t k = 0; k < std::min<size_t>(untied.size(), 10); ++k) ids += (k ? ", " : "") + std::to_string(untied[k]);
    if (untied.size() > 10) ids += ", ...";
    LogWarning(At(c.origin) + ": " + entity + ": " + std::to_string(untied.size()) + " of " +
               std::to_string(untied.size() + tied) + " slave nodes are not tied (farther than the position "
               "tolerance " + TieNumber(tol) + " from every master face): " + ids);
  }
}

}  // namespace flexmb::io::abaqus
