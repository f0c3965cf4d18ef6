#include "flexmb/fe_io/nastran/nastran_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "flexmb/common/error.h"

namespace flexmb::io {
namespace {

// a real in at most `width` characters: the shortest text that reads back
// to the same double where it fits (with the decimal point Nastran needs),
// else as many digits as fit
std::string Real(double v, int width) {
  if (!std::isfinite(v)) throw InputError("value " + std::to_string(v) + " is not finite");
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  std::string text(buf, end);
  const size_t e = text.find('e');
  if (text.find('.') == std::string::npos) text.insert(e == std::string::npos ? text.size() : e, ".");
  if (static_cast<int>(text.size()) <= width) return text;
  for (int digits = width - 7; digits >= 1; --digits) {
    std::snprintf(buf, sizeof buf, "%.*E", digits, v);
    if (static_cast<int>(std::string(buf).size()) <= width) return buf;
  }
  throw InputError("value " + std::to_string(v) + " does not fit a Nastran field");
}

std::string Pad(const std::string& s, int width) {
  return s.size() >= static_cast<size_t>(width) ? s : s + std::string(static_cast<size_t>(width) - s.size(), ' ');
}

// a small-field card: name and fields of 8 characters, 8 fields per line,
// continuation lines starting with "+"
void SmallCard(std::ostream& out, const std::string& name, const std::vector<std::string>& fields) {
  out << Pad(name, 8);
  for (size_t k = 0; k < fields.size(); ++k) {
    if (k > 0 && k % 8 == 0) out << "\n+       ";
    if (fields[k].size() > 8) throw InputError(name + " field '" + fields[k] + "' is longer than 8 characters");
    out << Pad(fields[k], 8);
  }
  out << '\n';
}

// a large-field card: name* and fields of 16 characters, 4 per line,
// continuation lines starting with "*"
void LargeCard(std::ostream& out, const std::string& name, const std::vector<std::string>& fields) {
  out << Pad(name + "*", 8);
  for (size_t k = 0; k < fields.size(); ++k) {
    if (k > 0 && k % 4 == 0) out << "\n*       ";
    out << Pad(fields[k], 16);
  }
  out << '\n';
}

std::string Int(int v) { return std::to_string(v); }

// ids written for entities with source ids `ids`: kept when all are positive
// and unique, else 1, 2, ...
template <typename T>
std::vector<int> WrittenIds(const std::vector<T>& items) {
  std::vector<int> ids;
  std::set<int> seen;
  bool keep = true;
  for (const T& t : items) {
    ids.push_back(t.id);
    keep = keep && t.id > 0 && seen.insert(t.id).second;
  }
  if (!keep)
    for (size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(k) + 1;
  return ids;
}

void Refuse(const std::string& what, const fe::Mesh& mesh) {
  throw InputError("the Nastran writer cannot carry " + what + " (only shells, MAT1, RBE2 and node sets)",
                   {mesh.source, 0, "FE model"});
}

}  // namespace

void WriteNastranBulk(const fe::Mesh& mesh, const std::string& path, const NastranDeckExtras& extras) {
  if (!mesh.beam_sections.empty() || !mesh.solid_sections.empty()) Refuse("beam or solid sections", mesh);
  if (!mesh.point_masses.empty()) Refuse(std::to_string(mesh.point_masses.size()) + " point masses", mesh);
  if (!mesh.springs.empty()) Refuse(std::to_string(mesh.springs.size()) + " springs", mesh);
  if (!mesh.linear_constraints.empty()) Refuse("linear constraints (RBE3, MPC)", mesh);
  if (!mesh.constraints.empty()) Refuse("single-point constraints", mesh);
  for (const fe::Node& n : mesh.nodes)
    if (n.id <= 0) throw InputError("node id " + Int(n.id) + " is not positive", {mesh.source, 0, "FE model"});

  std::ostringstream out;
  out << "$ written by flexmb (WriteNastranBulk), SI units: m, kg, s, N, Pa\n";
  for (const std::string& c : extras.comments) out << "$ " << c << '\n';
  out << "BEGIN BULK\n";
  const std::vector<int> mid = WrittenIds(mesh.materials);
  for (size_t k = 0; k < mesh.materials.size(); ++k) {
    const fe::Material& m = mesh.materials[k];
    const double g_iso = m.E / (2.0 * (1.0 + m.nu));
    const bool own_g = m.G > 0.0 && std::abs(m.G - g_iso) > 1e-9 * g_iso;
    LargeCard(out, "MAT1", {Int(mid[k]), Real(m.E, 16), own_g ? Real(m.G, 16) : "", Real(m.nu, 16), Real(m.rho, 16)});
  }
  const std::vector<int> pid = WrittenIds(mesh.shell_sections);
  for (size_t k = 0; k < mesh.shell_sections.size(); ++k) {
    const fe::ShellSection& s = mesh.shell_sections[k];
    if (s.laminate)
      throw InputError("shell section " + Int(s.id) + " is laminated (" + s.laminate->card +
                           "): the Nastran writer writes PSHELL only",
                       {s.origin.file, s.origin.line, "shell section " + Int(s.id)});
    if (s.material < 0 || s.material >= static_cast<int>(mesh.materials.size()))
      throw InputError("shell section " + Int(s.id) + " has no material", {mesh.source, 0, "FE model"});
    const std::string m = Int(mid[static_cast<size_t>(s.material)]);
    LargeCard(out, "PSHELL", {Int(pid[k]), m, Real(s.thickness, 16), m, "", m, "", Real(s.nsm, 16)});
  }
  for (const fe::Node& n : mesh.nodes)
    LargeCard(out, "GRID", {Int(n.id), "", Real(n.x.x(), 16), Real(n.x.y(), 16), Real(n.x.z(), 16)});
  int max_eid = 0;
  for (const fe::Element& e : mesh.elements) {
    const std::string entity = "element " + Int(e.id);
    if (e.type != fe::ElementType::kQuad4 && e.type != fe::ElementType::kTria3) Refuse(entity + " (" + std::string(fe::TypeName(e.type)) + ": only 3- and 4-node shells are written)", mesh);
    if (e.id <= 0) throw InputError(entity + ": id is not positive", {mesh.source, 0, entity});
    if (e.property < 0 || e.property >= static_cast<int>(mesh.shell_sections.size()))
      throw InputError(entity + " has no shell section", {mesh.source, 0, entity});
    max_eid = std::max(max_eid, e.id);
    std::vector<std::string> f = {Int(e.id), Int(pid[static_cast<size_t>(e.property)])};
    for (int n : e.nodes) f.push_back(Int(mesh.nodes[static_cast<size_t>(n)].id));
    const std::string card = e.type == fe::ElementType::kQuad4 ? "CQUAD4" : "CTRIA3";
    if (e.shell_offset == 0.0) {
      SmallCard(out, card, f);
    } else {  // THETA/MCID blank, ZOFFS in large field
      f.push_back("");
      f.push_back(Real(e.shell_offset, 16));
      LargeCard(out, card, f);
    }
  }
  int eid = max_eid;
  for (const fe::RigidLink& r : mesh.rigid_links) {
    std::string cm;
    for (int c = 0; c < 6; ++c)
      if (r.dofs & (1 << c)) cm += static_cast<char>('1' + c);
    std::vector<std::string> f = {Int(++eid), Int(mesh.nodes[static_cast<size_t>(r.independent)].id), cm};
    for (int n : r.dependent) f.push_back(Int(mesh.nodes[static_cast<size_t>(n)].id));
    SmallCard(out, "RBE2", f);
  }
  int sid = 0;
  for (const auto& [name, nodes] : mesh.node_sets) {
    if (nodes.empty()) continue;
    out << "$ SET1 " << sid + 1 << ": node set " << name << '\n';
    std::vector<std::string> f = {Int(++sid)};
    for (int n : nodes) f.push_back(Int(mesh.nodes[static_cast<size_t>(n)].id));
    SmallCard(out, "SET1", f);
  }
  if (!extras.interface_nodes.empty()) {
    std::vector<std::string> f = {"123456"};
    for (int n : extras.interface_nodes) f.push_back(Int(mesh.nodes.at(static_cast<size_t>(n)).id));
    SmallCard(out, "ASET1", f);
  }
  out << "ENDDATA\n";
  std::ofstream file(path);
  file << out.str();
  file.close();
  if (!file) throw InputError("cannot write the Nastran deck", {path, 0, ""});
}

}  // namespace flexmb::io
