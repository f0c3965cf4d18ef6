#include "flexmb/fe/elements/shell_macro.h"

#include <cmath>
#include <functional>

#include <Eigen/Cholesky>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/element_common.h"
#include "flexmb/fe/elements/shell_quad4.h"
#include "flexmb/fe/elements/shell_tria3.h"

namespace flexmb::fe::shell {
namespace {

// the element's points: its nodes, then the extra points at the places
// their weights interpolate
struct MacroPoints {
  std::vector<Vec3> x;
};

MacroPoints Points(const ElementInput& in, const MacroLayout& layout) {
  const Element& e = CheckElementNodes(in, layout.nodes, "shell");
  // the centre points of a membrane have no normal or rotational stiffness
  // to condense: second-order membranes are refused
  if (in.shell != nullptr && in.shell->laminate && in.shell->laminate->membrane_only)
    throw InputError("a second-order membrane (" + in.shell->laminate->card +
                         " has no bending material) is not supported: mesh the membrane with 4- or 3-node elements",
                     ElementContext(e));
  const int n = layout.nodes;
  MacroPoints p;
  p.x.assign(in.x, in.x + n);
  for (const std::vector<double>& w : layout.extra) {
    Vec3 xk = Vec3::Zero();
    for (int i = 0; i < n; ++i) xk += w[i] * in.x[i];
    p.x.push_back(xk);
  }
  return p;
}

// the normal and e1 of a shell on points x: quads by their diagonals,
// triangles by two edges; e1 along the first edge, in the plane
void Axes(const Vec3* x, int corners, Vec3& e1, Vec3& e3) {
  const Vec3 n = corners == 4 ? Vec3((x[2] - x[0]).cross(x[3] - x[1])) : Vec3((x[1] - x[0]).cross(x[2] - x[0]));
  e3 = n.normalized();
  e1 = ((x[1] - x[0]) - e3 * e3.dot(x[1] - x[0])).normalized();
}

double Area(const Vec3* x, int corners) {
  return 0.5 * (corners == 4 ? (x[2] - x[0]).cross(x[3] - x[1]) : (x[1] - x[0]).cross(x[2] - x[0])).norm();
}

// one sub-element: its element (the parent's id, type and origin name it
// in messages, its own material angle), coordinates and point indices
struct MacroSub {
  Element element;
  std::vector<Vec3> x;
  std::vector<int> points;
  ElementInput input;
  Vec3 e1, e3;
};

// calls f for each sub-element with its input bound
void ForEachSub(const ElementInput& in, const MacroLayout& layout, const MacroPoints& p,
                const std::function<void(MacroSub&)>& f) {
  // the material axis of the element, a vector in its plane
  Vec3 pe1, pe3;
  Axes(in.x, layout.corners, pe1, pe3);
  const Vec3 pe2 = pe3.cross(pe1);
  const double th = in.element->shell_theta;
  const Vec3 material = std::cos(th) * pe1 + std::sin(th) * pe2;
  for (const std::vector<int>& points : layout.subs) {
    MacroSub s;
    s.points = points;
    s.element = *in.element;
    s.element.nodes.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
      s.element.nodes[i] = static_cast<int>(i);
      s.x.push_back(p.x[points[i]]);
    }
    Axes(s.x.data(), static_cast<int>(points.size()), s.e1, s.e3);
    const Vec3 e2 = s.e3.cross(s.e1);
    s.element.shell_theta = std::isfinite(th) ? std::atan2(material.dot(e2), material.dot(s.e1)) : th;
    s.input = in;
    s.input.element = &s.element;
    s.input.x = s.x.data();
    f(s);
  }
}

// adds the sub-element's block (its points' DOF) into the points' matrix
void Scatter(const MacroSub& s, const MatX& block, MatX& out) {
  const int m = static_cast<int>(s.points.size());
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) out.block(6 * s.points[i], 6 * s.points[j], 6, 6) += block.block(6 * i, 6 * j, 6, 6);
}

// the sub-element's part of the points' vector
Eigen::VectorXd Gather(const MacroSub& s, const Eigen::VectorXd& v) {
  Eigen::VectorXd out(6 * s.points.size());
  for (size_t i = 0; i < s.points.size(); ++i) out.segment<6>(6 * i) = v.segment<6>(6 * s.points[i]);
  return out;
}

// the sub-elements' stiffness (and mass, if m is not null) over all points
MatX PointStiffness(const ElementInput& in, const MacroLayout& layout, const MacroPoints& p, MatX* m) {
  const Eigen::Index np = 6 * static_cast<Eigen::Index>(p.x.size());
  MatX kp = MatX::Zero(np, np), ks, ms;
  if (m != nullptr) *m = MatX::Zero(np, np);
  ForEachSub(in, layout, p, [&](MacroSub& s) {
    if (s.points.size() == 4)
      ShellQuad4Matrices(s.input, ks, ms);
    else
      ShellTria3Matrices(s.input, ks, ms);
    Scatter(s, ks, kp);
    if (m != nullptr) Scatter(s, ms, *m);
  });
  return kp;
}

// T (points' DOF from the element's): the nodes' own, the extra points'
// by static condensation, -Kcc^-1 Kcn
MatX Condensation(const MatX& kp, int n) {
  const Eigen::Index nn = 6 * n, nc = kp.rows() - nn;
  MatX t = MatX::Zero(kp.rows(), nn);
  t.topRows(nn).setIdentity();
  if (nc > 0) t.bottomRows(nc) = -kp.bottomRightCorner(nc, nc).ldlt().solve(kp.bottomLeftCorner(nc, nn));
  return t;
}

}  // namespace

void MacroMatrices(const ElementInput& in, const MacroLayout& layout, MatX& K, MatX& M) {
  const MacroPoints p = Points(in, layout);
  MatX mp;
  const MatX kp = PointStiffness(in, layout, p, &mp);
  const MatX t = Condensation(kp, layout.nodes);
  K = t.transpose() * kp * t;
  K = 0.5 * (K + K.transpose()).eval();
  M = t.transpose() * mp * t;
  M = 0.5 * (M + M.transpose()).eval();
}

void MacroStress(const ElementInput& in, const MacroLayout& layout, MatX& S, Eigen::Matrix3d& axes) {
  const MacroPoints p = Points(in, layout);
  const MatX t = Condensation(PointStiffness(in, layout, p, nullptr), layout.nodes);
  Vec3 pe1, pe3;
  Axes(in.x, layout.corners, pe1, pe3);
  axes.col(0) = pe1;
  axes.col(1) = pe3.cross(pe1);
  axes.col(2) = pe3;
  MatX sp = MatX::Zero(6, t.rows()), ss;
  Eigen::Matrix3d sub_axes;
  double total = 0.0;
  ForEachSub(in, layout, p, [&](MacroSub& s) {
    if (s.points.size() == 4)
      ShellQuad4Stress(s.input, ss, sub_axes);
    else
      ShellTria3Stress(s.input, ss, sub_axes);
    // the element's e1 at angle phi in the sub-element's axes: stresses in axes turned by phi
    const double phi = std::atan2(pe1.dot(sub_axes.col(1)), pe1.dot(sub_axes.col(0)));
    const double c = std::cos(phi), sn = std::sin(phi);
    Eigen::Matrix3d r;
    r << c * c, sn * sn, 2 * c * sn, sn * sn, c * c, -2 * c * sn, -c * sn, c * sn, c * c - sn * sn;
    const double w = Area(s.x.data(), static_cast<int>(s.points.size()));
    total += w;
    for (size_t i = 0; i < s.points.size(); ++i)
      for (int side = 0; side < 2; ++side)
        sp.block(3 * side, 6 * s.points[i], 3, 6) += w * r * ss.block(3 * side, 6 * i, 3, 6);
  });
  S = sp * t / total;
}

void MacroGeometricStiffness(const ElementInput& in, const MacroLayout& layout, const Eigen::VectorXd& u,
                             MatX& KG) {
  const MacroPoints p = Points(in, layout);
  const MatX t = Condensation(PointStiffness(in, layout, p, nullptr), layout.nodes);
  const Eigen::VectorXd up = t * u;
  MatX kp = MatX::Zero(t.rows(), t.rows()), kg;
  ForEachSub(in, layout, p, [&](MacroSub& s) {
    const Eigen::VectorXd us = Gather(s, up);
    if (s.points.size() == 4)
      ShellQuad4GeometricStiffness(s.input, us, kg);
    else
      ShellTria3GeometricStiffness(s.input, us, kg);
    Scatter(s, kg, kp);
  });
  KG = t.transpose() * kp * t;
  KG = 0.5 * (KG + KG.transpose()).eval();
}

}  // namespace flexmb::fe::shell
