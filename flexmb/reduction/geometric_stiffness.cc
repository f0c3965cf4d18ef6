#include "flexmb/reduction/geometric_stiffness.h"

#include <Eigen/Dense>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/elements/beam2.h"
#include "flexmb/fe/sparse_cholesky.h"

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
  for (const fe::Element& e : mesh.elements) {
    if (e.type != fe::ElementType::kBeam2) {
      throw InputError(std::string("element ") + std::to_string(e.id) + " is of type " + fe::TypeName(e.type) +
                           ", which has no geometric stiffness yet (only beam elements do): reduce without "
                           "geometric stiffening",
                       {e.origin.file, e.origin.line, "geometric stiffening"});
    }
  }
  if (support_nodes.empty() && mesh.constraints.empty()) {
    throw InputError("the static load cases need a support: give interface or fixed nodes", ctx);
  }

  // the model held at its supports
  fe::AssemblyOptions ao;
  ao.mass_form = mass_form;
  ao.extra_fixed_nodes = support_nodes;
  const fe::AssembledModel a = fe::Assemble(mesh, ao);
  const int nf = a.dofs.n_free;
  fe::SparseCholesky chol;
  if (nf > 0) {
    chol.Factorize(a.K, "K of the held body (geometric stiffening)", [&](int dof) {
      for (int k = 0; k < nn; ++k) {
        for (int c = 0; c < 6; ++c) {
          if (a.dofs.free[k][c] == dof) return "node " + std::to_string(a.dofs.node_ids[k]) + " component " + std::to_string(c + 1);
        }
      }
      return std::string("free DOF ") + std::to_string(dof);
    });
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
  MatX S, KG, He(12, n);
  Eigen::Matrix<double, 12, 1> ue;
  Eigen::Matrix3d axes;
  fe::Vec3 x[2];
  for (size_t ei = 0; ei < mesh.elements.size(); ++ei) {
    const fe::Element& e = mesh.elements[ei];
    const fe::BeamSection& sec = mesh.beam_sections.at(e.property);
    fe::ElementInput in;
    in.element = &e;
    x[0] = mesh.nodes[e.nodes[0]].x;
    x[1] = mesh.nodes[e.nodes[1]].x;
    in.x = x;
    in.beam = &sec;
    in.material = &mesh.materials.at(sec.material);
    fe::Beam2SectionForces(in, S, axes);
    for (int end = 0; end < 2; ++end) He.middleRows(6 * end, 6) = modes.middleRows(6 * e.nodes[end], 6);
    for (int c = 0; c < kCentrifugalCases; ++c) {
      for (int end = 0; end < 2; ++end) {
        for (int i = 0; i < 6; ++i) {
          const int f = a.dofs.full[e.nodes[end]][i];
          ue(6 * end + i) = f >= 0 ? u_full(f, c) : 0.0;
        }
      }
      const double N = 0.5 * (S.row(0).dot(ue) + S.row(6).dot(ue));
      if (info != nullptr) info->axial_force[c][ei] = N;
      if (N == 0.0) continue;
      fe::Beam2GeometricStiffness(in, N, KG);
      kg[c].noalias() += He.transpose() * (KG * He);
    }
  }
  for (MatX& m : kg) m = 0.5 * (m + m.transpose()).eval();
  return kg;
}

}  // namespace flexmb::reduction
