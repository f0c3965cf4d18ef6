#include "apps/flexmb/commands/post_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "flexmb/common/error.h"
#include "flexmb/durability/element_fatigue.h"
#include "flexmb/durability/modal_history.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/common/json_text.h"
#include "flexmb/results/vtk_animation.h"
#include "post_vtu.h"

namespace flexmb::commands {
namespace {

namespace fs = std::filesystem;
using durability::ElementResults;

// per mesh element: which table and position holds its stress
struct PostElementSlot {
  int table = -1;  // 0 shell, 1 solid, -1 none
  int k = -1;
};

std::optional<durability::SnCurve> PostCurve(const PostOptions& o) {
  const int given = !o.sn.empty() + !o.sn_file.empty() + !o.sn_basquin.empty();
  if (given > 1) throw InputError("give one S-N curve: --sn, --sn-file or --sn-basquin");
  if (!o.sn.empty()) return durability::SnCurve::Preset(o.sn);
  if (!o.sn_file.empty()) return durability::SnCurve::ReadCsv(o.sn_file);
  if (o.sn_basquin.empty()) return std::nullopt;
  const std::vector<double>& b = o.sn_basquin;
  if (b.size() != 3 && b.size() != 5 && b.size() != 6)
    throw InputError("--sn-basquin takes S_ref,N_ref,m1 or S_ref,N_ref,m1,N_knee,m2 or S_ref,N_ref,m1,N_knee,m2,N_cut");
  return durability::SnCurve::Basquin(b[0], b[1], b[2], b.size() > 3 ? b[3] : 0.0, b.size() > 3 ? b[4] : 0.0,
                                      b.size() > 5 ? b[5] : 0.0, {"", 0, "--sn-basquin"});
}

durability::MeanStress PostMeanStress(const PostOptions& o) {
  durability::MeanStress m;
  if (o.mean_stress == "goodman") m.method = durability::MeanStressCorrection::kGoodman;
  else if (o.mean_stress == "fkm") m.method = durability::MeanStressCorrection::kFkm;
  else if (o.mean_stress != "none")
    throw InputError("unknown mean-stress correction '" + o.mean_stress + "' (none, goodman, fkm)");
  m.ultimate = o.ultimate;
  m.sensitivity = o.sensitivity;
  durability::CheckMeanStress(m, "--mean-stress " + o.mean_stress);
  return m;
}

// centroid of an element's nodes in the body frame [m]
Eigen::Vector3d PostCentroid(const fe::Mesh& mesh, int e) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int n : mesh.elements[e].nodes) c += mesh.nodes[n].x;
  return c / static_cast<double>(mesh.elements[e].nodes.size());
}

std::string PostNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

}  // namespace

int Post(const PostOptions& o, std::ostream& out) {
  // inputs: the run's modal coordinates, the body file, the options
  const durability::ModalHistory hist = durability::ReadRunModalHistory(o.run_dir);
  const int b = hist.Body(o.body);
  const std::string body_entity = "body '" + o.body + "'";
  reduction::ReducedBody body;
  try {
    body = io::ReadBody(hist.bodies[b].body_file);
  } catch (const InputError& e) {
    throw InputError(std::string("cannot read the body file of the run: ") + e.what(), {hist.path, 0, body_entity});
  }
  const Eigen::MatrixXd& W = hist.coordinates[b];
  if (W.rows() != body.modes.cols())
    throw InputError("the body file has " + std::to_string(body.modes.cols()) + " modes, the run " +
                         std::to_string(W.rows()) + " (body file changed after the run?)",
                     {hist.bodies[b].body_file, 0, body_entity});
  if (o.top < 0) throw InputError("--top must be >= 0");
  durability::FatigueOptions fo;
  fo.measure = durability::ParseStressMeasure(o.measure);
  fo.curve = PostCurve(o);
  fo.mean_stress = PostMeanStress(o);
  if (o.distance_km && !(*o.distance_km > 0 && std::isfinite(*o.distance_km)))
    throw InputError("--distance-km must be a positive number");
  const fe::Mesh& mesh = body.mesh;
  const int ne = static_cast<int>(mesh.elements.size());
  std::vector<PostElementSlot> slot(ne);
  // stress tables: shells, solids (at their corner nodes when the body file
  // has them, else at the centroid), and beams at their sections' stress points
  constexpr int kPostTables = 3;
  const reduction::StressTable& solids =
      body.stress.solid_node.elements.empty() ? body.stress.solid : body.stress.solid_node;
  const reduction::StressTable* tables[kPostTables] = {&body.stress.shell, &solids, &body.stress.beam_fibre};
  for (int t = 0; t < kPostTables; ++t)
    for (size_t k = 0; k < tables[t]->elements.size(); ++k) slot[tables[t]->elements[k]] = {t, static_cast<int>(k)};
  auto element_index = [&](int id) {
    for (int e = 0; e < ne; ++e)
      if (mesh.elements[e].id == id) return e;
    throw InputError("element " + std::to_string(id) + " does not exist", {hist.bodies[b].body_file, 0, body_entity});
  };
  std::vector<int> history_elements;
  for (int id : o.elements) {
    const int e = element_index(id);
    if (slot[e].table < 0)
      throw InputError("element " + std::to_string(id) +
                           " has no stress modes (a beam needs stress recovery points in its section: PBAR C1 ... "
                           "F2, a PBARL or *BEAM SECTION shape)",
                       {hist.bodies[b].body_file, 0, body_entity});
    history_elements.push_back(e);
  }
  std::vector<int> history_nodes;
  for (int id : o.nodes) {
    int found = -1;
    for (size_t n = 0; n < mesh.nodes.size(); ++n)
      if (mesh.nodes[n].id == id) found = static_cast<int>(n);
    if (found < 0)
      throw InputError("node " + std::to_string(id) + " does not exist", {hist.bodies[b].body_file, 0, body_entity});
    history_nodes.push_back(found);
  }
  const fs::path dir = o.out_dir.empty() ? fs::path(o.run_dir) / ("post_" + o.body) : fs::path(o.out_dir);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError("cannot create the output folder: " + ec.message(), {dir.string(), 0, ""});

  // every element of the tables, in batches
  PostElementData data(ne);
  std::unique_ptr<durability::StressRecovery> rec[kPostTables];
  for (int t = 0; t < kPostTables; ++t) {
    if (tables[t]->elements.empty()) continue;
    rec[t] = std::make_unique<durability::StressRecovery>(*tables[t], W);
    const ElementResults r = durability::AnalyzeElements(*rec[t], fo);
    for (size_t k = 0; k < tables[t]->elements.size(); ++k) data.Set(tables[t]->elements[k], r, static_cast<int>(k), *rec[t]);
  }
  const double per_1000km = o.distance_km ? 1000.0 / *o.distance_km : 0.0;
  const std::vector<double>& times = hist.times;
  auto time_of = [&](int r) { return r < static_cast<int>(times.size()) ? times[r] : 0.0; };

  // elements.csv
  {
    std::ofstream f(dir / "elements.csv");
    f << "element,type,max_von_mises_Pa,max_von_mises_time_s,max_von_mises_point,min_signed_von_mises_Pa,"
         "max_signed_von_mises_Pa,max_principal_Pa,min_principal_Pa,range_Pa,damage,damage_per_1000km,life_km\n";
    for (int e = 0; e < ne; ++e) {
      if (!data.has[e]) continue;
      const double d = data.damage[e];
      f << mesh.elements[e].id << ',' << fe::TypeName(mesh.elements[e].type) << ',' << PostNumber(data.max_vm[e])
        << ',' << PostNumber(time_of(data.vm_instant[e])) << ',' << data.vm_point[e] << ','
        << PostNumber(data.min_svm[e]) << ',' << PostNumber(data.max_svm[e]) << ',' << PostNumber(data.max_p1[e])
        << ',' << PostNumber(data.min_p3[e]) << ',' << PostNumber(data.range[e]) << ',' << PostNumber(d) << ','
        << (o.distance_km ? PostNumber(d * per_1000km) : "") << ','
        << (o.distance_km && d > 0 ? PostNumber(*o.distance_km / d) : "") << '\n';
    }
    if (!f) throw InputError("cannot write elements.csv", {dir.string(), 0, ""});
  }

  // hot spots: top N by von Mises and by damage
  std::vector<int> order;
  for (int e = 0; e < ne; ++e)
    if (data.has[e]) order.push_back(e);
  auto top_by = [&](const std::vector<double>& v) {
    std::vector<int> s = order;
    const size_t n = std::min(s.size(), static_cast<size_t>(o.top));
    std::partial_sort(s.begin(), s.begin() + static_cast<long>(n), s.end(),
                      [&v](int a, int c) { return v[a] > v[c] || (v[a] == v[c] && a < c); });
    s.resize(n);
    return s;
  };
  const std::vector<int> hot = top_by(data.max_vm);
  const std::vector<int> worst = fo.curve ? top_by(data.damage) : std::vector<int>{};
  {
    std::ofstream f(dir / "hot_spots.csv");
    f << "rank,element,max_von_mises_Pa,time_s,point,x_m,y_m,z_m,damage\n";
    for (size_t i = 0; i < hot.size(); ++i) {
      const int e = hot[i];
      const Eigen::Vector3d c = PostCentroid(mesh, e);
      f << i + 1 << ',' << mesh.elements[e].id << ',' << PostNumber(data.max_vm[e]) << ','
        << PostNumber(time_of(data.vm_instant[e])) << ',' << data.vm_point_name[e] << ',' << PostNumber(c(0)) << ','
        << PostNumber(c(1)) << ',' << PostNumber(c(2)) << ',' << PostNumber(data.damage[e]) << '\n';
    }
  }

  // histories of the chosen elements and nodes
  for (int e : history_elements) {
    durability::StressRecovery& r = *rec[slot[e].table];
    const int k = slot[e].k;
    r.Recover(k, 1);
    std::ofstream f(dir / ("history_element_" + std::to_string(mesh.elements[e].id) + ".csv"));
    f << "t_s";
    const reduction::StressTable& tab = *tables[slot[e].table];
    for (int p = 0; p < r.Points(); ++p) {
      for (const std::string& c : tab.components) f << ',' << r.PointName(p) << '_' << c;
      for (const char* m : {"von_mises", "signed_von_mises", "max_principal", "min_principal"})
        f << ',' << r.PointName(p) << '_' << m;
    }
    f << '\n';
    std::vector<std::vector<double>> comp(r.Points() * tab.Components(), std::vector<double>(r.Instants()));
    for (int p = 0; p < r.Points(); ++p)
      for (int c = 0; c < tab.Components(); ++c) r.ComponentHistory(k, p, c, comp[p * tab.Components() + c].data());
    for (int t = 0; t < r.Instants(); ++t) {
      f << PostNumber(times[t]);
      for (int p = 0; p < r.Points(); ++p) {
        for (int c = 0; c < tab.Components(); ++c) f << ',' << PostNumber(comp[p * tab.Components() + c][t]);
        const durability::PointStress s = r.At(k, p, t);
        f << ',' << PostNumber(s.von_mises) << ',' << PostNumber(s.signed_von_mises) << ','
          << PostNumber(s.max_principal) << ',' << PostNumber(s.min_principal);
      }
      f << '\n';
    }
  }
  for (int n : history_nodes) {
    const Eigen::MatrixXd u = body.modes.middleRows(6 * static_cast<Eigen::Index>(n), 3) * W;
    std::ofstream f(dir / ("history_node_" + std::to_string(mesh.nodes[n].id) + ".csv"));
    f << "t_s,ux_m,uy_m,uz_m\n";
    for (Eigen::Index t = 0; t < u.cols(); ++t)
      f << PostNumber(times[t]) << ',' << PostNumber(u(0, t)) << ',' << PostNumber(u(1, t)) << ','
        << PostNumber(u(2, t)) << '\n';
  }

  // ParaView file of the undeformed mesh with the per-element results
  const std::string vtu = (dir / (o.body + "_post.vtu")).string();
  WritePostVtu(vtu, mesh, data, o.distance_km ? per_1000km : 0.0);

  // report
  if (o.json) {
    std::string j = "{\n  \"body\": " + io::JsonString(o.body) + ",\n  \"instants\": " +
                    std::to_string(times.size()) + ",\n  \"truncated\": " + (hist.truncated ? "true" : "false") +
                    ",\n  \"measure\": " + io::JsonString(o.measure) + ",\n  \"sn_curve\": " +
                    io::JsonString(fo.curve ? fo.curve->name() : "") + ",\n  \"hot_spots\": [";
    for (size_t i = 0; i < hot.size(); ++i)
      j += std::string(i ? ", " : "") + "{\"element\": " + std::to_string(mesh.elements[hot[i]].id) +
           ", \"max_von_mises_Pa\": " + io::JsonNumber(data.max_vm[hot[i]]) +
           ", \"time_s\": " + io::JsonNumber(time_of(data.vm_instant[hot[i]])) + ", \"point\": " +
           io::JsonString(data.vm_point_name[hot[i]]) + "}";
    j += "],\n  \"damage\": [";
    for (size_t i = 0; i < worst.size(); ++i)
      j += std::string(i ? ", " : "") + "{\"element\": " + std::to_string(mesh.elements[worst[i]].id) +
           ", \"damage\": " + io::JsonNumber(data.damage[worst[i]]) +
           (o.distance_km ? ", \"life_km\": " + io::JsonNumber(data.damage[worst[i]] > 0 ? *o.distance_km / data.damage[worst[i]] : -1.0) : "") +
           "}";
    j += "],\n  \"vtu\": " + io::JsonString(vtu) + "\n}\n";
    out << j;
    return 0;
  }
  out << "body '" << o.body << "': " << order.size() << " elements with stress modes, " << times.size()
      << " instants" << (hist.truncated ? " (last record truncated: interrupted run)" : "") << "\n";
  out << "hot spots (largest von Mises stress):\n";
  for (size_t i = 0; i < hot.size(); ++i) {
    const int e = hot[i];
    const Eigen::Vector3d c = PostCentroid(mesh, e);
    out << "  " << i + 1 << ". element " << mesh.elements[e].id << " (" << data.vm_point_name[e] << "): "
        << PostNumber(data.max_vm[e] * 1e-6) << " MPa at t = " << PostNumber(time_of(data.vm_instant[e]))
        << " s, at (" << PostNumber(c(0)) << ", " << PostNumber(c(1)) << ", " << PostNumber(c(2)) << ") m\n";
  }
  if (fo.curve) {
    out << "damage (" << fo.curve->name() << ", " << o.measure << ", mean stress " << o.mean_stress << "):\n";
    for (size_t i = 0; i < worst.size(); ++i) {
      const int e = worst[i];
      out << "  " << i + 1 << ". element " << mesh.elements[e].id << ": " << PostNumber(data.damage[e]);
      if (o.distance_km)
        out << " (" << PostNumber(data.damage[e] * per_1000km) << " per 1000 km, life "
            << (data.damage[e] > 0 ? PostNumber(*o.distance_km / data.damage[e]) + " km" : "unlimited") << ")";
      out << "\n";
    }
  }
  out << "files: " << (dir / "elements.csv").string() << ", " << (dir / "hot_spots.csv").string() << ", " << vtu
      << "\n";
  return 0;
}

}  // namespace flexmb::commands
