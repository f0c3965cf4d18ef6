#include "apps/flexmb/commands/reduce_commands.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/fe_model.h"
#include "apps/flexmb/commands/command_support.h"
#include "flexmb/fe_io/dof_map.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/fe_io/fe_model_file.h"
#include "flexmb/common/json_text.h"
#include "flexmb/fe_io/matrix_text.h"
#include "flexmb/body_file/modes_file.h"
#include "flexmb/body_file/unit_system.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/craig_bampton_basis.h"

namespace flexmb::io {
namespace {

using namespace command;  // the helpers shared with the other command group
namespace fs = std::filesystem;
using reduction::Mat3;
using reduction::Vec3;

// mass, centre of mass and inertia about it from the inertia invariants:
// M_vv = m I, M_vo = -skew(m c) + (rotational coupling, symmetric), M_oo =
// inertia about the body-frame origin
struct BodyMass {
  double mass = 0.0;
  Vec3 center = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
};

BodyMass MassOf(const reduction::InertiaInvariants& v) {
  BodyMass b;
  b.mass = v.mvv.trace() / 3.0;
  if (!(b.mass > 0.0)) return b;
  const Mat3 a = 0.5 * (v.mvo0 - v.mvo0.transpose());
  b.center = -Vec3(a(2, 1), a(0, 2), a(1, 0)) / b.mass;
  const Vec3& c = b.center;
  b.inertia = v.moo0 - b.mass * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  b.inertia = (0.5 * (b.inertia + b.inertia.transpose())).eval();
  // no "-0" in the reports
  b.center = (b.center.array() + 0.0).matrix();
  b.inertia = (b.inertia.array() + 0.0).matrix();
  return b;
}

// the JSON lines static_modes to inertia_kg_m2 shared by "reduce" and
// "body info"
// the acceleration modes in the body's basis (its provenance; 0 for files
// written before them)
int AccelerationModes(const reduction::ReducedBody& body) {
  for (const auto& [key, value] : body.provenance)
    if (key == "acceleration_modes") return std::atoi(value.c_str());
  return 0;
}

void JsonModesAndMass(std::ostream& s, const reduction::ReducedBody& body, const BodyMass& mp) {
  s << "  \"static_modes\": " << body.static_modes << ",\n";
  s << "  \"normal_modes\": " << body.normal_modes << ",\n";
  s << "  \"acceleration_modes\": " << AccelerationModes(body) << ",\n";
  s << "  \"rigid_modes_removed\": " << body.rigid_modes_removed << ",\n";
  s << "  \"flexible_modes\": " << body.frequencies_hz.size() << ",\n";
  s << "  \"frequencies_hz\": " << JsonArray(body.frequencies_hz) << ",\n";
  s << "  \"mass_kg\": " << JsonNumber(mp.mass) << ",\n";
  s << "  \"center_of_mass_m\": " << (mp.mass > 0.0 ? JsonVector(mp.center) : "null") << ",\n";
  s << "  \"inertia_kg_m2\": " << (mp.mass > 0.0 ? JsonMatrix(mp.inertia) : "null") << ",\n";
}

// The node index of `--frame node:ID`, or -1 for the mean axes ("mean",
// "tisserand", "buckens" or not given). Throws InputError for another
// value, a missing node, or the mean axes asked for together with --fix
// (clamped nodes leave no rigid-body modes: the frame is attached to them).
int FrameNode(const std::string& frame, bool has_fix, const fe::Mesh& mesh, const std::string& path) {
  if (frame.empty()) return -1;
  if (frame == "mean" || frame == "tisserand" || frame == "buckens") {
    if (has_fix) {
      throw InputError("--frame " + frame + " asks for the mean axes, but --fix clamps nodes: the body keeps no "
                       "rigid-body modes and its frame is attached to the fixed nodes. Leave out --fix, or give "
                       "--frame node:ID");
    }
    return -1;
  }
  const std::string prefix = "node:";
  if (frame.rfind(prefix, 0) != 0 || frame.size() == prefix.size()) {
    throw InputError("--frame expects mean, tisserand, buckens or node:ID, got '" + frame + "'");
  }
  const std::vector<int> node = command::NodeListOption(mesh, frame.substr(prefix.size()), path);
  if (node.size() != 1) {
    throw InputError("--frame node:ID takes one node, got '" + frame + "' (" + std::to_string(node.size()) +
                     " nodes)");
  }
  return node[0];
}

}  // namespace

int Reduce(const ReduceOptions& opt, std::ostream& out) {
  const std::string& path = opt.model_path;
  if (opt.output.empty()) throw InputError("-o needs the body file to write (BODY.h5)");
  const bool imported_modes = !opt.modes_file.empty();
  if (imported_modes && (!opt.interface.empty() || opt.modes >= 0 || opt.cutoff_hz != 0.0 || !opt.fix.empty() ||
                         !opt.frame.empty())) {
    throw InputError("--modes-file brings the interface and the modes: do not give --interface, --modes, --cutoff, "
                     "--fix or --frame with it");
  }
  if (!imported_modes && opt.interface.empty()) throw InputError("--interface needs node ids or a node set name");
  if (!imported_modes && opt.modes < 0 && !(opt.cutoff_hz > 0.0)) {
    throw InputError("give the number of fixed-interface normal modes (--modes K, 0 for Guyan) or a frequency "
                     "cut-off (--cutoff HZ)");
  }
  if (opt.modes < -1) throw InputError("--modes must be 0 or more, got " + std::to_string(opt.modes));
  if (!std::isfinite(opt.cutoff_hz) || opt.cutoff_hz < 0.0) {
    throw InputError("--cutoff must be a frequency > 0 [Hz], got " + Short(opt.cutoff_hz));
  }
  if (opt.keep == 0 || opt.keep < -1) throw InputError("--keep must be at least 1, got " + std::to_string(opt.keep));
  if (!opt.rayleigh.empty() && !opt.damping_ratio.empty()) {
    throw InputError("give either --rayleigh or --damping-ratio, not both");
  }

  const UnitSystem& units = ParseUnitsOption(opt.units);

  reduction::ReductionOptions ro;
  ro.normal_modes = opt.modes >= 0 ? opt.modes : 10;
  ro.cutoff_hz = opt.cutoff_hz;
  ro.keep = opt.keep;
  ro.geometric_stiffening = opt.geometric_stiffening;
  ro.deformation_stiffening = opt.deformation_stiffening;
  ro.acceleration_modes = opt.acceleration_modes;
  if (opt.acceleration_modes && imported_modes)
    throw InputError("--acceleration-modes needs the FE model's factor: not with --modes-file");
  ro.solid_corner_stress = opt.solid_corner_stress;
  ro.eigen_tolerance = opt.eigen_tolerance;
  if (imported_modes && opt.reducer) {
    throw InputError("--modes-file brings the modes: there is nothing for --backend petsc to solve");
  }
  if (!opt.rayleigh.empty()) {
    const std::vector<double> ab = NumberList(opt.rayleigh, "--rayleigh");
    if (ab.size() != 2 || ab[0] < 0.0 || ab[1] < 0.0) {
      throw InputError("--rayleigh expects ALPHA,BETA, both >= 0 (D = alpha M + beta K), got '" + opt.rayleigh + "'");
    }
    ro.rayleigh_alpha = ab[0];
    ro.rayleigh_beta = ab[1];
  }
  if (!opt.damping_ratio.empty()) {
    ro.damping_ratios = NumberList(opt.damping_ratio, "--damping-ratio");
    for (double z : ro.damping_ratios) {
      if (z < 0.0) throw InputError("--damping-ratio values must be >= 0, got '" + opt.damping_ratio + "'");
    }
  }

  const Clock::time_point t0 = Clock::now();
  const fe::FeModel model = InFile(path, [&] { return LoadFeModel(path); });
  ExchangeModes modes;
  if (imported_modes) {
    modes = InFile(opt.modes_file, [&] { return ReadModesFile(opt.modes_file); });
    // a modes file inside the exchange set it belongs to: check it against its DOF map
    const fs::path map_path = fs::path(opt.modes_file).parent_path() / "dof_map.txt";
    std::error_code ec;
    if (fs::is_directory(path, ec) && fs::equivalent(fs::path(path), fs::path(opt.modes_file).parent_path(), ec)) {
      const MatrixRowMap map = InFile(map_path.string(), [&] { return ReadDofMap(map_path.string()); });
      CheckModesAgainstDofMap(modes, map, opt.modes_file);
    }
    for (const DofMapRow& d : modes.static_dofs) {
      const int node = model.mesh.NodeIndex(d.node_id);
      if (node < 0) {
        throw InputError("static mode of node " + std::to_string(d.node_id) + ": the model has no such node",
                         {opt.modes_file, d.line, "modes file"});
      }
      if (std::find(ro.interface_nodes.begin(), ro.interface_nodes.end(), node) == ro.interface_nodes.end()) {
        ro.interface_nodes.push_back(node);
      }
    }
  } else {
    ro.interface_nodes = command::NodeListOption(model.mesh, opt.interface, path);
    ro.fixed_nodes = command::NodeListOption(model.mesh, opt.fix, path);
    const int frame_node = FrameNode(opt.frame, !opt.fix.empty(), model.mesh, path);
    for (std::vector<int>* list : {&ro.fixed_nodes, &ro.interface_nodes}) {
      if (frame_node >= 0 && std::find(list->begin(), list->end(), frame_node) == list->end()) {
        list->push_back(frame_node);
      }
    }
  }
  const Clock::time_point t1 = Clock::now();

  reduction::ReductionTimings t;
  reduction::ReducedBody body = InFile(path, [&] {
    if (!imported_modes) return opt.reducer ? opt.reducer(model, ro, &t) : reduction::ReduceCraigBampton(model, ro, &t);
    const Clock::time_point ta = Clock::now();
    fe::AssemblyOptions ao;
    ao.independent_nodes = ro.interface_nodes;  // as ReduceCraigBampton and fe export assemble
    const fe::AssembledModel a = fe::BuildMatrices(model, ao);
    t.assemble = Seconds(ta, Clock::now());
    // the modes' rows are the matrices' own rows: nodes, links or masses an
    // FE model file adds renumber them (fe::AssembleImported)
    if (model.imported && a.dofs.free != model.imported->dofs.free)
      throw InputError("the modes file's rows are those of the imported matrices, but this FE model file adds "
                       "nodes, rigid links or point masses to them, which renumbers the degrees of freedom: reduce "
                       "without --modes-file, or give the modes of the model as exported",
                       {opt.modes_file, 0, "modes"});
    const reduction::CraigBamptonBasis basis = BasisOfModes(modes, model.mesh, a, opt.modes_file);
    return reduction::ReduceBasis(model, a, basis, ro, &t);
  });
  const Clock::time_point t2 = Clock::now();
  if (!opt.root) return 0;  // another process of an MPI job: rank 0 writes and reports
  body.provenance.emplace_back("solver", imported_modes ? "none (the modes file's basis)" : opt.backend);
  // the FE model's units as given; numbers that do not look like them (SI only) warn
  body.units = units.attribute;
  if (&units == &SiUnits()) {
    for (const std::string& w : UnitPlausibilityWarnings(body, opt.output)) LogWarning(w);
  }
  InFile(opt.output, [&] { WriteBody(body, opt.output); });
  const Clock::time_point t3 = Clock::now();

  const BodyMass mp = MassOf(body.invariants);
  const int nk = static_cast<int>(body.frequencies_hz.size());
  const fe::Mesh& mesh = model.mesh;
  std::string frame;
  for (const auto& [key, value] : body.provenance) {
    if (key == "frame") frame = value;
  }
  std::ostringstream s;
  if (opt.json) {
    s << "{\n  \"file\": " << JsonString(path) << ",\n";
    s << "  \"output\": " << JsonString(opt.output) << ",\n";
    s << "  \"nodes\": " << mesh.nodes.size() << ",\n";
    s << "  \"elements\": " << mesh.elements.size() << ",\n";
    s << "  \"interface_nodes\": " << body.interface_nodes.size() << ",\n";
    s << "  \"fixed_nodes\": " << ro.fixed_nodes.size() << ",\n";
    s << "  \"frame\": " << JsonString(frame) << ",\n";
    s << "  \"solver\": " << JsonString(opt.backend) << ",\n";
    JsonModesAndMass(s, body, mp);
    // wall times need no 17 digits
    s << "  \"timings_s\": {\"read\": " << Short(Seconds(t0, t1)) << ", \"assemble\": " << Short(t.assemble)
      << ", \"factorize\": " << Short(t.factorize) << ", \"static_modes\": " << Short(t.static_modes)
      << ", \"normal_modes\": " << Short(t.normal_modes) << ", \"orthonormalize\": " << Short(t.orthonormalize)
      << ", \"invariants\": " << Short(t.invariants) << ", \"stress_modes\": " << Short(t.stress_modes)
      << ", \"stiffening\": " << Short(t.stiffening) << ", \"write\": " << Short(Seconds(t2, t3)) << ", \"total\": " << Short(Seconds(t0, t3)) << "}\n}\n";
  } else {
    s << ModelName(path) << ": " << mesh.nodes.size() << " nodes, " << mesh.elements.size() << " elements; "
      << body.interface_nodes.size() << " interface nodes";
    if (!ro.fixed_nodes.empty()) s << ", " << ro.fixed_nodes.size() << " nodes clamped";
    s << "\n";
    if (!frame.empty()) s << "floating frame: " << frame << "\n";
    if (opt.reducer) s << "factorization and modes: " << opt.backend << "\n";
    const int acceleration = AccelerationModes(body);
    s << "Craig-Bampton basis: " << body.static_modes << " static + " << body.normal_modes << " normal"
      << (acceleration > 0 ? " + " + std::to_string(acceleration) + " acceleration" : "") << " modes; "
      << body.rigid_modes_removed << " rigid-body modes removed; " << nk << " flexible modes kept\n";
    if (mp.mass > 0.0) s << "mass " << Short(mp.mass) << " kg, centre of mass " << ShortVector(mp.center) << " m\n";
    command::WriteFrequencyTable(s, body.frequencies_hz);
    s << "wrote " << opt.output << "\n";
    s << "read " << Short(Seconds(t0, t1)) << " s, assemble " << Short(t.assemble) << " s, factorize "
      << Short(t.factorize) << " s, static modes " << Short(t.static_modes) << " s, normal modes "
      << Short(t.normal_modes) << " s, orthonormalize " << Short(t.orthonormalize) << " s, invariants "
      << Short(t.invariants) << " s, stress modes " << Short(t.stress_modes) << " s, stiffening "
      << Short(t.stiffening) << " s, write "
      << Short(Seconds(t2, t3)) << " s, total " << Short(Seconds(t0, t3)) << " s\n";
  }
  out << s.str() << std::flush;
  return 0;
}

int BodyInfo(const BodyInfoOptions& opt, std::ostream& out) {
  const std::string& path = opt.body_path;
  const reduction::ReducedBody body = InFile(path, [&] { return ReadBody(path); });
  const BodyMass mp = MassOf(body.invariants);
  const fe::Mesh& mesh = body.mesh;
  const int nk = static_cast<int>(body.frequencies_hz.size());
  const std::pair<const char*, const reduction::StressTable*> tables[] = {
      {"shell", &body.stress.shell},
      {"beam", &body.stress.beam},
      {"solid", &body.stress.solid},
      {"beam_fibre", &body.stress.beam_fibre},
      {"solid_node", &body.stress.solid_node}};

  std::ostringstream s;
  if (opt.json) {
    s << "{\n  \"file\": " << JsonString(path) << ",\n";
    s << "  \"format_version\": " << reduction::ReducedBody::kFormatVersion << ",\n";
    s << "  \"units\": " << JsonString(body.units) << ",\n";
    s << "  \"nodes\": " << mesh.nodes.size() << ",\n";
    s << "  \"elements\": " << mesh.elements.size() << ",\n";
    s << "  \"interface_nodes\": [";
    for (size_t k = 0; k < body.interface_nodes.size(); ++k) {
      s << (k ? ", " : "") << mesh.nodes[body.interface_nodes[k]].id;
    }
    s << "],\n";
    JsonModesAndMass(s, body, mp);
    s << "  \"stress\": {";
    for (size_t k = 0; k < std::size(tables); ++k) {
      const reduction::StressTable& t = *tables[k].second;
      s << (k ? ", " : "") << JsonString(tables[k].first) << ": {\"elements\": " << t.elements.size()
        << ", \"locations\": " << t.locations.size() << ", \"components\": " << t.components.size() << "}";
    }
    s << "},\n";
    s << "  \"geometric_stiffening\": " << (body.geometric_stiffness.empty() ? "false" : "true") << ",\n";
    s << "  \"deformation_stiffening\": " << (body.deformation_stiffness.empty() ? "false" : "true") << ",\n";
    s << "  \"provenance\": {";
    std::set<std::string> seen;
    bool first = true;
    for (const auto& [key, value] : body.provenance) {
      if (!seen.insert(key).second) continue;
      s << (first ? "" : ", ") << JsonString(key) << ": " << JsonString(value);
      first = false;
    }
    s << "}\n}\n";
  } else {
    s << "file: " << path << " (flexmb body file, format version " << reduction::ReducedBody::kFormatVersion
      << ")\n";
    s << "units: " << body.units << "\n";
    s << "nodes: " << mesh.nodes.size() << ", elements: " << mesh.elements.size() << "\n";
    s << "interface nodes: " << body.interface_nodes.size();
    for (size_t k = 0; k < body.interface_nodes.size(); ++k) {
      s << (k ? "," : " (ids ") << mesh.nodes[body.interface_nodes[k]].id;
    }
    s << (body.interface_nodes.empty() ? "\n" : ")\n");
    const int acceleration = AccelerationModes(body);
    s << "modes: " << nk << " flexible (basis " << body.static_modes << " static + " << body.normal_modes << " normal"
      << (acceleration > 0 ? " + " + std::to_string(acceleration) + " acceleration" : "") << ", "
      << body.rigid_modes_removed << " rigid-body modes removed)\n";
    if (mp.mass > 0.0) {
      WriteMassText(s, mp.mass, mp.center, mp.inertia, "body");
    } else {
      s << "mass: 0 (no inertia invariants)\n";
    }
    command::WriteFrequencyTable(s, body.frequencies_hz);
    s << "stress modes:";
    bool any = false;
    for (const auto& [name, t] : tables) {
      if (t->elements.empty()) continue;
      s << (any ? "; " : " ") << name << " " << t->elements.size() << " elements x " << t->locations.size()
        << " locations x " << t->components.size() << " components";
      any = true;
    }
    s << (any ? "\n" : " none\n");
    s << "geometric stiffness: "
      << (body.geometric_stiffness.empty() ? "none"
                                           : "centrifugal, 6 load cases (wx*wx, wy*wy, wz*wz, wx*wy, wy*wz, wz*wx)")
      << "\n";
    s << "deformation stiffness: "
      << (body.deformation_stiffness.empty() ? "none" : std::to_string(nk) + " matrices (one per mode)") << "\n";
    s << "provenance:\n";
    for (const auto& [key, value] : body.provenance) s << "  " << key << ": " << value << "\n";
  }
  out << s.str() << std::flush;
  return 0;
}

}  // namespace flexmb::io
