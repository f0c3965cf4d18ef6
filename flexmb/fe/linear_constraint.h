#pragma once
/// \file linear_constraint.h
/// Linear multi-point constraints (fe::LinearConstraint, mesh.h): the rows
/// of an RBE3 interpolation element, and the exchange of dependent and
/// independent DOF that lets an RBE3 reference node be an interface node
/// (Nastran's UM). Formulation: docs/design.md, "RBE3 and linear
/// multi-point constraints".

#include <functional>
#include <string>
#include <vector>

#include "flexmb/fe/mesh.h"

namespace flexmb::fe {

/// One weight group of an RBE3: components `components` (bit mask, bit k =
/// DOF k+1) of the nodes `nodes` enter the fit with weight `weight`.
struct Rbe3Group {
  double weight = 1.0;            ///< > 0
  int components = 0b111;         ///< mask of 1..6
  std::vector<int> nodes;         ///< node indices
};

/// An RBE3 element: the components `ref_components` of node `ref_node`
/// follow the weighted least-squares rigid motion of the groups.
struct Rbe3Spec {
  int id = 0;                     ///< element id (EID)
  std::string card = "RBE3";      ///< card name for messages and the rows ("*COUPLING")
  int ref_node = -1;              ///< node index of the reference (dependent) grid
  int ref_components = 0b111111;  ///< REFC mask
  std::vector<Rbe3Group> groups;
  Origin origin;
};

/// The rows u_ref,c = sum_k G(c, k) u_k, one per component c of REFC, of
/// the fit G = A^-1 S^T W (design.md): S the rigid-body map of each
/// independent DOF from the reference point, W the weights (rotational
/// components weighted w Lc^2, Lc the mean distance of the independent
/// nodes from the reference node). Throws InputError (naming the card)
/// when the independent components cannot carry every rigid motion of the
/// reference node (A singular: collinear nodes with translations only, say),
/// when a weight is not positive, or when the reference node is independent.
std::vector<LinearConstraint> Rbe3Constraints(const Mesh& mesh, const Rbe3Spec& spec);

/// `constraints` with the dependent DOF of the nodes `nodes` made
/// independent: for every constraint card (same id and card name) whose rows
/// make k components of such a node dependent, k of its independent DOF
/// (chosen by column-pivoted QR among those `eligible(node, component)`
/// allows, never one of `nodes`, a dependent DOF or an independent DOF of
/// another card) become dependent instead, u_P = C_P^-1
/// (u_D - C_R u_R), an exact rewriting of the same constraint. Throws
/// InputError if no such choice exists.
std::vector<LinearConstraint> MakeNodesIndependent(const Mesh& mesh, const std::vector<LinearConstraint>& constraints,
                                                   const std::vector<int>& nodes,
                                                   const std::function<bool(int, int)>& eligible);

}  // namespace flexmb::fe
