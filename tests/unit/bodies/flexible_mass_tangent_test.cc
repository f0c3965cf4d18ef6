// d(M(q) a)/dq of a floating-frame flexible body (FlexibleMassTangent)
// against central differences of FlexibleBody::MassMatrix(q) a along the
// body's own retraction (position, rotation R exp(dtheta), modal
// coordinates), for the free bent bar at a general pose and modal state.

#include "flexmb/bodies/flexible_mass_tangent.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdio>

#include "flexmb/bodies/flexible_body.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb {
namespace {

TEST(FlexibleMassTangent, MatchesFiniteDifferencesOfMassTimesAcceleration) {
  const auto reduced = testing::FreeBentBar(3, 3);
  const int n = reduced->invariants.n, N = 6 + n;
  FlexibleBodyData d;
  d.reduced = reduced;
  d.p_WB = Vec3(0.3, -0.2, 1.1);
  d.R_WB = Eigen::AngleAxisd(0.9, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  d.w0 = 0.05 * VecX::LinSpaced(n, 1.0, -0.5);
  const FlexibleBody body("bar", d);
  VecX q(body.nq()), v(body.nv());
  body.InitialCoordinates(q.data(), v.data());
  const VecX a = VecX::LinSpaced(N, -2.0, 3.0);

  MatX K = MatX::Zero(N, N);
  const Eigen::Quaterniond quat(q(3), q(4), q(5), q(6));
  const FlexibleInertia inertia(reduced->invariants);
  FlexibleMassTangent(reduced->invariants, inertia).Add(quat.toRotationMatrix(), q.data() + 7, a.data(), 1.0, K);

  MatX fd(N, N), M;
  VecX qp(q.size()), qm(q.size()), dx = VecX::Zero(N);
  const double h = 1e-6;
  for (int j = 0; j < N; ++j) {
    dx.setZero();
    dx(j) = h;
    body.Retract(q.data(), dx.data(), qp.data());
    dx(j) = -h;
    body.Retract(q.data(), dx.data(), qm.data());
    body.MassMatrix(qp.data(), M);
    const VecX fp = M * a;
    body.MassMatrix(qm.data(), M);
    fd.col(j) = (fp - M * a) / (2.0 * h);
  }
  // the modal and rotation columns are not trivially zero; the position columns are
  EXPECT_GT(K.rightCols(n).norm(), 1e-3 * fd.norm());
  EXPECT_GT(K.middleCols(3, 3).norm(), 1e-3 * fd.norm());
  EXPECT_LT(K.leftCols(3).norm(), 1e-15);
  std::printf("d(M a)/dq: |analytic - central differences| / |fd| = %.2e (n = %d modes)\n", (K - fd).norm() / fd.norm(), n);
  EXPECT_LT((K - fd).norm(), 1e-7 * fd.norm()) << "analytic\n" << K << "\nfd\n" << fd;
}

}  // namespace
}  // namespace flexmb
