#include "flexmb/reduction/deformation_stiffness.h"

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/reduction/element_input.h"
#include "flexmb/reduction/geometric_stiffness.h"
#include "flexmb/reduction/parallel_rows.h"

namespace flexmb::reduction {

std::vector<MatX> ComputeDeformationStiffness(const fe::Mesh& mesh, const MatX& modes) {
  const Eigen::Index nn = static_cast<Eigen::Index>(mesh.nodes.size());
  const Eigen::Index n = modes.cols();
  if (modes.rows() != 6 * nn)
    throw InputError("mode matrix has " + std::to_string(modes.rows()) + " rows, expected 6 x " +
                         std::to_string(nn) + " nodes",
                     {mesh.source, 0, "deformation stiffening"});
  std::vector<MatX> g(static_cast<size_t>(n), MatX::Zero(n, n));
  // each range of modes j owns its G_j: no shared writes
  ParallelRows(n, ParallelRanges(n, 2), [&](int, Eigen::Index begin, Eigen::Index end) {
    MatX KG, He, KGHe;
    Eigen::VectorXd ue;
    std::vector<fe::Vec3> x;
    for (const fe::Element& e : mesh.elements) {
      const fe::ElementInput in = ResolveElementInput(mesh, e, x);
      const int dpn = fe::DofsPerNode(e.type);
      const int nen = static_cast<int>(e.nodes.size());
      He.resize(dpn * nen, n);
      for (int k = 0; k < nen; ++k) He.middleRows(dpn * k, dpn) = modes.middleRows(6 * e.nodes[k], dpn);
      for (Eigen::Index j = begin; j < end; ++j) {
        ue = He.col(j);
        if (ue.isZero(0.0)) continue;
        ElementGeometricStiffness(in, ue, KG);
        KGHe.noalias() = KG * He;
        g[static_cast<size_t>(j)].noalias() += He.transpose() * KGHe;
      }
    }
  });
  for (MatX& m : g) m = 0.5 * (m + m.transpose()).eval();
  return g;
}

}  // namespace flexmb::reduction
