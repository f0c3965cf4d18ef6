// The truck's elastic ladder frame (issue 7): the Craig-Bampton body of the
// generated shell frame against the full FE model of the same mesh.
// 1. Static sag: the frame clamped at its four spring seats under its own
//    weight and the cab, powertrain and cargo weights at their mount nodes
//    (lever-rule shares, as the mounts' preloads). Reduced solution from the
//    body file alone (modes, reduced stiffness, inertia invariants; rigid-
//    body motions added back, supports as constraints) against the direct
//    sparse solution of the full clamped FE model (independent reference).
//    The mount loads act on interface nodes, where the static modes make the
//    reduced solution exact; the self weight is carried by the 10
//    fixed-interface modes only approximately.
// 3. The frame in the standing truck (issue 18): the static equilibrium
//    of the truck with the elastic frame on its tires (SolveStatics), every
//    wrench the truck's springs, mounts, stabilizers and joints apply to the
//    frame's nodes collected from the model, and the full FE model of the
//    same mesh solved under these forces and the frame's own weight (one
//    seat node clamped; the loads balance, so its reaction vanishes). The
//    deformations (rigid motion removed by least squares over all nodes)
//    agree as in 1.: the mount forces act on interface nodes.
// 2. The rigid frame's mass properties (ShellMassProperties, by quadrature)
//    equal the reduced body's inertia invariants (from the FE mass matrix),
//    and the steel mass equals the plates' areas times thickness and density.
// docs/validation.md, "Truck elastic frame".
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <filesystem>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/fe/assembly.h"
#include "flexmb/fe/sparse_cholesky.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/solver/assembler.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/statics.h"
#include "flexmb/vehicle/ladder_frame.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_frame_test {

constexpr double kG = 9.81;

struct Fixture {
  TruckData d;
  reduction::ReducedBody body;  // read back from the body file
  std::vector<int> seats;       // spring-seat nodes
  std::vector<std::pair<int, double>> loads;  // node, downward force [N]
};

// the truck of `file` with its frame reduced and read back from a body file
Fixture LoadFixture(const std::string& file, bool acceleration_modes = false) {
  Fixture x;
  x.d = LoadLaneChangeTruck(file);
  FrameReductionData r;
  r.acceleration_modes = acceleration_modes;
  const auto reduced = ReduceTruckFrame(x.d, r);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("flexmb_truck_frame_test_" + std::to_string(::getpid()) + ".h5"))
          .string();
  io::WriteBody(*reduced, path);
  x.body = io::ReadBody(path);
  std::filesystem::remove(path);
  // part weights shared by the lever rule over their mounts, as BuildTruck's preloads
  for (const FrameAttachment& a : FrameAttachments(x.d, kG)) {
    const int node = NearestNode(x.body.mesh, a.point);
    if (a.name.rfind("spring_seat", 0) == 0) x.seats.push_back(node);
  }
  for (const auto& [name, part, mounts] :
       {std::tuple<std::string, const PartData*, const MountData*>{"cab", &x.d.cab, &x.d.cab_mounts},
        {"powertrain", &x.d.powertrain, &x.d.powertrain_mounts},
        {"cargo", &x.d.cargo, &x.d.cargo_mounts}}) {
    const double n = 2.0 * static_cast<double>(mounts->x.size());
    double xm = 0, sxx = 0;
    for (double xs : mounts->x) xm += 2 * xs / n;
    for (double xs : mounts->x) sxx += 2 * (xs - xm) * (xs - xm);
    // the cargo on a platform's top, the rest on the rails
    const double top = part == &x.d.cargo && x.d.ladder.platform.present
                           ? PlatformTopZ(x.d.ladder)
                           : x.d.ladder.bottom_z + x.d.ladder.web_height;
    for (double xs : mounts->x)
      for (double side : {1.0, -1.0}) {
        const double share = 1.0 / n + (sxx > 0 ? (part->cg.x() - xm) * (xs - xm) / sxx : 0.0);
        x.loads.emplace_back(NearestNode(x.body.mesh, Vec3(xs, side * x.d.ladder.half_spacing, top)),
                             share * part->mass * kG);
      }
  }
  return x;
}

const Fixture& Frame() {
  static const Fixture f = LoadFixture(TruckFile());
  return f;
}

// the 6x4 with its platform on brackets (the cargo on the platform)
const Fixture& Frame6x4() {
  static const Fixture f = LoadFixture(std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_6x4/truck.yaml");
  return f;
}

// z displacement of every node [m]: full FE, clamped seats, direct solution
Eigen::VectorXd FullSag(const Fixture& f) {
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = f.seats;
  const fe::AssembledModel a = fe::Assemble(f.body.mesh, o);
  // gravity: M_full times the unit z translation of every node, to the free DOF
  Eigen::VectorXd ez = Eigen::VectorXd::Zero(a.M_full.rows());
  for (const auto& dofs : a.dofs.full)
    if (dofs[2] >= 0) ez(dofs[2]) = 1.0;
  Eigen::VectorXd f_full = -kG * (a.M_full * ez);
  for (const auto& [node, force] : f.loads) f_full(a.dofs.full[static_cast<size_t>(node)][2]) -= force;
  const Eigen::VectorXd rhs = a.T.transpose() * f_full;
  fe::SparseCholesky chol;
  chol.Factorize(a.K, "K");
  const Eigen::VectorXd u_free = chol.Solve(rhs);
  const Eigen::VectorXd u_full = a.T * u_free;
  Eigen::VectorXd uz = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(f.body.mesh.nodes.size()));
  for (size_t k = 0; k < f.body.mesh.nodes.size(); ++k)
    if (a.dofs.full[k][2] >= 0) uz(static_cast<Eigen::Index>(k)) = u_full(a.dofs.full[k][2]);
  return uz;
}

// the same from the body file: coordinates (translation, rotation about the
// origin, modal), supports as Lagrange constraints
Eigen::VectorXd ReducedSag(const Fixture& f) {
  const reduction::ReducedBody& b = f.body;
  const reduction::InertiaInvariants& inv = b.invariants;
  const int n = inv.n, nc = 6 + n;
  const Vec3 g(0, 0, -kG);
  // node k's 6 displacements per unit coordinate
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
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nc + 6 * static_cast<int>(f.seats.size()), nc + 6 * static_cast<int>(f.seats.size()));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(K.rows());
  K.block(6, 6, n, n) = b.stiffness;
  rhs.segment<3>(0) = inv.mvv * g;
  rhs.segment<3>(3) = inv.mvo0.transpose() * g;
  rhs.segment(6, n) = inv.mvw.transpose() * g;
  for (const auto& [node, force] : f.loads) rhs.head(nc) += basis(node).topRows<3>().transpose() * Vec3(0, 0, -force);
  // constraint rows scaled to the stiffness (the modes are mass-normalized)
  const double scale = std::sqrt(b.stiffness.diagonal().maxCoeff());
  for (size_t s = 0; s < f.seats.size(); ++s) {
    const Eigen::MatrixXd B = scale * basis(f.seats[s]);
    K.block(nc + 6 * static_cast<int>(s), 0, 6, nc) = B;
    K.block(0, nc + 6 * static_cast<int>(s), nc, 6) = B.transpose();
  }
  const Eigen::VectorXd q = K.partialPivLu().solve(rhs).head(nc);
  Eigen::VectorXd uz(static_cast<Eigen::Index>(b.mesh.nodes.size()));
  for (int k = 0; k < static_cast<int>(b.mesh.nodes.size()); ++k) uz(k) = basis(k).row(2).dot(q);
  return uz;
}

TEST(TruckFrameValidation, StaticSagFromBodyFileEqualsFullFe) {
  const Fixture& f = Frame();
  ASSERT_EQ(f.seats.size(), 4u);
  const Eigen::VectorXd full = FullSag(f), red = ReducedSag(f);
  Eigen::Index kmax = 0;
  const double sag = full.cwiseAbs().maxCoeff(&kmax);
  const double err = (full - red).cwiseAbs().maxCoeff();
  double err_mounts = 0;
  for (const auto& [node, force] : f.loads) err_mounts = std::max(err_mounts, std::abs(full(node) - red(node)));
  std::printf("static sag: full FE %.4f mm at node %d (x = %.2f m), reduced %.4f mm; max difference %.2e mm "
              "(mount nodes %.2e mm)\n",
              sag * 1e3, f.body.mesh.nodes[static_cast<size_t>(kmax)].id,
              f.body.mesh.nodes[static_cast<size_t>(kmax)].x.x(), red(kmax) * 1e3, err * 1e3, err_mounts * 1e3);
  std::printf("(signed: full FE %.4f mm)\n", full(kmax) * 1e3);
  for (int k : f.seats) EXPECT_LT(std::abs(red(k)), 1e-9) << "seat node " << k;
  EXPECT_GT(sag, 1e-4);  // a real sag, not a clamped nothing
  // the self weight inside the frame: 10 fixed-interface modes (measured 0.34 %)
  EXPECT_LT(err, 0.01 * sag);
  // the loaded nodes are interface nodes: exact up to round-off
  EXPECT_LT(err_mounts, 1e-6 * sag);
}

// with the acceleration modes (ReductionOptions::acceleration_modes) the
// self weight's response with the interface held is in the basis: the
// reduced sag equals the full FE model's everywhere, not only at the loaded
// interface nodes
TEST(TruckFrameValidation, StaticSagWithAccelerationModesIsExact) {
  static const Fixture f = LoadFixture(TruckFile(), true);
  const Eigen::VectorXd full = FullSag(f), red = ReducedSag(f);
  const double sag = full.cwiseAbs().maxCoeff();
  const double err = (full - red).cwiseAbs().maxCoeff();
  std::printf("static sag with acceleration modes: full FE %.4f mm, largest difference %.2e mm (%.1e of the sag; "
              "without them %.2e mm)\n",
              sag * 1e3, err * 1e3, err / sag, (full - ReducedSag(Frame())).cwiseAbs().maxCoeff() * 1e3);
  EXPECT_GT(sag, 1e-4);
  EXPECT_LT(err, 1e-6 * sag);
}

// node translations with the rigid motion that fits them best (least
// squares over all nodes: a + theta x x_k) removed
std::vector<Vec3> Deformation(const std::vector<Vec3>& u, const fe::Mesh& mesh) {
  Eigen::Matrix<double, 6, 6> N = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> r = Eigen::Matrix<double, 6, 1>::Zero();
  auto A = [&](size_t k) {
    Eigen::Matrix<double, 3, 6> a;
    const Vec3 x = mesh.nodes[k].x;
    Mat3 sk;
    sk << 0, -x.z(), x.y(), x.z(), 0, -x.x(), -x.y(), x.x(), 0;
    a << Mat3::Identity(), -sk;
    return a;
  };
  for (size_t k = 0; k < u.size(); ++k) {
    N += A(k).transpose() * A(k);
    r += A(k).transpose() * u[k];
  }
  const Eigen::Matrix<double, 6, 1> p = N.ldlt().solve(r);
  std::vector<Vec3> d(u.size());
  for (size_t k = 0; k < u.size(); ++k) d[k] = u[k] - A(k) * p;
  return d;
}

// the frame's deformation in the standing truck against the full FE model
struct StandingTruckDeformation {
  double scale = 0;         ///< largest deformation of the full FE model [m]
  double rails_error = 0;   ///< largest difference on the rails and cross members [m]
  double platform_error = 0;  ///< largest difference on the platform (its brackets included) [m]
};

// (fills *out; ASSERTs leave it as it was); the rails' difference must stay
// below `rails_tolerance` of the largest deformation
void CheckStandingTruck(const Fixture& f, double rails_tolerance, StandingTruckDeformation* out) {
  TruckData d = f.d;
  d.elastic_frame = std::make_shared<reduction::ReducedBody>(f.body);
  Model m;
  auto zero = std::make_shared<double>(0.0);
  const TruckHandles h = BuildTruck(d, 0.0, 0.8, zero, zero, m);
  m.Finalize();
  State s = m.InitialState();
  Workspace ws;
  MakeConsistent(m, s, ws);
  const StaticsResult st = SolveStatics(m, s, ws, TruckStaticsSettings());
  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, false);
  ASSERT_TRUE(h.elastic);
  const auto& frame = static_cast<const FlexibleBody&>(*m.bodies[static_cast<size_t>(h.frame_body)]);
  const double* q = s.q.data() + frame.q_offset;
  Vec3 p_WB;
  Mat3 R_WB;
  frame.BodyFramePose(q, p_WB, R_WB);
  const fe::Mesh& mesh = f.body.mesh;
  const size_t nn = mesh.nodes.size();

  // every wrench on the frame, moved to its marker's node, body axes
  std::vector<Vec6> load(nn, Vec6::Zero());
  int loaded_markers = 0;
  auto add = [&](int marker, const Vec6& w_W) {
    const Marker& mk = m.markers[static_cast<size_t>(marker)];
    if (mk.body != h.frame_body || w_W.isZero(0.0)) return;
    ASSERT_GE(mk.node, 0) << "a load on frame marker " << mk.name << " without a node";
    const Vec3 lever = ws.markers[static_cast<size_t>(marker)].p_WM - frame.NodePosition(q, mk.node);
    load[static_cast<size_t>(mk.node)].head<3>() += R_WB.transpose() * w_W.head<3>();
    load[static_cast<size_t>(mk.node)].tail<3>() += R_WB.transpose() * (w_W.tail<3>() + lever.cross(w_W.head<3>()));
    ++loaded_markers;
  };
  for (size_t i = 0; i < m.forces.size(); ++i) {
    const ForceElement& el = *m.forces[i];
    for (int a = 0; a < el.NumMarkers(); ++a) add(el.MarkerAt(a), MarkerWrench(ws.forces[i], el.NumMarkers(), a));
  }
  for (size_t j = 0; j < m.joints.size(); ++j) {
    const Joint& jt = *m.joints[j];
    const JointEval& e = ws.joints[j];
    Vec6 wi = Vec6::Zero(), wj = Vec6::Zero();
    for (int k = 0; k < jt.NumEquations(); ++k) {
      const double lam = s.lambda(jt.lambda_offset + k);
      wi -= lam * e.D.block<1, 6>(k, 0).transpose();
      wj -= lam * e.D.block<1, 6>(k, 6).transpose();
    }
    add(jt.marker_i, wi);
    add(jt.marker_j, wj);
  }
  // the frame's weight balances them (the equilibrium holds, nothing missed)
  const Vec3 g_B = R_WB.transpose() * m.gravity_W;
  Vec3 total = f.body.invariants.mvv * g_B;
  for (const Vec6& w : load) total += w.head<3>();
  const double weight = f.body.invariants.mvv(0, 0) * kG;
  std::printf("standing truck: %d statics iterations, %d loaded frame markers; frame weight %.0f N, force balance "
              "%.2e N\n", st.iterations, loaded_markers, weight, total.norm());
  EXPECT_GE(loaded_markers, 26);
  EXPECT_LT(total.norm(), 1e-6 * weight);

  // full FE under these loads and the weight, one spring seat clamped
  fe::AssemblyOptions o;
  o.extra_fixed_nodes = {f.seats[0]};
  const fe::AssembledModel a = fe::Assemble(mesh, o);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(a.M_full.rows());
  for (const auto& dofs : a.dofs.full)
    for (int c = 0; c < 3; ++c)
      if (dofs[static_cast<size_t>(c)] >= 0) unit(dofs[static_cast<size_t>(c)]) = g_B(c);
  Eigen::VectorXd f_full = a.M_full * unit;
  for (size_t k = 0; k < nn; ++k)
    for (int c = 0; c < 6; ++c)
      if (load[k](c) != 0.0) {
        const int dof = a.dofs.full[k][static_cast<size_t>(c)];
        ASSERT_GE(dof, 0) << "node " << mesh.nodes[k].id << " component " << c;
        f_full(dof) += load[k](c);
      }
  fe::SparseCholesky chol;
  chol.Factorize(a.K, "K");
  const Eigen::VectorXd u = a.T * chol.Solve(a.T.transpose() * f_full);
  std::vector<Vec3> u_full(nn), u_red(nn);
  for (size_t k = 0; k < nn; ++k) {
    for (int c = 0; c < 3; ++c) u_full[k](c) = u(a.dofs.full[k][static_cast<size_t>(c)]);
    u_red[k] = frame.NodeDisplacement(q, static_cast<int>(k));
  }
  const std::vector<Vec3> def_full = Deformation(u_full, mesh), def_red = Deformation(u_red, mesh);
  // nodes of the rails and cross members, the rest is the platform
  std::vector<char> rail(nn, 0);
  for (const fe::Element& e : mesh.elements)
    if (e.property <= kCrossMemberSection)
      for (int n : e.nodes) rail[static_cast<size_t>(n)] = 1;
  StandingTruckDeformation r;
  size_t kmax = 0;
  for (size_t k = 0; k < nn; ++k) {
    if (def_full[k].norm() > r.scale) r.scale = def_full[k].norm(), kmax = k;
    double& err = rail[k] ? r.rails_error : r.platform_error;
    err = std::max(err, (def_full[k] - def_red[k]).norm());
  }
  std::printf("frame deformation in the standing truck: full FE %.4f mm at node %d (x = %.2f m), in the truck "
              "%.4f mm; largest difference on the rails %.2e mm (%.2f %%), on the platform %.2e mm (%.2f %%)\n",
              r.scale * 1e3, mesh.nodes[kmax].id, mesh.nodes[kmax].x.x(), def_red[kmax].norm() * 1e3,
              r.rails_error * 1e3, 100 * r.rails_error / r.scale, r.platform_error * 1e3,
              100 * r.platform_error / r.scale);
  EXPECT_GT(r.scale, 1e-4);  // millimetres, not nothing
  EXPECT_LT(r.scale, 0.05);
  // as test 1: the self weight carried by the fixed-interface modes
  EXPECT_LT(r.rails_error, rails_tolerance * r.scale);
  *out = r;
}

TEST(TruckFrameValidation, DeflectionInTheStandingTruckEqualsFullFeUnderItsMountForces) {
  StandingTruckDeformation r;
  CheckStandingTruck(Frame(), 0.01, &r);
  EXPECT_EQ(r.platform_error, 0.0);  // no platform
}

// the 6x4: three axles on a balancer bogie, the cargo on the platform whose
// brackets take its load to the rails; the rails agree as the 4x2's. The
// platform's own sag under its smeared deck mass, away from the interface
// nodes, is carried by the fixed-interface modes only and is reported, not
// held to the rails' bound (about 6 % of the largest deformation with 10 or
// 40 modes: the overhanging bearers' local bending; examples/truck_6x4/README.md).
TEST(TruckFrameValidation, FrameAndPlatformOfThe6x4InTheStandingTruckEqualFullFe) {
  StandingTruckDeformation r;
  CheckStandingTruck(Frame6x4(), 0.01, &r);
  EXPECT_GT(r.platform_error, 0.0);  // the platform's nodes were compared
}

// with the acceleration modes the platform's sag under its own distributed
// mass is in the basis: the platform agrees with the full FE model as the
// rails do, its difference falls by more than ten times. What is left (about
// 0.2 % on the rails) is not the basis (in a clamped frame under its weight
// the acceleration modes are exact to 1e-10: StaticSagWithAccelerationModesIsExact)
// but the truck: its loads act on the deformed frame.
TEST(TruckFrameValidation, FrameAndPlatformWithAccelerationModesEqualFullFe) {
  const Fixture f = LoadFixture(std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_6x4/truck.yaml", true);
  StandingTruckDeformation with, without;
  CheckStandingTruck(f, 0.01, &with);
  CheckStandingTruck(Frame6x4(), 0.01, &without);
  EXPECT_LT(with.platform_error, 0.01 * with.scale);
  EXPECT_LT(with.platform_error, 0.1 * without.platform_error);
}

TEST(TruckFrameValidation, RigidFrameMassPropertiesEqualTheReducedBody) {
  const Fixture& f = Frame();
  const reduction::InertiaInvariants& inv = f.body.invariants;
  const double m = inv.mvv(0, 0);
  // mvo0 = -m skew(c)
  const Vec3 c(inv.mvo0(2, 1) / -m, inv.mvo0(0, 2) / -m, inv.mvo0(1, 0) / -m);
  const Mat3 Ic = inv.moo0 - m * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  const PartData& p = f.d.frame;
  Mat3 Ip = p.inertia.asDiagonal();
  Ip(0, 1) = Ip(1, 0) = p.products.x();
  Ip(0, 2) = Ip(2, 0) = p.products.y();
  Ip(1, 2) = Ip(2, 1) = p.products.z();
  std::printf("frame: %.2f kg (steel and non-structural), cg (%.4f, %.4f, %.4f) m, inertia %.1f %.1f %.1f kg m^2\n", m,
              c.x(), c.y(), c.z(), Ic(0, 0), Ic(1, 1), Ic(2, 2));
  // the steel alone against the plates' areas by hand: two channels and the flat cross members
  const LadderFrameData& l = f.d.ladder;
  const double steel = l.rho * (2 * l.length * (l.web_height + 2 * l.flange_width) * l.thickness +
                                static_cast<double>(l.cross_members.size()) * 2 * l.half_spacing * l.web_height *
                                    l.cross_member_thickness);
  EXPECT_NEAR(GenerateLadderFrame(l, {}).steel_mass, steel, 1e-9 * steel);
  EXPECT_NEAR(p.mass, m, 1e-9 * m);
  EXPECT_NEAR(p.mass, f.d.ladder.total_mass, 1e-9 * m);
  EXPECT_LT((p.cg - c).norm(), 1e-9);
  // the quadrature leaves out the plates' own rotary inertia (order m t^2)
  EXPECT_LT((Ip - Ic).norm(), 1e-4 * Ic.norm());
}

}  // namespace truck_frame_test
}  // namespace flexmb::vehicle::testing
