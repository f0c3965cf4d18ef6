#include "flexmb/fe_io/nastran/nastran_sections.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace flexmb::io::nastran {

namespace {

// a rectangle of the section: centre (z, y), width along z, height along y
struct Rect {
  double z, y, bz, hy;
};

// cross product of (b - a) and (c - a) in the (y, z) plane
double SectionTurn(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// the convex hull of the rectangles' corners, (y, z) from the centroid,
// counter-clockwise (Andrew's monotone chain); points closer than 1e-9 of
// the section's size and turns within rounding of collinear are merged
std::vector<std::array<double, 2>> SectionHull(const std::vector<Rect>& rects, double yc, double zc) {
  std::vector<std::array<double, 2>> pts;
  double size = 0.0;
  for (const Rect& r : rects)
    for (double sy : {-0.5, 0.5})
      for (double sz : {-0.5, 0.5}) {
        pts.push_back({r.y + sy * r.hy - yc, r.z + sz * r.bz - zc});
        size = std::max({size, std::abs(pts.back()[0]), std::abs(pts.back()[1])});
      }
  const double tol = 1e-9 * size;
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end(),
                        [tol](const std::array<double, 2>& a, const std::array<double, 2>& b) {
                          return std::abs(a[0] - b[0]) <= tol && std::abs(a[1] - b[1]) <= tol;
                        }),
            pts.end());
  const double flat = tol * size;  // |cross| of a turn within rounding of collinear
  std::vector<std::array<double, 2>> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && SectionTurn(hull[k - 2], hull[k - 1], pts[i]) <= flat) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && SectionTurn(hull[k - 2], hull[k - 1], pts[i]) <= flat) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

// 8 points on a circle of radius r at 45 degree steps from +y
std::vector<std::array<double, 2>> CirclePoints(double r) {
  std::vector<std::array<double, 2>> pts;
  for (int k = 0; k < 8; ++k) pts.push_back({r * std::cos(k * M_PI / 4.0), r * std::sin(k * M_PI / 4.0)});
  return pts;
}

// A, I1, I2, I12 about the centroid of a union of disjoint rectangles
// (parallel axis theorem)
void RectangleUnion(const std::vector<Rect>& rects, ShapeProperties* p) {
  double area = 0.0, sz = 0.0, sy = 0.0;
  for (const Rect& r : rects) {
    const double a = r.bz * r.hy;
    area += a;
    sz += a * r.z;
    sy += a * r.y;
  }
  const double zc = sz / area, yc = sy / area;
  double i1 = 0.0, i2 = 0.0, i12 = 0.0;
  for (const Rect& r : rects) {
    const double a = r.bz * r.hy;
    const double dy = r.y - yc, dz = r.z - zc;
    i1 += r.bz * r.hy * r.hy * r.hy / 12.0 + a * dy * dy;
    i2 += r.hy * r.bz * r.bz * r.bz / 12.0 + a * dz * dz;
    i12 += a * dy * dz;
  }
  p->A = area;
  p->I1 = i1;
  p->I2 = i2;
  p->I12 = i12;
  p->points = SectionHull(rects, yc, zc);
}

std::string Need(bool ok, const std::string& what) { return ok ? std::string() : what; }

}  // namespace

int ShapeDimensionCount(const std::string& type) {
  static const std::map<std::string, int> kCounts = {
      {"ROD", 1}, {"TUBE", 2}, {"BAR", 2}, {"BOX", 4}, {"I", 6},
      {"CHAN", 4}, {"L", 4}, {"T", 4}, {"H", 4}};
  const auto it = kCounts.find(type);
  return it == kCounts.end() ? 0 : it->second;
}

std::string ComputeShape(const std::string& type, const std::vector<double>& d, double nu,
                         ShapeProperties* p) {
  const int n = ShapeDimensionCount(type);
  if (n == 0) return "section TYPE '" + type + "' is not supported";
  if (static_cast<int>(d.size()) != n)
    return "TYPE " + type + " needs " + std::to_string(n) + " dimensions";
  for (int i = 0; i < n; ++i)
    if (!(d[i] > 0.0) || !std::isfinite(d[i]))
      return "DIM" + std::to_string(i + 1) + " must be positive and finite";
  *p = ShapeProperties();
  std::string err;
  if (type == "ROD") {
    // solid circle: exact; shear factor by Cowper (1966), J. Appl. Mech. 33, 335-340
    const double r = d[0];
    p->A = M_PI * r * r;
    p->I1 = p->I2 = M_PI * std::pow(r, 4) / 4.0;
    p->J = M_PI * std::pow(r, 4) / 2.0;
    p->K1 = p->K2 = 6.0 * (1.0 + nu) / (7.0 + 6.0 * nu);
    p->points = CirclePoints(r);
  } else if (type == "TUBE") {
    // hollow circle: exact; Cowper's factor with m = r_in / r_out
    const double ro = d[0], ri = d[1];
    if (!(err = Need(ri < ro, "TUBE: inner radius DIM2 must be smaller than outer radius DIM1")).empty())
      return err;
    p->A = M_PI * (ro * ro - ri * ri);
    p->I1 = p->I2 = M_PI * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
    p->J = M_PI * (std::pow(ro, 4) - std::pow(ri, 4)) / 2.0;
    const double m = ri / ro, q = (1.0 + m * m) * (1.0 + m * m);
    p->K1 = p->K2 = 6.0 * (1.0 + nu) * q / ((7.0 + 6.0 * nu) * q + (20.0 + 12.0 * nu) * m * m);
    p->points = CirclePoints(ro);
  } else if (type == "BAR") {
    // rectangle DIM1 (z) x DIM2 (y); J by Roark's Formulas for Stress and
    // Strain (7th ed., Table 10.7 case 4): a b^3 [1/3 - 0.21 (b/a)(1 - b^4 / (12 a^4))],
    // a >= b the sides; shear factor by Cowper: 10 (1 + nu) / (12 + 11 nu)
    RectangleUnion({{0.0, 0.0, d[0], d[1]}}, p);
    const double a = std::max(d[0], d[1]), b = std::min(d[0], d[1]);
    p->J = a * b * b * b * (1.0 / 3.0 - 0.21 * (b / a) * (1.0 - std::pow(b / a, 4) / 12.0));
    p->K1 = p->K2 = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
  } else if (type == "BOX") {
    // hollow rectangle; J by Bredt's thin-walled formula on the wall mid-lines
    // (Roark 7th ed., Table 10.7 case 16): 2 t1 t2 (b - t2)^2 (h - t1)^2 / (b t2 + h t1 - t1^2 - t2^2)
    const double b = d[0], h = d[1], t1 = d[2], t2 = d[3];
    if (!(err = Need(h > 2.0 * t1, "BOX: DIM2 must exceed 2 DIM3")).empty()) return err;
    if (!(err = Need(b > 2.0 * t2, "BOX: DIM1 must exceed 2 DIM4")).empty()) return err;
    const double hc = h - 2.0 * t1;
    RectangleUnion({{0.0, 0.5 * (h - t1), b, t1},
                    {0.0, -0.5 * (h - t1), b, t1},
                    {0.5 * (b - t2), 0.0, t2, hc},
                    {-0.5 * (b - t2), 0.0, t2, hc}},
                   p);
    p->J = 2.0 * t1 * t2 * (b - t2) * (b - t2) * (h - t1) * (h - t1) /
           (b * t2 + h * t1 - t1 * t1 - t2 * t2);
    p->K1 = 2.0 * hc * t2 / p->A;
    p->K2 = 2.0 * (b - 2.0 * t2) * t1 / p->A;
  } else if (type == "I") {
    // open thin-walled sections (I, CHAN, L, T, H): J = sum l t^3 / 3 over the
    // walls with mid-line lengths l (Saint-Venant thin-strip approximation,
    // Timoshenko & Goodier, Theory of Elasticity, 3rd ed., sec. 109);
    // K = web (or flange) area / A, the engineering shear-area approximation
    const double h = d[0], wb = d[1], wt = d[2], tw = d[3], tb = d[4], tt = d[5];
    if (!(err = Need(h > tb + tt, "I: DIM1 must exceed DIM5 + DIM6")).empty()) return err;
    if (!(err = Need(tw <= std::min(wb, wt), "I: web thickness DIM4 exceeds a flange width")).empty())
      return err;
    const double hw = h - tb - tt;
    RectangleUnion({{0.0, 0.5 * tb, wb, tb}, {0.0, h - 0.5 * tt, wt, tt}, {0.0, tb + 0.5 * hw, tw, hw}},
                   p);
    p->J = (wb * tb * tb * tb + wt * tt * tt * tt + (h - 0.5 * (tb + tt)) * tw * tw * tw) / 3.0;
    p->K1 = hw * tw / p->A;
    p->K2 = (wb * tb + wt * tt) / p->A;
  } else if (type == "CHAN") {
    const double b = d[0], h = d[1], tw = d[2], tf = d[3];
    if (!(err = Need(h > 2.0 * tf, "CHAN: DIM2 must exceed 2 DIM4")).empty()) return err;
    if (!(err = Need(b > tw, "CHAN: DIM1 must exceed DIM3")).empty()) return err;
    const double bf = b - tw;
    RectangleUnion({{0.5 * tw, 0.5 * h, tw, h},
                    {tw + 0.5 * bf, h - 0.5 * tf, bf, tf},
                    {tw + 0.5 * bf, 0.5 * tf, bf, tf}},
                   p);
    p->J = (2.0 * (b - 0.5 * tw) * tf * tf * tf + (h - tf) * tw * tw * tw) / 3.0;
    p->K1 = (h - 2.0 * tf) * tw / p->A;
    p->K2 = 2.0 * bf * tf / p->A;
  } else if (type == "L") {
    const double b = d[0], h = d[1], t1 = d[2], t2 = d[3];
    if (!(err = Need(h > t1, "L: DIM2 must exceed DIM3")).empty()) return err;
    if (!(err = Need(b > t2, "L: DIM1 must exceed DIM4")).empty()) return err;
    RectangleUnion({{0.5 * b, 0.5 * t1, b, t1}, {0.5 * t2, t1 + 0.5 * (h - t1), t2, h - t1}}, p);
    p->J = ((b - 0.5 * t2) * t1 * t1 * t1 + (h - 0.5 * t1) * t2 * t2 * t2) / 3.0;
    p->K1 = (h - t1) * t2 / p->A;
    p->K2 = (b - t2) * t1 / p->A;
  } else if (type == "T") {
    const double b = d[0], h = d[1], tf = d[2], tw = d[3];
    if (!(err = Need(h > tf, "T: DIM2 must exceed DIM3")).empty()) return err;
    if (!(err = Need(b >= tw, "T: DIM4 exceeds the flange width DIM1")).empty()) return err;
    RectangleUnion({{0.0, h - 0.5 * tf, b, tf}, {0.0, 0.5 * (h - tf), tw, h - tf}}, p);
    p->J = (b * tf * tf * tf + (h - 0.5 * tf) * tw * tw * tw) / 3.0;
    p->K1 = (h - tf) * tw / p->A;
    p->K2 = b * tf / p->A;
  } else if (type == "H") {
    // two vertical flanges of thickness DIM2 / 2 and height DIM3 joined by a
    // horizontal web of length DIM1 and thickness DIM4
    const double w = d[0], tf = 0.5 * d[1], hf = d[2], tw = d[3];
    if (!(err = Need(hf > tw, "H: DIM3 must exceed DIM4")).empty()) return err;
    const double zf = 0.5 * (w + tf);
    RectangleUnion({{-zf, 0.0, tf, hf}, {zf, 0.0, tf, hf}, {0.0, 0.0, w, tw}}, p);
    p->J = (2.0 * hf * tf * tf * tf + (w + tf) * tw * tw * tw) / 3.0;
    p->K1 = 2.0 * hf * tf / p->A;
    p->K2 = w * tw / p->A;
  }
  return std::string();
}

}  // namespace flexmb::io::nastran
