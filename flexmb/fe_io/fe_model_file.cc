#include "flexmb/fe_io/fe_model_file.h"

#include <yaml-cpp/yaml.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "flexmb/common/error.h"
#include "flexmb/common/text.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/mesh_checks.h"
#include "flexmb/fe_io/exchange_set.h"
#include "flexmb/fe_io/format_registry.h"
#include "flexmb/fe_io/imported_matrices.h"
#include "flexmb/fe_io/node_selection.h"
#include "flexmb/yaml/yaml_context.h"

namespace flexmb::io {
namespace {

namespace fs = std::filesystem;
using fe::ElementType;

// a mesh file of any supported format (not an FE model file or directory)
bool ReadMeshFile(const std::string& path, fe::Mesh& mesh) {
  const FeFileFormat* format = FindMeshFormat(path);
  if (!format) return false;
  mesh = format->read_mesh(path);
  return true;
}

// names of a map's keys for messages, at most 12
template <class Map>
std::string KeyList(const Map& map) {
  std::string out;
  int k = 0;
  for (const auto& [name, value] : map) {
    if (k == 12) return out + ", ...";
    out += (k++ ? ", " : "") + name;
  }
  return out.empty() ? "none" : out;
}

std::string NodeName(const fe::Mesh& mesh, int n) { return "node " + std::to_string(mesh.nodes[n].id); }

std::string ElementName(const fe::Element& e) {
  return std::string(fe::TypeName(e.type)) + " element " + std::to_string(e.id);
}

using Family = fe::ElementFamily;
using fe::FamilyName;

Family FamilyOf(ElementType t) { return fe::Traits(t).family; }

// reading one FE model file
class FeModelFileParser {
 public:
  FeModelFileParser(const std::string& path, YamlContext& ctx) : path_(path), ctx_(ctx) {
    dir_ = fs::path(path).parent_path();
  }

  fe::FeModel Parse(const YAML::Node& root) {
    ctx_.SetEntity("");
    if (!root.IsDefined() || root.IsNull()) ctx_.Fail(root, "the FE model file is empty");
    if (!root.IsMap()) ctx_.Fail(root, "expected a map of 'key: value' entries at the top level");
    if (root["matrices"]) return ParseMatrices(root);
    ctx_.CheckKeys(root, {"mesh", "matrices", "nodes", "materials", "sections", "drop_elements", "fixed",
                          "point_masses", "rigid_links"});
    fe::FeModel model;
    mesh_ = &model.mesh;
    LoadMesh(root);
    if (root["nodes"]) ParseNodes(root["nodes"]);
    if (root["drop_elements"]) DropElements(root["drop_elements"]);
    if (root["materials"]) ParseMaterials(root["materials"]);
    if (root["sections"]) ParseSections(root["sections"]);
    CheckProperties();
    if (root["fixed"]) ParseFixed(root["fixed"]);
    if (root["point_masses"]) ParsePointMasses(root["point_masses"]);
    if (root["rigid_links"]) ParseRigidLinks(root["rigid_links"]);
    return model;
  }

 private:
  // a path of the file, relative to the FE model file's folder
  std::string Resolve(const std::string& p) const {
    const fs::path q(p);
    return (q.is_absolute() || dir_.empty() ? q : dir_ / q).string();
  }

  std::string ExistingFile(const YAML::Node& node, const char* key) {
    const std::string value = ctx_.String(node, key);
    if (value.empty()) ctx_.Fail(node[key], Quoted(key) + " must not be empty");
    const std::string path = Resolve(value);
    std::error_code ec;
    if (!fs::exists(path, ec)) ctx_.Fail(node[key], "file " + Quoted(value) + " does not exist (looked for " + path + ")");
    return path;
  }

  fe::FeModel ParseMatrices(const YAML::Node& root) {
    if (root["mesh"])
      ctx_.Fail(root["mesh"], "'mesh' and 'matrices' exclude each other: a model is a mesh with properties, or "
                              "imported matrices with their geometry");
    ctx_.CheckKeys(root, {"matrices", "nodes", "fixed", "point_masses", "rigid_links"});
    const YAML::Node m = root["matrices"];
    ctx_.SetEntity("matrices");
    ctx_.CheckKeys(m, {"stiffness", "mass", "dof_map", "geometry"});
    ImportedMatricesSpec spec;
    spec.stiffness = ExistingFile(m, "stiffness");
    spec.mass = ExistingFile(m, "mass");
    if (m["dof_map"]) spec.dof_map = ExistingFile(m, "dof_map");
    spec.geometry = ExistingFile(m, "geometry");
    fe::FeModel model = ctx_.Guard(m, [&] { return ReadImportedMatrices(spec); });
    mesh_ = &model.mesh;
    mesh_name_ = fs::path(spec.geometry).filename().string();
    if (root["nodes"]) ParseNodes(root["nodes"]);
    if (root["fixed"]) ParseFixed(root["fixed"]);
    if (root["point_masses"]) ParsePointMasses(root["point_masses"]);
    if (root["rigid_links"]) ParseRigidLinks(root["rigid_links"]);
    return model;
  }

  // nodes added to the mesh or geometry: {id, x: [x, y, z]}
  void ParseNodes(const YAML::Node& node) {
    ExpectList(node, "nodes");
    std::set<int> added;
    for (size_t k = 0; k < node.size(); ++k) {
      const YAML::Node s = node[k];
      ctx_.SetEntity("node #" + std::to_string(k + 1));
      ctx_.CheckKeys(s, {"id", "x"});
      if (!s["id"]) ctx_.Fail(s, "missing required key 'id'");
      const double id = ctx_.Number(s["id"], "'id'");
      if (id != std::floor(id) || id < 1 || id > 2147483647.0)
        ctx_.Fail(s["id"], "'id' must be a positive whole number, got " + Quoted(s["id"].Scalar()));
      fe::Node n;
      n.id = static_cast<int>(id);
      if (mesh_->NodeIndex(n.id) >= 0)
        ctx_.Fail(s["id"], "node " + std::to_string(n.id) + " already exists in " + MeshName());
      if (!added.insert(n.id).second)
        ctx_.Fail(s["id"], "node " + std::to_string(n.id) + " is listed twice in 'nodes'");
      if (!s["x"]) ctx_.Fail(s, "missing required key 'x' (the node's position [x, y, z])");
      n.x = ctx_.Vector3(s, "x");
      n.origin = {path_, YamlContext::Line(s)};
      mesh_->nodes.push_back(n);
    }
    mesh_->IndexNodes();
  }

  void LoadMesh(const YAML::Node& root) {
    ctx_.SetEntity("mesh");
    if (!root["mesh"]) ctx_.Fail(root, "missing required key 'mesh' (or 'matrices')");
    const YAML::Node v = root["mesh"];
    const std::string path = ExistingFile(root, "mesh");
    std::error_code ec;
    if (fs::is_directory(path, ec)) ctx_.Fail(v, "'mesh' must be a mesh file, got the directory " + path);
    const bool known = ctx_.Guard(v, [&] { return ReadMeshFile(path, *mesh_); });
    if (!known)
      ctx_.Fail(v, "'mesh' file " + Quoted(v.Scalar()) + " has an unknown extension (known: " + MeshFormatList() + ")");
    mesh_name_ = fs::path(path).filename().string();
  }

  // the list at `node` (a single scalar counts as a list of one)
  std::vector<YAML::Node> Items(const YAML::Node& node, const char* what) {
    std::vector<YAML::Node> out;
    if (node.IsSequence()) {
      for (const YAML::Node& item : node) out.push_back(item);
    } else if (node.IsScalar()) {
      out.push_back(node);
    } else {
      ctx_.Fail(node, std::string("expected ") + what);
    }
    return out;
  }

  // element indices of the set named by `v`
  const std::vector<int>& ElementSet(const YAML::Node& v) {
    if (!v.IsScalar()) ctx_.Fail(v, "expected the name of an element set");
    const auto it = mesh_->element_sets.find(v.Scalar());
    if (it == mesh_->element_sets.end())
      ctx_.Fail(v, "there is no element set named " + Quoted(v.Scalar()) + " in " + mesh_name_ +
                       " (element sets: " + KeyList(mesh_->element_sets) + ")");
    return it->second;
  }

  void DropElements(const YAML::Node& node) {
    ctx_.SetEntity("drop_elements");
    std::vector<uint8_t> drop(mesh_->elements.size(), 0);
    for (const YAML::Node& v : Items(node, "a list of element set names")) {
      for (int e : ElementSet(v)) drop[e] = 1;
    }
    std::vector<int> renumber(mesh_->elements.size(), -1);
    std::vector<fe::Element> kept;
    for (size_t e = 0; e < mesh_->elements.size(); ++e) {
      if (drop[e]) continue;
      renumber[e] = static_cast<int>(kept.size());
      kept.push_back(std::move(mesh_->elements[e]));
    }
    mesh_->elements = std::move(kept);
    for (auto& [name, set] : mesh_->element_sets) {
      std::vector<int> remaining;
      for (int e : set)
        if (renumber[e] >= 0) remaining.push_back(renumber[e]);
      set = std::move(remaining);
    }
  }

  void ParseMaterials(const YAML::Node& node) {
    ctx_.SetEntity("materials");
    if (!node.IsMap()) ctx_.Fail(node, "expected 'materials' as a map 'name: {E, nu, rho}'");
    int next_id = 1;
    for (const fe::Material& m : mesh_->materials) next_id = std::max(next_id, m.id + 1);
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (!it->first.IsScalar()) ctx_.Fail(it->first, "a material name must be a plain name");
      const std::string name = it->first.Scalar();
      ctx_.SetEntity("material " + Quoted(name));
      const YAML::Node m = it->second;
      ctx_.CheckKeys(m, {"E", "nu", "rho", "G"});
      fe::Material mat;
      mat.id = next_id++;
      mat.name = name;
      mat.E = ctx_.Positive(m, "E");
      mat.nu = ctx_.Double(m, "nu");
      if (!(mat.nu > -1.0 && mat.nu < 0.5)) ctx_.Fail(m["nu"], "'nu' must be in (-1, 0.5)");
      mat.rho = ctx_.Double(m, "rho");
      if (mat.rho < 0.0) ctx_.Fail(m["rho"], "'rho' must not be negative");
      mat.G = m["G"] ? ctx_.Positive(m, "G") : mat.E / (2.0 * (1.0 + mat.nu));
      mat.origin = {path_, YamlContext::Line(m)};
      if (!materials_.emplace(name, static_cast<int>(mesh_->materials.size())).second)
        ctx_.Fail(it->first, "material " + Quoted(name) + " is defined twice");
      mesh_->materials.push_back(mat);
    }
  }

  void ParseSections(const YAML::Node& node) {
    ExpectList(node, "sections");
    const int shell_base = NextId(mesh_->shell_sections), beam_base = NextId(mesh_->beam_sections),
              solid_base = NextId(mesh_->solid_sections);
    for (size_t k = 0; k < node.size(); ++k) {
      const YAML::Node s = node[k];
      ctx_.SetEntity("section #" + std::to_string(k + 1));
      if (!s.IsMap()) ctx_.Fail(s, "expected a map with 'elements', 'type', 'material', ...");
      const std::string type = ctx_.String(s, "type");
      Family family;
      int property = -1;
      const int id = static_cast<int>(k);
      if (type == "shell") {
        ctx_.CheckKeys(s, {"elements", "type", "material", "thickness", "nsm"});
        family = Family::kShell;
        fe::ShellSection sec;
        sec.id = shell_base + id;
        sec.material = Material(s);
        sec.thickness = ctx_.Positive(s, "thickness");
        sec.nsm = NonNegative(s, "nsm");
        sec.origin = {path_, YamlContext::Line(s)};
        property = static_cast<int>(mesh_->shell_sections.size());
        mesh_->shell_sections.push_back(sec);
      } else if (type == "beam") {
        ctx_.CheckKeys(s, {"elements", "type", "material", "A", "Iy", "Iz", "Iyz", "J", "ky", "kz", "nsm",
                           "orientation"});
        family = Family::kBeam;
        fe::BeamSection sec;
        sec.id = beam_base + id;
        sec.material = Material(s);
        sec.A = ctx_.Positive(s, "A");
        sec.Iy = ctx_.Positive(s, "Iy");
        sec.Iz = ctx_.Positive(s, "Iz");
        sec.Iyz = ctx_.Double(s, "Iyz", 0.0);
        if (!(sec.Iy * sec.Iz > sec.Iyz * sec.Iyz)) ctx_.Fail(s["Iyz"], "'Iyz' must satisfy Iyz^2 < Iy Iz");
        sec.J = ctx_.Positive(s, "J");
        sec.ky = NonNegative(s, "ky");
        sec.kz = NonNegative(s, "kz");
        sec.nsm = NonNegative(s, "nsm");
        sec.origin = {path_, YamlContext::Line(s)};
        orientation_ = ctx_.Vector3(s, "orientation");
        if (!(orientation_.norm() > 0.0)) ctx_.Fail(s["orientation"], "'orientation' must not be the zero vector");
        property = static_cast<int>(mesh_->beam_sections.size());
        mesh_->beam_sections.push_back(sec);
      } else if (type == "solid") {
        ctx_.CheckKeys(s, {"elements", "type", "material"});
        family = Family::kSolid;
        fe::SolidSection sec;
        sec.id = solid_base + id;
        sec.material = Material(s);
        sec.origin = {path_, YamlContext::Line(s)};
        property = static_cast<int>(mesh_->solid_sections.size());
        mesh_->solid_sections.push_back(sec);
      } else {
        ctx_.Fail(s["type"], "unknown section type " + Quoted(type) + " (allowed: shell, beam, solid)");
      }
      Assign(s, family, property);
    }
  }

  // the value of `key` must be a list of entries; names `key` as the entity
  void ExpectList(const YAML::Node& node, const char* key) {
    ctx_.SetEntity(key);
    if (!node.IsSequence()) ctx_.Fail(node, std::string("expected '") + key + "' as a list of entries ('- ...')");
  }

  template <class V>
  static int NextId(const V& list) {
    int id = 1;
    for (const auto& x : list) id = std::max(id, x.id + 1);
    return id;
  }

  double NonNegative(const YAML::Node& s, const char* key) {
    const double x = ctx_.Double(s, key, 0.0);
    if (x < 0.0) ctx_.Fail(s[key], Quoted(key) + " must not be negative");
    return x;
  }

  int Material(const YAML::Node& s) {
    const std::string name = ctx_.String(s, "material");
    const auto it = materials_.find(name);
    if (it == materials_.end())
      ctx_.Fail(s["material"], "there is no material named " + Quoted(name) + " in 'materials' (materials: " +
                                   KeyList(materials_) + ")");
    return it->second;
  }

  // gives the elements named by s["elements"] the property; later entries override earlier ones
  void Assign(const YAML::Node& s, Family family, int property) {
    if (!s["elements"]) ctx_.Fail(s, "missing required key 'elements' (an element set name or 'all')");
    int count = 0;
    for (const YAML::Node& v : Items(s["elements"], "an element set name, a list of them, or 'all'")) {
      if (v.IsScalar() && v.Scalar() == "all") {
        for (fe::Element& e : mesh_->elements) {
          if (FamilyOf(e.type) != family) continue;
          Give(e, family, property);
          ++count;
        }
        continue;
      }
      const std::vector<int>& set = ElementSet(v);
      for (int index : set) {
        fe::Element& e = mesh_->elements[index];
        if (FamilyOf(e.type) != family)
          ctx_.Fail(v, std::string("element set ") + Quoted(v.Scalar()) + " holds " + ElementName(e) +
                           (e.origin.line > 0 ? " (" + e.origin.file + ":" + std::to_string(e.origin.line) + ")" : "") +
                           ", which cannot take a " + FamilyName(family) + " section");
        Give(e, family, property);
        ++count;
      }
    }
    if (count == 0) ctx_.Fail(s["elements"], std::string("'elements' names no ") + FamilyName(family) + " elements");
  }

  void Give(fe::Element& e, Family family, int property) {
    e.property = property;
    if (family == Family::kBeam) e.orientation = orientation_;
  }

  // every element must have a property of its family
  void CheckProperties() {
    for (size_t k = 0; k < mesh_->elements.size(); ++k) {
      const fe::Element& e = mesh_->elements[k];
      if (e.property >= 0) continue;
      std::string sets;
      for (const auto& [name, list] : mesh_->element_sets)
        if (std::find(list.begin(), list.end(), static_cast<int>(k)) != list.end())
          sets += (sets.empty() ? "" : ", ") + Quoted(name);
      throw InputError("has no section: no entry of 'sections' in " + fs::path(path_).filename().string() +
                           " covers it (element sets: " + (sets.empty() ? "none" : sets) +
                           "); assign one, or remove boundary elements with 'drop_elements'",
                       {e.origin.file, e.origin.line, ElementName(e)});
    }
  }

  // node indices named by a scalar (node id or node set) or a list of them
  std::vector<int> Nodes(const YAML::Node& node) {
    std::vector<int> out;
    if (node.IsMap()) return Selected(node);
    for (const YAML::Node& v : Items(node, "a node id, a node set name, a selection {cylinder: ...} or {box: ...}, "
                                           "or a list of them")) {
      if (v.IsMap()) {
        const std::vector<int> chosen = Selected(v);
        out.insert(out.end(), chosen.begin(), chosen.end());
        continue;
      }
      if (!v.IsScalar()) ctx_.Fail(v, "expected a node id, a node set name or a selection {cylinder: ...} or {box: ...}");
      // an unquoted whole number is a node id; anything else names a set
      double x = 0.0;
      bool number = v.Tag() != "!";
      if (number) {
        try {
          x = v.as<double>();
        } catch (const YAML::Exception&) {
          number = false;
        }
      }
      if (number) {
        if (x != std::floor(x) || x < 1 || x > 2147483647.0)
          ctx_.Fail(v, "a node id must be a positive whole number, got " + Quoted(v.Scalar()));
        const int n = mesh_->NodeIndex(static_cast<int>(x));
        if (n < 0) ctx_.Fail(v, "node " + v.Scalar() + " does not exist in " + MeshName());
        out.push_back(n);
        continue;
      }
      const auto it = mesh_->node_sets.find(v.Scalar());
      if (it == mesh_->node_sets.end())
        ctx_.Fail(v, "there is no node set named " + Quoted(v.Scalar()) + " in " + MeshName() + " (node sets: " +
                         KeyList(mesh_->node_sets) + ")");
      if (it->second.empty()) ctx_.Fail(v, "node set " + Quoted(v.Scalar()) + " is empty");
      out.insert(out.end(), it->second.begin(), it->second.end());
    }
    return out;
  }

  std::vector<int> Selected(const YAML::Node& v) { return SelectNodes(*mesh_, MeshName(), v, ctx_); }

  std::string MeshName() const {
    return mesh_name_.empty() ? fs::path(mesh_->source).filename().string() : mesh_name_;
  }

  // exactly one node
  int OneNode(const YAML::Node& s, const char* key) {
    if (!s[key]) ctx_.Fail(s, std::string("missing required key '") + key + "'");
    std::vector<int> nodes = Nodes(s[key]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (nodes.size() != 1)
      ctx_.Fail(s[key], Quoted(key) + " must name exactly one node, got " + std::to_string(nodes.size()));
    return nodes[0];
  }

  // a component mask given as digits, e.g. 123 or 123456
  int Dofs(const YAML::Node& s, const char* key) {
    const YAML::Node v = s[key];
    if (!v) return 0b111111;
    if (!v.IsScalar()) ctx_.Fail(v, Quoted(key) + " must be digits 1 to 6, e.g. 123 or 123456");
    int mask = 0;
    for (char c : v.Scalar()) {
      if (c < '1' || c > '6' || (mask & (1 << (c - '1'))))
        ctx_.Fail(v, Quoted(key) + " must be distinct digits 1 to 6 (1-3 translations, 4-6 rotations), got " +
                         Quoted(v.Scalar()));
      mask |= 1 << (c - '1');
    }
    if (mask == 0) ctx_.Fail(v, Quoted(key) + " must not be empty");
    return mask;
  }

  void ParseFixed(const YAML::Node& node) {
    const std::vector<YAML::Node> items =
        node.IsMap() ? std::vector<YAML::Node>{node}
                     : Items(node, "a node id, a node set name, a selection, a map {nodes, dofs} or a list");
    for (size_t k = 0; k < items.size(); ++k) {
      const YAML::Node v = items[k];
      ctx_.SetEntity("fixed #" + std::to_string(k + 1));
      std::vector<int> nodes;
      int dofs = 0b111111;
      if (v.IsMap() && !v["cylinder"] && !v["box"]) {
        ctx_.CheckKeys(v, {"nodes", "dofs"});
        if (!v["nodes"]) ctx_.Fail(v, "missing required key 'nodes'");
        nodes = Nodes(v["nodes"]);
        dofs = Dofs(v, "dofs");
      } else {
        nodes = Nodes(v);
      }
      for (int n : nodes) {
        fe::Constraint c;
        c.node = n;
        c.dofs = dofs;
        c.origin = {path_, YamlContext::Line(v)};
        mesh_->constraints.push_back(c);
      }
    }
  }

  void ParsePointMasses(const YAML::Node& node) {
    ExpectList(node, "point_masses");
    int next_id = NextId(mesh_->point_masses);
    for (size_t k = 0; k < node.size(); ++k) {
      const YAML::Node s = node[k];
      ctx_.SetEntity("point mass #" + std::to_string(k + 1));
      ctx_.CheckKeys(s, {"node", "mass", "offset", "inertia"});
      fe::PointMass pm;
      pm.id = next_id++;
      pm.node = OneNode(s, "node");
      pm.mass = ctx_.Positive(s, "mass");
      pm.offset = ctx_.Vector3(s, "offset", fe::Vec3::Zero());
      if (s["inertia"]) pm.inertia = Inertia(s["inertia"]);
      pm.origin = {path_, YamlContext::Line(s)};
      mesh_->point_masses.push_back(pm);
    }
  }

  // [ixx, iyy, izz], [ixx, iyy, izz, ixy, ixz, iyz] or a symmetric 3x3 matrix
  fe::Mat3 Inertia(const YAML::Node& v) {
    const char* forms =
        "expected 'inertia' as [ixx, iyy, izz], [ixx, iyy, izz, ixy, ixz, iyz] or a 3x3 matrix [[..], [..], [..]]";
    if (!v.IsSequence()) ctx_.Fail(v, forms);
    fe::Mat3 I = fe::Mat3::Zero();
    if (v.size() == 3 && v[0].IsSequence()) {
      for (int r = 0; r < 3; ++r) {
        const YAML::Node row = v[r];
        if (!row.IsSequence() || row.size() != 3) ctx_.Fail(row, forms);
        for (int c = 0; c < 3; ++c)
          I(r, c) = ctx_.Number(row[c], "'inertia' row " + std::to_string(r + 1) + " entry " + std::to_string(c + 1));
      }
      if ((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-9 * I.cwiseAbs().maxCoeff())
        ctx_.Fail(v, "the 'inertia' matrix is not symmetric");
      I = 0.5 * (I + I.transpose());
    } else {
      if (v.size() != 3 && v.size() != 6) ctx_.Fail(v, forms);
      double e[6] = {0, 0, 0, 0, 0, 0};
      for (size_t k = 0; k < v.size(); ++k) e[k] = ctx_.Number(v[k], "'inertia' entry " + std::to_string(k + 1));
      I << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
    }
    const double scale = I.cwiseAbs().maxCoeff();
    if (Eigen::SelfAdjointEigenSolver<fe::Mat3>(I, Eigen::EigenvaluesOnly).eigenvalues().minCoeff() < -1e-12 * scale)
      ctx_.Fail(v, "the 'inertia' is not positive semi-definite");
    return I;
  }

  void ParseRigidLinks(const YAML::Node& node) {
    ExpectList(node, "rigid_links");
    int next_id = NextId(mesh_->rigid_links);
    for (size_t k = 0; k < node.size(); ++k) {
      const YAML::Node s = node[k];
      ctx_.SetEntity("rigid link #" + std::to_string(k + 1));
      ctx_.CheckKeys(s, {"independent", "dependent", "dofs"});
      fe::RigidLink link;
      link.id = next_id++;
      link.independent = OneNode(s, "independent");
      if (!s["dependent"]) ctx_.Fail(s, "missing required key 'dependent'");
      // a selection leaves out the independent node (often on the face it picks)
      std::vector<int> dep;
      const YAML::Node d = s["dependent"];
      for (const YAML::Node& item : d.IsMap() ? std::vector<YAML::Node>{d} : Items(d, "dependent nodes")) {
        std::vector<int> nodes = Nodes(item);
        if (item.IsMap()) {
          nodes.erase(std::remove(nodes.begin(), nodes.end(), link.independent), nodes.end());
          if (nodes.empty()) ctx_.Fail(item, "the selection picks no node but the independent one");
        }
        dep.insert(dep.end(), nodes.begin(), nodes.end());
      }
      if (dep.empty()) ctx_.Fail(d, "'dependent' names no node");
      std::set<int> seen;
      for (int n : dep) {
        if (n == link.independent)
          ctx_.Fail(s["dependent"], NodeName(*mesh_, n) + " is both the independent and a dependent node");
        if (seen.insert(n).second) link.dependent.push_back(n);
      }
      link.dofs = Dofs(s, "dofs");
      link.origin = {path_, YamlContext::Line(s)};
      mesh_->rigid_links.push_back(link);
    }
  }

  std::string path_;
  fs::path dir_;
  YamlContext& ctx_;
  fe::Mesh* mesh_ = nullptr;
  std::string mesh_name_;
  std::map<std::string, int> materials_;
  fe::Vec3 orientation_ = fe::Vec3::Zero();
};

fe::FeModel LoadFeModelFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot open the FE model file: " + std::string(std::strerror(errno)), {path, 0, ""});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read the FE model file", {path, 0, ""});
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw InputError("YAML syntax error: " + e.msg, {path, e.mark.is_null() ? 0 : e.mark.line + 1, ""});
  }
  YamlContext ctx(path);
  try {
    return FeModelFileParser(path, ctx).Parse(root);
  } catch (const YAML::Exception& e) {
    throw InputError(e.msg, {path, e.mark.is_null() ? 0 : e.mark.line + 1, ctx.entity()});
  }
}

}  // namespace

namespace {

// the model's connected parts and unused nodes, as warnings (fe/mesh_checks.h);
// not for imported matrices, whose mesh holds display cells only (the
// matrices, not the cells, join the nodes and give them degrees of freedom)
fe::FeModel Checked(fe::FeModel model, const std::string& path) {
  if (model.imported) return model;
  for (const std::string& w : fe::MeshCheckWarnings(model.mesh, fe::CheckMesh(model.mesh), path)) LogWarning(w);
  return model;
}

}  // namespace

fe::FeModel LoadFeModel(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return ReadExchangeSet(path);
  const std::string ext = LowerExtension(path);
  if (ext == ".yaml" || ext == ".yml") return Checked(LoadFeModelFile(path), path);
  fe::FeModel model;
  if (!ReadMeshFile(path, model.mesh))
    throw InputError("unknown FE model file type " + Quoted(ext.empty() ? fs::path(path).filename().string() : ext) +
                         " (known: " + MeshFormatList() + ", .yaml/.yml (FE model file), or an exchange-set directory)",
                     {path, 0, ""});
  if (model.mesh.nodes.empty())
    throw InputError("the file defines no nodes (no GRID or *NODE): an empty or truncated deck, or the nodes are "
                     "in a file it does not include",
                     {path, 0, ""});
  return Checked(std::move(model), path);
}

std::vector<int> ResolveNodeList(const fe::Mesh& mesh, const std::string& ids_or_set) {
  const std::string& file = mesh.source;
  const auto set = mesh.node_sets.find(ids_or_set);
  if (set != mesh.node_sets.end()) {
    if (set->second.empty()) throw InputError("node set is empty", {file, 0, "node set " + Quoted(ids_or_set)});
    return set->second;
  }
  const bool list = !ids_or_set.empty() &&
                    ids_or_set.find_first_not_of("0123456789, ") == std::string::npos &&
                    ids_or_set.find_first_of("0123456789") != std::string::npos;
  if (!list)
    throw InputError("there is no node set named " + Quoted(ids_or_set) + " (node sets: " + KeyList(mesh.node_sets) +
                         "), and it is not a comma-separated list of node ids",
                     {file, 0, "node set " + Quoted(ids_or_set)});
  std::vector<int> out;
  std::set<int> seen;
  std::stringstream items(ids_or_set);
  std::string item;
  while (std::getline(items, item, ',')) {
    const size_t a = item.find_first_not_of(' '), b = item.find_last_not_of(' ');
    if (a == std::string::npos)
      throw InputError("empty entry in the node list " + Quoted(ids_or_set), {file, 0, ""});
    const std::string digits = item.substr(a, b - a + 1);
    if (digits.find(' ') != std::string::npos || digits.size() > 10 || std::stoll(digits) > 2147483647LL ||
        std::stoll(digits) < 1)
      throw InputError("bad node id " + Quoted(digits) + " in " + Quoted(ids_or_set), {file, 0, "node " + digits});
    const int id = static_cast<int>(std::stoll(digits));
    const int n = mesh.NodeIndex(id);
    if (n < 0) throw InputError("does not exist in the mesh", {file, 0, "node " + std::to_string(id)});
    if (seen.insert(n).second) out.push_back(n);
  }
  if (ids_or_set.back() == ',') throw InputError("empty entry in the node list " + Quoted(ids_or_set), {file, 0, ""});
  return out;
}

}  // namespace flexmb::io
