// Checks every joint's analytic derivatives against central finite
// differences in the marker variations (PerturbMarker), its equations at
// poses that satisfy it, and the assembled constraint Jacobian B and geometric
// stiffness d(B^T lambda)/dq against finite differences under RetractAll.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/cylindrical.h"
#include "flexmb/joints/distance.h"
#include "flexmb/joints/fixed.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/planar.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/joints/universal.h"
#include "flexmb/model/model.h"
#include "flexmb/solver/assembler.h"

namespace flexmb {
namespace {

constexpr double kEps = 1e-6;

/// f(t) = a + b t + c t^2 (for the motion driver).
class Quadratic final : public ScalarFunction {
 public:
  Quadratic(double a, double b, double c) : a_(a), b_(b), c_(c) {}
  double Value(double t) const override { return a_ + b_ * t + c_ * t * t; }
  double Derivative(double t) const override { return b_ + 2 * c_ * t; }
  double SecondDerivative(double) const override { return 2 * c_; }

 private:
  double a_, b_, c_;
};

struct JointCase {
  std::string label;
  std::unique_ptr<Joint> owner;   // the joint under test
  std::unique_ptr<Joint> target;  // driven joint, for motion drivers
};

std::vector<JointCase> AllJoints() {
  std::vector<JointCase> c;
  auto add = [&](std::string label, std::unique_ptr<Joint> j) {
    c.push_back(JointCase{std::move(label), std::move(j), nullptr});
  };
  add("fixed", std::make_unique<FixedJoint>("j"));
  add("revolute", std::make_unique<RevoluteJoint>("j"));
  add("prismatic", std::make_unique<PrismaticJoint>("j"));
  add("cylindrical", std::make_unique<CylindricalJoint>("j"));
  add("spherical", std::make_unique<SphericalJoint>("j"));
  add("universal", std::make_unique<UniversalJoint>("j"));
  add("planar", std::make_unique<PlanarJoint>("j"));
  add("distance", std::make_unique<DistanceJoint>("j", 0.7));
  auto f = std::make_shared<Quadratic>(0.4, -0.8, 0.3);
  {
    auto target = std::make_unique<RevoluteJoint>("rev");
    auto drv = std::make_unique<MotionDriver>("j", target.get(), 0, f);
    c.push_back(JointCase{"motion on revolute", std::move(drv), std::move(target)});
  }
  {
    auto target = std::make_unique<PrismaticJoint>("pri");
    auto drv = std::make_unique<MotionDriver>("j", target.get(), 0, f);
    c.push_back(JointCase{"motion on prismatic", std::move(drv), std::move(target)});
  }
  return c;
}

MarkerState RandomMarker(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MarkerState m;
  m.p_WM = Vec3(u(rng), u(rng), u(rng));
  m.R_WM = ExpSO3(3.0 * Vec3(u(rng), u(rng), u(rng)));
  return m;
}

/// Marker k-th variation (k in 0..11: i then j) of the pair (mi, mj).
void Perturb(const MarkerState& mi, const MarkerState& mj, int k, double eps, MarkerState& pi,
             MarkerState& pj) {
  pi = k < 6 ? PerturbMarker(mi, k, eps) : mi;
  pj = k < 6 ? mj : PerturbMarker(mj, k - 6, eps);
}

JointEval MakeEval(const Joint& j) {
  JointEval e;
  e.phi.setZero(j.NumEquations());
  e.phi_t.setZero(j.NumEquations());
  e.D.setZero(j.NumEquations(), 12);
  return e;
}

TEST(JointJacobian, DerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  for (auto& jc : AllJoints()) {
    const Joint& j = *jc.owner;
    const int n = j.NumEquations();
    for (int trial = 0; trial < 5; ++trial) {
      const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
      const double t = 0.37 * trial;
      JointEval e = MakeEval(j), ep = MakeEval(j), em = MakeEval(j);
      j.Evaluate(mi, mj, t, e);
      for (int k = 0; k < 12; ++k) {
        MarkerState ip, jp, im, jm;
        Perturb(mi, mj, k, kEps, ip, jp);
        Perturb(mi, mj, k, -kEps, im, jm);
        j.Evaluate(ip, jp, t, ep);
        j.Evaluate(im, jm, t, em);
        for (int r = 0; r < n; ++r) {
          // driven angles wrap: take the difference modulo 2 pi
          const double dphi = std::remainder(ep.phi(r) - em.phi(r), 2 * M_PI);
          EXPECT_NEAR(e.D(r, k), dphi / (2 * kEps), 1e-7)
              << jc.label << " equation " << r << " variation " << k << " trial " << trial;
        }
      }
    }
  }
}

TEST(JointJacobian, TimeDerivativeOfDriver) {
  std::mt19937 rng(11);
  for (auto& jc : AllJoints()) {
    const Joint& j = *jc.owner;
    const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
    JointEval e = MakeEval(j), ep = MakeEval(j), em = MakeEval(j);
    const double t = 0.8, h = 1e-5;
    j.Evaluate(mi, mj, t, e);
    j.Evaluate(mi, mj, t + h, ep);
    j.Evaluate(mi, mj, t - h, em);
    for (int r = 0; r < j.NumEquations(); ++r) {
      const double fd = std::remainder(ep.phi(r) - em.phi(r), 2 * M_PI) / (2 * h);
      // phi_t is only written by rheonomic joints; the assembler zeroes it
      const double phi_t = jc.target ? e.phi_t(r) : 0.0;
      EXPECT_NEAR(phi_t, fd, 1e-8) << jc.label << " equation " << r;
    }
  }
}

TEST(JointJacobian, GeometricStiffnessMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (auto& jc : AllJoints()) {
    const Joint& j = *jc.owner;
    const int n = j.NumEquations();
    for (int trial = 0; trial < 5; ++trial) {
      const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
      double lambda[8];
      for (int r = 0; r < n; ++r) lambda[r] = u(rng);
      Mat12 H = Mat12::Zero();
      j.AddGeometricStiffness(mi, mj, lambda, H);
      JointEval ep = MakeEval(j), em = MakeEval(j);
      Mat12 H_fd;
      for (int k = 0; k < 12; ++k) {
        MarkerState ip, jp, im, jm;
        Perturb(mi, mj, k, kEps, ip, jp);
        Perturb(mi, mj, k, -kEps, im, jm);
        j.Evaluate(ip, jp, 0.0, ep);
        j.Evaluate(im, jm, 0.0, em);
        Vec12 wp = Vec12::Zero(), wm = Vec12::Zero();
        for (int r = 0; r < n; ++r) {
          wp += lambda[r] * ep.D.row(r).transpose();
          wm += lambda[r] * em.D.row(r).transpose();
        }
        H_fd.col(k) = (wp - wm) / (2 * kEps);
      }
      EXPECT_LT((H - H_fd).cwiseAbs().maxCoeff(), 1e-6)
          << jc.label << " trial " << trial << "\nanalytic:\n" << H << "\nfinite differences:\n" << H_fd;
    }
  }
}

TEST(JointJacobian, CoordinateDerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(5);
  for (auto& jc : AllJoints()) {
    const Joint& j = *jc.owner;
    for (int c = 0; c < j.NumCoordinates(); ++c) {
      for (int trial = 0; trial < 5; ++trial) {
        const MarkerState mi = RandomMarker(rng), mj = RandomMarker(rng);
        Vec12 dq;
        j.Coordinate(c, mi, mj, &dq);
        for (int k = 0; k < 12; ++k) {
          MarkerState ip, jp, im, jm;
          Perturb(mi, mj, k, kEps, ip, jp);
          Perturb(mi, mj, k, -kEps, im, jm);
          double diff = j.Coordinate(c, ip, jp, nullptr) - j.Coordinate(c, im, jm, nullptr);
          if (j.CoordinateIsAngle(c)) diff = std::remainder(diff, 2 * M_PI);
          EXPECT_NEAR(dq(k), diff / (2 * kEps), 1e-7)
              << jc.label << " coordinate " << c << " variation " << k;
        }
      }
    }
  }
}

Mat3 Rz(double a) { return ExpSO3(Vec3(0, 0, a)); }
Mat3 Rx(double a) { return ExpSO3(Vec3(a, 0, 0)); }

/// Evaluates the joint's equations at (mi, mj) and expects them all zero.
void ExpectSatisfied(const Joint& j, const MarkerState& mi, const MarkerState& mj, double t,
                     const std::string& label) {
  JointEval e = MakeEval(j);
  j.Evaluate(mi, mj, t, e);
  EXPECT_LT(e.phi.cwiseAbs().maxCoeff(), 1e-12) << label << ": phi = " << e.phi.transpose();
}

TEST(JointJacobian, EquationsVanishAtSatisfyingPosesAndCoordinatesAreKnown) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    const MarkerState mi = RandomMarker(rng);
    const Mat3& Ri = mi.R_WM;
    const double angle = 3.0 * u(rng), s = 2.0 * u(rng), x = u(rng), y = u(rng);
    MarkerState mj = mi;

    // fixed: same pose
    ExpectSatisfied(FixedJoint("f"), mi, mj, 0.0, "fixed");

    // revolute: same origin, z_j = z_i, any angle about z
    RevoluteJoint rev("r");
    mj.p_WM = mi.p_WM;
    mj.R_WM = Ri * Rz(angle);
    ExpectSatisfied(rev, mi, mj, 0.0, "revolute");
    EXPECT_NEAR(std::remainder(rev.Coordinate(0, mi, mj, nullptr) - angle, 2 * M_PI), 0.0, 1e-12);

    // motion driver on it with f(t) = angle + 2 pi (wraps)
    MotionDriver drv_rev("d", &rev, 0, std::make_shared<Quadratic>(angle + 2 * M_PI - 0.5, 0.5, 0.0));
    ExpectSatisfied(drv_rev, mi, mj, 1.0, "motion on revolute");

    // cylindrical: and a translation s along z_i
    CylindricalJoint cyl("c");
    mj.p_WM = mi.p_WM + s * Ri.col(2);
    ExpectSatisfied(cyl, mi, mj, 0.0, "cylindrical");
    EXPECT_NEAR(cyl.Coordinate(0, mi, mj, nullptr), s, 1e-12);
    EXPECT_NEAR(std::remainder(cyl.Coordinate(1, mi, mj, nullptr) - angle, 2 * M_PI), 0.0, 1e-12);

    // prismatic: same orientation, translation s along z_i
    PrismaticJoint pri("p");
    mj.R_WM = Ri;
    ExpectSatisfied(pri, mi, mj, 0.0, "prismatic");
    EXPECT_NEAR(pri.Coordinate(0, mi, mj, nullptr), s, 1e-12);
    MotionDriver drv_pri("d", &pri, 0, std::make_shared<Quadratic>(s, 0.0, 0.0));
    ExpectSatisfied(drv_pri, mi, mj, 0.3, "motion on prismatic");

    // spherical: same origin, any orientation
    mj = RandomMarker(rng);
    mj.p_WM = mi.p_WM;
    ExpectSatisfied(SphericalJoint("s"), mi, mj, 0.0, "spherical");

    // universal: same origin, z_j perpendicular to z_i
    mj.R_WM = Ri * Rz(angle) * Rx(M_PI / 2) * Rz(3 * u(rng));
    ExpectSatisfied(UniversalJoint("u"), mi, mj, 0.0, "universal");

    // planar: origin j in the x-y plane of i, z_j = z_i
    mj.p_WM = mi.p_WM + Ri * Vec3(x, y, 0.0);
    mj.R_WM = Ri * Rz(angle);
    ExpectSatisfied(PlanarJoint("pl"), mi, mj, 0.0, "planar");

    // distance: any direction at the given length
    mj = RandomMarker(rng);
    mj.p_WM = mi.p_WM + 0.7 * Vec3(u(rng), u(rng), u(rng) + 3.0).normalized();
    ExpectSatisfied(DistanceJoint("dist", 0.7), mi, mj, 0.0, "distance");
  }
}

/// Rigid body with centre of mass away from its frame origin, at a random pose.
std::unique_ptr<RigidBody> RandomBody(const std::string& name, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RigidBodyData d;
  d.mass = 2.0;
  d.inertia_C = Vec3(0.3, 0.4, 0.5).asDiagonal();
  d.c_B = Vec3(0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng));
  d.p_WB = Vec3(u(rng), u(rng), u(rng));
  d.R_WB = ExpSO3(2.0 * Vec3(u(rng), u(rng), u(rng)));
  return std::make_unique<RigidBody>(name, d);
}

/// A chain of five rigid bodies on the ground, joined by every joint type,
/// with off-centre markers at random poses (the joints are not satisfied).
std::unique_ptr<Model> JointChain() {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto m = std::make_unique<Model>();
  int body[6] = {0};
  for (int k = 1; k <= 5; ++k) body[k] = m->AddBody(RandomBody("b" + std::to_string(k), rng));
  int count = 0;
  auto marker = [&](int b) {
    return m->AddMarker(b, "m" + std::to_string(count++), Vec3(u(rng), u(rng), u(rng)),
                        ExpSO3(2.0 * Vec3(u(rng), u(rng), u(rng))));
  };
  auto join = [&](std::unique_ptr<Joint> j, int a, int b) {
    return m->AddJoint(std::move(j), marker(body[a]), marker(body[b]));
  };
  auto f = std::make_shared<Quadratic>(0.2, 0.5, 0.0);
  const int rev = join(std::make_unique<RevoluteJoint>("rev"), 0, 1);
  m->AddJoint(std::make_unique<MotionDriver>("drive_rev", m->joints[rev].get(), 0, f),
              m->joints[rev]->marker_i, m->joints[rev]->marker_j);
  join(std::make_unique<SphericalJoint>("sph"), 1, 2);
  const int pri = join(std::make_unique<PrismaticJoint>("pri"), 2, 3);
  m->AddJoint(std::make_unique<MotionDriver>("drive_pri", m->joints[pri].get(), 0, f),
              m->joints[pri]->marker_i, m->joints[pri]->marker_j);
  join(std::make_unique<CylindricalJoint>("cyl"), 3, 4);
  join(std::make_unique<UniversalJoint>("uni"), 4, 5);
  join(std::make_unique<PlanarJoint>("pla"), 1, 3);
  join(std::make_unique<DistanceJoint>("dis", 0.5), 2, 5);
  join(std::make_unique<FixedJoint>("fix"), 5, 1);
  join(std::make_unique<FixedJoint>("fix_ground"), 4, 0);
  m->Finalize();
  return m;
}

TEST(JointJacobian, AssembledJacobianMatchesFiniteDifferences) {
  auto model = JointChain();
  Workspace ws;
  InitWorkspace(*model, ws);
  State s = model->InitialState();
  s.t = 0.4;
  EvaluateMarkers(*model, s, ws);
  EvaluateConstraints(*model, s, ws);
  const MatX B = MatX(ws.B);
  ASSERT_EQ(B.rows(), model->nc);

  State sp = s;
  VecX dx = VecX::Zero(model->nv);
  MatX B_fd(model->nc, model->nv);
  for (int k = 0; k < model->nv; ++k) {
    dx.setZero();
    dx(k) = kEps;
    RetractAll(*model, s.q, dx, sp.q);
    EvaluateMarkers(*model, sp, ws);
    EvaluateConstraints(*model, sp, ws);
    const VecX phi_p = ws.phi;
    dx(k) = -kEps;
    RetractAll(*model, s.q, dx, sp.q);
    EvaluateMarkers(*model, sp, ws);
    EvaluateConstraints(*model, sp, ws);
    for (int r = 0; r < model->nc; ++r)
      B_fd(r, k) = std::remainder(phi_p(r) - ws.phi(r), 2 * M_PI) / (2 * kEps);
  }
  EXPECT_LT((B - B_fd).cwiseAbs().maxCoeff(), 1e-7) << "B - B_fd:\n" << (B - B_fd);
}

TEST(JointJacobian, AssembledGeometricStiffnessMatchesFiniteDifferences) {
  auto model = JointChain();
  Workspace ws;
  InitWorkspace(*model, ws);
  State s = model->InitialState();
  s.t = 0.4;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int e = 0; e < model->nc; ++e) s.lambda(e) = u(rng);

  // top-left block with only the stiffness term: d(B^T lambda)/dq (rigid
  // bodies without force elements contribute no dQ/dq)
  EvaluateMarkers(*model, s, ws);
  EvaluateConstraints(*model, s, ws);
  EvaluateForces(*model, s, ws, true);
  MatrixCoefficients c;
  c.mass = 0.0;
  c.damping = 0.0;
  c.stiffness = 1.0;
  c.geometric = true;
  AssembleIterationMatrix(*model, s, ws, c);
  const MatX K = MatX(ws.S).topLeftCorner(model->nv, model->nv);

  auto reaction = [&](const VecX& q) {
    State sp = s;
    sp.q = q;
    EvaluateMarkers(*model, sp, ws);
    EvaluateConstraints(*model, sp, ws);
    return VecX(MatX(ws.B).transpose() * s.lambda);
  };
  VecX dx = VecX::Zero(model->nv), qp(model->nq), qm(model->nq);
  MatX K_fd(model->nv, model->nv);
  for (int k = 0; k < model->nv; ++k) {
    dx.setZero();
    dx(k) = kEps;
    RetractAll(*model, s.q, dx, qp);
    dx(k) = -kEps;
    RetractAll(*model, s.q, dx, qm);
    K_fd.col(k) = (reaction(qp) - reaction(qm)) / (2 * kEps);
  }
  EXPECT_LT((K - K_fd).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, K_fd.cwiseAbs().maxCoeff()))
      << "K - K_fd:\n" << (K - K_fd);
}

}  // namespace
}  // namespace flexmb
