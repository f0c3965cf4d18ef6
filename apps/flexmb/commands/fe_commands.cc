#include "apps/flexmb/commands/fe_commands.h"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/fe/modal.h"
#include "apps/flexmb/commands/command_support.h"
#include "flexmb/fe/mesh_checks.h"
#include "flexmb/fe_io/exchange_set.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/common/json_text.h"
#include "flexmb/body_file/modes_file.h"
#include "flexmb/reduction/craig_bampton_basis.h"

namespace flexmb::io {
namespace {

namespace fs = std::filesystem;
using namespace command;  // the helpers shared with the other command group

// mass properties of the unconstrained model: M_full (all active DOF, node by
// node, before rigid links and constraints) with the identity as T; `a`'s
// M_full is borrowed and given back
fe::MassProperties UnconstrainedMassProperties(const fe::Mesh& mesh, fe::AssembledModel& a) {
  fe::AssembledModel view;
  view.dofs.full = a.dofs.full;
  view.dofs.free = a.dofs.full;
  view.dofs.node_ids = a.dofs.node_ids;
  view.dofs.n_full = a.dofs.n_full;
  view.dofs.n_free = a.dofs.n_full;
  view.M.swap(a.M_full);
  view.T.resize(a.dofs.n_full, a.dofs.n_full);
  view.T.setIdentity();
  struct GiveBack {
    fe::SparseMat& from;
    fe::SparseMat& to;
    ~GiveBack() { to.swap(from); }
  } give_back{view.M, a.M_full};
  if (view.M.rows() != a.dofs.n_full || view.M.cols() != a.dofs.n_full)
    throw InputError("the mass matrix of all DOF has " + std::to_string(view.M.rows()) + " rows, the DOF map " +
                     std::to_string(a.dofs.n_full) + " DOF");
  fe::MassProperties p = fe::ComputeMassProperties(mesh, view);
  p.inertia = (0.5 * (p.inertia + p.inertia.transpose())).eval();  // exactly symmetric in the output
  return p;
}

// stored entries of the lower triangle (diagonal included): what a symmetric
// Harwell-Boeing file holds
long LowerNonZeros(const fe::SparseMat& a) {
  long n = 0;
  for (int j = 0; j < a.outerSize(); ++j)
    for (fe::SparseMat::InnerIterator it(a, j); it; ++it)
      if (it.row() >= j) ++n;
  return n;
}

// "1 node", "3 nodes"
std::string Count(size_t n, const char* noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

}  // namespace

int FeModes(const FeModesOptions& opt, std::ostream& out) {
  const std::string& path = opt.model_path;
  if (opt.count < 1) throw InputError("--count must be at least 1, got " + std::to_string(opt.count));
  if (!std::isfinite(opt.shift) || opt.shift > 0.0)
    throw InputError("--shift must be a negative number [rad^2/s^2] (or 0 for automatic), got " + Short(opt.shift));

  const Clock::time_point t0 = Clock::now();
  const fe::FeModel model = InFile(path, [&] { return LoadFeModel(path); });
  const fe::Mesh& mesh = model.mesh;
  if (opt.lumped && model.imported)
    throw InputError("--lumped needs a mesh with elements; this model holds imported matrices, whose mass matrix is "
                     "used as it is",
                     {path, 0, ""});
  const std::vector<int> fixed = command::NodeListOption(model.mesh, opt.fix, path);
  const Clock::time_point t1 = Clock::now();

  fe::AssemblyOptions ao;
  ao.mass_form = opt.lumped ? fe::MassForm::kLumped : fe::MassForm::kConsistent;
  ao.extra_fixed_nodes = fixed;
  fe::AssembledModel a = InFile(path, [&] { return fe::BuildMatrices(model, ao); });
  const fe::MassProperties mp = InFile(path, [&] { return UnconstrainedMassProperties(mesh, a); });
  const Clock::time_point t2 = Clock::now();

  if (a.dofs.n_free == 0)
    throw InputError("the model has no free DOF (all constrained or fixed): nothing to solve", {path, 0, ""});
  fe::ModalOptions mo;
  mo.count = opt.count;
  mo.shift = opt.shift;
  const fe::ModalResult r = InFile(path, [&] { return fe::SolveModes(a, mo); });
  const Clock::time_point t3 = Clock::now();

  std::ostringstream s;
  if (opt.json) {
    s << "{\n  \"file\": " << JsonString(path) << ",\n";
    s << "  \"nodes\": " << mesh.nodes.size() << ",\n";
    s << "  \"elements\": " << mesh.elements.size() << ",\n";
    s << "  \"fixed_nodes\": " << fixed.size() << ",\n";
    s << "  \"dofs\": " << a.dofs.n_free << ",\n";
    s << "  \"mass_form\": " << JsonString(model.imported ? "imported" : opt.lumped ? "lumped" : "consistent")
      << ",\n";
    s << "  \"frequencies_hz\": " << JsonArray(r.frequencies_hz) << ",\n";
    s << "  \"mass_kg\": " << JsonNumber(mp.mass) << ",\n";
    s << "  \"center_of_mass_m\": " << (mp.mass > 0.0 ? JsonVector(mp.center) : "null") << ",\n";
    s << "  \"inertia_kg_m2\": " << (mp.mass > 0.0 ? JsonMatrix(mp.inertia) : "null") << ",\n";
    // wall times need no 17 digits
    s << "  \"timings_s\": {\"read\": " << Short(Seconds(t0, t1)) << ", \"assemble\": " << Short(Seconds(t1, t2))
      << ", \"solve\": " << Short(Seconds(t2, t3)) << "}\n}\n";
  } else {
    s << ModelName(path) << ": " << mesh.nodes.size() << " nodes, " << mesh.elements.size() << " elements, "
      << a.dofs.n_free << " free DOF";
    if (!fixed.empty()) s << " (" << fixed.size() << " nodes fixed by --fix)";
    s << "\n";
    if (mp.mass > 0.0)
      s << "mass " << Short(mp.mass) << " kg, centre of mass " << ShortVector(mp.center) << " m\n";
    else
      s << "mass 0 kg\n";
    command::WriteFrequencyTable(s, r.frequencies_hz);
    s << "read " << Short(Seconds(t0, t1)) << " s, assemble " << Short(Seconds(t1, t2)) << " s, solve "
      << Short(Seconds(t2, t3)) << " s\n";
  }
  out << s.str() << std::flush;
  return 0;
}

int FeInfo(const FeInfoOptions& opt, std::ostream& out) {
  const std::string& path = opt.model_path;
  const fe::FeModel model = InFile(path, [&] { return LoadFeModel(path); });
  const fe::Mesh& mesh = model.mesh;
  const fe::MeshCheck check = fe::CheckMesh(mesh);

  std::map<fe::ElementType, int> by_type;
  for (const fe::Element& e : mesh.elements) ++by_type[e.type];
  std::set<int> constrained_nodes;
  for (const fe::Constraint& c : mesh.constraints) constrained_nodes.insert(c.node);
  size_t dependent = 0;
  for (const fe::RigidLink& l : mesh.rigid_links) dependent += l.dependent.size();
  fe::Vec3 lo = fe::Vec3::Zero(), hi = fe::Vec3::Zero();
  for (size_t n = 0; n < mesh.nodes.size(); ++n) {
    lo = n ? lo.cwiseMin(mesh.nodes[n].x) : mesh.nodes[n].x;
    hi = n ? hi.cwiseMax(mesh.nodes[n].x) : mesh.nodes[n].x;
  }

  // mass properties of the unconstrained model, if it assembles
  fe::MassProperties mp;
  std::string mass_error;
  try {
    fe::AssemblyOptions ao;
    ao.apply_constraints = false;
    fe::AssembledModel a = InFile(path, [&] { return fe::BuildMatrices(model, ao); });
    mp = InFile(path, [&] { return UnconstrainedMassProperties(mesh, a); });
  } catch (const Error& e) {
    mass_error = e.what();
  }
  const bool has_mass = mass_error.empty() && mp.mass > 0.0;
  if (mass_error.empty() && !has_mass) mass_error = "the model has no mass";

  std::ostringstream s;
  if (opt.json) {
    s << "{\n  \"file\": " << JsonString(path) << ",\n";
    s << "  \"nodes\": " << mesh.nodes.size() << ",\n";
    s << "  \"elements\": {";
    bool first = true;
    for (const auto& [type, count] : by_type) {
      s << (first ? "" : ", ") << JsonString(fe::TypeName(type)) << ": " << count;
      first = false;
    }
    s << "},\n";
    s << "  \"materials\": " << mesh.materials.size() << ",\n";
    s << "  \"sections\": {\"shell\": " << mesh.shell_sections.size() << ", \"beam\": " << mesh.beam_sections.size()
      << ", \"solid\": " << mesh.solid_sections.size() << "},\n";
    for (const auto* sets : {&mesh.node_sets, &mesh.element_sets}) {
      s << "  \"" << (sets == &mesh.node_sets ? "node_sets" : "element_sets") << "\": {";
      first = true;
      for (const auto& [name, members] : *sets) {
        s << (first ? "" : ", ") << JsonString(name) << ": " << members.size();
        first = false;
      }
      s << "},\n";
    }
    s << "  \"rigid_links\": " << mesh.rigid_links.size() << ",\n";
    s << "  \"linear_constraints\": " << mesh.linear_constraints.size() << ",\n";
    s << "  \"point_masses\": " << mesh.point_masses.size() << ",\n";
    s << "  \"springs\": " << mesh.springs.size() << ",\n";
    s << "  \"constraints\": " << mesh.constraints.size() << ",\n";
    s << "  \"parts\": " << check.parts.size() << ",\n";
    s << "  \"unused_nodes\": " << check.unused_nodes.size() << ",\n";
    if (mesh.nodes.empty())
      s << "  \"bounding_box_m\": null,\n";
    else
      s << "  \"bounding_box_m\": {\"min\": " << JsonVector(lo) << ", \"max\": " << JsonVector(hi) << "},\n";
    if (model.imported) {
      const fe::AssembledModel& m = *model.imported;
      s << "  \"matrices\": {\"dofs\": " << m.dofs.n_free << ", \"k_nonzeros\": " << m.K.nonZeros()
        << ", \"m_nonzeros\": " << m.M.nonZeros() << "},\n";
    }
    if (has_mass) {
      s << "  \"mass_kg\": " << JsonNumber(mp.mass) << ",\n";
      s << "  \"center_of_mass_m\": " << JsonVector(mp.center) << ",\n";
      s << "  \"inertia_kg_m2\": " << JsonMatrix(mp.inertia) << "\n}\n";
    } else {
      s << "  \"mass_kg\": " << (mass_error == "the model has no mass" ? "0" : "null") << ",\n";
      s << "  \"center_of_mass_m\": null,\n  \"inertia_kg_m2\": null,\n";
      s << "  \"mass_error\": " << JsonString(mass_error) << "\n}\n";
    }
  } else {
    s << "file: " << path << "\n";
    s << "nodes: " << mesh.nodes.size() << "\n";
    s << "elements: " << mesh.elements.size() << "\n";
    for (const auto& [type, count] : by_type) s << "  " << fe::TypeName(type) << ": " << count << "\n";
    s << "materials: " << mesh.materials.size() << "\n";
    s << "sections: " << mesh.shell_sections.size() << " shell, " << mesh.beam_sections.size() << " beam, "
      << mesh.solid_sections.size() << " solid\n";
    s << "node sets: " << mesh.node_sets.size() << "\n";
    for (const auto& [name, members] : mesh.node_sets)
      s << "  " << name << ": " << Count(members.size(), "node") << "\n";
    s << "element sets: " << mesh.element_sets.size() << "\n";
    for (const auto& [name, members] : mesh.element_sets)
      s << "  " << name << ": " << Count(members.size(), "element") << "\n";
    s << "rigid links: " << mesh.rigid_links.size() << " (" << Count(dependent, "dependent node") << ")\n";
    if (!mesh.linear_constraints.empty())
      s << "linear constraints (RBE3, MPC, *EQUATION, *TIE, skew supports, chains): " << Count(mesh.linear_constraints.size(), "dependent DOF") << "\n";
    s << "point masses: " << mesh.point_masses.size() << "\n";
    s << "scalar springs: " << mesh.springs.size() << "\n";
    s << "constraints: " << mesh.constraints.size() << " (on " << Count(constrained_nodes.size(), "node") << ")\n";
    if (!mesh.elements.empty())
      s << "connected parts: " << check.parts.size() << (check.parts.size() > 1 ? " (see the warning)" : "")
        << "; unused nodes: " << check.unused_nodes.size() << "\n";
    if (model.imported) {
      const fe::AssembledModel& m = *model.imported;
      s << "matrices: imported, " << m.dofs.n_free << " x " << m.dofs.n_free << ", K " << m.K.nonZeros() << " and M "
        << m.M.nonZeros() << " non-zeros (both triangles)\n";
    }
    if (mesh.nodes.empty())
      s << "bounding box: none (no nodes)\n";
    else
      s << "bounding box: " << ShortVector(lo) << " to " << ShortVector(hi) << " m\n";
    if (has_mass) {
      WriteMassText(s, mp.mass, mp.center, mp.inertia, "basic");
    } else {
      s << "mass: not available: " << mass_error << "\n";
    }
  }
  out << s.str() << std::flush;
  return 0;
}

namespace {

// The exchange set holds the free DOF only: the mass on constrained DOF
// (SPCs, --fix) is not in it, nor are element data (stress modes). Says so,
// with the mass and inertia that a body reduced from it would lack.
void WarnOfMissingMass(const fe::Mesh& mesh, fe::AssembledModel& a, const std::string& path, const std::string& dir) {
  std::string note = dir + ": an exchange set carries matrices, not elements: a body reduced from it has no stress "
                           "modes (reduce " + path + " itself for stresses)";
  fe::MassProperties full;
  try {
    full = UnconstrainedMassProperties(mesh, a);
  } catch (const Error&) {
    LogWarning(note);
    return;
  }
  fe::Vec3 x0;
  const Eigen::Matrix<double, 6, 6> mrr = fe::RigidBodyMass(mesh, a, x0);
  const double mass = mrr.topLeftCorner<3, 3>().trace() / 3.0;
  if (full.mass > 0.0 && mass < (1.0 - 1e-9) * full.mass) {
    // the inertia about x0 of the whole model, against what the free DOF carry
    const fe::Vec3 c = full.center - x0;
    const double j_full = full.inertia.trace() + 2.0 * full.mass * c.squaredNorm();
    const double j_kept = mrr.bottomRightCorner<3, 3>().trace();
    std::ostringstream s;
    s << dir << ": the exchange set holds the free DOF only: the mass on the constrained DOF (SPCs, --fix) is not in "
      << "M_CCS.hb: " << Short(mass) << " kg of the model's " << Short(full.mass) << " kg ("
      << Short(100.0 * (1.0 - mass / full.mass)) << " % missing; of the rotational inertia "
      << Short(100.0 * (1.0 - j_kept / j_full)) << " %). A body reduced from it lacks that mass; reduce " << path
      << " itself (flexmb reduce keeps the whole mass)";
    LogWarning(s.str());
  }
  LogWarning(note);
}

}  // namespace

int FeExport(const FeExportOptions& opt, std::ostream& out) {
  const std::string& path = opt.model_path;
  if (opt.hb_dir.empty()) throw InputError("--hb needs the directory to write the exchange set to");
  const fe::FeModel model = InFile(path, [&] { return LoadFeModel(path); });
  const fe::Mesh& mesh = model.mesh;
  fe::AssemblyOptions ao;
  ao.extra_fixed_nodes = command::NodeListOption(model.mesh, opt.fix, path);
  // an RBE3 reference node as interface node keeps its own DOF (as in reduce)
  if (!opt.interface.empty()) ao.independent_nodes = command::NodeListOption(mesh, opt.interface, path);
  fe::AssembledModel a = InFile(path, [&] { return fe::BuildMatrices(model, ao); });
  if (a.dofs.n_free == 0)
    throw InputError("the model has no free DOF (all constrained or fixed): nothing to export", {path, 0, ""});
  // the writer's errors name the directory
  InFile(opt.hb_dir, [&] { WriteExchangeSet(mesh, a, opt.hb_dir); });
  WarnOfMissingMass(mesh, a, path, opt.hb_dir);
  int static_modes = -1, normal_modes = 0;
  if (!opt.interface.empty()) {
    if (opt.modes < 0) throw InputError("--modes must be 0 or more, got " + std::to_string(opt.modes));
    reduction::ReductionOptions ro;
    ro.interface_nodes = command::NodeListOption(mesh, opt.interface, path);
    ro.normal_modes = opt.modes;
    const reduction::CraigBamptonBasis basis =
        InFile(path, [&] { return reduction::BuildCraigBamptonBasis(mesh, a, ro); });
    const std::string modes_path = (fs::path(opt.hb_dir) / kModesFileName).string();
    InFile(modes_path, [&] { WriteModesFile(ModesOfBasis(basis, mesh, a.dofs), modes_path); });
    static_modes = basis.static_modes();
    normal_modes = basis.normal_modes();
  }

  const fs::path dir(opt.hb_dir);
  const std::string n = std::to_string(a.dofs.n_free);
  std::ostringstream s;
  s << "wrote the exchange set of " << ModelName(path) << " (" << n << " free DOF";
  if (!ao.extra_fixed_nodes.empty()) s << ", " << ao.extra_fixed_nodes.size() << " nodes fixed by --fix";
  s << ") to " << opt.hb_dir << ":\n";
  s << "  " << (dir / "K_CCS.hb").string() << ": stiffness, " << n << " x " << n << ", " << LowerNonZeros(a.K)
    << " entries in the lower triangle\n";
  s << "  " << (dir / "M_CCS.hb").string() << ": mass, " << n << " x " << n << ", " << LowerNonZeros(a.M)
    << " entries in the lower triangle\n";
  s << "  " << (dir / "geometry.vtk").string() << ": " << mesh.nodes.size() << " nodes, " << mesh.elements.size()
    << " elements\n";
  s << "  " << (dir / "dof_map.txt").string() << ": node and component of each of the " << n << " rows\n";
  if (static_modes >= 0) {
    s << "  " << (dir / kModesFileName).string() << ": " << static_modes << " static and " << normal_modes
      << " fixed-interface normal modes\n";
  }
  out << s.str() << std::flush;
  return 0;
}

}  // namespace flexmb::io
