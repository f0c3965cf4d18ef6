// Mass properties of an assembled model (declared in fe/assembly.h): the
// rigid-body mass R^T M R about the mean of the node positions, and from it
// the total mass, the centre of mass and the inertia about it.

#include <Eigen/Dense>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"

namespace flexmb::fe {

Eigen::Matrix<double, 6, 6> RigidBodyMass(const Mesh& mesh, const AssembledModel& model, Vec3& x0) {
  const DofMap& dm = model.dofs;
  const int nn = static_cast<int>(mesh.nodes.size());
  // rigid-body vectors about a reference point near the model, free DOF
  x0 = Vec3::Zero();
  for (const Node& node : mesh.nodes) x0 += node.x;
  if (nn > 0) x0 /= nn;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(dm.n_free, 6);
  for (int n = 0; n < nn; ++n) {
    const Vec3 r = mesh.nodes[n].x - x0;
    for (int c = 0; c < 6; ++c) {
      const int f = dm.free[n][c];
      if (f < 0) continue;
      if (c < 3) {
        // translation e_c, rotation about x0: (theta x r)_c
        R(f, c) = 1.0;
        const int j = (c + 1) % 3, k = (c + 2) % 3;
        R(f, 3 + j) = r[k];
        R(f, 3 + k) = -r[j];
      } else {
        R(f, c) = 1.0;
      }
    }
  }
  return R.transpose() * (model.M * R);
}

MassProperties ComputeMassProperties(const Mesh& mesh, const AssembledModel& model) {
  const DofMap& dm = model.dofs;
  const int nn = static_cast<int>(mesh.nodes.size());
  if (static_cast<int>(dm.free.size()) != nn || model.M.rows() != dm.n_free) {
    throw InputError("mass properties: the assembled model does not belong to this mesh");
  }
  // a constrained DOF has an empty row of T: its mass would be missing
  Eigen::VectorXi row_count = Eigen::VectorXi::Zero(dm.n_full);
  for (int k = 0; k < model.T.outerSize(); ++k) {
    for (SparseMat::InnerIterator it(model.T, k); it; ++it) row_count[it.row()] += 1;
  }
  if (dm.n_full > 0 && row_count.minCoeff() == 0) {
    throw InputError("mass properties need the model assembled without constraints or fixed nodes");
  }
  Vec3 x0;
  const Eigen::Matrix<double, 6, 6> mrr = RigidBodyMass(mesh, model, x0);

  MassProperties p;
  p.mass = mrr.topLeftCorner<3, 3>().trace() / 3.0;
  if (!(p.mass > 0.0)) {
    if (p.mass == 0.0) return p;
    throw NumericalError("mass properties: the mass matrix gives a negative total mass");
  }
  // top-right block is -m skew(c) for a centre c relative to x0
  const Mat3 s = -0.5 * (mrr.topRightCorner<3, 3>() - mrr.topRightCorner<3, 3>().transpose()) / p.mass;
  const Vec3 c(s(2, 1), s(0, 2), s(1, 0));
  Mat3 sc;
  sc << 0.0, -c.z(), c.y(), c.z(), 0.0, -c.x(), -c.y(), c.x(), 0.0;
  const Mat3 j0 = 0.5 * (mrr.bottomRightCorner<3, 3>() + mrr.bottomRightCorner<3, 3>().transpose());
  p.center = x0 + c;
  p.inertia = j0 + p.mass * sc * sc;
  return p;
}

}  // namespace flexmb::fe
