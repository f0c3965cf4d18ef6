#include "apps/flexmb/commands/fe_static.h"

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "apps/flexmb/commands/command_support.h"
#include "flexmb/common/error.h"
#include "flexmb/common/json_text.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe/sparse_cholesky.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/reduction/geometric_stiffness.h"

namespace flexmb::io {
namespace {

using namespace command;

// the numbers of an option's value, `n_min` or `n_max` of them
std::vector<double> CountedNumbers(const std::string& text, int n_min, int n_max, const std::string& option) {
  const std::vector<double> x = NumberList(text, option);
  const int n = static_cast<int>(x.size());
  if (n != n_min && n != n_max)
    throw InputError(option + " '" + text + "': expected " + std::to_string(n_min) +
                     (n_max != n_min ? " or " + std::to_string(n_max) : std::string()) + " numbers, got " +
                     std::to_string(n));
  return x;
}

// one --force: node index and the 6 load components
struct NodalLoad {
  int node = -1;
  double f[6] = {0, 0, 0, 0, 0, 0};
};

NodalLoad ParseForce(const fe::Mesh& mesh, const std::string& text, const std::string& path) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos)
    throw InputError("--force '" + text + "': expected NODE:fx,fy,fz or NODE:fx,fy,fz,mx,my,mz");
  NodalLoad l;
  const std::vector<int> node = NodeListOption(mesh, text.substr(0, colon), path);
  if (node.size() != 1) throw InputError("--force '" + text + "': expected one node id before ':'");
  l.node = node.front();
  const std::vector<double> v = CountedNumbers(text.substr(colon + 1), 3, 6, "--force");
  for (size_t c = 0; c < v.size(); ++c) l.f[c] = v[c];
  return l;
}

// one --support: an SPC of the node's components (Nastran digits 1-6)
fe::Constraint ParseSupport(const fe::Mesh& mesh, const std::string& text, const std::string& path) {
  const size_t colon = text.find(':');
  const std::string digits = colon == std::string::npos ? "" : text.substr(colon + 1);
  if (digits.empty()) throw InputError("--support '" + text + "': expected NODE:COMPONENTS, e.g. 1:12346");
  const std::vector<int> node = NodeListOption(mesh, text.substr(0, colon), path);
  if (node.size() != 1) throw InputError("--support '" + text + "': expected one node id before ':'");
  fe::Constraint c;
  c.node = node.front();
  c.dofs = 0;
  for (const char d : digits) {
    if (d < '1' || d > '6')
      throw InputError("--support '" + text + "': components are the digits 1 to 6 (ux uy uz rx ry rz), got '" +
                       std::string(1, d) + "'");
    c.dofs |= 1 << (d - '1');
  }
  return c;
}

}  // namespace

int FeStatic(const FeStaticOptions& opt, std::ostream& out) {
  const std::string& path = opt.model_path;
  const Clock::time_point t0 = Clock::now();
  fe::FeModel model = InFile(path, [&] { return LoadFeModel(path); });
  if (model.imported)
    throw InputError("fe static needs a mesh with node positions (for the weight and the nodal loads); this model "
                     "holds imported matrices",
                     {path, 0, ""});
  const fe::Mesh& mesh = model.mesh;
  const std::vector<int> fixed = NodeListOption(mesh, opt.fix, path);
  for (const std::string& text : opt.supports) model.mesh.constraints.push_back(ParseSupport(mesh, text, path));
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  if (!opt.gravity.empty()) {
    const std::vector<double> v = CountedNumbers(opt.gravity, 3, 3, "--gravity");
    g = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  std::vector<NodalLoad> loads;
  for (const std::string& f : opt.forces) loads.push_back(ParseForce(mesh, f, path));
  std::vector<int> report = NodeListOption(mesh, opt.nodes, path);
  if (opt.nodes.empty())
    for (const NodalLoad& l : loads) report.push_back(l.node);
  if (loads.empty() && g.norm() == 0.0) throw InputError("fe static: no load (give --gravity or --force)");

  fe::AssemblyOptions ao;
  ao.extra_fixed_nodes = fixed;
  const fe::AssembledModel a = InFile(path, [&] { return fe::BuildMatrices(model, ao); });
  if (a.dofs.n_free == 0) throw InputError("the model has no free DOF (all constrained or fixed)", {path, 0, ""});
  const Clock::time_point t1 = Clock::now();

  // loads on the full DOF: weight M_full (g on the translations), nodal loads
  Eigen::VectorXd f = Eigen::VectorXd::Zero(a.dofs.n_full);
  if (g.norm() > 0.0) {
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(a.dofs.n_full);
    for (const auto& dofs : a.dofs.full)
      for (int c = 0; c < 3; ++c)
        if (dofs[c] >= 0) unit(dofs[c]) = g(c);
    f = a.M_full * unit;
  }
  for (const NodalLoad& l : loads)
    for (int c = 0; c < 6; ++c) {
      if (l.f[c] == 0.0) continue;
      const int i = a.dofs.full[l.node][c];
      if (i < 0)
        throw InputError("--force on node " + std::to_string(a.dofs.node_ids[l.node]) + ": the node has no " +
                             fe::kDofComponentNames[c] + " DOF (e.g. a moment on a solid element's node)",
                         {path, 0, "node " + std::to_string(a.dofs.node_ids[l.node])});
      f(i) += l.f[c];
    }
  Eigen::Vector3d resultant = Eigen::Vector3d::Zero();
  for (const auto& dofs : a.dofs.full)
    for (int c = 0; c < 3; ++c)
      if (dofs[c] >= 0) resultant(c) += f(dofs[c]);

  fe::SparseCholesky chol;
  InFile(path, [&] {
    chol.Factorize(a.K, "fe static: K with the supports (a mechanism if singular)",
                   [&](int dof) { return fe::DescribeFreeDof(a.dofs, dof); });
  });
  Eigen::VectorXd u = a.T * chol.Solve(a.T.transpose() * f);
  if (opt.second_order) {
    // (K + K_G(sigma(u_linear))) u = f: the element stresses of the linear
    // solution stiffen or soften the structure (P-delta)
    const fe::SparseMat kg = InFile(path, [&] { return reduction::AssembleGeometricStiffness(model.mesh, a.dofs, u); });
    const fe::SparseMat kt = a.K + fe::SparseMat(a.T.transpose() * kg * a.T);
    fe::SparseCholesky chol2;
    InFile(path, [&] {
      chol2.Factorize(kt,
                      "fe static --second-order: K + K_G of the supported part under this load (the linear K "
                      "was positive definite, so the load is at or beyond the part's first buckling load)",
                      [&](int dof) { return fe::DescribeFreeDof(a.dofs, dof); });
    });
    u = a.T * chol2.Solve(a.T.transpose() * f);
  }
  const Clock::time_point t2 = Clock::now();

  auto component = [&](int node, int c) {
    const int i = a.dofs.full[node][c];
    return i < 0 ? 0.0 : u(i);
  };
  double max_u = 0.0;
  int max_node = 0;
  for (int k = 0; k < static_cast<int>(a.dofs.full.size()); ++k) {
    const double un = Eigen::Vector3d(component(k, 0), component(k, 1), component(k, 2)).norm();
    if (un > max_u) max_u = un, max_node = k;
  }
  const double energy = 0.5 * u.dot(f);

  std::ostringstream s;
  if (opt.json) {
    s << "{\n  \"file\": " << JsonString(path) << ",\n  \"dofs\": " << a.dofs.n_free
      << ",\n  \"fixed_nodes\": " << fixed.size() << ",\n  \"supports\": " << opt.supports.size()
      << ",\n  \"second_order\": " << (opt.second_order ? "true" : "false")
      << ",\n  \"gravity_m_s2\": " << JsonVector(g)
      << ",\n  \"load_resultant_n\": " << JsonVector(resultant) << ",\n  \"nodes\": [";
    for (size_t r = 0; r < report.size(); ++r) {
      const int k = report[r];
      s << (r ? ",\n    " : "\n    ") << "{\"id\": " << a.dofs.node_ids[k] << ", \"displacement_m\": "
        << JsonVector({component(k, 0), component(k, 1), component(k, 2)}) << ", \"rotation_rad\": "
        << JsonVector({component(k, 3), component(k, 4), component(k, 5)}) << "}";
    }
    s << "],\n  \"max_displacement_m\": " << JsonNumber(max_u) << ",\n  \"max_displacement_node\": "
      << a.dofs.node_ids[max_node] << ",\n  \"strain_energy_j\": " << JsonNumber(energy)
      << ",\n  \"timings_s\": {\"assemble\": " << Short(Seconds(t0, t1)) << ", \"solve\": " << Short(Seconds(t1, t2))
      << "}\n}\n";
  } else {
    s << ModelName(path) << ": " << a.dofs.n_free << " free DOF";
    if (!fixed.empty()) s << " (" << fixed.size() << " nodes fixed by --fix)";
    if (!opt.supports.empty()) s << " (" << opt.supports.size() << " supports)";
    if (opt.second_order) s << "; second order (K + K_G of the linear solution's stresses)";
    s << "; load resultant " << ShortVector(resultant) << " N\n";
    s << "node        ux [m]        uy [m]        uz [m]      rx [rad]      ry [rad]      rz [rad]\n";
    for (const int k : report) {
      char line[160];
      std::snprintf(line, sizeof line, "%-8d %13.6g %13.6g %13.6g %13.6g %13.6g %13.6g\n", a.dofs.node_ids[k],
                    component(k, 0), component(k, 1), component(k, 2), component(k, 3), component(k, 4),
                    component(k, 5));
      s << line;
    }
    s << "largest displacement " << Short(max_u) << " m at node " << a.dofs.node_ids[max_node]
      << "; strain energy " << Short(energy) << " J\n";
    s << "assemble " << Short(Seconds(t0, t1)) << " s, solve " << Short(Seconds(t1, t2)) << " s\n";
  }
  out << s.str() << std::flush;
  return 0;
}

}  // namespace flexmb::io
