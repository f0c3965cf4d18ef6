// Stiffening of a flexible body by its own deformation
// (reduction/deformation_stiffness.h, bodies/deformation_stiffening.h):
// - the reduction's matrices G_j equal the projection of the globally
//   assembled geometric stiffness of each mode's deformation (the
//   independent path of AssembleGeometricStiffness);
// - the modal force is -(sum_j w_j G_j) w and its tangent the derivative
//   of the force (central differences);
// - the body's analytic tangents with it match central differences; its
//   strain energy stays 1/2 w^T K w;
// - the body file keeps the matrices, and the model file's
//   `deformation_stiffening` key (default: on if the body file has them;
//   true without them is an error naming the file).

#include <gtest/gtest.h>

#include <unistd.h>

#include <Eigen/Dense>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "flexmb/bodies/deformation_stiffening.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/model/model.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/reduction/deformation_stiffness.h"
#include "flexmb/reduction/geometric_stiffness.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb::deformation_stiffening_test {
namespace {

constexpr double kFdStep = 1e-6;

std::shared_ptr<reduction::ReducedBody> StiffenedBar() {
  const fe::FeModel model = testing::BentBar(3);
  reduction::ReductionOptions o;
  o.interface_nodes = {0, 6};
  o.normal_modes = 3;
  o.deformation_stiffening = true;
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
}

TEST(DeformationStiffness, EqualsTheProjectedAssembledGeometricStiffness) {
  const auto r = StiffenedBar();
  const int n = r->invariants.n;
  ASSERT_EQ(static_cast<int>(r->deformation_stiffness.size()), n);
  const fe::AssembledModel a = fe::Assemble(r->mesh, {});
  // the modes on the full DOF numbering
  MatX H = MatX::Zero(a.dofs.n_full, n);
  for (size_t k = 0; k < r->mesh.nodes.size(); ++k) {
    for (int c = 0; c < 6; ++c) {
      const int f = a.dofs.full[k][c];
      if (f >= 0) H.row(f) = r->modes.row(6 * static_cast<Eigen::Index>(k) + c);
    }
  }
  double scale = 0.0;
  for (const MatX& g : r->deformation_stiffness) scale = std::max(scale, g.cwiseAbs().maxCoeff());
  ASSERT_GT(scale, 0.0);
  for (int j = 0; j < n; ++j) {
    const MatX kg(reduction::AssembleGeometricStiffness(r->mesh, a.dofs, H.col(j)));
    const MatX ref = H.transpose() * kg * H;
    EXPECT_LT((r->deformation_stiffness[j] - ref).cwiseAbs().maxCoeff(), 1e-10 * scale) << "mode " << j;
    EXPECT_LT((r->deformation_stiffness[j] - r->deformation_stiffness[j].transpose()).cwiseAbs().maxCoeff(),
              1e-12 * scale);
  }
}

TEST(DeformationStiffening, ForceAndTangent) {
  const int n = 5;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<MatX> g(n);
  for (MatX& m : g) {
    m = MatX::NullaryExpr(n, n, [&] { return u(rng); });
    m = (m + m.transpose()).eval();
  }
  const DeformationStiffeningForce f(g, n);
  VecX w = VecX::NullaryExpr(n, [&] { return u(rng); });
  VecX Q = VecX::Zero(n);
  MatX dQ = MatX::Zero(n, n);
  f.Add(w.data(), Q, dQ);
  VecX Qv = VecX::Zero(n);
  f.Add(w.data(), Qv);
  EXPECT_EQ((Q - Qv).norm(), 0.0);
  MatX G = MatX::Zero(n, n);
  for (int j = 0; j < n; ++j) G += w(j) * g[j];
  const VecX ref = -G * w;
  EXPECT_LT((Q - ref).norm(), 1e-13 * ref.norm());
  for (int k = 0; k < n; ++k) {
    VecX wp = w, wm = w;
    wp(k) += kFdStep;
    wm(k) -= kFdStep;
    VecX Qp = VecX::Zero(n), Qm = VecX::Zero(n);
    f.Add(wp.data(), Qp);
    f.Add(wm.data(), Qm);
    const VecX col = (Qp - Qm) / (2 * kFdStep);
    EXPECT_LT((dQ.col(k) - col).cwiseAbs().maxCoeff(), 1e-7 * std::max(1.0, col.cwiseAbs().maxCoeff())) << k;
  }
  // quadratic in w: Q(2 w) = 4 Q(w)
  const VecX w2 = 2.0 * w;
  VecX Q2 = VecX::Zero(n);
  f.Add(w2.data(), Q2);
  EXPECT_LT((Q2 - 4.0 * Q).norm(), 1e-12 * Q2.norm());
  EXPECT_THROW(DeformationStiffeningForce(g, n + 1), InputError);
}

std::unique_ptr<FlexibleBody> Make(const std::shared_ptr<reduction::ReducedBody>& r, GeometricStiffening mode) {
  const int n = r->invariants.n;
  FlexibleBodyData d;
  d.reduced = r;
  d.p_WB = Vec3(0.3, -0.2, 1.1);
  d.R_WB = ExpSO3(Vec3(0.4, -0.7, 1.3));
  d.v_WB = Vec3(1.0, -2.0, 0.5);
  d.w_WB = Vec3(3.0, 1.5, -2.0);
  d.w0 = 1e-2 * VecX::LinSpaced(n, 1.0, -0.5);
  d.wd0 = 1e-1 * VecX::LinSpaced(n, -1.0, 2.0);
  d.deformation_stiffening = mode;
  return std::make_unique<FlexibleBody>("bar", d);
}

VecX Forces(const FlexibleBody& b, const VecX& q, const VecX& v, MatX* dq = nullptr) {
  const int N = b.nv();
  VecX Q = VecX::Zero(N);
  MatX a = MatX::Zero(N, N), c = MatX::Zero(N, N);
  b.AddForces(q.data(), v.data(), Vec3(0.0, 0.0, -9.81), Q, a, c);
  if (dq) *dq = a;
  return Q;
}

TEST(DeformationStiffening, BodyForceTangentAndEnergy) {
  const auto r = StiffenedBar();
  const auto on = Make(r, GeometricStiffening::kAuto), off = Make(r, GeometricStiffening::kOff);
  EXPECT_TRUE(on->HasDeformationStiffening());
  EXPECT_FALSE(off->HasDeformationStiffening());
  const int n = r->invariants.n, N = on->nv();
  VecX q(on->nq()), v(N);
  on->InitialCoordinates(q.data(), v.data());
  // the extra force is the modal force of the cubic energy, nothing else
  const DeformationStiffeningForce f(r->deformation_stiffness, n);
  VecX ref = VecX::Zero(n);
  f.Add(q.data() + 7, ref);
  const VecX dQ = Forces(*on, q, v) - Forces(*off, q, v);
  ASSERT_GT(ref.norm(), 0.0);
  EXPECT_LT(dQ.head(6).norm(), 1e-12 * ref.norm());
  EXPECT_LT((dQ.tail(n) - ref).norm(), 1e-10 * ref.norm());
  EXPECT_EQ(on->StrainEnergy(q.data()), off->StrainEnergy(q.data()));
  // the vector-only path agrees
  VecX Qv = VecX::Zero(N);
  on->AddForceVector(q.data(), v.data(), Vec3(0.0, 0.0, -9.81), Qv);
  EXPECT_LT((Qv - Forces(*on, q, v)).norm(), 1e-12 * Qv.norm());
  // tangent against central differences
  MatX dq;
  Forces(*on, q, v, &dq);
  MatX fq(N, N);
  VecX qp(q.size()), qm(q.size());
  for (int k = 0; k < N; ++k) {
    VecX e = VecX::Zero(N);
    e(k) = kFdStep;
    on->Retract(q.data(), e.data(), qp.data());
    on->Retract(q.data(), (-e).eval().data(), qm.data());
    fq.col(k) = (Forces(*on, qp, v) - Forces(*on, qm, v)) / (2 * kFdStep);
  }
  EXPECT_LT((dq - fq).cwiseAbs().maxCoeff() / std::max(1.0, fq.cwiseAbs().maxCoeff()), 1e-6);
  // a body file without it: on is refused, auto is off
  auto plain = std::make_shared<reduction::ReducedBody>(*r);
  plain->deformation_stiffness.clear();
  EXPECT_FALSE(Make(plain, GeometricStiffening::kAuto)->HasDeformationStiffening());
  EXPECT_THROW(Make(plain, GeometricStiffening::kOn), InputError);
}

TEST(DeformationStiffening, BodyFileAndModelFileKey) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("flexmb_ds_model_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto r = StiffenedBar();
  io::WriteBody(*r, (dir / "ds.h5").string());
  const reduction::ReducedBody back = io::ReadBody((dir / "ds.h5").string());
  ASSERT_EQ(back.deformation_stiffness.size(), r->deformation_stiffness.size());
  for (size_t j = 0; j < back.deformation_stiffness.size(); ++j)
    EXPECT_EQ(back.deformation_stiffness[j], r->deformation_stiffness[j]) << j;
  EXPECT_TRUE(back.geometric_stiffness.empty());
  reduction::ReducedBody plain = *r;
  plain.deformation_stiffness.clear();
  io::WriteBody(plain, (dir / "plain.h5").string());
  auto load = [&](const std::string& file, const std::string& extra) {
    const fs::path p = dir / "model.yaml";
    std::ofstream(p) << "bodies:\n  - name: bar\n    type: flexible\n    file: " << file << "\n" << extra;
    return LoadModelFile(p.string());
  };
  auto stiffened = [](const Model& m) {
    return dynamic_cast<const FlexibleBody&>(*m.bodies[1]).HasDeformationStiffening();
  };
  EXPECT_TRUE(stiffened(*load("ds.h5", "")));
  EXPECT_TRUE(stiffened(*load("ds.h5", "    deformation_stiffening: true\n")));
  EXPECT_FALSE(stiffened(*load("ds.h5", "    deformation_stiffening: false\n")));
  EXPECT_FALSE(stiffened(*load("plain.h5", "")));
  try {
    load("plain.h5", "    deformation_stiffening: true\n");
    ADD_FAILURE() << "no error for deformation_stiffening: true without the matrices";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("plain.h5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("--deformation-stiffening"), std::string::npos) << msg;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flexmb::deformation_stiffening_test
