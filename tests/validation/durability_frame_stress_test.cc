// Stress recovery from the modal coordinates (durability/stress_recovery.h)
// of the truck's elastic frame against the full FE model's static solution
// (docs/validation.md, "Durability"): the frame clamped at its four spring
// seats, the cab, powertrain and cargo weights on their mount nodes (the
// lever-rule shares of truck_frame_test.cc). Reference: the direct sparse
// solution of the full clamped FE model and the element stresses of its
// displacements (the same element recovery, fe/elements/). The reduced
// solution uses the body's reduced stiffness and its rigid-body and modal
// coordinates with the seats as constraints; its stresses come from the
// stress modes in a batch, as "flexmb post" recovers them.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/durability/element_fatigue.h"
#include "flexmb/durability/modal_history.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/sparse_cholesky.h"
#include "flexmb/reduction/stress_modes.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace durability_frame_stress_test {

constexpr double kStressG = 9.81;

struct StressFixture {
  TruckData d;
  std::vector<int> seats;
  std::vector<std::pair<int, double>> loads;  // node, downward force [N]
};

StressFixture MakeStressFixture(const fe::Mesh& mesh) {
  StressFixture x;
  x.d = LoadLaneChangeTruck(TruckFile());
  for (const FrameAttachment& a : FrameAttachments(x.d, kStressG))
    if (a.name.rfind("spring_seat", 0) == 0) x.seats.push_back(NearestNode(mesh, a.point));
  const PartData* parts[3] = {&x.d.cab, &x.d.powertrain, &x.d.cargo};
  const MountData* mounts[3] = {&x.d.cab_mounts, &x.d.powertrain_mounts, &x.d.cargo_mounts};
  for (int p = 0; p < 3; ++p) {
    const double n = 2.0 * static_cast<double>(mounts[p]->x.size());
    double xm = 0, sxx = 0;
    for (double xs : mounts[p]->x) xm += 2 * xs / n;
    for (double xs : mounts[p]->x) sxx += 2 * (xs - xm) * (xs - xm);
    const double top = x.d.ladder.bottom_z + x.d.ladder.web_height;
    for (double xs : mounts[p]->x)
      for (double side : {1.0, -1.0}) {
        const double share = 1.0 / n + (sxx > 0 ? (parts[p]->cg.x() - xm) * (xs - xm) / sxx : 0.0);
        x.loads.emplace_back(NearestNode(mesh, Vec3(xs, side * x.d.ladder.half_spacing, top)),
                             share * parts[p]->mass * kStressG);
      }
  }
  return x;
}

// element von Mises (largest of bottom and top) of the full clamped FE model
Eigen::VectorXd FullStress(const reduction::ReducedBody& b, const StressFixture& f) {
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = f.seats;
  const fe::AssembledModel a = fe::Assemble(b.mesh, o);
  Eigen::VectorXd f_full = Eigen::VectorXd::Zero(a.M_full.rows());
  for (const auto& [node, force] : f.loads) f_full(a.dofs.full[static_cast<size_t>(node)][2]) -= force;
  fe::SparseCholesky chol;
  chol.Factorize(a.K, "K");
  const Eigen::VectorXd u_full = a.T * chol.Solve(a.T.transpose() * f_full);
  Eigen::MatrixXd U = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(b.mesh.nodes.size()), 1);
  for (size_t k = 0; k < b.mesh.nodes.size(); ++k)
    for (int c = 0; c < 6; ++c)
      if (a.dofs.full[k][c] >= 0) U(6 * static_cast<Eigen::Index>(k) + c, 0) = u_full(a.dofs.full[k][c]);
  const reduction::StressModes s = reduction::ComputeStressModes(b.mesh, U);
  Eigen::VectorXd values, vm;
  reduction::ElementVonMises(s.shell, Eigen::VectorXd::Ones(1), values, vm);
  return vm;
}

// modal coordinates of the reduced static solution: rigid-body and modal
// coordinates, the seats' six displacements as Lagrange constraints
Eigen::VectorXd ReducedModal(const reduction::ReducedBody& b, const StressFixture& f) {
  const int n = b.invariants.n, nc = 6 + n, ns = static_cast<int>(f.seats.size());
  auto basis = [&](int k) {
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, nc);
    const Vec3 x = b.mesh.nodes[static_cast<size_t>(k)].x;
    B.block<3, 3>(0, 0).setIdentity();
    Mat3 sk;
    sk << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
    B.block<3, 3>(0, 3) = -sk;
    B.block<3, 3>(3, 3).setIdentity();
    B.block(0, 6, 6, n) = b.modes.block(6 * k, 0, 6, n);
    return B;
  };
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nc + 6 * ns, nc + 6 * ns);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(K.rows());
  K.block(6, 6, n, n) = b.stiffness;
  for (const auto& [node, force] : f.loads) rhs.head(nc) += basis(node).topRows<3>().transpose() * Vec3(0, 0, -force);
  const double scale = std::sqrt(b.stiffness.diagonal().maxCoeff());
  for (int s = 0; s < ns; ++s) {
    const Eigen::MatrixXd B = scale * basis(f.seats[static_cast<size_t>(s)]);
    K.block(nc + 6 * s, 0, 6, nc) = B;
    K.block(0, nc + 6 * s, nc, 6) = B.transpose();
  }
  return K.partialPivLu().solve(rhs).segment(6, n);
}

// largest relative difference over the 10 hot spots of the full model
double HotSpotError(const reduction::ReducedBody& b, const StressFixture& f, int normal_modes) {
  const Eigen::VectorXd full = FullStress(b, f);
  const Eigen::MatrixXd W = ReducedModal(b, f);
  durability::StressRecovery rec(b.stress.shell, W);
  durability::FatigueOptions opt;
  const durability::ElementResults r = durability::AnalyzeElements(rec, opt);
  std::vector<int> order(static_cast<size_t>(full.size()));
  std::iota(order.begin(), order.end(), 0);
  std::partial_sort(order.begin(), order.begin() + 10, order.end(), [&](int a, int c) { return full(a) > full(c); });
  double worst = 0;
  for (int i = 0; i < 10; ++i) {
    const int k = order[static_cast<size_t>(i)];
    worst = std::max(worst, std::abs(r.max_von_mises[static_cast<size_t>(k)] - full(k)) / full(k));
  }
  std::printf("%d normal modes (%d modal coordinates): hot spot %d full %.3f MPa, reduced %.3f MPa; largest "
              "difference over the 10 hot spots %.2e\n",
              normal_modes, b.invariants.n, b.mesh.elements[static_cast<size_t>(b.stress.shell.elements[order[0]])].id,
              full(order[0]) * 1e-6, r.max_von_mises[static_cast<size_t>(order[0])] * 1e-6, worst);
  EXPECT_GT(full(order[0]), 1e6);  // a real stress, not a clamped nothing
  return worst;
}

TEST(DurabilityFrameStress, MountLoadsRecoveredFromStaticModesMatchFullFe) {
  // Guyan: the static modes of the interface (mount, seat, pivot) nodes alone
  FrameReductionData guyan;
  guyan.normal_modes = 0;
  const TruckData d = LoadLaneChangeTruck(TruckFile());
  const auto body = ReduceTruckFrame(d, guyan);
  const StressFixture f = MakeStressFixture(body->mesh);
  ASSERT_EQ(f.seats.size(), 4u);
  EXPECT_LT(HotSpotError(*body, f, 0), 0.02);
}

// the elastic truck's lane change keeps the frame's modal coordinates; the
// stresses recovered from them afterwards give the run's own frame maximum
// (FrameResponse of lane_change_test.cc, evaluated during the run): same
// value, element and time; the history refers to the run's DIR/frame.h5
TEST(DurabilityFrameStress, LaneChangeModalCoordinatesGiveTheRunsFrameMaximum) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("flexmb_durability_lane_change_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  LaneChangeOptions o;
  o.file = TruckFile();
  o.out_dir = dir.string();
  o.frame = "elastic";
  o.speed_kmh = 55.0;
  o.stop_distance = 50.0;
  const LaneChangeResult r = RunLaneChange(o);
  ASSERT_TRUE(r.completed) << r.message;
  const durability::ModalHistory h = durability::ReadRunModalHistory(dir.string());
  const int b = h.Body("frame");
  // the history refers to the frame's body file the run wrote (DIR/frame.h5), not to a second copy
  EXPECT_EQ(h.bodies[static_cast<size_t>(b)].body_file, (dir / "frame.h5").string());
  EXPECT_FALSE(std::filesystem::exists(dir / "bodies"));
  const reduction::ReducedBody body = io::ReadBody(h.bodies[static_cast<size_t>(b)].body_file);
  durability::StressRecovery rec(body.stress.shell, h.coordinates[static_cast<size_t>(b)]);
  const durability::ElementResults e = durability::AnalyzeElements(rec, durability::FatigueOptions{});
  const auto k = std::max_element(e.max_von_mises.begin(), e.max_von_mises.end()) - e.max_von_mises.begin();
  const int element = body.mesh.elements[static_cast<size_t>(body.stress.shell.elements[static_cast<size_t>(k)])].id;
  const double t = h.times[static_cast<size_t>(e.max_von_mises_instant[static_cast<size_t>(k)])];
  std::printf("run: %.4f MPa in element %d at %.3f s; post: %.4f MPa in element %d at %.3f s (%zu instants)\n",
              r.max_frame_stress * 1e-6, r.max_stress_element, r.max_stress_time, e.max_von_mises[static_cast<size_t>(k)] * 1e-6,
              element, t, h.times.size());
  EXPECT_NEAR(e.max_von_mises[static_cast<size_t>(k)], r.max_frame_stress, 1e-9 * r.max_frame_stress);
  EXPECT_EQ(element, r.max_stress_element);
  EXPECT_EQ(t, r.max_stress_time);
  std::filesystem::remove_all(dir);
}

}  // namespace durability_frame_stress_test
}  // namespace flexmb::vehicle::testing
