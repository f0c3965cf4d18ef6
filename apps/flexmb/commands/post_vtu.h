#pragma once
/// \file post_vtu.h
/// Per-element results of "flexmb post" and their ParaView file: the
/// undeformed FE mesh of the body (XML unstructured grid, ASCII) with the
/// results as cell data.

#include <string>
#include <vector>

#include "flexmb/durability/element_fatigue.h"
#include "flexmb/fe/mesh.h"

namespace flexmb::commands {

/// Results per mesh element (index as in fe::Mesh::elements); elements
/// without stress modes (beams) have has = 0 and zeros.
struct PostElementData {
  explicit PostElementData(int elements);
  /// Copies element k of an AnalyzeElements result into mesh element e.
  void Set(int e, const durability::ElementResults& r, int k, const durability::StressRecovery& rec);

  std::vector<int> has;               ///< 1 if the element has stress modes
  std::vector<double> max_vm;         ///< largest von Mises [Pa]
  std::vector<int> vm_instant;        ///< its instant
  std::vector<int> vm_point;          ///< its recovery point index
  std::vector<std::string> vm_point_name;  ///< its recovery point name
  std::vector<double> min_svm, max_svm;    ///< extremes of the signed von Mises [Pa]
  std::vector<double> max_p1, min_p3;      ///< extremes of the principal stresses [Pa]
  std::vector<double> range;          ///< range of the counted measure [Pa]
  std::vector<double> damage;         ///< Miner damage of the run
};

/// Writes `path`: the mesh with cell data element_id, has_stress,
/// max_von_mises, min_signed_von_mises, max_signed_von_mises,
/// max_principal, min_principal, range (Pa), damage and, if
/// damage_per_1000km_factor > 0, damage_per_1000km (= damage times the
/// factor). Throws InputError naming the path if it cannot be written.
void WritePostVtu(const std::string& path, const fe::Mesh& mesh, const PostElementData& data,
                  double damage_per_1000km_factor);

}  // namespace flexmb::commands
