// Geometric stiffening of the flexible body: the extra modal force equals
// -(sum_c p_c(om) Kg_c) w, it is absent when switched off, and the body's
// analytic force tangents with stiffening match central finite differences
// (the reference of tests/unit/bodies/flexible_body_test.cc), and the model
// file's `geometric_stiffening` key (default: on if the body file has it;
// true without it is an error naming the file).

#include <gtest/gtest.h>

#include <unistd.h>

#include <Eigen/Dense>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/model/model.h"
#include "flexmb/reduction/geometric_stiffness.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb::geometric_stiffening_test {
namespace {

constexpr double kFdStep = 1e-6;

std::shared_ptr<reduction::ReducedBody> StiffenedBar() {
  const fe::FeModel model = testing::BentBar(3);
  reduction::ReductionOptions o;
  o.interface_nodes = {0, 6};
  o.normal_modes = 3;
  o.geometric_stiffening = true;
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
}

std::unique_ptr<FlexibleBody> Make(const std::shared_ptr<reduction::ReducedBody>& r, GeometricStiffening mode) {
  const int n = r->invariants.n;
  FlexibleBodyData d;
  d.reduced = r;
  d.p_WB = Vec3(0.3, -0.2, 1.1);
  d.R_WB = ExpSO3(Vec3(0.4, -0.7, 1.3));
  d.v_WB = Vec3(1.0, -2.0, 0.5);
  d.w_WB = Vec3(30.0, 15.0, -20.0);
  d.w0 = 1e-2 * VecX::LinSpaced(n, 1.0, -0.5);
  d.wd0 = 1e-1 * VecX::LinSpaced(n, -1.0, 2.0);
  d.geometric_stiffening = mode;
  return std::make_unique<FlexibleBody>("bar", d);
}

VecX Forces(const FlexibleBody& b, const VecX& q, const VecX& v, MatX* dq = nullptr, MatX* dv = nullptr) {
  const int N = b.nv();
  VecX Q = VecX::Zero(N);
  MatX a = MatX::Zero(N, N), c = MatX::Zero(N, N);
  b.AddForces(q.data(), v.data(), Vec3(0.0, 0.0, -9.81), Q, a, c);
  if (dq) *dq = a;
  if (dv) *dv = c;
  return Q;
}

TEST(GeometricStiffening, ModalForceAndSwitch) {
  const auto r = StiffenedBar();
  ASSERT_EQ(r->geometric_stiffness.size(), 6u);
  const auto on = Make(r, GeometricStiffening::kAuto), off = Make(r, GeometricStiffening::kOff);
  EXPECT_TRUE(on->HasGeometricStiffening());
  EXPECT_FALSE(off->HasGeometricStiffening());
  const int n = r->invariants.n;
  VecX q(on->nq()), v(on->nv());
  on->InitialCoordinates(q.data(), v.data());
  const VecX dQ = Forces(*on, q, v) - Forces(*off, q, v);
  const Vec3 om(v[3], v[4], v[5]);
  const auto p = reduction::CentrifugalProducts(om);
  MatX G = MatX::Zero(n, n);
  for (int c = 0; c < 6; ++c) G += p[c] * r->geometric_stiffness[c];
  const VecX ref = -G * q.tail(n);
  EXPECT_LT(dQ.head(6).norm(), 1e-12 * ref.norm());
  EXPECT_LT((dQ.tail(n) - ref).norm(), 1e-12 * ref.norm());
  EXPECT_GT(ref.norm(), 0.0);
  // a body file without it: on is refused, auto is off
  auto plain = std::make_shared<reduction::ReducedBody>(*r);
  plain->geometric_stiffness.clear();
  EXPECT_FALSE(Make(plain, GeometricStiffening::kAuto)->HasGeometricStiffening());
  EXPECT_THROW(Make(plain, GeometricStiffening::kOn), InputError);
}

TEST(GeometricStiffening, TangentsMatchFiniteDifferences) {
  const auto b = Make(StiffenedBar(), GeometricStiffening::kOn);
  const int N = b->nv();
  VecX q(b->nq()), v(N);
  b->InitialCoordinates(q.data(), v.data());
  MatX dq, dv;
  Forces(*b, q, v, &dq, &dv);
  MatX fq(N, N), fv(N, N);
  VecX qp(q.size()), qm(q.size());
  for (int k = 0; k < N; ++k) {
    VecX e = VecX::Zero(N);
    e(k) = kFdStep;
    b->Retract(q.data(), e.data(), qp.data());
    b->Retract(q.data(), (-e).eval().data(), qm.data());
    fq.col(k) = (Forces(*b, qp, v) - Forces(*b, qm, v)) / (2 * kFdStep);
    fv.col(k) = (Forces(*b, q, v + e) - Forces(*b, q, v - e)) / (2 * kFdStep);
  }
  const double sq = std::max(1.0, fq.cwiseAbs().maxCoeff()), sv = std::max(1.0, fv.cwiseAbs().maxCoeff());
  EXPECT_LT((dq - fq).cwiseAbs().maxCoeff() / sq, 1e-6);
  EXPECT_LT((dv - fv).cwiseAbs().maxCoeff() / sv, 1e-6);
}

TEST(GeometricStiffening, ModelFileKey) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("flexmb_gs_model_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto r = StiffenedBar();
  io::WriteBody(*r, (dir / "gs.h5").string());
  reduction::ReducedBody plain = *r;
  plain.geometric_stiffness.clear();
  io::WriteBody(plain, (dir / "plain.h5").string());
  // the flexible body of a model file with `extra` after its file key
  auto load = [&](const std::string& file, const std::string& extra) {
    const fs::path p = dir / "model.yaml";
    std::ofstream(p) << "bodies:\n  - name: bar\n    type: flexible\n    file: " << file << "\n" << extra;
    return LoadModelFile(p.string());
  };
  auto stiffened = [](const Model& m) { return dynamic_cast<const FlexibleBody&>(*m.bodies[1]).HasGeometricStiffening(); };
  EXPECT_TRUE(stiffened(*load("gs.h5", "")));
  EXPECT_TRUE(stiffened(*load("gs.h5", "    geometric_stiffening: true\n")));
  EXPECT_FALSE(stiffened(*load("gs.h5", "    geometric_stiffening: false\n")));
  EXPECT_FALSE(stiffened(*load("plain.h5", "")));
  EXPECT_FALSE(stiffened(*load("plain.h5", "    geometric_stiffening: false\n")));
  try {
    load("plain.h5", "    geometric_stiffening: true\n");
    ADD_FAILURE() << "no error for geometric_stiffening: true without the matrices";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("plain.h5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("--geometric-stiffening"), std::string::npos) << msg;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace flexmb::geometric_stiffening_test
