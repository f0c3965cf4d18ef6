#include "flexmb/fe/assembly.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/linear_constraint.h"
#include "flexmb/fe/point_mass.h"

namespace flexmb::fe {

namespace {

std::string Where(const Origin& o) {
  if (o.file.empty()) return "";
  return " (" + o.file + (o.line > 0 ? ":" + std::to_string(o.line) : std::string()) + ")";
}

// a membrane: a shell of a membrane section
bool IsMembrane(const Mesh& mesh, const Element& e) {
  if (Traits(e.type).family != ElementFamily::kShell) return false;
  if (e.property < 0 || e.property >= static_cast<int>(mesh.shell_sections.size())) return false;
  const ShellSection& s = mesh.shell_sections[static_cast<size_t>(e.property)];
  return s.laminate != nullptr && s.laminate->membrane_only;
}

std::string ElementName(const Element& e) {
  return std::string(TypeName(e.type)) + " element " + std::to_string(e.id);
}

[[noreturn]] void Fail(const Origin& o, const std::string& entity, const std::string& message) {
  throw InputError(message, {o.file, o.line, entity});
}

// free-DOF expansion of every full DOF: u_full[f] = sum coef * u_free[idx]
struct Expansion {
  std::vector<int> ptr, idx;
  std::vector<double> coef;
};

// the free DOF touched by one element or mass, and where each local DOF lands
struct BlockMap {
  std::vector<int> union_dofs;          // sorted free DOF indices
  std::vector<int> entry_ptr;           // local dof -> range in entry_pos/entry_coef
  std::vector<int> entry_pos;           // position in union_dofs
  std::vector<double> entry_coef;

  void Build(const int* full, int n, const Expansion& x) {
    union_dofs.clear();
    for (int i = 0; i < n; ++i) {
      if (full[i] < 0) continue;
      for (int k = x.ptr[full[i]]; k < x.ptr[full[i] + 1]; ++k) union_dofs.push_back(x.idx[k]);
    }
    std::sort(union_dofs.begin(), union_dofs.end());
    union_dofs.erase(std::unique(union_dofs.begin(), union_dofs.end()), union_dofs.end());
    entry_ptr.assign(n + 1, 0);
    entry_pos.clear();
    entry_coef.clear();
    for (int i = 0; i < n; ++i) {
      if (full[i] >= 0) {
        for (int k = x.ptr[full[i]]; k < x.ptr[full[i] + 1]; ++k) {
          entry_pos.push_back(static_cast<int>(
              std::lower_bound(union_dofs.begin(), union_dofs.end(), x.idx[k]) - union_dofs.begin()));
          entry_coef.push_back(x.coef[k]);
        }
      }
      entry_ptr[i + 1] = static_cast<int>(entry_pos.size());
    }
  }
};

// element inputs resolved from the mesh
struct Resolved {
  const Material* material = nullptr;
  const ShellSection* shell = nullptr;
  const BeamSection* beam = nullptr;
};

Resolved ResolveElement(const Mesh& mesh, const Element& e) {
  const std::string name = ElementName(e);
  const int nn = static_cast<int>(mesh.nodes.size());
  if (static_cast<int>(e.nodes.size()) != NodeCount(e.type)) {
    Fail(e.origin, name, "has " + std::to_string(e.nodes.size()) + " nodes, expected " +
                             std::to_string(NodeCount(e.type)));
  }
  for (int n : e.nodes) {
    if (n < 0 || n >= nn) Fail(e.origin, name, "refers to a node that does not exist (index " + std::to_string(n) + ")");
  }
  // the element's section in the list of its family, checked
  auto section = [&](const auto& list, const char* family) {
    if (e.property < 0 || e.property >= static_cast<int>(list.size())) {
      Fail(e.origin, name, std::string("has no ") + family + " section");
    }
    return &list[e.property];
  };
  Resolved r;
  int material = -1;
  switch (Traits(e.type).family) {
    case ElementFamily::kShell:
      r.shell = section(mesh.shell_sections, "shell");
      material = r.shell->material;
      break;
    case ElementFamily::kBeam:
      r.beam = section(mesh.beam_sections, "beam");
      material = r.beam->material;
      break;
    case ElementFamily::kSolid:
      material = section(mesh.solid_sections, "solid")->material;
      break;
  }
  if (r.shell != nullptr && r.shell->laminate && material < 0) return r;  // the plies carry the material
  if (material < 0 || material >= static_cast<int>(mesh.materials.size())) {
    Fail(e.origin, name,
         "its section has no material (a mesh read back from a body file has none for laminated shells, "
         "membranes and beams with PBEAM axis offsets: assemble the FE model itself)");
  }
  r.material = &mesh.materials[material];
  return r;
}

// M_full (assembly.h): element and point masses on the full numbering,
// before rigid-link elimination and constraints; pattern from the blocks'
// full DOF, values added block by block
class FullMassAssembler {
 public:
  FullMassAssembler(int n_full, const std::vector<int>& block_ptr, const std::vector<int>& block_full)
      : m_(n_full, n_full) {
    const int nb = static_cast<int>(block_ptr.size()) - 1;
    std::vector<int64_t> col_ptr(n_full + 1, 0);
    std::vector<int> dofs;
    auto block_dofs = [&](int b) {
      dofs.clear();
      for (int k = block_ptr[b]; k < block_ptr[b + 1]; ++k)
        if (block_full[k] >= 0) dofs.push_back(block_full[k]);
      std::sort(dofs.begin(), dofs.end());
      dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    };
    for (int b = 0; b < nb; ++b) {
      block_dofs(b);
      for (int q : dofs) col_ptr[q + 1] += static_cast<int64_t>(dofs.size());
    }
    for (int q = 0; q < n_full; ++q) col_ptr[q + 1] += col_ptr[q];
    std::vector<int> rows(col_ptr[n_full]);
    std::vector<int64_t> fill(col_ptr.begin(), col_ptr.end() - 1);
    for (int b = 0; b < nb; ++b) {
      block_dofs(b);
      for (int q : dofs) {
        std::copy(dofs.begin(), dofs.end(), rows.begin() + fill[q]);
        fill[q] += static_cast<int64_t>(dofs.size());
      }
    }
    std::vector<int> outer(n_full + 1, 0);
    int64_t nnz = 0;
    for (int q = 0; q < n_full; ++q) {
      auto first = rows.begin() + col_ptr[q], last = rows.begin() + col_ptr[q + 1];
      std::sort(first, last);
      last = std::unique(first, last);
      std::copy(first, last, rows.begin() + nnz);
      nnz += last - first;
      if (nnz > INT32_MAX) throw InputError("model too large: more than 2^31 stored mass matrix entries");
      outer[q + 1] = static_cast<int>(nnz);
    }
    m_.resizeNonZeros(nnz);
    std::copy(outer.begin(), outer.end(), m_.outerIndexPtr());
    std::copy(rows.begin(), rows.begin() + nnz, m_.innerIndexPtr());
    std::fill(m_.valuePtr(), m_.valuePtr() + nnz, 0.0);
  }

  // adds the symmetric part of one block's mass matrix (local DOF -> full[])
  void Add(const int* full, int n, const MatX& me) {
    order_.clear();
    for (int i = 0; i < n; ++i)
      if (full[i] >= 0) order_.emplace_back(full[i], i);
    std::sort(order_.begin(), order_.end());
    const int* outer = m_.outerIndexPtr();
    const int* inner = m_.innerIndexPtr();
    double* value = m_.valuePtr();
    for (const auto& [col, j] : order_) {
      int p = outer[col];
      for (const auto& [row, i] : order_) {
        while (inner[p] != row) ++p;
        value[p] += 0.5 * (me(i, j) + me(j, i));
      }
    }
  }

  SparseMat Take() { return std::move(m_); }

 private:
  SparseMat m_;
  std::vector<std::pair<int, int>> order_;
};

}  // namespace

bool ActsOnTranslationsOnly(const Mesh& mesh, const Element& e) {
  return Traits(e.type).translations_only || IsMembrane(mesh, e);
}

namespace {

// adds imported matrices (rows named by base.dofs.full) to an assembled
// model: K += Tb^T K_b Tb and M likewise, with Tb the rows of T (the
// expansion x) of the imported rows, and M_full += S M_b S^T with S the
// imported rows' places in the full numbering
void AddImported(const AssembledModel& base, const Expansion& x, AssembledModel& out) {
  const DofMap& dm = out.dofs;
  const int nb = static_cast<int>(base.K.rows());
  std::vector<int> full_of_row(static_cast<size_t>(nb), -1);
  for (size_t n = 0; n < base.dofs.full.size(); ++n)
    for (int c = 0; c < 6; ++c)
      if (base.dofs.full[n][c] >= 0) full_of_row[static_cast<size_t>(base.dofs.full[n][c])] = dm.full[n][c];
  std::vector<Eigen::Triplet<double, int>> t;
  for (int r = 0; r < nb; ++r) {
    const int f = full_of_row[static_cast<size_t>(r)];
    for (int k = x.ptr[f]; k < x.ptr[f + 1]; ++k) t.emplace_back(r, x.idx[k], x.coef[k]);
  }
  SparseMat Tb(nb, dm.n_free);
  Tb.setFromTriplets(t.begin(), t.end());
  t.clear();
  t.shrink_to_fit();
  const SparseMat Tbt = Tb.transpose();
  const bool full_is_free = dm.n_full == dm.n_free;
  // one product at a time; exactly symmetric, as the element blocks are added
  for (auto [a, sum] : {std::make_pair(&base.K, &out.K), std::make_pair(&base.M, &out.M)}) {
    SparseMat p = Tbt * (*a * Tb);
    const SparseMat pt = p.transpose();
    *sum = *sum + 0.5 * (p + pt);
    sum->makeCompressed();
  }
  if (full_is_free) {
    out.M_full = out.M;
    return;
  }
  t.clear();
  t.reserve(static_cast<size_t>(base.M.nonZeros()));
  for (int j = 0; j < base.M.outerSize(); ++j)
    for (SparseMat::InnerIterator it(base.M, j); it; ++it)
      t.emplace_back(full_of_row[static_cast<size_t>(it.row())], full_of_row[static_cast<size_t>(j)], it.value());
  SparseMat Mb(dm.n_full, dm.n_full);
  Mb.setFromTriplets(t.begin(), t.end());
  out.M_full = out.M_full + Mb;
  out.M_full.makeCompressed();
}

// Assemble and AssembleImported: `base`, when given, holds imported K and M
// on the rows base->dofs.full names (its node list may be shorter than the
// mesh's); the mesh's elements are then display cells and are not assembled
AssembledModel AssembleImpl(const Mesh& mesh, const AssemblyOptions& options, const AssembledModel* base) {
  const int nn = static_cast<int>(mesh.nodes.size());
  const int ne = base != nullptr ? 0 : static_cast<int>(mesh.elements.size());
  auto node_id = [&](int n) { return std::to_string(mesh.nodes[n].id); };

  // resolve elements, masses, links and constraints, checking every reference
  std::vector<Resolved> resolved(ne);
  for (int e = 0; e < ne; ++e) resolved[e] = ResolveElement(mesh, mesh.elements[e]);
  std::vector<Mat6> mass6(mesh.point_masses.size());
  for (size_t k = 0; k < mesh.point_masses.size(); ++k) {
    const PointMass& pm = mesh.point_masses[k];
    if (pm.node < 0 || pm.node >= nn) {
      Fail(pm.origin, "point mass " + std::to_string(pm.id), "refers to a node that does not exist");
    }
    mass6[k] = PointMassMatrix(pm);
  }
  for (const ScalarSpring& sp : mesh.springs) {
    const std::string name = "scalar spring " + std::to_string(sp.id);
    if (sp.node_a < 0 || sp.node_a >= nn || sp.node_b < -1 || sp.node_b >= nn)
      Fail(sp.origin, name, "refers to a node that does not exist");
    if (sp.directional) {
      for (int c = 0; c < 6; ++c)
        if (!std::isfinite(sp.coef_a[c]) || !std::isfinite(sp.coef_b[c])) Fail(sp.origin, name, "coefficients must be finite");
    } else {
      if (sp.component_a < 0 || sp.component_a > 5 || (sp.node_b >= 0 && (sp.component_b < 0 || sp.component_b > 5)))
        Fail(sp.origin, name, "component must be 0 to 5 (ux uy uz rx ry rz)");
      if (sp.node_a == sp.node_b && sp.component_a == sp.component_b)
        Fail(sp.origin, name, "connects a DOF to itself");
    }
    if (!std::isfinite(sp.k) || sp.k < 0.0) Fail(sp.origin, name, "stiffness must be finite and >= 0");
  }
  for (const RigidLink& link : mesh.rigid_links) {
    const std::string name = "rigid link " + std::to_string(link.id);
    if (link.independent < 0 || link.independent >= nn) {
      Fail(link.origin, name, "independent node does not exist");
    }
    if (link.dofs <= 0 || link.dofs > 0b111111) Fail(link.origin, name, "component mask must be a subset of 123456");
    if (link.dependent.empty()) Fail(link.origin, name, "has no dependent nodes");
    for (int d : link.dependent) {
      if (d < 0 || d >= nn) Fail(link.origin, name, "a dependent node does not exist (index " + std::to_string(d) + ")");
      if (d == link.independent) Fail(link.origin, name, "node " + node_id(d) + " is both independent and dependent");
    }
  }
  if (options.apply_constraints) {
    for (const Constraint& c : mesh.constraints) {
      if (c.node < 0 || c.node >= nn) Fail(c.origin, "constraint", "refers to a node that does not exist");
      if (c.dofs < 0 || c.dofs > 0b111111) Fail(c.origin, "constraint", "component mask must be a subset of 123456");
    }
  }
  for (int n : options.extra_fixed_nodes) {
    if (n < 0 || n >= nn) throw InputError("fixed node index " + std::to_string(n) + " does not exist in the mesh");
  }

  // active slots from elements (or imported rows) and masses
  std::vector<uint8_t> active(nn, 0);
  if (base != nullptr) {
    if (base->dofs.full.size() > static_cast<size_t>(nn))
      throw InputError("the imported matrices name " + std::to_string(base->dofs.full.size()) +
                           " nodes, the mesh has only " + std::to_string(nn),
                       {mesh.source, 0, ""});
    for (size_t n = 0; n < base->dofs.full.size(); ++n)
      for (int c = 0; c < 6; ++c)
        if (base->dofs.full[n][c] >= 0) active[n] |= 1 << c;
  }
  for (int k = 0; k < ne; ++k) {
    const Element& e = mesh.elements[k];
    const uint8_t mask = DofsPerNode(e.type) == 6 && !ActsOnTranslationsOnly(mesh, e) ? 0b111111 : 0b000111;
    for (int n : e.nodes) active[n] |= mask;
  }
  for (size_t k = 0; k < mesh.point_masses.size(); ++k) {
    for (int c = 0; c < 6; ++c) {
      if (mass6[k].row(c).cwiseAbs().maxCoeff() > 0.0) active[mesh.point_masses[k].node] |= 1 << c;
    }
  }
  for (const ScalarSpring& sp : mesh.springs) {
    if (sp.directional) {
      for (int c = 0; c < 6; ++c) {
        if (sp.coef_a[c] != 0.0) active[sp.node_a] |= 1 << c;
        if (sp.node_b >= 0 && sp.coef_b[c] != 0.0) active[sp.node_b] |= 1 << c;
      }
      continue;
    }
    active[sp.node_a] |= 1 << sp.component_a;
    if (sp.node_b >= 0) active[sp.node_b] |= 1 << sp.component_b;
  }

  // dependent slots: each at most once, never an independent node
  std::vector<std::array<int, 6>> owner(nn);
  for (auto& o : owner) o.fill(-1);
  for (size_t l = 0; l < mesh.rigid_links.size(); ++l) {
    const RigidLink& link = mesh.rigid_links[l];
    for (int d : link.dependent) {
      for (int c = 0; c < 6; ++c) {
        if (!(link.dofs & (1 << c))) continue;
        if (owner[d][c] >= 0) {
          const RigidLink& other = mesh.rigid_links[owner[d][c]];
          if (static_cast<size_t>(owner[d][c]) == l) {
            Fail(link.origin, "rigid link " + std::to_string(link.id), "lists dependent node " + node_id(d) + " twice");
          }
          Fail(link.origin, "rigid link " + std::to_string(link.id),
               "node " + node_id(d) + " component " + kDofComponentNames[c] +
                   " is already dependent in rigid link " + std::to_string(other.id) + Where(other.origin));
        }
        owner[d][c] = static_cast<int>(l);
      }
    }
  }
  for (const RigidLink& link : mesh.rigid_links) {
    for (int c = 0; c < 6; ++c) {
      const int o = owner[link.independent][c];
      if (o >= 0) {
        Fail(link.origin, "rigid link " + std::to_string(link.id),
             "independent node " + node_id(link.independent) + " is itself dependent in rigid link " +
                 std::to_string(mesh.rigid_links[o].id) + Where(mesh.rigid_links[o].origin));
      }
    }
  }
  // independent slots that dependent slots need: u_dep = u_ind - skew(r) theta_ind, theta_dep = theta_ind
  std::vector<uint8_t> from_links(nn, 0);
  for (const RigidLink& link : mesh.rigid_links) {
    const int a = link.independent;
    bool acts = false;
    for (int d : link.dependent) {
      const Vec3 r = mesh.nodes[d].x - mesh.nodes[a].x;
      for (int c = 0; c < 6; ++c) {
        if (!(link.dofs & active[d] & (1 << c))) continue;
        acts = true;
        from_links[a] |= 1 << c;
        if (c < 3) {
          const int j = (c + 1) % 3, k = (c + 2) % 3;
          // (theta x r)_c = theta_j r_k - theta_k r_j
          if (r[k] != 0.0) from_links[a] |= 1 << (3 + j);
          if (r[j] != 0.0) from_links[a] |= 1 << (3 + k);
        }
      }
    }
    if (!acts) {
      std::string digits;
      for (int c = 0; c < 6; ++c)
        if (link.dofs & (1 << c)) digits += static_cast<char>('1' + c);
      LogWarning("rigid link " + std::to_string(link.id) + Where(link.origin) +
                 " does nothing: none of its dependent nodes has a degree of freedom among the components " + digits +
                 " it links (the nodes of solids have translations 123 only)");
    }
  }
  for (int n = 0; n < nn; ++n) active[n] |= from_links[n];

  // fixed slots; a fixed slot may not be dependent
  std::vector<uint8_t> fixed(nn, 0);
  std::vector<const Origin*> fixed_origin(nn, nullptr);
  if (options.apply_constraints) {
    for (const Constraint& c : mesh.constraints) {
      fixed[c.node] |= c.dofs;
      fixed_origin[c.node] = &c.origin;
    }
  }
  for (int n : options.extra_fixed_nodes) fixed[n] = 0b111111;
  for (int n = 0; n < nn; ++n) {
    for (int c = 0; c < 6; ++c) {
      const int bit = 1 << c;
      if ((fixed[n] & active[n] & bit) && owner[n][c] >= 0) {
        const RigidLink& link = mesh.rigid_links[owner[n][c]];
        std::string by = fixed_origin[n] != nullptr && fixed_origin[n]->file.size() ? "a constraint" + Where(*fixed_origin[n])
                                                                                   : "a constraint";
        Fail(link.origin, "rigid link " + std::to_string(link.id),
             "dependent node " + node_id(n) + " component " + kDofComponentNames[c] + " is also fixed by " + by);
      }
    }
  }

  // linear constraints (RBE3 rows, MPC): each dependent slot owned once, no
  // chains; their dependent and independent slots are active
  std::vector<LinearConstraint> swapped;
  if (!options.independent_nodes.empty() && !mesh.linear_constraints.empty()) {
    for (int n : options.independent_nodes)
      if (n < 0 || n >= nn) throw InputError("independent node index " + std::to_string(n) + " does not exist");
    swapped = MakeNodesIndependent(mesh, mesh.linear_constraints, options.independent_nodes,
                                   [&](int n, int c) { return owner[n][c] < 0 && !(fixed[n] & (1 << c)); });
  }
  const std::vector<LinearConstraint>& mpcs = options.independent_nodes.empty() ? mesh.linear_constraints : swapped;
  std::vector<std::array<int, 6>> mpc_owner(nn);
  for (auto& o : mpc_owner) o.fill(-1);
  auto mpc_name = [&](const LinearConstraint& row) { return row.card + " " + std::to_string(row.id); };
  auto slot_name = [&](int n, int c) { return "node " + node_id(n) + " component " + kDofComponentNames[c]; };
  for (size_t k = 0; k < mpcs.size(); ++k) {
    const LinearConstraint& row = mpcs[k];
    if (row.node < 0 || row.node >= nn) Fail(row.origin, mpc_name(row), "dependent node does not exist");
    if (row.component < 0 || row.component > 5) Fail(row.origin, mpc_name(row), "component must be 0 to 5");
    const int n = row.node, c = row.component;
    if (owner[n][c] >= 0) {
      const RigidLink& other = mesh.rigid_links[owner[n][c]];
      Fail(row.origin, mpc_name(row),
           slot_name(n, c) + " is already dependent in rigid link " + std::to_string(other.id) + Where(other.origin));
    }
    if (mpc_owner[n][c] >= 0) {
      const LinearConstraint& other = mpcs[mpc_owner[n][c]];
      Fail(row.origin, mpc_name(row),
           slot_name(n, c) + " is already dependent in " + mpc_name(other) + Where(other.origin));
    }
    if (fixed[n] & (1 << c)) {
      const std::string by = fixed_origin[n] != nullptr && fixed_origin[n]->file.size()
                                 ? "a constraint" + Where(*fixed_origin[n])
                                 : "a constraint";
      Fail(row.origin, mpc_name(row), "dependent " + slot_name(n, c) + " is also fixed by " + by);
    }
    mpc_owner[n][c] = static_cast<int>(k);
    active[n] |= 1 << c;
  }
  for (const LinearConstraint& row : mpcs) {
    for (const MpcTerm& t : row.terms) {
      if (t.node < 0 || t.node >= nn || t.component < 0 || t.component > 5)
        Fail(row.origin, mpc_name(row), "an independent DOF does not exist");
      if (!std::isfinite(t.coef)) Fail(row.origin, mpc_name(row), "a coefficient is not finite");
      const int o = owner[t.node][t.component], m = mpc_owner[t.node][t.component];
      if (o >= 0 || m >= 0) {
        const std::string other = o >= 0 ? "rigid link " + std::to_string(mesh.rigid_links[o].id) + Where(mesh.rigid_links[o].origin)
                                         : mpc_name(mpcs[m]) + Where(mpcs[m].origin);
        Fail(row.origin, mpc_name(row),
             "independent " + slot_name(t.node, t.component) + " is itself dependent in " + other +
                 " (chained constraints are not supported)");
      }
      active[t.node] |= 1 << t.component;
    }
  }
  for (const RigidLink& link : mesh.rigid_links) {
    for (int c = 0; c < 6; ++c) {
      const int m = mpc_owner[link.independent][c];
      if (m >= 0)
        Fail(link.origin, "rigid link " + std::to_string(link.id),
             "independent node " + node_id(link.independent) + " is itself dependent in " + mpc_name(mpcs[m]) +
                 Where(mpcs[m].origin) + " (chained constraints are not supported)");
    }
  }

  // numbering, node by node
  AssembledModel out;
  DofMap& dm = out.dofs;
  dm.full.assign(nn, {-1, -1, -1, -1, -1, -1});
  dm.free.assign(nn, {-1, -1, -1, -1, -1, -1});
  dm.node_ids.resize(nn);
  for (int n = 0; n < nn; ++n) dm.node_ids[n] = mesh.nodes[n].id;
  for (int n = 0; n < nn; ++n) {
    for (int c = 0; c < 6; ++c) {
      if (!(active[n] & (1 << c))) continue;
      dm.full[n][c] = dm.n_full++;
      if (!(fixed[n] & (1 << c)) && owner[n][c] < 0 && mpc_owner[n][c] < 0) dm.free[n][c] = dm.n_free++;
    }
  }

  // full -> free expansion (rows of T)
  Expansion x;
  x.ptr.assign(dm.n_full + 1, 0);
  x.idx.reserve(dm.n_full);
  x.coef.reserve(dm.n_full);
  for (int n = 0; n < nn; ++n) {
    for (int c = 0; c < 6; ++c) {
      const int f = dm.full[n][c];
      if (f < 0) continue;
      if (dm.free[n][c] >= 0) {
        x.idx.push_back(dm.free[n][c]);
        x.coef.push_back(1.0);
      } else if (owner[n][c] >= 0) {
        const int a = mesh.rigid_links[owner[n][c]].independent;
        if (dm.free[a][c] >= 0) {
          x.idx.push_back(dm.free[a][c]);
          x.coef.push_back(1.0);
        }
        if (c < 3) {
          const Vec3 r = mesh.nodes[n].x - mesh.nodes[a].x;
          const int j = (c + 1) % 3, k = (c + 2) % 3;
          if (r[k] != 0.0 && dm.free[a][3 + j] >= 0) {
            x.idx.push_back(dm.free[a][3 + j]);
            x.coef.push_back(r[k]);
          }
          if (r[j] != 0.0 && dm.free[a][3 + k] >= 0) {
            x.idx.push_back(dm.free[a][3 + k]);
            x.coef.push_back(-r[j]);
          }
        }
      } else if (mpc_owner[n][c] >= 0) {
        // a fixed independent DOF contributes nothing
        for (const MpcTerm& t : mpcs[mpc_owner[n][c]].terms) {
          if (dm.free[t.node][t.component] < 0) continue;
          x.idx.push_back(dm.free[t.node][t.component]);
          x.coef.push_back(t.coef);
        }
      }
      x.ptr[f + 1] = static_cast<int>(x.idx.size());
    }
  }
  {
    std::vector<Eigen::Triplet<double, int>> t;
    t.reserve(x.idx.size());
    for (int f = 0; f < dm.n_full; ++f) {
      for (int k = x.ptr[f]; k < x.ptr[f + 1]; ++k) t.emplace_back(f, x.idx[k], x.coef[k]);
    }
    out.T.resize(dm.n_full, dm.n_free);
    out.T.setFromTriplets(t.begin(), t.end());
  }

  // local -> full DOF of each block (elements first, then point masses, then springs)
  const int np = static_cast<int>(mesh.point_masses.size());
  const int nb = ne + np + static_cast<int>(mesh.springs.size());
  std::vector<int> block_ptr(nb + 1, 0), block_full;
  for (int e = 0; e < ne; ++e) {
    const Element& el = mesh.elements[e];
    const int dpn = DofsPerNode(el.type);
    // rods: their torsion only where all rotations of all its nodes are
    // active; membranes and shear panels: never (their rotational terms come
    // only from the rigid offsets of warped corners, which must not depend
    // on the neighbours)
    const bool translations = ActsOnTranslationsOnly(mesh, el);
    bool rotations = !(translations && Traits(el.type).family == ElementFamily::kShell);
    if (translations)
      for (int n : el.nodes)
        for (int c = 3; c < 6; ++c) rotations = rotations && dm.full[n][c] >= 0;
    for (int n : el.nodes) {
      for (int c = 0; c < dpn; ++c) block_full.push_back(c < 3 || rotations ? dm.full[n][c] : -1);
    }
    block_ptr[e + 1] = static_cast<int>(block_full.size());
  }
  for (size_t k = 0; k < mesh.point_masses.size(); ++k) {
    for (int c = 0; c < 6; ++c) block_full.push_back(dm.full[mesh.point_masses[k].node][c]);
    block_ptr[ne + k + 1] = static_cast<int>(block_full.size());
  }
  for (size_t k = 0; k < mesh.springs.size(); ++k) {
    const ScalarSpring& sp = mesh.springs[k];
    if (sp.directional) {
      // all six DOF of each end
      for (int c = 0; c < 6; ++c) block_full.push_back(dm.full[sp.node_a][c]);
      if (sp.node_b >= 0)
        for (int c = 0; c < 6; ++c) block_full.push_back(dm.full[sp.node_b][c]);
    } else {
      block_full.push_back(dm.full[sp.node_a][sp.component_a]);
      if (sp.node_b >= 0) block_full.push_back(dm.full[sp.node_b][sp.component_b]);
    }
    block_ptr[ne + np + k + 1] = static_cast<int>(block_full.size());
  }
  // blocks outside the subset: no DOF, so neither pattern nor values
  if (!options.block_subset.empty()) {
    if (static_cast<int>(options.block_subset.size()) != nb) {
      throw InputError("assembly: the block subset has " + std::to_string(options.block_subset.size()) +
                       " entries for " + std::to_string(nb) + " blocks");
    }
    for (int b = 0; b < nb; ++b) {
      if (!options.block_subset[b]) std::fill(block_full.begin() + block_ptr[b], block_full.begin() + block_ptr[b + 1], -1);
    }
  }

  // sparsity pattern: count, fill, sort and unique per column
  const int nf = dm.n_free;
  BlockMap bm;
  std::vector<int64_t> col_ptr(nf + 1, 0);
  for (int b = 0; b < nb; ++b) {
    bm.Build(block_full.data() + block_ptr[b], block_ptr[b + 1] - block_ptr[b], x);
    for (int q : bm.union_dofs) col_ptr[q + 1] += static_cast<int64_t>(bm.union_dofs.size());
  }
  for (int q = 0; q < nf; ++q) col_ptr[q + 1] += col_ptr[q];
  std::vector<int> rows(col_ptr[nf]);
  {
    std::vector<int64_t> fill(col_ptr.begin(), col_ptr.end() - 1);
    for (int b = 0; b < nb; ++b) {
      bm.Build(block_full.data() + block_ptr[b], block_ptr[b + 1] - block_ptr[b], x);
      for (int q : bm.union_dofs) {
        std::copy(bm.union_dofs.begin(), bm.union_dofs.end(), rows.begin() + fill[q]);
        fill[q] += static_cast<int64_t>(bm.union_dofs.size());
      }
    }
  }
  std::vector<int> outer(nf + 1, 0);
  int64_t nnz = 0;
  for (int q = 0; q < nf; ++q) {
    auto first = rows.begin() + col_ptr[q], last = rows.begin() + col_ptr[q + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    const int64_t count = last - first;
    std::copy(first, last, rows.begin() + nnz);
    nnz += count;
    if (nnz > INT32_MAX) throw InputError("model too large: more than 2^31 stored matrix entries");
    outer[q + 1] = static_cast<int>(nnz);
  }
  for (SparseMat* a : {&out.K, &out.M}) {
    a->resize(nf, nf);
    a->resizeNonZeros(nnz);
    std::copy(outer.begin(), outer.end(), a->outerIndexPtr());
    std::copy(rows.begin(), rows.begin() + nnz, a->innerIndexPtr());
    std::fill(a->valuePtr(), a->valuePtr() + nnz, 0.0);
  }
  rows.clear();
  rows.shrink_to_fit();
  // M_full is M itself when T is the identity (no dependent or fixed DOF)
  const bool full_is_free = dm.n_full == dm.n_free;
  std::optional<FullMassAssembler> full_mass;
  if (!full_is_free) full_mass.emplace(dm.n_full, block_ptr, block_full);

  // element matrices, reduced to the block's free DOF and added
  const int* inner = out.K.innerIndexPtr();
  double* kv = out.K.valuePtr();
  double* mv = out.M.valuePtr();
  MatX ke, me, kl, ml;
  std::vector<Vec3> coords;
  for (int b = 0; b < nb; ++b) {
    if (!options.block_subset.empty() && !options.block_subset[b]) continue;
    const int* full = block_full.data() + block_ptr[b];
    const int n = block_ptr[b + 1] - block_ptr[b];
    if (b < ne) {
      const Element& el = mesh.elements[b];
      coords.clear();
      for (int node : el.nodes) coords.push_back(mesh.nodes[node].x);
      ElementInput in;
      in.element = &el;
      in.x = coords.data();
      in.material = resolved[b].material;
      in.shell = resolved[b].shell;
      in.beam = resolved[b].beam;
      in.mass_form = options.mass_form;
      ElementMatrices(in, ke, me);
    } else if (b < ne + np) {
      ke.setZero(6, 6);
      me = mass6[b - ne];
    } else {
      // k (u_a - u_b)^2 / 2, or k u_a^2 / 2 to ground
      const ScalarSpring& sp = mesh.springs[b - ne - np];
      if (sp.directional) {
        // k (g_a - g_b)^2 / 2, g = coef . u
        Eigen::VectorXd v(n);
        for (int c = 0; c < 6; ++c) {
          v(c) = sp.coef_a[c];
          if (n == 12) v(6 + c) = -sp.coef_b[c];
        }
        ke.noalias() = sp.k * v * v.transpose();
      } else {
        ke.setConstant(n, n, -sp.k);
        ke.diagonal().setConstant(sp.k);
      }
      me.setZero(n, n);
    }
    if (full_mass) full_mass->Add(full, n, me);
    bm.Build(full, n, x);
    const int u = static_cast<int>(bm.union_dofs.size());
    if (u == 0) continue;
    kl.setZero(u, u);
    ml.setZero(u, u);
    for (int j = 0; j < n; ++j) {
      for (int qj = bm.entry_ptr[j]; qj < bm.entry_ptr[j + 1]; ++qj) {
        const int pj = bm.entry_pos[qj];
        const double cj = bm.entry_coef[qj];
        for (int i = 0; i < n; ++i) {
          const double kij = ke(i, j), mij = me(i, j);
          if (kij == 0.0 && mij == 0.0) continue;
          for (int qi = bm.entry_ptr[i]; qi < bm.entry_ptr[i + 1]; ++qi) {
            const double c = bm.entry_coef[qi] * cj;
            kl(bm.entry_pos[qi], pj) += c * kij;
            ml(bm.entry_pos[qi], pj) += c * mij;
          }
        }
      }
    }
    for (int q = 0; q < u; ++q) {
      const int col = bm.union_dofs[q];
      int p = outer[col];
      for (int r = 0; r < u; ++r) {
        while (inner[p] != bm.union_dofs[r]) ++p;
        kv[p] += 0.5 * (kl(r, q) + kl(q, r));
        mv[p] += 0.5 * (ml(r, q) + ml(q, r));
      }
    }
  }
  out.M_full = full_mass ? full_mass->Take() : out.M;
  if (base != nullptr) AddImported(*base, x, out);
  return out;
}

}  // namespace

AssembledModel Assemble(const Mesh& mesh, const AssemblyOptions& options) { return AssembleImpl(mesh, options, nullptr); }

AssembledModel AssembleImported(const Mesh& mesh, const AssembledModel& matrices, const AssemblyOptions& options) {
  if (!options.block_subset.empty()) throw InputError("imported matrices cannot be assembled block by block");
  // as io::ReadImportedMatrices builds them: rows numbered as they are (full = free, T = I)
  if (matrices.dofs.full != matrices.dofs.free || matrices.dofs.n_full != matrices.dofs.n_free ||
      matrices.dofs.n_free != matrices.K.rows() || matrices.T.rows() != matrices.T.cols() ||
      matrices.T.nonZeros() != matrices.T.rows())
    throw InputError("the imported matrices must come as read, every row a free DOF (T the identity)",
                     {mesh.source, 0, ""});
  const size_t n = static_cast<size_t>(matrices.K.rows());
  if (matrices.K.cols() != matrices.K.rows() || matrices.M.rows() != matrices.K.rows() ||
      matrices.M.cols() != matrices.K.cols())
    throw InputError("the imported K and M differ in size");
  std::vector<char> seen(n, 0);
  for (const auto& node : matrices.dofs.full)
    for (int r : node)
      if (r >= 0) {
        if (static_cast<size_t>(r) >= n || seen[static_cast<size_t>(r)])
          throw InputError("the imported matrices' DOF map names row " + std::to_string(r + 1) + " twice or beyond " +
                           std::to_string(n));
        seen[static_cast<size_t>(r)] = 1;
      }
  if (std::count(seen.begin(), seen.end(), 0) > 0)
    throw InputError("a row of the imported matrices belongs to no node of the DOF map");
  return AssembleImpl(mesh, options, &matrices);
}

}  // namespace flexmb::fe
