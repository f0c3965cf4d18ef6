/// \file fe_modes.cc
/// fe_modes_bench: time and peak memory of building, assembling and solving
/// 20 modes of a generated truck ladder frame of 4-node shells (two C-channel
/// rails joined by flat cross members, free-free, consistent mass), about
/// 5,400 nodes / 33,000 DOF at the default element size. Prints a markdown
/// table; see docs/PERFORMANCE.md, "FE assembly and modes".
///
/// Usage: fe_modes_bench [--h H] [--count N] [--lumped]
///   H: element size [m] (default 0.04; 0.0125 gives about 320,000 DOF)
///   N: number of modes (default 20)

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <tuple>

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/modal.h"

namespace {

using flexmb::fe::Element;
using flexmb::fe::ElementType;
using flexmb::fe::Mesh;
using flexmb::fe::Vec3;

double PeakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// ladder frame: rails along x at y = +-b/2 (web in the x-z plane, flanges
// pointing inwards), cross members in y-z planes sharing the rails' web nodes
Mesh LadderFrame(double h) {
  const double length = 6.0, b = 0.9, web = 0.3, flange = 0.08;
  const int nx = std::max(1, static_cast<int>(std::lround(length / h)));
  const int nz = std::max(1, static_cast<int>(std::lround(web / h)));
  const int nf = std::max(1, static_cast<int>(std::lround(flange / h)));
  const int ny = std::max(2, static_cast<int>(std::lround(b / h)));
  Mesh mesh;
  mesh.source = "generated ladder frame";
  flexmb::fe::Material steel;
  steel.id = 1;
  steel.E = 2.1e11;
  steel.nu = 0.3;
  steel.G = steel.E / 2.6;
  steel.rho = 7850.0;
  mesh.materials.push_back(steel);
  for (double t : {0.006, 0.005}) {
    flexmb::fe::ShellSection s;
    s.id = static_cast<int>(mesh.shell_sections.size()) + 1;
    s.material = 0;
    s.thickness = t;
    mesh.shell_sections.push_back(s);
  }
  std::map<std::tuple<long, long, long>, int> index;
  auto node = [&](const Vec3& x) {
    const auto key = std::make_tuple(std::lround(x.x() * 1e6), std::lround(x.y() * 1e6), std::lround(x.z() * 1e6));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    flexmb::fe::Node n;
    n.id = static_cast<int>(mesh.nodes.size()) + 1;
    n.x = x;
    mesh.nodes.push_back(n);
    index[key] = n.id - 1;
    return n.id - 1;
  };
  auto quad = [&](int property, int a, int c, int d, int e) {
    Element el;
    el.id = static_cast<int>(mesh.elements.size()) + 1;
    el.type = ElementType::kQuad4;
    el.property = property;
    el.nodes = {a, c, d, e};
    mesh.elements.push_back(el);
  };
  // a structured patch p(u, v), u in [0, nu], v in [0, nv]
  auto patch = [&](int property, int nu, int nv, auto p) {
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        quad(property, node(p(i, j)), node(p(i + 1, j)), node(p(i + 1, j + 1)), node(p(i, j + 1)));
      }
  };
  const double dx = length / nx, dz = web / nz, df = flange / nf;
  for (double side : {-1.0, 1.0}) {
    const double y = side * b / 2;
    patch(0, nx, nz, [&](int i, int j) { return Vec3(i * dx, y, -web / 2 + j * dz); });
    for (double zf : {-web / 2, web / 2}) {
      patch(0, nx, nf, [&](int i, int j) { return Vec3(i * dx, y - side * j * df, zf); });
    }
  }
  const int n_cross = 8;
  const double dy = b / ny;
  for (int k = 0; k < n_cross; ++k) {
    const double x = std::round((0.25 + k * (length - 0.5) / (n_cross - 1)) / dx) * dx;
    patch(1, ny, nz, [&](int i, int j) { return Vec3(x, -b / 2 + i * dy, -web / 2 + j * dz); });
  }
  mesh.IndexNodes();
  return mesh;
}

double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  double h = 0.04;
  int count = 20;
  bool lumped = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--h") && i + 1 < argc) {
      h = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--count") && i + 1 < argc) {
      count = std::atoi(argv[++i]);
    } else if (!std::strcmp(argv[i], "--lumped")) {
      lumped = true;
    } else {
      std::fprintf(stderr, "usage: fe_modes_bench [--h H] [--count N] [--lumped]\n");
      return 2;
    }
  }
  auto t0 = std::chrono::steady_clock::now();
  const Mesh mesh = LadderFrame(h);
  const double t_build = Seconds(t0);
  const double rss_build = PeakRssMb();

  flexmb::fe::AssemblyOptions options;
  options.mass_form = lumped ? flexmb::fe::MassForm::kLumped : flexmb::fe::MassForm::kConsistent;
  t0 = std::chrono::steady_clock::now();
  const flexmb::fe::AssembledModel model = flexmb::fe::Assemble(mesh, options);
  const double t_assemble = Seconds(t0);
  const double rss_assemble = PeakRssMb();

  t0 = std::chrono::steady_clock::now();
  const flexmb::fe::MassProperties mp = flexmb::fe::ComputeMassProperties(mesh, model);
  const double t_mass = Seconds(t0);

  flexmb::fe::ModalOptions modal;
  modal.count = count;
  t0 = std::chrono::steady_clock::now();
  const flexmb::fe::ModalResult r = flexmb::fe::SolveModes(model, modal);
  const double t_modes = Seconds(t0);
  const double rss_modes = PeakRssMb();

  std::printf("ladder frame, h = %g m: %zu nodes, %zu shells, %d DOF, nnz(K) = %lld, mass %.3f kg\n\n", h,
              mesh.nodes.size(), mesh.elements.size(), model.dofs.n_free, static_cast<long long>(model.K.nonZeros()),
              mp.mass);
  std::printf("| step | time [s] | peak RSS after [MB] |\n|---|---|---|\n");
  std::printf("| generate mesh | %.3f | %.0f |\n", t_build, rss_build);
  std::printf("| assemble K, M (%s) | %.3f | %.0f |\n", lumped ? "lumped" : "consistent", t_assemble, rss_assemble);
  std::printf("| mass properties | %.3f | %.0f |\n", t_mass, rss_assemble);
  std::printf("| %d modes (CHOLMOD + Spectra) | %.3f | %.0f |\n\n", count, t_modes, rss_modes);
  std::printf("frequencies [Hz]:");
  for (int k = 0; k < r.frequencies_hz.size(); ++k) std::printf(" %.4g", r.frequencies_hz[k]);
  std::printf("\n");
  return 0;
}
