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

}  // namespace

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
  if (!(estimate <= kMaxLadderFrameShells)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "element_size %g m makes about %.3g shells, more than %d: raise it (0.04 m: about 5,500)",
                  h, estimate, kMaxLadderFrameShells);
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
  for (double t : {p.thickness, p.cross_member_thickness}) {
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
    patch(0, nx, nz, [&](int i, int j) { return fe::Vec3(rear_x + i * dx, y, z0 + j * dz); });
    for (double zf : {z0, z0 + p.web_height})
      patch(0, nx, nf, [&](int i, int j) { return fe::Vec3(rear_x + i * dx, y - side * j * df, zf); });
  }
  for (double xc : p.cross_members) {
    if (xc > p.front_x + 1e-9 || xc < rear_x - 1e-9) fail("cross member at x = " + std::to_string(xc) + " m is off the rails");
    // on the rails' grid so that it shares the web nodes
    const double x = rear_x + std::round((xc - rear_x) / dx) * dx;
    patch(1, ny, nz, [&](int i, int j) { return fe::Vec3(x, -p.half_spacing + i * dy, z0 + j * dz); });
  }
  mesh.IndexNodes();

  // steel mass, then the non-structural mass of the rails
  double steel_mass = 0.0, rail_area = 0.0;
  for (const fe::Element& e : mesh.elements)
    IntegrateQuad(mesh, e, [&](const fe::Vec3&, double dA) {
      steel_mass += ArealDensity(mesh, e) * dA;
      if (e.property == 0) rail_area += dA;
    });
  out.steel_mass = steel_mass;
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

void AddSpiders(fe::Mesh& mesh, const std::vector<int>& nodes, double radius) {
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
      if (!taken[k] && (mesh.nodes[k].x - c).norm() <= radius) {
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
