#include "flexmb/fe_io/abaqus/abaqus_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/solid_hex8.h"
#include "flexmb/fe_io/abaqus/abaqus_deck.h"
#include "flexmb/fe_io/text_scanner.h"

namespace flexmb::io {
namespace {

using abaqus::IsBeam;
using abaqus::IsShell;
using abaqus::IsSolid;
using abaqus::Upper;

std::string Num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool PlainName(const std::string& s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

std::string Name(const std::string& s, const std::string& entity) {
  if (PlainName(s)) return s;
  if (s.empty() || s.find('"') != std::string::npos || s.find('\n') != std::string::npos)
    throw InputError("name '" + Printable(s) + "' cannot be written to an Abaqus deck", {"", 0, entity});
  return "\"" + s + "\"";
}

// writes `ids` 16 to a line
void WriteIds(std::FILE* f, const std::vector<int>& ids) {
  for (size_t k = 0; k < ids.size(); ++k) {
    std::fprintf(f, "%d%s", ids[k], (k + 1 == ids.size() || k % 16 == 15) ? "\n" : ", ");
  }
}

// whether Abaqus names a variant of the type without shear flexibility
bool HasEulerBernoulliName(fe::ElementType type) {
  for (const fe::AbaqusName& a : fe::Traits(type).abaqus)
    if (a.variant == fe::AbaqusVariant::kEulerBernoulli) return true;
  return false;
}

// the type's first Abaqus name; a beam without shear flexibility gets its
// Euler-Bernoulli name (B33)
const char* AbaqusType(const fe::Mesh& mesh, const fe::Element& e) {
  const fe::ElementTraits& t = fe::Traits(e.type);
  if (IsBeam(e.type)) {
    const fe::BeamSection& s = mesh.beam_sections.at(e.property);
    if (s.ky == 0.0 && s.kz == 0.0)
      for (const fe::AbaqusName& a : t.abaqus)
        if (a.variant == fe::AbaqusVariant::kEulerBernoulli) return a.name;
  }
  if (e.type == fe::kHex8Selective) return "C3D8";  // Abaqus's C3D8, under the Abaqus/CAE line
  return t.abaqus.empty() ? "?" : t.abaqus.front().name;
}

// checks the mesh before anything is written, so that nothing half-written
// is left for a bad mesh; returns the material names for the deck
std::vector<std::string> CheckWritable(const fe::Mesh& mesh) {
  // C3D8 means Abaqus's or CalculiX's element by the deck's header line:
  // one deck cannot carry both
  bool calculix_c3d8 = false, abaqus_c3d8 = false;
  for (const fe::Element& e : mesh.elements) {
    calculix_c3d8 = calculix_c3d8 || e.type == fe::kHex8Full;
    abaqus_c3d8 = abaqus_c3d8 || e.type == fe::kHex8Selective;
  }
  if (calculix_c3d8 && abaqus_c3d8)
    throw InputError("the mesh has both CalculiX's C3D8 (plain integration) and Abaqus's (selectively reduced): one "
                     "Abaqus deck cannot carry both",
                     {mesh.source, 0, "FE model"});
  const int nn = static_cast<int>(mesh.nodes.size());
  auto element_entity = [](const fe::Element& e) {
    return std::string(fe::TypeName(e.type)) + " element " + std::to_string(e.id);
  };
  std::vector<bool> shell_or_beam_material(mesh.materials.size(), false);
  for (const fe::Element& e : mesh.elements) {
    for (int n : e.nodes)
      if (n < 0 || n >= nn) throw InputError("refers to a node that does not exist", {e.origin.file, e.origin.line, element_entity(e)});
    if (static_cast<int>(e.nodes.size()) != fe::NodeCount(e.type))
      throw InputError("wrong number of nodes", {e.origin.file, e.origin.line, element_entity(e)});
    if (fe::Traits(e.type).abaqus.empty() && e.type != fe::kHex8Selective)
      throw InputError(std::string("a ") + fe::Traits(e.type).description + " has no Abaqus element to be written as",
                       {e.origin.file, e.origin.line, element_entity(e)});
    int material = -1;
    if (IsShell(e.type)) {
      if (e.property < 0 || e.property >= static_cast<int>(mesh.shell_sections.size()))
        throw InputError("has no shell section", {e.origin.file, e.origin.line, element_entity(e)});
      const fe::ShellSection& s = mesh.shell_sections[e.property];
      if (s.laminate)
        throw InputError("a laminated section (" + s.laminate->card + ") cannot be written to an Abaqus deck",
                         {s.origin.file, s.origin.line, "shell section " + std::to_string(s.id)});
      if (s.nsm != 0.0)
        throw InputError("non-structural mass cannot be written to an Abaqus deck", {s.origin.file, s.origin.line, "shell section " + std::to_string(s.id)});
      material = s.material;
    } else if (IsBeam(e.type)) {
      if (e.property < 0 || e.property >= static_cast<int>(mesh.beam_sections.size()))
        throw InputError("has no beam section", {e.origin.file, e.origin.line, element_entity(e)});
      const fe::BeamSection& s = mesh.beam_sections[e.property];
      const std::string se = "beam section " + std::to_string(s.id);
      if (s.nsm != 0.0) throw InputError("non-structural mass cannot be written to an Abaqus deck", {s.origin.file, s.origin.line, se});
      if (s.HasAxisOffsets())
        throw InputError("a neutral axis or a non-structural mass off the beam axis (PBEAM N, M, NSI) cannot be "
                         "written to an Abaqus deck",
                         {s.origin.file, s.origin.line, se});
      if ((s.ky == 0.0) != (s.kz == 0.0))
        throw InputError("shear factors with one of ky, kz zero cannot be written", {s.origin.file, s.origin.line, se});
      if (s.ky == 0.0 && s.kz == 0.0 && !fe::Traits(e.type).translations_only && !HasEulerBernoulliName(e.type))
        throw InputError("a beam without shear flexibility (ky = kz = 0) has no Abaqus name for this element "
                         "(Abaqus's Euler-Bernoulli beam B33 has 2 nodes)",
                         {e.origin.file, e.origin.line, element_entity(e)});
      if (!e.offset_a.isZero(0.0) || !e.offset_b.isZero(0.0))
        throw InputError("beam end offsets cannot be written to an Abaqus deck", {e.origin.file, e.origin.line, element_entity(e)});
      material = s.material;
    } else {
      if (e.property < 0 || e.property >= static_cast<int>(mesh.solid_sections.size()))
        throw InputError("has no solid section", {e.origin.file, e.origin.line, element_entity(e)});
      material = mesh.solid_sections[e.property].material;
    }
    if (material < 0 || material >= static_cast<int>(mesh.materials.size()))
      throw InputError("its section has no material", {e.origin.file, e.origin.line, element_entity(e)});
    if (!IsSolid(e.type)) shell_or_beam_material[material] = true;
  }
  std::vector<std::string> material_name(mesh.materials.size());
  std::set<std::string> used_names;
  for (size_t k = 0; k < mesh.materials.size(); ++k) {
    const fe::Material& m = mesh.materials[k];
    const std::string entity = "material " + (m.name.empty() ? std::to_string(m.id) : m.name);
    const double g = m.E / (2.0 * (1.0 + m.nu));
    if (shell_or_beam_material[k] && m.G > 0.0 && std::abs(m.G - g) > 1e-12 * g)
      throw InputError("shear modulus G = " + Num(m.G) + " is not E / (2 (1 + nu)) = " + Num(g) +
                           "; an Abaqus isotropic material cannot carry it",
                       {m.origin.file, m.origin.line, entity});
    std::string name = m.name;
    if (name.empty() || used_names.count(Upper(name))) name = "MAT" + std::to_string(k + 1);
    while (used_names.count(Upper(name))) name += "_";
    used_names.insert(Upper(name));
    material_name[k] = Name(name, entity);
  }
  for (const fe::PointMass& pm : mesh.point_masses) {
    const std::string entity = "point mass " + std::to_string(pm.id);
    if (pm.node < 0 || pm.node >= nn) throw InputError("refers to a node that does not exist", {pm.origin.file, pm.origin.line, entity});
    if (!pm.offset.isZero(0.0))
      throw InputError("an offset point mass cannot be written to an Abaqus deck", {pm.origin.file, pm.origin.line, entity});
    if (pm.general)
      throw InputError("a general 6 x 6 nodal mass matrix (CONM1) cannot be written to an Abaqus deck",
                       {pm.origin.file, pm.origin.line, entity});
  }
  if (!mesh.springs.empty()) {
    const fe::ScalarSpring& sp = mesh.springs.front();
    throw InputError("scalar springs (CELAS1, CELAS2) cannot be written to an Abaqus deck yet",
                     {sp.origin.file, sp.origin.line, "scalar spring " + std::to_string(sp.id)});
  }
  for (const fe::RigidLink& l : mesh.rigid_links) {
    const std::string entity = "rigid link " + std::to_string(l.id);
    if (l.independent < 0 || l.independent >= nn || l.dofs <= 0 || l.dofs > 0b111111)
      throw InputError("bad independent node or component mask", {l.origin.file, l.origin.line, entity});
    for (int n : l.dependent)
      if (n < 0 || n >= nn) throw InputError("refers to a node that does not exist", {l.origin.file, l.origin.line, entity});
  }
  for (const fe::Constraint& c : mesh.constraints)
    if (c.node < 0 || c.node >= nn) throw InputError("refers to a node that does not exist", {c.origin.file, c.origin.line, "constraint"});
  for (const fe::LinearConstraint& row : mesh.linear_constraints) {
    bool ok = row.node >= 0 && row.node < nn && row.component >= 0 && row.component < 6;
    for (const fe::MpcTerm& t : row.terms) ok = ok && t.node >= 0 && t.node < nn && t.component >= 0 && t.component < 6;
    if (!ok)
      throw InputError("refers to a node or component that does not exist",
                       {row.origin.file, row.origin.line, row.card + " " + std::to_string(row.id)});
  }
  return material_name;
}

}  // namespace

void WriteAbaqus(const fe::Mesh& mesh, const std::string& path) {
  const std::vector<std::string> material_name = CheckWritable(mesh);
  const int nn = static_cast<int>(mesh.nodes.size());
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw InputError("cannot open for writing", {path, 0, ""});
  std::fprintf(f, "** written by flexmb from %s\n", mesh.source.empty() ? "a mesh built in memory" : mesh.source.c_str());
  // Abaqus's C3D8 (selectively reduced): the reader takes C3D8 as Abaqus's
  // under this line (WrittenByAbaqusCae), as CalculiX's without it
  if (std::any_of(mesh.elements.begin(), mesh.elements.end(),
                  [](const fe::Element& e) { return e.type == fe::kHex8Selective; }))
    std::fprintf(f, "** Generated by: Abaqus/CAE conventions (flexmb): C3D8 is Abaqus's selectively reduced "
                    "hexahedron\n");
  std::fprintf(f, "*NODE\n");
  for (const fe::Node& n : mesh.nodes)
    std::fprintf(f, "%d, %s, %s, %s\n", n.id, Num(n.x.x()).c_str(), Num(n.x.y()).c_str(), Num(n.x.z()).c_str());

  // runs of elements sharing type and section (and, for beams, orientation;
  // for shells, offset) get one *ELEMENT card and one section element set
  struct Group {
    const fe::Element* first;
    std::string elset;
  };
  std::vector<Group> groups;
  // names of the writer's own sets, distinct from the mesh's sets and each other
  std::set<std::string> taken;
  for (const auto& [name, set] : mesh.node_sets) taken.insert(Upper(name));
  for (const auto& [name, set] : mesh.element_sets) taken.insert(Upper(name));
  auto unique = [&](const std::string& base) {
    std::string name = base;
    for (int k = 2; taken.count(Upper(name)); ++k) name = base + "_" + std::to_string(k);
    taken.insert(Upper(name));
    return name;
  };
  std::map<std::string, int> group_of_key;
  int max_element_id = 0;
  const fe::Element* run_start = nullptr;
  std::string run_key;
  for (const fe::Element& e : mesh.elements) {
    max_element_id = std::max(max_element_id, e.id);
    std::string key = std::string(AbaqusType(mesh, e)) + "/" + std::to_string(e.property);
    if (IsBeam(e.type)) key += "/" + Num(e.orientation.x()) + "," + Num(e.orientation.y()) + "," + Num(e.orientation.z());
    if (IsShell(e.type)) key += "/" + Num(e.shell_offset);
    auto [it, fresh] = group_of_key.emplace(key, static_cast<int>(groups.size()));
    if (fresh) {
      const char* family = fe::FamilyName(fe::Traits(e.type).family);
      groups.push_back({&e, unique("flexmb_" + std::string(family) + "_section_" + std::to_string(e.property + 1))});
    }
    if (run_start == nullptr || key != run_key) {
      std::fprintf(f, "*ELEMENT, TYPE=%s, ELSET=%s\n", AbaqusType(mesh, e), groups[it->second].elset.c_str());
      run_start = &e;
      run_key = key;
    }
    // at most 16 entries per data line (Abaqus and CalculiX); a line ending
    // in a comma continues on the next (C3D20: 21 entries)
    std::fprintf(f, "%d", e.id);
    for (size_t k = 0; k < e.nodes.size(); ++k)
      std::fprintf(f, (k + 1) % 16 == 0 ? ",\n%d" : ", %d", mesh.nodes[e.nodes[k]].id);
    std::fprintf(f, "\n");
  }
  // point masses as MASS and ROTARYI elements: the mass keeps its id if no
  // element has it, ROTARYI elements get ids after all others
  std::set<int> used_ids;
  for (const fe::Element& e : mesh.elements) used_ids.insert(e.id);
  int next_id = max_element_id;
  for (const fe::PointMass& pm : mesh.point_masses) next_id = std::max(next_id, pm.id);
  std::vector<std::pair<int, int>> mass_ids(mesh.point_masses.size(), {0, 0});
  std::vector<std::string> mass_set(mesh.point_masses.size()), inertia_set(mesh.point_masses.size());
  for (size_t k = 0; k < mesh.point_masses.size(); ++k) {
    const fe::PointMass& pm = mesh.point_masses[k];
    const int node = mesh.nodes[pm.node].id;
    if (pm.mass != 0.0 || pm.inertia.isZero(0.0)) {
      mass_ids[k].first = pm.id > 0 && used_ids.insert(pm.id).second ? pm.id : ++next_id;
      used_ids.insert(mass_ids[k].first);
      mass_set[k] = unique("flexmb_mass_" + std::to_string(k + 1));
      std::fprintf(f, "*ELEMENT, TYPE=MASS, ELSET=%s\n%d, %d\n", mass_set[k].c_str(), mass_ids[k].first, node);
    }
    if (!pm.inertia.isZero(0.0)) {
      mass_ids[k].second = pm.mass == 0.0 && pm.id > 0 && used_ids.insert(pm.id).second ? pm.id : ++next_id;
      used_ids.insert(mass_ids[k].second);
      inertia_set[k] = unique("flexmb_inertia_" + std::to_string(k + 1));
      std::fprintf(f, "*ELEMENT, TYPE=ROTARYI, ELSET=%s\n%d, %d\n", inertia_set[k].c_str(), mass_ids[k].second, node);
    }
  }

  // sets of the mesh
  for (const auto& [name, nodes] : mesh.node_sets) {
    std::vector<int> ids;
    for (int n : nodes) {
      if (n < 0 || n >= nn) {
        std::fclose(f);
        throw InputError("refers to a node that does not exist", {"", 0, "node set " + name});
      }
      ids.push_back(mesh.nodes[n].id);
    }
    std::fprintf(f, "*NSET, NSET=%s\n", Name(name, "node set").c_str());
    WriteIds(f, ids);
  }
  for (const auto& [name, elements] : mesh.element_sets) {
    std::vector<int> ids;
    for (int e : elements) {
      if (e < 0 || e >= static_cast<int>(mesh.elements.size())) {
        std::fclose(f);
        throw InputError("refers to an element that does not exist", {"", 0, "element set " + name});
      }
      ids.push_back(mesh.elements[e].id);
    }
    std::fprintf(f, "*ELSET, ELSET=%s\n", Name(name, "element set").c_str());
    WriteIds(f, ids);
  }

  // materials
  for (size_t k = 0; k < mesh.materials.size(); ++k) {
    const fe::Material& m = mesh.materials[k];
    std::fprintf(f, "*MATERIAL, NAME=%s\n*ELASTIC\n%s, %s\n*DENSITY\n%s\n", material_name[k].c_str(), Num(m.E).c_str(),
                 Num(m.nu).c_str(), Num(m.rho).c_str());
  }

  // sections, one per group
  for (const Group& g : groups) {
    const fe::Element& e = *g.first;
    if (IsShell(e.type)) {
      const fe::ShellSection& s = mesh.shell_sections[e.property];
      std::fprintf(f, "*SHELL SECTION, ELSET=%s, MATERIAL=%s", g.elset.c_str(), material_name[s.material].c_str());
      if (e.shell_offset != 0.0) std::fprintf(f, ", OFFSET=%s", Num(-e.shell_offset / s.thickness).c_str());
      std::fprintf(f, "\n%s\n", Num(s.thickness).c_str());
    } else if (fe::Traits(e.type).translations_only) {
      // rods as trusses (T3D2): the area only
      const fe::BeamSection& s = mesh.beam_sections[e.property];
      if (s.J != 0.0)
        LogWarning(FormatWithContext("T3D2 elements carry no torsion: the rods' torsion constant J = " + Num(s.J) +
                                         " is not written",
                                     {s.origin.file, s.origin.line, "rod section " + std::to_string(s.id)}));
      std::fprintf(f, "*SOLID SECTION, ELSET=%s, MATERIAL=%s\n%s\n", g.elset.c_str(),
                   material_name[s.material].c_str(), Num(s.A).c_str());
    } else if (IsBeam(e.type)) {
      const fe::BeamSection& s = mesh.beam_sections[e.property];
      const fe::Material& m = mesh.materials[s.material];
      std::fprintf(f, "*BEAM GENERAL SECTION, ELSET=%s, SECTION=GENERAL, MATERIAL=%s\n", g.elset.c_str(),
                   material_name[s.material].c_str());
      std::fprintf(f, "%s, %s, %s, %s, %s\n", Num(s.A).c_str(), Num(s.Iy).c_str(), Num(s.Iyz).c_str(), Num(s.Iz).c_str(),
                   Num(s.J).c_str());
      std::fprintf(f, "%s, %s, %s\n", Num(e.orientation.x()).c_str(), Num(e.orientation.y()).c_str(),
                   Num(e.orientation.z()).c_str());
      if (s.ky > 0.0) {
        const double G = m.G > 0.0 ? m.G : m.E / (2.0 * (1.0 + m.nu));
        std::fprintf(f, "*TRANSVERSE SHEAR STIFFNESS\n%s, %s\n", Num(s.kz * G * s.A).c_str(), Num(s.ky * G * s.A).c_str());
      }
    } else {
      const fe::SolidSection& s = mesh.solid_sections[e.property];
      std::fprintf(f, "*SOLID SECTION, ELSET=%s, MATERIAL=%s\n", g.elset.c_str(), material_name[s.material].c_str());
    }
  }
  for (size_t k = 0; k < mesh.point_masses.size(); ++k) {
    const fe::PointMass& pm = mesh.point_masses[k];
    if (mass_ids[k].first) std::fprintf(f, "*MASS, ELSET=%s\n%s\n", mass_set[k].c_str(), Num(pm.mass).c_str());
    if (mass_ids[k].second) {
      const fe::Mat3& j = pm.inertia;
      std::fprintf(f, "*ROTARY INERTIA, ELSET=%s\n%s, %s, %s, %s, %s, %s\n", inertia_set[k].c_str(), Num(j(0, 0)).c_str(),
                   Num(j(1, 1)).c_str(), Num(j(2, 2)).c_str(), Num(j(0, 1)).c_str(), Num(j(0, 2)).c_str(),
                   Num(j(1, 2)).c_str());
    }
  }

  // rigid links
  for (size_t k = 0; k < mesh.rigid_links.size(); ++k) {
    const fe::RigidLink& l = mesh.rigid_links[k];
    std::vector<int> ids;
    for (int n : l.dependent) ids.push_back(mesh.nodes[n].id);
    const int ref = mesh.nodes[l.independent].id;
    const std::string set = unique("flexmb_link_" + std::to_string(k + 1));
    std::fprintf(f, "*NSET, NSET=%s\n", set.c_str());
    WriteIds(f, ids);
    if (l.dofs == 0b111111) {
      std::fprintf(f, "*RIGID BODY, NSET=%s, REF NODE=%d\n", set.c_str(), ref);
    } else {
      std::fprintf(f, "*SURFACE, NAME=%s_surface, TYPE=NODE\n%s\n", set.c_str(), set.c_str());
      std::fprintf(f, "*COUPLING, REF NODE=%d, SURFACE=%s_surface, CONSTRAINT NAME=%s\n*KINEMATIC\n", ref, set.c_str(),
                   set.c_str());
      for (int c = 0; c < 6; ++c)
        if (l.dofs & (1 << c)) std::fprintf(f, "%d, %d\n", c + 1, c + 1);
    }
  }

  // linear constraints (RBE3 rows) as *EQUATION, the dependent DOF first:
  // u_d - sum c_k u_k = 0
  for (const fe::LinearConstraint& row : mesh.linear_constraints) {
    std::fprintf(f, "*EQUATION\n%d\n", static_cast<int>(row.terms.size()) + 1);
    std::fprintf(f, "%d, %d, 1.", mesh.nodes[row.node].id, row.component + 1);
    int on_line = 1;
    for (const fe::MpcTerm& t : row.terms) {
      // at most four terms on a data line
      std::fprintf(f, on_line == 4 ? "\n" : ", ");
      on_line = on_line == 4 ? 1 : on_line + 1;
      std::fprintf(f, "%d, %d, %s", mesh.nodes[t.node].id, t.component + 1, Num(-t.coef).c_str());
    }
    std::fprintf(f, "\n");
  }

  // single-point constraints, as runs of consecutive components
  if (!mesh.constraints.empty()) std::fprintf(f, "*BOUNDARY\n");
  for (const fe::Constraint& c : mesh.constraints) {
    const int id = mesh.nodes[c.node].id;
    for (int k = 0; k < 6;) {
      if (!(c.dofs & (1 << k))) {
        ++k;
        continue;
      }
      int last = k;
      while (last + 1 < 6 && (c.dofs & (1 << (last + 1)))) ++last;
      std::fprintf(f, "%d, %d, %d\n", id, k + 1, last + 1);
      k = last + 1;
    }
  }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw InputError("cannot write the file", {path, 0, ""});
}

}  // namespace flexmb::io
