#include "flexmb/reduction/geometric_stiffness.h"

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/element_traits.h"
#include "flexmb/fe/elements/element_common.h"
#include "flexmb/fe/modal.h"
#include "flexmb/fe/sparse_cholesky.h"
#include "flexmb/reduction/element_input.h"

namespace flexmb::reduction {

const std::array<const char*, kCentrifugalCases> kCentrifugalCaseNames = {"wx*wx", "wy*wy", "wz*wz",
                                                                         "wx*wy", "wy*wz", "wz*wx"};

Vec3 CentrifugalAcceleration(int c, const Vec3& x) {
  // om x (om x x) = om (om . x) - |om|^2 x, sorted by the products of om
  if (c < 3) {
    Vec3 a = -x;
    a(c) += x(c);
    return a;
  }
  const int i = c - 3, j = (c - 2) % 3;  // (x, y), (y, z), (z, x)
  Vec3 a = Vec3::Zero();
  a(i) += x(j);
  a(j) += x(i);
  return a;
}

void ElementGeometricStiffness(const fe::ElementInput& in, const Eigen::VectorXd& u, MatX& KG, double* axial_force) {
  const fe::Element& e = *in.element;
  const int nd = fe::NodeCount(e.type) * fe::DofsPerNode(e.type);
  if (u.size() != nd)
    throw InputError("prestress displacement has " + std::to_string(u.size()) + " values, expected " + std::to_string(nd),
                     fe::ElementContext(e));
  if (axial_force != nullptr) *axial_force = 0.0;
  fe::Traits(e.type).geometric_stiffness(in, u, KG, axial_force);
}

fe::SparseMat AssembleGeometricStiffness(const fe::Mesh& mesh, const fe::DofMap& dofs, const Eigen::VectorXd& u_full) {
  if (u_full.size() != dofs.n_full)
    throw InputError("prestress displacement has " + std::to_string(u_full.size()) + " values, expected " +
                         std::to_string(dofs.n_full),
                     {mesh.source, 0, "geometric stiffness"});
  std::vector<Eigen::Triplet<double>> trip;
  std::vector<fe::Vec3> x;
  std::vector<int> idx;
  MatX KG;
  Eigen::VectorXd ue;
  for (const fe::Element& e : mesh.elements) {
    const fe::ElementInput in = ResolveElementInput(mesh, e, x);
    const int dpn = fe::DofsPerNode(e.type);
    const int nd = static_cast<int>(e.nodes.size()) * dpn;
    idx.assign(nd, -1);
    ue.setZero(nd);
    for (size_t a = 0; a < e.nodes.size(); ++a) {
      for (int c = 0; c < dpn; ++c) {
        const int f = dofs.full[e.nodes[a]][c];
        idx[dpn * a + c] = f;
        if (f >= 0) ue(dpn * a + c) = u_full(f);
      }
    }
    ElementGeometricStiffness(in, ue, KG);
    for (int i = 0; i < nd; ++i) {
      if (idx[i] < 0) continue;
      for (int j = 0; j < nd; ++j) {
        if (idx[j] >= 0 && KG(i, j) != 0.0) trip.emplace_back(idx[i], idx[j], KG(i, j));
      }
    }
  }
  fe::SparseMat kg(dofs.n_full, dofs.n_full);
  kg.setFromTriplets(trip.begin(), trip.end());
  return kg;
}

std::vector<MatX> ComputeGeometricStiffness(const fe::Mesh& mesh, const MatX& modes,
                                            const std::vector<int>& support_nodes, fe::MassForm mass_form,
                                            GeometricStiffnessInfo* info) {
  const ErrorContext ctx{mesh.source, 0, "geometric stiffening"};
  const int nn = static_cast<int>(mesh.nodes.size());
  const Eigen::Index n = modes.cols();
  if (modes.rows() != 6 * static_cast<Eigen::Index>(nn))
    throw InputError("mode matrix has " + std::to_string(modes.rows()) + " rows, expected 6 x " +
                         std::to_string(nn) + " nodes",
                     ctx);
  if (support_nodes.empty() && mesh.constraints.empty()) {
    throw InputError("the static load cases need a support: give interface or fixed nodes", ctx);
  }

  // the model held at its supports
  fe::AssemblyOptions ao;
  ao.mass_form = mass_form;
  ao.extra_fixed_nodes = support_nodes;
  ao.independent_nodes = support_nodes;
  const fe::AssembledModel a = fe::Assemble(mesh, ao);
  const int nf = a.dofs.n_free;
  fe::SparseCholesky chol;
  if (nf > 0) {
    chol.Factorize(a.K, "K of the held body (geometric stiffening)",
                   [&](int dof) { return fe::DescribeFreeDof(a.dofs, dof); });
  }

  // unit inertial loads -M_full a_c on the full DOF, to the free DOF, solved
  Eigen::MatrixXd acc = Eigen::MatrixXd::Zero(a.dofs.n_full, kCentrifugalCases);
  for (int k = 0; k < nn; ++k) {
    for (int c = 0; c < kCentrifugalCases; ++c) {
      const Vec3 ac = CentrifugalAcceleration(c, mesh.nodes[k].x);
      for (int i = 0; i < 3; ++i) {
        const int f = a.dofs.full[k][i];
        if (f >= 0) acc(f, c) = ac(i);
      }
    }
  }
  const Eigen::MatrixXd f_full = -(a.M_full * acc);
  Eigen::MatrixXd u_full = Eigen::MatrixXd::Zero(a.dofs.n_full, kCentrifugalCases);
  if (nf > 0) {
    const Eigen::MatrixXd f_free = a.T.transpose() * f_full;
    u_full = a.T * chol.Solve(f_free);
  }

  // element axial forces, geometric stiffness, projection onto the modes
  std::vector<MatX> kg(kCentrifugalCases, MatX::Zero(n, n));
  if (info != nullptr) {
    info->support_nodes = support_nodes;
    for (auto& v : info->axial_force) v.assign(mesh.elements.size(), 0.0);
  }
  MatX KG, He;
  Eigen::VectorXd ue;
  std::vector<fe::Vec3> x;
  for (size_t ei = 0; ei < mesh.elements.size(); ++ei) {
    const fe::Element& e = mesh.elements[ei];
    const fe::ElementInput in = ResolveElementInput(mesh, e, x);
    const int dpn = fe::DofsPerNode(e.type);
    const int nen = static_cast<int>(e.nodes.size());
    He.resize(dpn * nen, n);
    for (int k = 0; k < nen; ++k) He.middleRows(dpn * k, dpn) = modes.middleRows(6 * e.nodes[k], dpn);
    ue.resize(dpn * nen);
    for (int c = 0; c < kCentrifugalCases; ++c) {
      for (int k = 0; k < nen; ++k) {
        for (int i = 0; i < dpn; ++i) {
          const int f = a.dofs.full[e.nodes[k]][i];
          ue(dpn * k + i) = f >= 0 ? u_full(f, c) : 0.0;
        }
      }
      if (ue.isZero(0.0)) continue;
      double N = 0.0;
      ElementGeometricStiffness(in, ue, KG, &N);
      if (info != nullptr) info->axial_force[c][ei] = N;
      kg[c].noalias() += He.transpose() * (KG * He);
    }
  }
  for (MatX& m : kg) m = 0.5 * (m + m.transpose()).eval();
  return kg;
}

}  // namespace flexmb::reduction
