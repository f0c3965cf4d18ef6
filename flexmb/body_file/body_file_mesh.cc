#include "flexmb/body_file/body_file_mesh.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "flexmb/fe/element_traits.h"

namespace flexmb::io {

namespace {

using hdf5::Dims;
using hdf5::Handle;
using hdf5::Size;

// element type codes of the file (HDF5 enum /mesh/elements/types): the
// body_file_code and name of each row of fe/element_traits.h
signed char CodeOf(fe::ElementType t) {
  for (const fe::ElementTraits& c : fe::AllElementTraits()) {
    if (c.type == t) return static_cast<signed char>(c.body_file_code);
  }
  return -1;
}

// the element type enum over base type `base` (file: H5T_STD_I8LE, memory: H5T_NATIVE_SCHAR)
Handle TypeEnum(hid_t base) {
  Handle t(H5Tenum_create(base), H5Tclose);
  for (const fe::ElementTraits& c : fe::AllElementTraits()) {
    const signed char code = static_cast<signed char>(c.body_file_code);
    if (code >= 0) H5Tenum_insert(t.get(), c.name, &code);
  }
  return t;
}

// a floating-point column of a table of entities: its dataset and member
template <class T>
struct Column {
  const char* name;
  double T::*member;
};
constexpr Column<fe::Material> kMaterialColumns[] = {
    {"E", &fe::Material::E}, {"nu", &fe::Material::nu}, {"G", &fe::Material::G}, {"rho", &fe::Material::rho}};
constexpr Column<fe::ShellSection> kShellColumns[] = {{"thickness", &fe::ShellSection::thickness},
                                                      {"nsm", &fe::ShellSection::nsm}};
constexpr Column<fe::BeamSection> kBeamColumns[] = {
    {"A", &fe::BeamSection::A},   {"Iy", &fe::BeamSection::Iy}, {"Iz", &fe::BeamSection::Iz},
    {"Iyz", &fe::BeamSection::Iyz}, {"J", &fe::BeamSection::J},   {"ky", &fe::BeamSection::ky},
    {"kz", &fe::BeamSection::kz}, {"nsm", &fe::BeamSection::nsm}};

template <class T>
void WriteColumns(hdf5::Writer& w, const std::string& group, const std::vector<T>& rows,
                  std::span<const Column<T>> cols) {
  for (const Column<T>& c : cols) {
    std::vector<double> v;
    for (const T& x : rows) v.push_back(x.*c.member);
    w.Doubles(group + "/" + c.name, v);
  }
}

template <class T>
void ReadColumns(const hdf5::Reader& r, const std::string& group, std::vector<T>& rows,
                 std::span<const Column<T>> cols) {
  for (const Column<T>& c : cols) {
    const std::vector<double> v = r.Doubles(group + "/" + c.name, {Size(rows.size())});
    for (size_t k = 0; k < rows.size(); ++k) rows[k].*c.member = v[k];
  }
}

// the material index a section is written with: a laminated shell section
// (a PCOMP, a generalized PSHELL, a membrane) and a beam section with a
// neutral axis or non-structural mass off its axis are written with -1,
// since the body file does not hold the laminate or the offsets;
// re-assembling such a mesh is then an error naming the element, never a
// different model
template <class T>
int WrittenMaterial(const T& s) {
  return s.material;
}
template <>
int WrittenMaterial(const fe::ShellSection& s) {
  return s.laminate ? -1 : s.material;
}
template <>
int WrittenMaterial(const fe::BeamSection& s) {
  return s.HasAxisOffsets() ? -1 : s.material;
}

// a section table: ids, material indices, then the columns
template <class T>
void WriteSections(hdf5::Writer& w, const std::string& group, const std::vector<T>& sections,
                   std::span<const Column<T>> cols) {
  w.Group(group);
  std::vector<int> ids, mats;
  for (const T& s : sections) {
    ids.push_back(s.id);
    mats.push_back(WrittenMaterial(s));
  }
  w.Ints(group + "/ids", ids);
  w.Ints(group + "/materials", mats);
  WriteColumns(w, group, sections, cols);
}

template <class T>
std::vector<T> ReadSections(const hdf5::Reader& r, const std::string& group, int materials,
                            const fe::Origin& origin, std::span<const Column<T>> cols) {
  const size_t n = r.Length(group + "/ids");
  const std::vector<int> ids = r.Ints(group + "/ids", n);
  const std::vector<int> mats = r.Ints(group + "/materials", n);
  r.InRange(group + "/materials", mats, -1, materials, "material");
  std::vector<T> sections(n);
  for (size_t k = 0; k < n; ++k) {
    sections[k].id = ids[k];
    sections[k].material = mats[k];
    sections[k].origin = origin;
  }
  ReadColumns(r, group, sections, cols);
  return sections;
}

using Sets = std::map<std::string, std::vector<int>>;

void WriteElements(hdf5::Writer& w, const fe::Mesh& mesh) {
  w.Group("/mesh/elements");
  const size_t ne = mesh.elements.size();
  std::vector<int> ids, props, nodes;
  std::vector<signed char> types;
  std::vector<int64_t> offsets = {0};
  std::vector<double> orient, oa, ob, shell;
  for (const fe::Element& e : mesh.elements) {
    ids.push_back(e.id);
    types.push_back(CodeOf(e.type));
    props.push_back(e.property);
    nodes.insert(nodes.end(), e.nodes.begin(), e.nodes.end());
    offsets.push_back(static_cast<int64_t>(nodes.size()));
    orient.insert(orient.end(), e.orientation.data(), e.orientation.data() + 3);
    oa.insert(oa.end(), e.offset_a.data(), e.offset_a.data() + 3);
    ob.insert(ob.end(), e.offset_b.data(), e.offset_b.data() + 3);
    shell.push_back(e.shell_offset);
  }
  w.Ints("/mesh/elements/ids", ids);
  const Handle file_enum = TypeEnum(H5T_STD_I8LE), mem_enum = TypeEnum(H5T_NATIVE_SCHAR);
  w.Data("/mesh/elements/types", file_enum.get(), mem_enum.get(), {Size(ne)}, types.data());
  w.Ints("/mesh/elements/properties", props);
  w.Longs("/mesh/elements/node_offsets", offsets);
  w.Ints("/mesh/elements/node_indices", nodes);
  w.Doubles("/mesh/elements/orientations", {Size(ne), 3}, orient.data());
  w.Doubles("/mesh/elements/offsets_a", {Size(ne), 3}, oa.data());
  w.Doubles("/mesh/elements/offsets_b", {Size(ne), 3}, ob.data());
  w.Doubles("/mesh/elements/shell_offsets", shell);
}

void WriteExtras(hdf5::Writer& w, const fe::Mesh& mesh) {
  w.Group("/mesh/point_masses");
  {
    std::vector<int> ids, nodes;
    std::vector<double> mass, offsets;
    std::vector<fe::Mat3> inertia;
    for (const fe::PointMass& p : mesh.point_masses) {
      ids.push_back(p.id);
      nodes.push_back(p.node);
      mass.push_back(p.mass);
      offsets.insert(offsets.end(), p.offset.data(), p.offset.data() + 3);
      inertia.push_back(p.inertia);
    }
    const hsize_t np = Size(mesh.point_masses.size());
    w.Ints("/mesh/point_masses/ids", ids);
    w.Ints("/mesh/point_masses/nodes", nodes);
    w.Doubles("/mesh/point_masses/mass", mass);
    w.Doubles("/mesh/point_masses/offsets", {np, 3}, offsets.data());
    w.Doubles("/mesh/point_masses/inertia", {np, 3, 3}, hdf5::Blocks(inertia).data());
    // general 6 x 6 nodal mass matrices (CONM1), only if there are any
    std::vector<int> general;
    std::vector<double> matrices;
    for (const fe::PointMass& p : mesh.point_masses) {
      general.push_back(p.general ? 1 : 0);
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) matrices.push_back(p.matrix(i, j));
    }
    if (std::count(general.begin(), general.end(), 1) > 0) {
      w.Ints("/mesh/point_masses/general", general);
      w.Doubles("/mesh/point_masses/matrices", {np, 6, 6}, matrices.data());
    }
  }

  // scalar springs (CELAS1, CELAS2), only if there are any: [S, 2] nodes
  // and components, node -1 for a grounded end
  if (!mesh.springs.empty()) {
    w.Group("/mesh/springs");
    std::vector<int> ids, nodes, components;
    std::vector<double> k;
    for (const fe::ScalarSpring& s : mesh.springs) {
      ids.push_back(s.id);
      nodes.insert(nodes.end(), {s.node_a, s.node_b});
      components.insert(components.end(), {s.component_a, s.node_b >= 0 ? s.component_b : 0});
      k.push_back(s.k);
    }
    const hsize_t ns = Size(mesh.springs.size());
    w.Ints("/mesh/springs/ids", ids);
    w.Data("/mesh/springs/nodes", H5T_STD_I32LE, H5T_NATIVE_INT, {ns, 2}, nodes.data());
    w.Data("/mesh/springs/components", H5T_STD_I32LE, H5T_NATIVE_INT, {ns, 2}, components.data());
    w.Doubles("/mesh/springs/stiffness", k);
    // directional springs (CELAS in a displacement system, CBUSH), only if
    // there are any: flag and [S, 12] coefficients (coef_a, coef_b)
    std::vector<int> directional;
    std::vector<double> coefs;
    for (const fe::ScalarSpring& s : mesh.springs) {
      directional.push_back(s.directional ? 1 : 0);
      coefs.insert(coefs.end(), s.coef_a.begin(), s.coef_a.end());
      coefs.insert(coefs.end(), s.coef_b.begin(), s.coef_b.end());
    }
    if (std::count(directional.begin(), directional.end(), 1) > 0) {
      w.Ints("/mesh/springs/directional", directional);
      w.Doubles("/mesh/springs/coefficients", {ns, 12}, coefs.data());
    }
  }

  w.Group("/mesh/rigid_links");
  {
    std::vector<int> ids, indep, masks, dep;
    std::vector<int64_t> offsets = {0};
    for (const fe::RigidLink& l : mesh.rigid_links) {
      ids.push_back(l.id);
      indep.push_back(l.independent);
      masks.push_back(l.dofs);
      dep.insert(dep.end(), l.dependent.begin(), l.dependent.end());
      offsets.push_back(static_cast<int64_t>(dep.size()));
    }
    w.Ints("/mesh/rigid_links/ids", ids);
    w.Ints("/mesh/rigid_links/independent", indep);
    w.Ints("/mesh/rigid_links/components", masks);
    w.Longs("/mesh/rigid_links/dependent_offsets", offsets);
    w.Ints("/mesh/rigid_links/dependent", dep);
  }

  w.Group("/mesh/constraints");
  {
    std::vector<int> nodes, masks;
    for (const fe::Constraint& c : mesh.constraints) {
      nodes.push_back(c.node);
      masks.push_back(c.dofs);
    }
    w.Ints("/mesh/constraints/nodes", nodes);
    w.Ints("/mesh/constraints/components", masks);
  }

  for (const auto& [group, sets] :
       {std::pair<std::string, const Sets*>{"/mesh/node_sets", &mesh.node_sets},
        {"/mesh/element_sets", &mesh.element_sets}}) {
    w.Group(group);
    std::vector<std::string> names;
    std::vector<int64_t> offsets = {0};
    std::vector<int> members;
    for (const auto& [name, m] : *sets) {
      names.push_back(name);
      members.insert(members.end(), m.begin(), m.end());
      offsets.push_back(static_cast<int64_t>(members.size()));
    }
    w.Strings(group + "/names", names);
    w.Longs(group + "/offsets", offsets);
    w.Ints(group + "/members", members);
  }
}

void ReadElements(const hdf5::Reader& r, int nn, int ne, const fe::Origin& origin, fe::Mesh& mesh) {
  const std::string g = "/mesh/elements/";
  const std::vector<int> ids = r.Ints(g + "ids", ne);
  std::vector<signed char> codes(ne);
  {
    const Handle d = r.Checked(g + "types", H5T_ENUM, {Size(ne)});
    const Handle mem = TypeEnum(H5T_NATIVE_SCHAR);
    r.Read(g + "types", d, mem.get(), codes.data());
  }
  const std::vector<int> props = r.Ints(g + "properties", ne);
  const std::vector<int64_t> offsets = r.Offsets(g + "node_offsets", ne);
  const std::vector<int> nodes = r.Ints(g + "node_indices", static_cast<size_t>(offsets[ne]));
  r.InRange(g + "node_indices", nodes, 0, nn, "node");
  const std::vector<double> orient = r.Doubles(g + "orientations", {Size(ne), 3});
  const std::vector<double> oa = r.Doubles(g + "offsets_a", {Size(ne), 3});
  const std::vector<double> ob = r.Doubles(g + "offsets_b", {Size(ne), 3});
  const std::vector<double> shell = r.Doubles(g + "shell_offsets", {Size(ne)});
  mesh.elements.resize(ne);
  for (int k = 0; k < ne; ++k) {
    fe::Element& e = mesh.elements[k];
    const std::string what = "element " + std::to_string(ids[k]) + " (entry " + std::to_string(k) + ")";
    const fe::ElementTraits* tc = nullptr;
    for (const fe::ElementTraits& c : fe::AllElementTraits()) {
      if (c.body_file_code >= 0 && c.body_file_code == codes[k]) tc = &c;
    }
    if (tc == nullptr) {
      r.Fail("dataset " + g + "types", what + ": unknown element type code " + std::to_string(codes[k]));
    }
    e.id = ids[k];
    e.type = tc->type;
    e.property = props[k];
    const size_t family = tc->family == fe::ElementFamily::kShell  ? mesh.shell_sections.size()
                          : tc->family == fe::ElementFamily::kBeam ? mesh.beam_sections.size()
                                                                   : mesh.solid_sections.size();
    if (e.property < -1 || e.property >= static_cast<int>(family)) {
      r.Fail("dataset " + g + "properties", what + ": section index " + std::to_string(e.property) +
                                                " is out of range (" + std::to_string(family) +
                                                " sections of its family)");
    }
    const int64_t count = offsets[k + 1] - offsets[k];
    if (count != fe::NodeCount(e.type)) {
      r.Fail("dataset " + g + "node_offsets", what + ": " + std::to_string(count) + " nodes, a " + tc->name +
                                                  " has " + std::to_string(fe::NodeCount(e.type)));
    }
    e.nodes.assign(nodes.begin() + offsets[k], nodes.begin() + offsets[k + 1]);
    e.orientation = fe::Vec3(orient[3 * k], orient[3 * k + 1], orient[3 * k + 2]);
    e.offset_a = fe::Vec3(oa[3 * k], oa[3 * k + 1], oa[3 * k + 2]);
    e.offset_b = fe::Vec3(ob[3 * k], ob[3 * k + 1], ob[3 * k + 2]);
    e.shell_offset = shell[k];
    e.origin = origin;
  }
}

void ReadExtras(const hdf5::Reader& r, int nn, int ne, const fe::Origin& origin, fe::Mesh& mesh) {
  {
    const std::string g = "/mesh/point_masses/";
    const size_t n = r.Length(g + "ids");
    const std::vector<int> ids = r.Ints(g + "ids", n);
    const std::vector<int> nodes = r.Ints(g + "nodes", n);
    r.InRange(g + "nodes", nodes, 0, nn, "node");
    const std::vector<double> mass = r.Doubles(g + "mass", {Size(n)});
    const std::vector<double> off = r.Doubles(g + "offsets", {Size(n), 3});
    const std::vector<fe::Mat3> inertia = r.Blocks(g + "inertia", {Size(n), 3, 3});
    // optional (files without general mass matrices have none)
    const bool has_general = r.Exists(g + "general");
    const std::vector<int> general = has_general ? r.Ints(g + "general", n) : std::vector<int>(n, 0);
    if (has_general) r.InRange(g + "general", general, 0, 2, "flag");
    const std::vector<double> matrices =
        has_general ? r.Doubles(g + "matrices", {Size(n), 6, 6}) : std::vector<double>();
    for (size_t k = 0; k < n; ++k) {
      fe::PointMass p;
      p.id = ids[k];
      p.node = nodes[k];
      p.mass = mass[k];
      p.offset = fe::Vec3(off[3 * k], off[3 * k + 1], off[3 * k + 2]);
      p.inertia = inertia[k];
      p.general = general[k] != 0;
      if (p.general) p.matrix = Eigen::Map<const fe::Mat6>(matrices.data() + 36 * k).transpose();
      p.origin = origin;
      mesh.point_masses.push_back(p);
    }
  }
  if (r.Exists("/mesh/springs/ids")) {
    // optional: files of meshes without scalar springs have none
    const std::string g = "/mesh/springs/";
    const size_t n = r.Length(g + "ids");
    const std::vector<int> ids = r.Ints(g + "ids", n);
    auto pairs = [&](const std::string& name) {
      std::vector<int> v(2 * n);
      r.Read(g + name, r.Checked(g + name, H5T_INTEGER, {Size(n), 2}), H5T_NATIVE_INT, v.data());
      return v;
    };
    const std::vector<int> nodes = pairs("nodes");
    r.InRange(g + "nodes", nodes, -1, nn, "node");
    const std::vector<int> components = pairs("components");
    r.InRange(g + "components", components, 0, 6, "component");
    const std::vector<double> k = r.Doubles(g + "stiffness", {Size(n)});
    const bool has_directional = r.Exists(g + "directional");
    const std::vector<int> directional = has_directional ? r.Ints(g + "directional", n) : std::vector<int>(n, 0);
    const std::vector<double> coefs =
        has_directional ? r.Doubles(g + "coefficients", {Size(n), 12}) : std::vector<double>(12 * n, 0.0);
    for (size_t s = 0; s < n; ++s) {
      fe::ScalarSpring sp;
      sp.id = ids[s];
      sp.node_a = nodes[2 * s];
      sp.node_b = nodes[2 * s + 1];
      sp.component_a = components[2 * s];
      sp.component_b = components[2 * s + 1];
      sp.k = k[s];
      sp.directional = directional[s] != 0;
      std::copy(coefs.begin() + 12 * s, coefs.begin() + 12 * s + 6, sp.coef_a.begin());
      std::copy(coefs.begin() + 12 * s + 6, coefs.begin() + 12 * s + 12, sp.coef_b.begin());
      sp.origin = origin;
      if (sp.node_a < 0) r.Fail("dataset " + g + "nodes", "spring " + std::to_string(sp.id) + " has no first node");
      mesh.springs.push_back(sp);
    }
  }
  {
    const std::string g = "/mesh/rigid_links/";
    const size_t n = r.Length(g + "ids");
    const std::vector<int> ids = r.Ints(g + "ids", n);
    const std::vector<int> indep = r.Ints(g + "independent", n);
    r.InRange(g + "independent", indep, 0, nn, "node");
    const std::vector<int> masks = r.Ints(g + "components", n);
    r.InRange(g + "components", masks, 0, 64, "component mask");
    const std::vector<int64_t> offsets = r.Offsets(g + "dependent_offsets", n);
    const std::vector<int> dep = r.Ints(g + "dependent", static_cast<size_t>(offsets[n]));
    r.InRange(g + "dependent", dep, 0, nn, "node");
    for (size_t k = 0; k < n; ++k) {
      fe::RigidLink l;
      l.id = ids[k];
      l.independent = indep[k];
      l.dofs = masks[k];
      l.dependent.assign(dep.begin() + offsets[k], dep.begin() + offsets[k + 1]);
      l.origin = origin;
      mesh.rigid_links.push_back(l);
    }
  }
  {
    const size_t n = r.Length("/mesh/constraints/nodes");
    const std::vector<int> nodes = r.Ints("/mesh/constraints/nodes", n);
    r.InRange("/mesh/constraints/nodes", nodes, 0, nn, "node");
    const std::vector<int> masks = r.Ints("/mesh/constraints/components", n);
    r.InRange("/mesh/constraints/components", masks, 0, 64, "component mask");
    for (size_t k = 0; k < n; ++k) mesh.constraints.push_back({nodes[k], masks[k], origin});
  }
  for (const auto& [group, sets, bound, of] :
       {std::tuple<std::string, Sets*, int, const char*>{"/mesh/node_sets", &mesh.node_sets, nn, "node"},
        {"/mesh/element_sets", &mesh.element_sets, ne, "element"}}) {
    const size_t n = r.Length(group + "/names");
    const std::vector<std::string> names = r.Strings(group + "/names", n);
    const std::vector<int64_t> offsets = r.Offsets(group + "/offsets", n);
    const std::vector<int> members = r.Ints(group + "/members", static_cast<size_t>(offsets[n]));
    r.InRange(group + "/members", members, 0, bound, of);
    for (size_t k = 0; k < n; ++k) {
      if (!sets->emplace(names[k], std::vector<int>(members.begin() + offsets[k], members.begin() + offsets[k + 1]))
               .second) {
        r.Fail("dataset " + group + "/names", "set '" + names[k] + "' is given twice");
      }
    }
  }
}

}  // namespace

bool HasBodyFileTypeCode(fe::ElementType type) { return CodeOf(type) >= 0; }

void WriteBodyMesh(hdf5::Writer& w, const fe::Mesh& mesh) {
  w.Group("/mesh");
  w.AttributeString("/mesh", "source", mesh.source);

  w.Group("/mesh/nodes");
  {
    std::vector<int> ids;
    std::vector<double> x;
    for (const fe::Node& nd : mesh.nodes) {
      ids.push_back(nd.id);
      x.insert(x.end(), nd.x.data(), nd.x.data() + 3);
    }
    w.Ints("/mesh/nodes/ids", ids);
    w.Doubles("/mesh/nodes/coordinates", {Size(mesh.nodes.size()), 3}, x.data());
  }

  WriteElements(w, mesh);

  w.Group("/mesh/materials");
  {
    std::vector<int> ids;
    std::vector<std::string> names;
    for (const fe::Material& m : mesh.materials) {
      ids.push_back(m.id);
      names.push_back(m.name);
    }
    w.Ints("/mesh/materials/ids", ids);
    w.Strings("/mesh/materials/names", names);
    WriteColumns<fe::Material>(w, "/mesh/materials", mesh.materials, kMaterialColumns);
  }
  WriteSections<fe::ShellSection>(w, "/mesh/shell_sections", mesh.shell_sections, kShellColumns);
  WriteSections<fe::BeamSection>(w, "/mesh/beam_sections", mesh.beam_sections, kBeamColumns);
  WriteSections<fe::SolidSection>(w, "/mesh/solid_sections", mesh.solid_sections, {});

  WriteExtras(w, mesh);
}

fe::Mesh ReadBodyMesh(const hdf5::Reader& r, int nn, int ne, const std::string& path) {
  fe::Mesh mesh;
  mesh.source = r.AttributeString("/mesh", "source");
  const fe::Origin origin{path, 0};

  const std::vector<int> node_ids = r.Ints("/mesh/nodes/ids", nn);
  const std::vector<double> x = r.Doubles("/mesh/nodes/coordinates", {Size(nn), 3});
  mesh.nodes.resize(nn);
  std::set<int> seen;
  for (int k = 0; k < nn; ++k) {
    if (node_ids[k] <= 0 || !seen.insert(node_ids[k]).second) {
      r.Fail("dataset /mesh/nodes/ids", "node id " + std::to_string(node_ids[k]) + " at entry " + std::to_string(k) +
                                            (node_ids[k] <= 0 ? " is not positive" : " is given twice"));
    }
    mesh.nodes[k].id = node_ids[k];
    mesh.nodes[k].x = fe::Vec3(x[3 * k], x[3 * k + 1], x[3 * k + 2]);
    mesh.nodes[k].origin = origin;
  }
  mesh.IndexNodes();

  // materials and sections first: elements refer to them
  const size_t nm = r.Length("/mesh/materials/ids");
  {
    const std::vector<int> ids = r.Ints("/mesh/materials/ids", nm);
    const std::vector<std::string> names = r.Strings("/mesh/materials/names", nm);
    mesh.materials.resize(nm);
    for (size_t k = 0; k < nm; ++k) {
      mesh.materials[k].id = ids[k];
      mesh.materials[k].name = names[k];
      mesh.materials[k].origin = origin;
    }
    ReadColumns<fe::Material>(r, "/mesh/materials", mesh.materials, kMaterialColumns);
  }
  const int imat = static_cast<int>(nm);
  mesh.shell_sections = ReadSections<fe::ShellSection>(r, "/mesh/shell_sections", imat, origin, kShellColumns);
  mesh.beam_sections = ReadSections<fe::BeamSection>(r, "/mesh/beam_sections", imat, origin, kBeamColumns);
  mesh.solid_sections = ReadSections<fe::SolidSection>(r, "/mesh/solid_sections", imat, origin, {});

  ReadElements(r, nn, ne, origin, mesh);
  ReadExtras(r, nn, ne, origin, mesh);
  return mesh;
}

}  // namespace flexmb::io
