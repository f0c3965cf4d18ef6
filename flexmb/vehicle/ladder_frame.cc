#include "flexmb/vehicle/ladder_frame.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <tuple>

#include "flexmb/common/error.h"

namespace flexmb::vehicle {
namespace {

int Divisions(double length, double h) { return std::max(1, static_cast<int>(std::lround(length / h))); }

// areal density [kg/m^2] of a shell element
double ArealDensity(const fe::Mesh& mesh, const fe::Element& e) {
  const fe::ShellSection& s = mesh.shell_sections[static_cast<size_t>(e.property)];
  return mesh.materials[static_cast<size_t>(s.material)].rho * s.thickness + s.nsm;
}

// area of the bilinear quad by 2 x 2 Gauss quadrature, calling f(point, weight * dA) per point
template <class F>
void IntegrateQuad(const fe::Mesh& mesh, const fe::Element& e, F f) {
  const double g = 1.0 / std::sqrt(3.0);
  const fe::Vec3& a = mesh.nodes[static_cast<size_t>(e.nodes[0])].x;
  const fe::Vec3& b = mesh.nodes[static_cast<size_t>(e.nodes[1])].x;
  const fe::Vec3& c = mesh.nodes[static_cast<size_t>(e.nodes[2])].x;
  const fe::Vec3& d = mesh.nodes[static_cast<size_t>(e.nodes[3])].x;
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      const fe::Vec3 x = 0.25 * ((1 - xi) * (1 - eta) * a + (1 + xi) * (1 - eta) * b + (1 + xi) * (1 + eta) * c +
                                 (1 - xi) * (1 + eta) * d);
      const fe::Vec3 dxi = 0.25 * ((1 - eta) * (b - a) + (1 + eta) * (c - d));
      const fe::Vec3 deta = 0.25 * ((1 - xi) * (d - a) + (1 + xi) * (c - b));
      f(x, dxi.cross(deta).norm());
    }
}

// a number for a message: %g, so 0.02 reads "0.02", not "0.020000"
std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// the platform's data against itself and the frame
template <class Fail>
void CheckPlatform(const LadderFrameData& p, Fail fail) {
  const PlatformData& pl = p.platform;
  for (const auto& [key, v] : {std::pair<const char*, double>{"length", pl.length},
                               {"width", pl.width},
                               {"spacer", pl.spacer},
                               {"sill_height", pl.sill_height},
                               {"sill_flange_width", pl.sill_flange_width},
                               {"sill_thickness", pl.sill_thickness},
                               {"bearer_spacing", pl.bearer_spacing},
                               {"bearer_thickness", pl.bearer_thickness},
                               {"bearer_flange_width", pl.bearer_flange_width},
                               {"side_rail_thickness", pl.side_rail_thickness},
                               {"side_rail_flange_width", pl.side_rail_flange_width},
                               {"bracket_length", pl.bracket_length},
                               {"bracket_thickness", pl.bracket_thickness},
                               {"mass", pl.mass}})
    if (!(v > 0) || !std::isfinite(v)) fail(std::string("platform: '") + key + "' must be positive, not " + Num(v));
  if (!std::isfinite(pl.front_x)) fail("platform: 'front_x' must be finite");
  if (pl.front_x > p.front_x + 1e-9)
    fail("platform: front_x " + Num(pl.front_x) + " m is ahead of the rails' front end (" + Num(p.front_x) + " m)");
  if (!(0.5 * pl.width > p.half_spacing + p.element_size))
    fail("platform: width " + Num(pl.width) + " m leaves no overhang beyond the rails (half spacing " +
         Num(p.half_spacing) + " m)");
  // the gaps between the platform's plates across y, and the spacer: at
  // least a millimetre (nodes are merged on micrometre keys)
  const double hs = p.half_spacing, we = 0.5 * pl.width;
  if (pl.spacer < 1e-3) fail("platform: 'spacer' must be at least 1 mm, not " + Num(pl.spacer) + " m");
  if (hs - 2 * pl.sill_flange_width < 1e-3)
    fail("platform: the sill flanges (" + Num(pl.sill_flange_width) + " m) leave less than 1 mm between them");
  if (we - pl.side_rail_flange_width - hs < 1e-3)
    fail("platform: the side rails' flanges reach the sills (width " + Num(pl.width) + " m, side_rail_flange_width " +
         Num(pl.side_rail_flange_width) + " m)");
  if (pl.brackets.size() < 2) fail("platform: give at least two 'brackets' (x of the brackets on the rails)");
  const double rear_x = p.front_x - p.length, prear = pl.front_x - pl.length;
  for (double xb : pl.brackets) {
    const double lo = xb - 0.5 * pl.bracket_length, hi = xb + 0.5 * pl.bracket_length;
    if (!std::isfinite(xb) || lo < std::max(rear_x, prear) - 1e-9 || hi > std::min(p.front_x, pl.front_x) + 1e-9)
      fail("platform: the bracket at x = " + Num(xb) + " m (bracket_length " + Num(pl.bracket_length) +
           " m) is not under the platform (x = " + Num(prear) + " to " + Num(pl.front_x) + " m) and on the rails (" +
           Num(rear_x) + " to " + Num(p.front_x) + " m)");
  }
  std::vector<double> sorted = pl.brackets;
  std::sort(sorted.begin(), sorted.end());
  for (size_t k = 1; k < sorted.size(); ++k)
    if (sorted[k] - sorted[k - 1] < pl.bracket_length)
      fail("platform: the brackets at x = " + Num(sorted[k - 1]) + " and " + Num(sorted[k]) +
           " m overlap (bracket_length " + Num(pl.bracket_length) + " m)");
}

}  // namespace

double PlatformTopZ(const LadderFrameData& p) {
  return p.bottom_z + p.web_height + p.platform.spacer + p.platform.sill_height;
}

LadderFrame GenerateLadderFrame(const LadderFrameData& p, const std::vector<FrameAttachment>& attachments) {
  auto fail = [](const std::string& what) { throw InputError(what, {"", 0, "ladder frame"}); };
  for (double v : {p.length, p.half_spacing, p.web_height, p.flange_width, p.thickness, p.cross_member_thickness,
                   p.element_size, p.E, p.rho})
    if (!(v > 0) || !std::isfinite(v)) fail("dimensions, element size, E and density must be positive");
  if (!(p.nu > -1 && p.nu < 0.5)) fail("Poisson's ratio must be in (-1, 0.5)");
  if (p.flange_width >= p.half_spacing) fail("the flanges must not reach the centre plane");
  const double h = p.element_size;
  // the shells' number, estimated before any int division count is formed:
  // a mistyped element size must not take the memory or overflow
  const double estimate = (p.length / h) * (2 * (p.web_height + 2 * p.flange_width) / h + 1) +
                          p.cross_members.size() * (2 * p.half_spacing / h) * (p.web_height / h + 1);
  const PlatformData& pl = p.platform;
  const bool platform = pl.present;
  if (platform) CheckPlatform(p, fail);
  // (sills and side rails along the platform, bearers' webs and flanges
  // across it, brackets; rounded up)
  const double along = pl.length / h + 1, across = pl.width / h + 8;
  const double platform_estimate =
      platform ? 2 * along * ((pl.sill_height + 2 * pl.sill_flange_width) / h + 3) +
                     2 * along * ((pl.sill_height + pl.side_rail_flange_width) / h + 2) +
                     (pl.length / pl.bearer_spacing + 2) * across *
                         ((pl.sill_height + pl.bearer_flange_width) / h + 2) +
                     static_cast<double>(pl.brackets.size()) * 2 * (pl.bracket_length / h + 1) * (pl.spacer / h + 1)
               : 0.0;
  if (!(estimate + platform_estimate <= kMaxLadderFrameShells)) {
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "element_size %g m makes about %.3g shells, more than %d: raise it (0.04 m: about 5,500 for the "
                  "rails, 12,000 with the 6x4's platform)%s",
                  h, estimate + platform_estimate, kMaxLadderFrameShells,
                  platform_estimate > estimate ? ", or check the platform's size and bearer_spacing" : "");
    fail(buf);
  }
  const int nx = Divisions(p.length, h), nz = Divisions(p.web_height, h), nf = Divisions(p.flange_width, h);
  const int ny = std::max(2, Divisions(2 * p.half_spacing, h));
  const double dx = p.length / nx, dz = p.web_height / nz, df = p.flange_width / nf, dy = 2 * p.half_spacing / ny;
  const double rear_x = p.front_x - p.length, z0 = p.bottom_z;

  LadderFrame out;
  fe::Mesh& mesh = out.mesh;
  mesh.source = "generated ladder frame (flexmb/vehicle/ladder_frame.cc)";
  fe::Material steel;
  steel.id = 1;
  steel.name = "steel";
  steel.E = p.E;
  steel.nu = p.nu;
  steel.G = p.E / (2 * (1 + p.nu));
  steel.rho = p.rho;
  mesh.materials.push_back(steel);
  // sections in the order of LadderSection, the platform's only with one
  std::vector<double> thickness = {p.thickness, p.cross_member_thickness};
  if (platform)
    thickness.insert(thickness.end(), {pl.sill_thickness, pl.bearer_thickness, pl.side_rail_thickness,
                                       pl.bracket_thickness});
  for (double t : thickness) {
    fe::ShellSection s;
    s.id = static_cast<int>(mesh.shell_sections.size()) + 1;
    s.material = 0;
    s.thickness = t;
    mesh.shell_sections.push_back(s);
  }
  // nodes are merged by their coordinates (micrometre keys)
  std::map<std::tuple<long, long, long>, int> index;
  auto node = [&](const fe::Vec3& x) {
    const auto key = std::make_tuple(std::lround(x.x() * 1e6), std::lround(x.y() * 1e6), std::lround(x.z() * 1e6));
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    fe::Node n;
    n.id = static_cast<int>(mesh.nodes.size()) + 1;
    n.x = x;
    mesh.nodes.push_back(n);
    index[key] = n.id - 1;
    return n.id - 1;
  };
  // a structured patch p(i, j), i in [0, nu], j in [0, nv]
  auto patch = [&](int property, int nu, int nv, auto at) {
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        fe::Element el;
        el.id = static_cast<int>(mesh.elements.size()) + 1;
        el.type = fe::ElementType::kQuad4;
        el.property = property;
        el.nodes = {node(at(i, j)), node(at(i + 1, j)), node(at(i + 1, j + 1)), node(at(i, j + 1))};
        mesh.elements.push_back(el);
      }
  };
  for (double side : {-1.0, 1.0}) {
    const double y = side * p.half_spacing;
    patch(kRailSection, nx, nz, [&](int i, int j) { return fe::Vec3(rear_x + i * dx, y, z0 + j * dz); });
    for (double zf : {z0, z0 + p.web_height})
      patch(kRailSection, nx, nf, [&](int i, int j) { return fe::Vec3(rear_x + i * dx, y - side * j * df, zf); });
  }
  for (double xc : p.cross_members) {
    if (xc > p.front_x + 1e-9 || xc < rear_x - 1e-9) fail("cross member at x = " + std::to_string(xc) + " m is off the rails");
    // on the rails' grid so that it shares the web nodes
    const double x = rear_x + std::round((xc - rear_x) / dx) * dx;
    patch(kCrossMemberSection, ny, nz,
          [&](int i, int j) { return fe::Vec3(x, -p.half_spacing + i * dy, z0 + j * dz); });
  }
  if (platform) {
    // on the rails' x grid (extended beyond the rails where the platform
    // overhangs them), so that the brackets share the rails' web nodes
    auto grid = [&](double x) { return static_cast<int>(std::lround((x - rear_x) / dx)); };
    auto xi = [&](int i) { return rear_x + i * dx; };
    const int i0 = grid(pl.front_x - pl.length), i1 = std::max(i0 + 1, grid(pl.front_x));
    const double z_top = z0 + p.web_height, zs0 = z_top + pl.spacer, zs1 = zs0 + pl.sill_height;
    const int nzs = Divisions(pl.sill_height, h), nsp = Divisions(pl.spacer, h);
    const double dzs = pl.sill_height / nzs, dsp = pl.spacer / nsp;
    // the y stations shared by the cross bearers, the sills' webs and flanges
    // and the side rails' webs and flanges
    const double hs = p.half_spacing, we = 0.5 * pl.width, fr = pl.side_rail_flange_width, fs = pl.sill_flange_width;
    const std::vector<double> breaks = {-we, -we + fr, -hs, -hs + fs, hs - fs, hs, we - fr, we};
    std::vector<double> ys;
    std::vector<int> first;  // index in ys of each break
    for (size_t k = 0; k + 1 < breaks.size(); ++k) {
      first.push_back(static_cast<int>(ys.size()));
      const int n = Divisions(breaks[k + 1] - breaks[k], h);
      for (int j = 0; j < n; ++j) ys.push_back(breaks[k] + j * (breaks[k + 1] - breaks[k]) / n);
    }
    first.push_back(static_cast<int>(ys.size()));
    ys.push_back(we);
    // the number of stations' intervals in the segment [breaks[k], breaks[k + 1]]
    auto segment = [&](size_t k) { return first[k + 1] - first[k]; };
    // the brackets' cells on the grid: at least one each, none shared
    std::vector<std::pair<int, int>> bracket_cells;
    for (double xb : pl.brackets) {
      const int b0 = grid(xb - 0.5 * pl.bracket_length), b1 = std::max(b0 + 1, grid(xb + 0.5 * pl.bracket_length));
      for (const auto& [c0, c1] : bracket_cells)
        if (b0 < c1 && c0 < b1)
          fail("platform: the bracket at x = " + Num(xb) + " m shares its elements with another on the " + Num(dx) +
               " m element grid: space the brackets further apart");
      bracket_cells.emplace_back(b0, b1);
    }
    for (double side : {-1.0, 1.0}) {
      const double y = side * hs, ye = side * we;
      const size_t sill_flange = side < 0 ? 2 : 4, rail_flange = side < 0 ? 0 : 6;
      // sill: web and two flanges inwards
      patch(kSillSection, i1 - i0, nzs, [&](int i, int j) { return fe::Vec3(xi(i0 + i), y, zs0 + j * dzs); });
      for (double zf : {zs0, zs1})
        patch(kSillSection, i1 - i0, segment(sill_flange),
              [&](int i, int j) { return fe::Vec3(xi(i0 + i), ys[static_cast<size_t>(first[sill_flange] + j)], zf); });
      // side rail: web and a bottom flange inwards
      patch(kSideRailSection, i1 - i0, nzs, [&](int i, int j) { return fe::Vec3(xi(i0 + i), ye, zs0 + j * dzs); });
      patch(kSideRailSection, i1 - i0, segment(rail_flange),
            [&](int i, int j) { return fe::Vec3(xi(i0 + i), ys[static_cast<size_t>(first[rail_flange] + j)], zs0); });
      // brackets: shear plates over the spacer gap, rail web top to sill web bottom
      for (const std::pair<int, int>& cell : bracket_cells) {
        const int b0 = cell.first;  // a local, not a structured binding: lambdas capture it (C++17)
        patch(kBracketSection, cell.second - b0, nsp,
              [&](int i, int j) { return fe::Vec3(xi(b0 + i), y, z_top + j * dsp); });
      }
    }
    // cross bearers at both ends and evenly between, across the whole width:
    // a web and a top flange pointing into the platform (beside the sills'
    // top flanges, not over them)
    const int nb = std::max(1, static_cast<int>(std::ceil((i1 - i0) * dx / pl.bearer_spacing - 1e-9)));
    const int kf = std::max(1, static_cast<int>(std::lround(pl.bearer_flange_width / dx)));
    std::vector<int> bearers;
    for (int k = 0; k <= nb; ++k) {
      const int i = i0 + static_cast<int>(std::lround(static_cast<double>(k) * (i1 - i0) / nb));
      if (!bearers.empty() && i - bearers.back() <= 2 * kf)
        fail("platform: cross bearers " + Num((i - bearers.back()) * dx) +
             " m apart leave no room for their flanges (bearer_flange_width " + Num(pl.bearer_flange_width) + " m): " +
             (i1 - i0 <= 2 * kf ? "the platform is too short for them" : "raise bearer_spacing"));
      bearers.push_back(i);
    }
    const int nys = static_cast<int>(ys.size()) - 1;
    for (int i : bearers) {
      const double x = xi(i);
      patch(kBearerSection, nys, nzs,
            [&](int a, int j) { return fe::Vec3(x, ys[static_cast<size_t>(a)], zs0 + j * dzs); });
      // the flange rearwards of the front bearer, forwards of the others;
      // meshed along +x then +y, so that its normal is +z as the sills' flanges'
      const int start = i == i1 ? i - kf : i;
      for (size_t k = 0; k + 1 < breaks.size(); ++k)
        if (k != 2 && k != 4)
          patch(kBearerSection, kf, segment(k), [&](int m, int a) {
            return fe::Vec3(xi(start + m), ys[static_cast<size_t>(first[k] + a)], zs1);
          });
    }
  }
  mesh.IndexNodes();

  // steel mass, then the non-structural mass of the rails and the platform
  double steel_mass = 0.0, rail_area = 0.0, platform_steel = 0.0, platform_area = 0.0;
  for (const fe::Element& e : mesh.elements)
    IntegrateQuad(mesh, e, [&](const fe::Vec3&, double dA) {
      (e.property <= kCrossMemberSection ? steel_mass : platform_steel) += ArealDensity(mesh, e) * dA;
      if (e.property == kRailSection) rail_area += dA;
      if (e.property == kSillSection || e.property == kBearerSection) platform_area += dA;
    });
  out.steel_mass = steel_mass;
  out.platform_steel_mass = platform_steel;
  if (platform) {
    if (pl.mass < platform_steel * (1 - 1e-12))
      fail("platform: mass " + Num(pl.mass) + " kg is below its steel mass " + Num(platform_steel) + " kg");
    out.platform_nsm = (pl.mass - platform_steel) / platform_area;
    for (int k : {kSillSection, kBearerSection})
      mesh.shell_sections[static_cast<size_t>(k)].nsm = out.platform_nsm;
  }
  if (p.total_mass > 0) {
    if (p.total_mass < steel_mass * (1 - 1e-12))
      fail("total mass " + std::to_string(p.total_mass) + " kg is below the steel mass " + std::to_string(steel_mass) +
           " kg");
    out.nsm = (p.total_mass - steel_mass) / rail_area;
    mesh.shell_sections[0].nsm = out.nsm;
  }

  // interface nodes: nearest mesh node to each attachment point
  for (const FrameAttachment& a : attachments) {
    out.names.push_back(a.name);
    out.nodes.push_back(NearestNode(mesh, a.point));
  }
  return out;
}

int NearestNode(const fe::Mesh& mesh, const fe::Vec3& point) {
  int best = -1;
  double dmin = std::numeric_limits<double>::infinity();
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    const double d = (mesh.nodes[n].x - point).squaredNorm();
    if (d < dmin) {
      dmin = d;
      best = static_cast<int>(n);
    }
  }
  return best;
}

std::vector<int> FramePartOfNodes(const fe::Mesh& mesh) {
  std::vector<int> part(mesh.nodes.size(), 0);
  for (const fe::Element& e : mesh.elements)
    if (e.property >= kSillSection && e.property <= kSideRailSection)
      for (int n : e.nodes) part[static_cast<size_t>(n)] = 1;
  return part;
}

void AddSpiders(fe::Mesh& mesh, const std::vector<int>& nodes, double radius, const std::vector<int>* part) {
  std::vector<char> taken(mesh.nodes.size(), 0);
  for (int n : nodes) taken[static_cast<size_t>(n)] = 1;
  for (const fe::RigidLink& l : mesh.rigid_links)
    for (int n : l.dependent) taken[static_cast<size_t>(n)] = 1;
  std::vector<int> done;
  for (int n : nodes) {
    if (std::find(done.begin(), done.end(), n) != done.end()) continue;
    done.push_back(n);
    fe::RigidLink link;
    link.id = static_cast<int>(mesh.rigid_links.size()) + 1;
    link.independent = n;
    const fe::Vec3& c = mesh.nodes[static_cast<size_t>(n)].x;
    for (size_t k = 0; k < mesh.nodes.size(); ++k)
      if (!taken[k] && (mesh.nodes[k].x - c).norm() <= radius &&
          (part == nullptr || (*part)[k] == (*part)[static_cast<size_t>(n)])) {
        link.dependent.push_back(static_cast<int>(k));
        taken[k] = 1;
      }
    if (!link.dependent.empty()) mesh.rigid_links.push_back(std::move(link));
  }
}

void AddBracket(fe::Mesh& mesh, int node, const std::vector<fe::Vec3>& points, double radius) {
  std::vector<char> taken(mesh.nodes.size(), 0);
  taken[static_cast<size_t>(node)] = 1;
  for (const fe::RigidLink& l : mesh.rigid_links) {
    taken[static_cast<size_t>(l.independent)] = 1;
    for (int n : l.dependent) taken[static_cast<size_t>(n)] = 1;
  }
  fe::RigidLink link;
  link.id = static_cast<int>(mesh.rigid_links.size()) + 1;
  link.independent = node;
  std::vector<fe::Vec3> centres = points;
  centres.push_back(mesh.nodes[static_cast<size_t>(node)].x);
  for (size_t k = 0; k < mesh.nodes.size(); ++k)
    for (const fe::Vec3& c : centres)
      if (!taken[k] && (mesh.nodes[k].x - c).norm() <= radius) {
        link.dependent.push_back(static_cast<int>(k));
        taken[k] = 1;
      }
  if (!link.dependent.empty()) mesh.rigid_links.push_back(std::move(link));
}

MassProperties3 ShellMassProperties(const fe::Mesh& mesh) {
  MassProperties3 mp;
  fe::Vec3 first = fe::Vec3::Zero();
  fe::Mat3 second = fe::Mat3::Zero();  // int rho x x^T dA
  for (const fe::Element& e : mesh.elements) {
    if (e.type != fe::ElementType::kQuad4) throw InputError("only 4-node shells are supported", {"", 0, "frame mass"});
    const double mu = ArealDensity(mesh, e);
    IntegrateQuad(mesh, e, [&](const fe::Vec3& x, double dA) {
      mp.mass += mu * dA;
      first += mu * dA * x;
      second += mu * dA * x * x.transpose();
    });
  }
  mp.cg = first / mp.mass;
  const fe::Mat3 s = second - mp.mass * mp.cg * mp.cg.transpose();  // about the cg
  mp.inertia = s.trace() * fe::Mat3::Identity() - s;
  return mp;
}

}  // namespace flexmb::vehicle
