// fe::FaceShapeFunctions and fe::ProjectOntoFace: the shape functions are 1
// at their own node and 0 at the others, sum to 1 everywhere, and their
// derivatives equal central differences; a point built at a known distance
// along the normal above a known point of a curved face is projected back
// onto that point; a point beyond an edge is clamped to the edge with the
// right normal and in-face distances.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "flexmb/fe/face_projection.h"

namespace flexmb::fe {
namespace {

// face coordinates of the nodes, Abaqus face order
std::vector<std::array<double, 2>> NodeCoordinates(int count) {
  if (count == 3) return {{0, 0}, {1, 0}, {0, 1}};
  if (count == 6) return {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  if (count == 4) return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
}

// a face of `count` nodes: the reference coordinates mapped to a curved,
// tilted surface (mid-side nodes bulged for 6 and 8 nodes)
std::vector<Vec3> CurvedFace(int count) {
  std::vector<Vec3> x;
  for (const auto& c : NodeCoordinates(count)) {
    const double u = c[0], v = c[1];
    x.push_back(Vec3(0.3 + 0.5 * u + 0.1 * v, 0.2 * u + 0.45 * v, 0.1 * u - 0.05 * v + 0.08 * (u * u + v * v)));
  }
  return x;
}

class FaceShapes : public ::testing::TestWithParam<int> {};

TEST_P(FaceShapes, KroneckerPartitionOfUnityAndDerivatives) {
  const int count = GetParam();
  const auto nodes = NodeCoordinates(count);
  std::array<double, 8> n{}, np{}, nm{};
  std::array<std::array<double, 2>, 8> dn{}, scratch{};
  for (int k = 0; k < count; ++k) {
    FaceShapeFunctions(count, nodes[k][0], nodes[k][1], n, dn);
    for (int j = 0; j < count; ++j) EXPECT_NEAR(n[j], j == k ? 1.0 : 0.0, 1e-15) << "node " << k << " N" << j;
  }
  const double xi = count == 3 || count == 6 ? 0.21 : 0.37, eta = count == 3 || count == 6 ? 0.33 : -0.52;
  FaceShapeFunctions(count, xi, eta, n, dn);
  double sum = 0.0;
  for (int j = 0; j < count; ++j) sum += n[j];
  EXPECT_NEAR(sum, 1.0, 1e-15);
  const double h = 1e-6;
  for (int dir = 0; dir < 2; ++dir) {
    FaceShapeFunctions(count, xi + (dir == 0 ? h : 0), eta + (dir == 1 ? h : 0), np, scratch);
    FaceShapeFunctions(count, xi - (dir == 0 ? h : 0), eta - (dir == 1 ? h : 0), nm, scratch);
    for (int j = 0; j < count; ++j) EXPECT_NEAR(dn[j][dir], (np[j] - nm[j]) / (2 * h), 1e-9) << "N" << j << " d" << dir;
  }
}

TEST_P(FaceShapes, PointAboveTheFaceProjectsBackOntoIt) {
  const int count = GetParam();
  const std::vector<Vec3> x = CurvedFace(count);
  const bool tri = count == 3 || count == 6;
  for (const auto& c : std::vector<std::array<double, 2>>{{0.2, 0.3}, {0.6, 0.1}, {0.05, 0.9}}) {
    const double xi = tri ? c[0] : 2 * c[0] - 0.5, eta = tri ? c[1] : 2 * c[1] - 0.9;
    std::array<double, 8> n{};
    std::array<std::array<double, 2>, 8> dn{};
    FaceShapeFunctions(count, xi, eta, n, dn);
    Vec3 at = Vec3::Zero(), t1 = Vec3::Zero(), t2 = Vec3::Zero();
    for (int k = 0; k < count; ++k) {
      at += n[k] * x[k];
      t1 += dn[k][0] * x[k];
      t2 += dn[k][1] * x[k];
    }
    const double d = 0.013;
    const Vec3 p = at + d * t1.cross(t2).normalized();
    const FaceProjection r = ProjectOntoFace(x, p);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.xi, xi, 1e-10);
    EXPECT_NEAR(r.eta, eta, 1e-10);
    EXPECT_NEAR(r.normal_distance, d, 1e-12);
    EXPECT_EQ(r.outside, 0.0);
    EXPECT_LT((r.point - at).norm(), 1e-12);
    Vec3 from_weights = Vec3::Zero();
    for (int k = 0; k < count; ++k) from_weights += r.weights[k] * x[k];
    EXPECT_LT((from_weights - at).norm(), 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(Counts, FaceShapes, ::testing::Values(3, 4, 6, 8));

TEST(FaceProjection, BeyondAnEdgeIsClampedToTheEdge) {
  // unit square at z = 0 and its two triangles
  const std::vector<Vec3> quad = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  const FaceProjection q = ProjectOntoFace(quad, Vec3(1.2, 0.5, 0.3));
  ASSERT_TRUE(q.converged);
  EXPECT_NEAR(q.normal_distance, 0.3, 1e-14);
  EXPECT_NEAR(q.outside, 0.2, 1e-14);
  EXPECT_LT((q.point - Vec3(1, 0.5, 0)).norm(), 1e-14);
  EXPECT_NEAR(q.weights[1] + q.weights[2], 1.0, 1e-14);
  const std::vector<Vec3> tri = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const FaceProjection t = ProjectOntoFace(tri, Vec3(0.7, 0.7, -0.1));
  ASSERT_TRUE(t.converged);
  EXPECT_NEAR(t.normal_distance, 0.1, 1e-14);
  EXPECT_NEAR(t.outside, std::sqrt(2.0) * 0.2, 1e-14);
  EXPECT_LT((t.point - Vec3(0.5, 0.5, 0)).norm(), 1e-14);
  // a face of zero area does not converge
  const std::vector<Vec3> flat = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  EXPECT_FALSE(ProjectOntoFace(flat, Vec3(0.5, 0.5, 0)).converged);
}

}  // namespace
}  // namespace flexmb::fe
