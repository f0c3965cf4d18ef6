#include "flexmb/fe/point_mass.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "flexmb/common/error.h"

namespace flexmb::fe {
namespace {

// the node velocity (v, w) moves the rigid mass: its kinetic energy is
// 1/2 m |v + w x d|^2 + 1/2 w^T I_c w, independently of the matrix form
TEST(PointMass, KineticEnergyOfTheRigidMass) {
  PointMass pm;
  pm.mass = 3.7;
  pm.offset = Vec3(0.3, -1.2, 0.8);
  Mat3 a;
  a << 0.9, 0.1, -0.2, 0.1, 1.4, 0.3, -0.2, 0.3, 2.1;
  pm.inertia = a;
  const Mat6 m = PointMassMatrix(pm);
  EXPECT_LT((m - m.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Matrix<double, 6, 1> nu = Eigen::Matrix<double, 6, 1>::Random();
    const Vec3 v = nu.head<3>(), w = nu.tail<3>();
    const double reference = 0.5 * pm.mass * (v + w.cross(pm.offset)).squaredNorm() + 0.5 * w.dot(pm.inertia * w);
    EXPECT_NEAR(0.5 * nu.dot(m * nu), reference, 1e-13 * reference);
  }
}

TEST(PointMass, RejectsBadData) {
  PointMass pm;
  pm.id = 42;
  pm.origin = {"model.bdf", 17};
  pm.mass = -1.0;
  try {
    PointMassMatrix(pm);
    FAIL() << "negative mass accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("model.bdf:17"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("point mass 42"), std::string::npos) << e.what();
  }
  pm.mass = 1.0;
  pm.inertia << 1, 0.5, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_THROW(PointMassMatrix(pm), InputError);
  pm.inertia = Mat3::Identity();
  pm.inertia(2, 2) = -1.0;
  EXPECT_THROW(PointMassMatrix(pm), InputError);
}

}  // namespace
}  // namespace flexmb::fe
