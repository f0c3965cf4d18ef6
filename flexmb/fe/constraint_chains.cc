#include "flexmb/fe/constraint_chains.h"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/common/error.h"

namespace flexmb::fe {

namespace {

using ChainDof = std::pair<int, int>;  // node index, component

// the rows of a rigid link: u_d = u_i + theta_i x r, theta_d = theta_i
void ChainLinkRows(const Mesh& mesh, const RigidLink& link, std::vector<LinearConstraint>& rows) {
  for (int d : link.dependent) {
    const Vec3 r = mesh.nodes[d].x - mesh.nodes[link.independent].x;
    for (int c = 0; c < 6; ++c) {
      if (!(link.dofs & (1 << c))) continue;
      LinearConstraint row;
      row.id = link.id;
      row.card = "rigid link";
      row.node = d;
      row.component = c;
      row.origin = link.origin;
      row.terms.push_back(MpcTerm{link.independent, c, 1.0});
      if (c < 3) {
        // (theta x r)_c = theta_j r_k - theta_k r_j
        const int j = (c + 1) % 3, k = (c + 2) % 3;
        if (r[k] != 0.0) row.terms.push_back(MpcTerm{link.independent, 3 + j, r[k]});
        if (r[j] != 0.0) row.terms.push_back(MpcTerm{link.independent, 3 + k, -r[j]});
      }
      rows.push_back(std::move(row));
    }
  }
}

std::string ChainName(const LinearConstraint& row) {
  return row.card + " " + std::to_string(row.id) + " (" + row.origin.file + ":" + std::to_string(row.origin.line) + ")";
}

// substitutes the dependent DOF among the terms of row r (depth first)
void ChainExpand(std::vector<LinearConstraint>& rows, const std::map<ChainDof, int>& owner, std::vector<int>& state,
                 std::vector<int>& path, int r) {
  if (state[r] == 2) return;
  state[r] = 1;
  path.push_back(r);
  std::map<ChainDof, double> sum;
  std::vector<ChainDof> order;
  auto add = [&](const ChainDof& dof, double coef) {
    if (sum.emplace(dof, 0.0).second) order.push_back(dof);
    sum[dof] += coef;
  };
  for (const MpcTerm& t : rows[r].terms) {
    const auto it = owner.find({t.node, t.component});
    if (it == owner.end()) {
      add({t.node, t.component}, t.coef);
      continue;
    }
    const int o = it->second;
    if (state[o] == 1) {
      std::string loop;
      for (size_t k = 0; k < path.size(); ++k)
        if (loop.size() || path[k] == o) loop += ChainName(rows[path[k]]) + " -> ";
      loop += ChainName(rows[o]);
      const Origin& at = rows[r].origin;
      throw InputError("constraints form a loop (each moves an independent DOF of the next): " + loop,
                       ErrorContext{at.file, at.line, rows[r].card + " " + std::to_string(rows[r].id)});
    }
    ChainExpand(rows, owner, state, path, o);
    for (const MpcTerm& u : rows[o].terms) add({u.node, u.component}, t.coef * u.coef);
  }
  std::vector<MpcTerm> terms;
  for (const ChainDof& dof : order)
    if (sum[dof] != 0.0) terms.push_back(MpcTerm{dof.first, dof.second, sum[dof]});
  rows[r].terms = std::move(terms);
  path.pop_back();
  state[r] = 2;
}

}  // namespace

void ResolveConstraintChains(Mesh& mesh) {
  std::set<ChainDof> used;
  std::set<int> dependent_nodes;
  for (const RigidLink& link : mesh.rigid_links)
    for (int d : link.dependent) dependent_nodes.insert(d);
  for (const LinearConstraint& row : mesh.linear_constraints) {
    dependent_nodes.insert(row.node);
    for (const MpcTerm& t : row.terms) used.insert({t.node, t.component});
  }
  // links in a chain become rows, until no further link is touched
  std::vector<char> convert(mesh.rigid_links.size(), 0);
  bool changed = true;
  while (changed) {
    changed = false;
    for (size_t l = 0; l < mesh.rigid_links.size(); ++l) {
      if (convert[l]) continue;
      const RigidLink& link = mesh.rigid_links[l];
      bool chained = dependent_nodes.count(link.independent) > 0;
      for (int d : link.dependent)
        for (int c = 0; c < 6; ++c) chained = chained || ((link.dofs & (1 << c)) && used.count({d, c}));
      if (!chained) continue;
      convert[l] = 1;
      changed = true;
      for (int c = 0; c < 6; ++c) used.insert({link.independent, c});
    }
  }
  std::vector<LinearConstraint> rows = mesh.linear_constraints;
  std::vector<RigidLink> kept;
  for (size_t l = 0; l < mesh.rigid_links.size(); ++l) {
    if (convert[l]) {
      ChainLinkRows(mesh, mesh.rigid_links[l], rows);
    } else {
      kept.push_back(mesh.rigid_links[l]);
    }
  }
  // substitution; a DOF dependent twice is left to the assembly's message
  std::map<ChainDof, int> owner;
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) owner.emplace(ChainDof{rows[r].node, rows[r].component}, r);
  bool any = false;
  for (const LinearConstraint& row : rows)
    for (const MpcTerm& t : row.terms) any = any || owner.count({t.node, t.component}) > 0;
  if (!any && kept.size() == mesh.rigid_links.size()) return;
  std::vector<int> state(rows.size(), 0), path;
  for (int r = 0; r < static_cast<int>(rows.size()); ++r) ChainExpand(rows, owner, state, path, r);
  mesh.rigid_links = std::move(kept);
  mesh.linear_constraints = std::move(rows);
}

}  // namespace flexmb::fe
