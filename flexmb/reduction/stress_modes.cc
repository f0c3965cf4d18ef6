#include "flexmb/reduction/stress_modes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_matrices.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/element_common.h"
#include "flexmb/fe/elements/rod2.h"
#include "flexmb/reduction/element_input.h"
#include "flexmb/reduction/parallel_rows.h"

namespace flexmb::reduction {
namespace {

// stress tables in the order of fe::ElementFamily
constexpr int kStressFamilies = 3;

int FamilyOf(fe::ElementType type) { return static_cast<int>(fe::Traits(type).family); }

// recovery matrix (element dof -> the table's values of one element) and frame
void Recovery(const fe::ElementInput& in, MatX& S, Mat3& axes) {
  axes.setIdentity();
  fe::Traits(in.element->type).stress(in, S, axes);
}

StressTable MakeTable(const char* name, std::vector<std::string> components,
                      std::vector<std::string> locations) {
  StressTable t;
  t.name = name;
  t.components = std::move(components);
  t.locations = std::move(locations);
  return t;
}

// the rows of `modes` of element `el`'s DOF (dpn per node) into ue
void ElementModeRows(const fe::Element& el, const MatX& modes, MatX& ue) {
  const int dpn = fe::DofsPerNode(el.type);
  const int nodes = static_cast<int>(el.nodes.size());
  ue.resize(dpn * nodes, modes.cols());
  for (int i = 0; i < nodes; ++i)
    ue.middleRows(dpn * i, dpn) = modes.middleRows(6 * static_cast<Eigen::Index>(el.nodes[i]), dpn);
}

// the solid_node table (StressModes::solid_node) of the solid elements
// `solids`: each corner's stress rows, the last corner repeated up to the
// most corners any of them has
StressTable SolidNodeTable(const fe::Mesh& mesh, const MatX& modes, const std::vector<int>& solids,
                           const std::vector<char>* subset) {
  int most = 0;
  for (int e : solids) most = std::max(most, fe::Traits(mesh.elements[e].type).corners);
  std::vector<std::string> locations;
  for (int c = 0; c < most; ++c) locations.push_back("n" + std::to_string(c + 1));
  StressTable t = MakeTable("solid_node", {"sxx", "syy", "szz", "sxy", "syz", "szx"}, locations);
  t.elements = solids;
  t.axes.assign(solids.size(), Mat3::Identity());
  t.modes.resize(t.Row(static_cast<int>(solids.size()), 0, 0), modes.cols());
  if (subset != nullptr) {
    t.modes.setZero();
    for (size_t k = 0; k < solids.size(); ++k)
      if (!(*subset)[solids[k]]) t.axes[k].setZero();
  }
  if (modes.cols() == 0) return t;
  const int ns = static_cast<int>(solids.size());
  ParallelRows(ns, ParallelRanges(ns, 512), [&](int, Eigen::Index begin, Eigen::Index end) {
    std::vector<Vec3> x;
    MatX S, ue;
    for (Eigen::Index k = begin; k < end; ++k) {
      if (subset != nullptr && !(*subset)[solids[k]]) continue;
      const fe::Element& el = mesh.elements[solids[k]];
      const fe::ElementInput in = ResolveElementInput(mesh, el, x);
      fe::Traits(el.type).corner_stress(in, S);
      ElementModeRows(el, modes, ue);
      const int corners = static_cast<int>(S.rows() / 6);
      const int kk = static_cast<int>(k);
      for (int c = 0; c < corners; ++c)
        t.modes.middleRows(t.Row(kk, c, 0), 6).noalias() = S.middleRows(6 * c, 6) * ue;
      for (int c = corners; c < most; ++c)  // a copy: the same bits
        t.modes.middleRows(t.Row(kk, c, 0), 6) = t.modes.middleRows(t.Row(kk, corners - 1, 0), 6);
    }
  });
  return t;
}

// the weights (N, My, Mz) of the normal stress at (y, z) of a bending
// section (BeamNormalStress): sigma = N / A + z' a - y' b with (y', z') from
// the neutral axis and (a, b) from the moments about it, (My - ez N, Mz + ey N)
std::array<double, 3> NormalStressWeights(const fe::BeamSection& s, double y, double z) {
  const double det = s.Iy * s.Iz - s.Iyz * s.Iyz;
  const double ey = s.neutral_axis[0], ez = s.neutral_axis[1];
  const double yy = y - ey, zz = z - ez;
  const double my = (zz * s.Iz - yy * s.Iyz) / det, mz = (zz * s.Iyz - yy * s.Iy) / det;
  return {1.0 / s.A - ez * my + ey * mz, my, mz};
}

// the beam_fibre table from the section forces of the beam table (see
// StressModes::beam_fibre): sigma = N / A + (z Iz - y Iyz) My / det +
// (z Iyz - y Iy) Mz / det, det = Iy Iz - Iyz^2, with (y, z) and the moments
// taken about the neutral axis where it lies off the beam axis
// (NormalStressWeights, BeamNormalStress)
StressTable BeamFibreTable(const fe::Mesh& mesh, const StressTable& beam) {
  size_t most = 0;
  std::vector<int> with;  // positions in the beam table of beams with points
  for (size_t k = 0; k < beam.elements.size(); ++k) {
    const fe::BeamSection& sec = mesh.beam_sections[mesh.elements[beam.elements[k]].property];
    if (sec.stress_points.empty()) continue;
    with.push_back(static_cast<int>(k));
    most = std::max(most, sec.stress_points.size());
  }
  std::vector<std::string> locations;
  for (const char* end : {"end_a", "end_b"})
    for (size_t p = 0; p < most; ++p) locations.push_back(std::string(end) + "_p" + std::to_string(p + 1));
  StressTable t = MakeTable("beam_fibre", {"sxx"}, locations);
  t.modes.resize(static_cast<Eigen::Index>(with.size() * locations.size()), beam.modes.cols());
  for (size_t i = 0; i < with.size(); ++i) {
    const int kb = with[i];
    const int e = beam.elements[kb];
    const fe::BeamSection& sec = mesh.beam_sections[mesh.elements[e].property];
    const double det = sec.Iy * sec.Iz - sec.Iyz * sec.Iyz;
    // a rod section carries no bending moments: sigma = N / A at every point
    const bool rod = fe::IsRodSection(sec);
    if (!(sec.A > 0.0) || !(rod || det > 0.0))
      throw InputError("beam fibre stress: section " + std::to_string(sec.id) + " of element " +
                       std::to_string(mesh.elements[e].id) + " needs A > 0 and Iy Iz > Iyz^2");
    t.elements.push_back(e);
    t.axes.push_back(beam.axes[kb]);
    if (beam.modes.cols() == 0) continue;
    for (int end = 0; end < 2; ++end)
      for (size_t p = 0; p < most; ++p) {
        const auto& [y, z] = sec.stress_points[std::min(p, sec.stress_points.size() - 1)];
        const int l = end * static_cast<int>(most) + static_cast<int>(p);
        if (rod) {
          t.modes.row(t.Row(static_cast<int>(i), l, 0)) = beam.modes.row(beam.Row(kb, end, 0)) / sec.A;
          continue;
        }
        const std::array<double, 3> w = NormalStressWeights(sec, y, z);
        t.modes.row(t.Row(static_cast<int>(i), l, 0)) = w[0] * beam.modes.row(beam.Row(kb, end, 0)) +
                                                         w[1] * beam.modes.row(beam.Row(kb, end, 4)) +
                                                         w[2] * beam.modes.row(beam.Row(kb, end, 5));
      }
  }
  return t;
}

}  // namespace

StressModes ComputeStressModes(const fe::Mesh& mesh, const MatX& modes, bool solid_corners,
                               const std::vector<char>* element_subset) {
  const Eigen::Index nn = static_cast<Eigen::Index>(mesh.nodes.size());
  if (modes.rows() != 6 * nn)
    throw InputError("stress modes: the mode matrix has " + std::to_string(modes.rows()) +
                     " rows, expected 6 per node = " + std::to_string(6 * nn));
  const Eigen::Index n = modes.cols();
  StressModes out;
  out.shell = MakeTable("shell", {"sxx", "syy", "sxy"}, {"bottom", "top"});
  out.beam = MakeTable("beam", {"N", "Vy", "Vz", "T", "My", "Mz"}, {"end_a", "end_b"});
  out.solid = MakeTable("solid", {"sxx", "syy", "szz", "sxy", "syz", "szx"}, {"centroid"});
  StressTable* tables[kStressFamilies] = {&out.shell, &out.beam, &out.solid};

  // each element's table and position in it
  const int ne = static_cast<int>(mesh.elements.size());
  std::vector<int> position(ne);
  for (int e = 0; e < ne; ++e) {
    StressTable& t = *tables[FamilyOf(mesh.elements[e].type)];
    position[e] = static_cast<int>(t.elements.size());
    t.elements.push_back(e);
  }
  for (StressTable* t : tables) {
    const int count = static_cast<int>(t->elements.size());
    t->axes.assign(count, Mat3::Identity());
    t->modes.resize(t->Row(count, 0, 0), n);
    if (element_subset != nullptr) {
      t->modes.setZero();
      for (int k = 0; k < count; ++k)
        if (!(*element_subset)[t->elements[k]]) t->axes[k].setZero();
    }
  }

  // per element: one product of its recovery matrix with its rows of the modes
  ParallelRows(ne, ParallelRanges(ne, 512), [&](int, Eigen::Index begin, Eigen::Index end) {
    std::vector<Vec3> x;
    MatX S, ue;
    Mat3 axes;
    for (Eigen::Index e = begin; e < end; ++e) {
      if (element_subset != nullptr && !(*element_subset)[e]) continue;
      const fe::Element& el = mesh.elements[e];
      const fe::ElementInput in = ResolveElementInput(mesh, el, x);
      Recovery(in, S, axes);
      StressTable& t = *tables[FamilyOf(el.type)];
      const int k = position[e];
      t.axes[k] = axes;
      if (n == 0) continue;  // no modes: blocks of empty matrices are UB in Eigen
      ElementModeRows(el, modes, ue);
      t.modes.middleRows(t.Row(k, 0, 0), S.rows()).noalias() = S * ue;
    }
  });
  out.beam_fibre = BeamFibreTable(mesh, out.beam);
  if (solid_corners) out.solid_node = SolidNodeTable(mesh, modes, out.solid.elements, element_subset);
  return out;
}

double VonMises(const Eigen::Vector3d& s) {
  return std::sqrt(std::max(0.0, s(0) * s(0) - s(0) * s(1) + s(1) * s(1) + 3.0 * s(2) * s(2)));
}

double VonMises(const Eigen::Matrix<double, 6, 1>& s) {
  const double a = s(0) - s(1), b = s(1) - s(2), c = s(2) - s(0);
  return std::sqrt(0.5 * (a * a + b * b + c * c) +
                   3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

VecX PointVonMises(const StressTable& table, const VecX& v) {
  const int c = table.Components();
  if ((c != 3 && c != 6) || table.components.front() != "sxx")
    throw InputError("von Mises: the " + table.name +
                     " table does not hold stress vectors (sxx syy sxy or sxx ... szx)");
  const Eigen::Index points = static_cast<Eigen::Index>(table.elements.size()) * table.Locations();
  if (v.size() != points * c)
    throw InputError("von Mises: " + std::to_string(v.size()) + " values for the " + table.name +
                     " table, expected " + std::to_string(points * c));
  VecX out(points);
  for (Eigen::Index p = 0; p < points; ++p)
    out(p) = c == 3 ? VonMises(Eigen::Vector3d(v.segment<3>(3 * p)))
                    : VonMises(Eigen::Matrix<double, 6, 1>(v.segment<6>(6 * p)));
  return out;
}

namespace {
// the checks shared by the element von Mises routines
void CheckStressVectorTable(const StressTable& table) {
  const int c = table.Components();
  if ((c != 3 && c != 6) || table.components.front() != "sxx")
    throw InputError("von Mises: the " + table.name +
                     " table does not hold stress vectors (sxx syy sxy or sxx ... szx)");
  const Eigen::Index expected = static_cast<Eigen::Index>(table.elements.size()) * table.Locations() * c;
  if (table.modes.rows() != expected)
    throw InputError("von Mises: the " + table.name + " table has " + std::to_string(table.modes.rows()) +
                     " rows, expected " + std::to_string(expected));
}
}  // namespace

void ElementVonMises(const StressTable& table, const Eigen::Ref<const VecX>& w, VecX& values, VecX& von_mises) {
  CheckStressVectorTable(table);
  if (w.size() != table.modes.cols())
    throw InputError("von Mises: " + std::to_string(w.size()) + " modal coordinates for the " + table.name +
                     " table of " + std::to_string(table.modes.cols()) + " modes");
  if (values.size() != table.modes.rows()) values.resize(table.modes.rows());
  values.noalias() = table.modes * w;
  ElementVonMisesOfValues(table, values, von_mises);
}

void ElementVonMisesOfValues(const StressTable& table, const Eigen::Ref<const VecX>& values, VecX& von_mises) {
  CheckStressVectorTable(table);
  if (values.size() != table.modes.rows())
    throw InputError("von Mises: " + std::to_string(values.size()) + " stress values for the " + table.name +
                     " table of " + std::to_string(table.modes.rows()) + " rows");
  const int c = table.Components();
  const Eigen::Index elements = static_cast<Eigen::Index>(table.elements.size());
  const int locations = table.Locations();
  if (von_mises.size() != elements) von_mises.resize(elements);
  for (Eigen::Index k = 0; k < elements; ++k) {
    double vm = 0.0;
    for (int l = 0; l < locations; ++l) {
      const Eigen::Index row = table.Row(static_cast<int>(k), l, 0);
      vm = std::max(vm, c == 3 ? VonMises(Eigen::Vector3d(values.segment<3>(row)))
                               : VonMises(Eigen::Matrix<double, 6, 1>(values.segment<6>(row))));
    }
    von_mises(k) = vm;
  }
}

double BeamNormalStress(const Eigen::Matrix<double, 6, 1>& f, const fe::BeamSection& section,
                        double y, double z) {
  const double det = section.Iy * section.Iz - section.Iyz * section.Iyz;
  if (section.A > 0.0 && fe::IsRodSection(section)) return f(0) / section.A;
  if (!(section.A > 0.0) || !(det > 0.0))
    throw InputError("beam normal stress: section " + std::to_string(section.id) +
                     " needs A > 0 and Iy Iz > Iyz^2");
  const std::array<double, 3> w = NormalStressWeights(section, y, z);
  return w[0] * f(0) + w[1] * f(4) + w[2] * f(5);
}

}  // namespace flexmb::reduction
