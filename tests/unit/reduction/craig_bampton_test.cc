#include "flexmb/reduction/craig_bampton.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/assembly.h"
#include "flexmb/fe/modal.h"
#include "flexmb/reduction/craig_bampton_basis.h"
#include "tests/unit/reduction/reduction_test_models.h"

namespace flexmb::reduction {
namespace {

using fe::testing::AddNode;
using fe::testing::AddPointMass;
using fe::testing::AddRigidLink;
using testing::AddPlate;

template <class E>
std::string MessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong exception: ") + e.what();
  }
  return "no exception";
}

// a free 0.6 x 0.4 m plate, 6 x 4 shells, interface at two corners
struct PlateModel {
  fe::FeModel model;
  std::vector<int> grid;
  ReductionOptions options;
};
PlateModel Plate() {
  PlateModel p;
  p.grid = AddPlate(p.model.mesh, 6, 4, 0.6, 0.4, 0.004);
  p.options.interface_nodes = {p.grid[0], p.grid[6]};
  p.options.normal_modes = 5;
  return p;
}

TEST(CraigBampton, CountsAndShapes) {
  PlateModel p = Plate();
  p.options.interface_nodes.push_back(p.grid[0]);   // listed twice: counts once
  ReductionTimings t;
  const ReducedBody body = ReduceCraigBampton(p.model, p.options, &t);
  EXPECT_EQ(body.static_modes, 12);
  EXPECT_EQ(body.normal_modes, 5);
  EXPECT_EQ(body.rigid_modes_removed, 6);
  EXPECT_EQ(body.frequencies_hz.size(), 12 + 5 - 6);
  EXPECT_EQ(body.interface_nodes, (std::vector<int>{p.grid[0], p.grid[6]}));
  EXPECT_EQ(body.modes.rows(), 6 * static_cast<Eigen::Index>(p.model.mesh.nodes.size()));
  EXPECT_EQ(body.modes.cols(), 11);
  for (int j = 1; j < body.frequencies_hz.size(); ++j) EXPECT_GE(body.frequencies_hz[j], body.frequencies_hz[j - 1]);
  EXPECT_GT(body.frequencies_hz[0], 1.0);
  EXPECT_EQ(body.mass, Eigen::MatrixXd::Identity(11, 11));
  for (int j = 0; j < 11; ++j) {
    EXPECT_NEAR(body.stiffness(j, j), std::pow(2.0 * M_PI * body.frequencies_hz[j], 2), 1e-9 * body.stiffness(j, j));
  }
  EXPECT_EQ(body.damping, Eigen::MatrixXd::Zero(11, 11));
  EXPECT_GT(t.factorize, 0.0);
  EXPECT_GT(t.assemble, 0.0);
  EXPECT_GT(t.invariants, 0.0);
  EXPECT_GT(t.stress_modes, 0.0);
  // every element has stress modes, one column per flexible mode
  const StressModes& st = body.stress;
  EXPECT_EQ(st.shell.elements.size() + st.beam.elements.size() + st.solid.elements.size(),
            p.model.mesh.elements.size());
  for (const StressTable* table : {&st.shell, &st.beam, &st.solid}) {
    if (!table->elements.empty()) EXPECT_EQ(table->modes.cols(), 11) << table->name;
  }
  auto value = [&](const std::string& key) {
    for (const auto& [k, v] : body.provenance) {
      if (k == key) return v;
    }
    return std::string("<missing>");
  };
  EXPECT_EQ(value("source"), "test.bdf");
  EXPECT_EQ(value("interface_nodes"), "1,7");
  EXPECT_EQ(value("rigid_modes_removed"), "6");
  EXPECT_NE(value("date"), "<missing>");
  EXPECT_NE(value("flexmb_version"), "<missing>");
}

// The reduced matrices of the basis against their definition H^T A H with
// H = Expand(I): the mass is that product, the stiffness its Schur-complement
// form (zero coupling, no product over the interior), equal to round-off.
TEST(CraigBampton, ReducedMatricesEqualTheProjection) {
  PlateModel p = Plate();
  const fe::AssembledModel a = fe::BuildMatrices(p.model, fe::AssemblyOptions{});
  const CraigBamptonBasis basis = BuildCraigBamptonBasis(p.model.mesh, a, p.options);
  const Eigen::MatrixXd h = basis.Expand(Eigen::MatrixXd::Identity(basis.size(), basis.size()));
  const Eigen::MatrixXd m = h.transpose() * (a.M * h), k = h.transpose() * (a.K * h);
  EXPECT_LT((basis.mass - m).norm(), 1e-13 * m.norm());
  EXPECT_LT((basis.stiffness - k).norm(), 1e-11 * k.norm()) << (basis.stiffness - k).norm() / k.norm();
  const int nb = basis.static_modes();
  EXPECT_EQ(basis.stiffness.topRightCorner(nb, basis.normal_modes()).norm(), 0.0);
  // and the literal coupling is zero to the solve's round-off
  EXPECT_LT(k.topRightCorner(nb, basis.normal_modes()).norm(), 1e-11 * k.norm());
}

// Spectra alone (the bench's baseline) and block Lanczos find the same
// fixed-interface modes, hence the same body.
TEST(CraigBampton, SpectraAndBlockLanczosGiveTheSameBody) {
  PlateModel p = Plate();
  const ReducedBody block = ReduceCraigBampton(p.model, p.options);
  p.options.eigen_solver = ReductionOptions::EigenSolver::kSpectra;
  const ReducedBody spectra = ReduceCraigBampton(p.model, p.options);
  ASSERT_EQ(block.frequencies_hz.size(), spectra.frequencies_hz.size());
  for (Eigen::Index j = 0; j < block.frequencies_hz.size(); ++j) {
    EXPECT_NEAR(spectra.frequencies_hz[j], block.frequencies_hz[j], 1e-9 * block.frequencies_hz[j]) << j;
  }
}

TEST(CraigBampton, KeepTruncatesToTheLowestModes) {
  PlateModel p = Plate();
  const ReducedBody all = ReduceCraigBampton(p.model, p.options);
  p.options.keep = 4;
  const ReducedBody four = ReduceCraigBampton(p.model, p.options);
  ASSERT_EQ(four.frequencies_hz.size(), 4);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(four.frequencies_hz[j], all.frequencies_hz[j], 1e-10 * all.frequencies_hz[j]);
  p.options.keep = 12;
  const std::string msg = MessageOf<InputError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("keep = 12"), std::string::npos) << msg;
  EXPECT_NE(msg.find("only 11"), std::string::npos) << msg;
}

// D = alpha I + beta diag(omega^2), or diag(2 zeta_j omega_j) with the last
// ratio repeated
TEST(CraigBampton, Damping) {
  PlateModel p = Plate();
  p.options.rayleigh_alpha = 0.5;
  p.options.rayleigh_beta = 1e-5;
  const ReducedBody r = ReduceCraigBampton(p.model, p.options);
  const int n = static_cast<int>(r.frequencies_hz.size());
  for (int j = 0; j < n; ++j) {
    const double w = 2.0 * M_PI * r.frequencies_hz[j];
    EXPECT_NEAR(r.damping(j, j), 0.5 + 1e-5 * w * w, 1e-9 * r.damping(j, j));
  }
  EXPECT_EQ((r.damping - Eigen::MatrixXd(r.damping.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 0.0);
  p.options.damping_ratios = {0.01, 0.02};
  const ReducedBody z = ReduceCraigBampton(p.model, p.options);
  for (int j = 0; j < n; ++j) {
    const double w = 2.0 * M_PI * z.frequencies_hz[j];
    EXPECT_NEAR(z.damping(j, j), 2.0 * (j == 0 ? 0.01 : 0.02) * w, 1e-9 * z.damping(j, j));
  }
}

// all fixed-interface modes below a cut-off: as many as the fixed-interface
// problem (interface nodes clamped, fe::SolveModes) has below it
TEST(CraigBampton, FrequencyCutoff) {
  PlateModel p = Plate();
  const fe::AssembledModel clamped = fe::FixNodes(fe::Assemble(p.model.mesh), p.options.interface_nodes);
  fe::ModalOptions modal;
  modal.count = 30;
  const fe::ModalResult fixed = fe::SolveModes(clamped, modal);
  const double cutoff = 0.5 * (fixed.frequencies_hz[12] + fixed.frequencies_hz[13]);
  p.options.cutoff_hz = cutoff;
  p.options.normal_modes = 0;
  const ReducedBody body = ReduceCraigBampton(p.model, p.options);
  EXPECT_EQ(body.normal_modes, 13);
}

// interface node errors name the node
TEST(CraigBampton, BadInterfaceNodes) {
  PlateModel p = Plate();
  p.options.interface_nodes = {p.grid[0], 999};
  std::string msg = MessageOf<InputError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("interface node index 999 does not exist"), std::string::npos) << msg;
  // a node no element uses
  const int lonely = AddNode(p.model.mesh, fe::Vec3(2.0, 2.0, 2.0));
  p.options.interface_nodes = {p.grid[0], lonely};
  msg = MessageOf<InputError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("interface node " + std::to_string(lonely + 1)), std::string::npos) << msg;
  EXPECT_NE(msg.find("no degrees of freedom"), std::string::npos) << msg;
}

// Guyan with a single interface node on a free plate: the basis is the six
// rigid motions and nothing else (the rigid test with no next mode); with
// normal modes added, those remain as the flexible modes
TEST(CraigBampton, SingleInterfaceNodeGuyanIsRigid) {
  PlateModel p = Plate();
  p.options.interface_nodes = {p.grid[17]};
  p.options.normal_modes = 0;
  const ReducedBody rigid = ReduceCraigBampton(p.model, p.options);
  EXPECT_EQ(rigid.static_modes, 6);
  EXPECT_EQ(rigid.rigid_modes_removed, 6);
  EXPECT_EQ(rigid.frequencies_hz.size(), 0);
  EXPECT_EQ(rigid.modes.cols(), 0);
  p.options.normal_modes = 4;
  const ReducedBody flexible = ReduceCraigBampton(p.model, p.options);
  EXPECT_EQ(flexible.rigid_modes_removed, 6);
  ASSERT_EQ(flexible.frequencies_hz.size(), 4);
  EXPECT_GT(flexible.frequencies_hz[0], 1.0);
}

// no interface and nothing fixed: K_ii = K of a free body, singular
TEST(CraigBampton, FreeBodyWithoutInterface) {
  PlateModel p = Plate();
  p.options.interface_nodes.clear();
  const std::string msg = MessageOf<NumericalError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("K_ii"), std::string::npos) << msg;
  EXPECT_NE(msg.find("held by fixed nodes"), std::string::npos) << msg;
  // the same plate clamped at a corner reduces to its normal modes
  p.options.fixed_nodes = {p.grid[0]};
  const ReducedBody body = ReduceCraigBampton(p.model, p.options);
  EXPECT_EQ(body.static_modes, 0);
  EXPECT_EQ(body.rigid_modes_removed, 0);
  ASSERT_EQ(body.frequencies_hz.size(), 5);
  fe::ModalOptions modal;
  modal.count = 5;
  const fe::ModalResult ref = fe::SolveModes(fe::FixNodes(fe::Assemble(p.model.mesh), {p.grid[0]}), modal);
  for (int j = 0; j < 5; ++j) EXPECT_NEAR(body.frequencies_hz[j], ref.frequencies_hz[j], 1e-9 * ref.frequencies_hz[j]);
}

TEST(CraigBampton, MoreModesThanInteriorDof) {
  PlateModel p = Plate();
  const int interior = 35 * 6 - 12;
  p.options.normal_modes = interior;
  const std::string msg = MessageOf<InputError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("only " + std::to_string(interior) + " interior DOF"), std::string::npos) << msg;
  p.options.normal_modes = interior - 1;
  EXPECT_NO_THROW(ReduceCraigBampton(p.model, p.options));
}

TEST(CraigBampton, BadOptions) {
  PlateModel p = Plate();
  for (const std::function<void(ReductionOptions&)>& spoil : std::vector<std::function<void(ReductionOptions&)>>{
           [](ReductionOptions& o) { o.normal_modes = -1; }, [](ReductionOptions& o) { o.cutoff_hz = -1.0; },
           [](ReductionOptions& o) { o.cutoff_hz = NAN; }, [](ReductionOptions& o) { o.keep = 0; },
           [](ReductionOptions& o) { o.rayleigh_beta = -1.0; },
           [](ReductionOptions& o) { o.damping_ratios = {0.01, INFINITY}; }}) {
    ReductionOptions o = p.options;
    spoil(o);
    EXPECT_THROW(ReduceCraigBampton(p.model, o), InputError);
  }
}

// a mass with rotary inertia on a node that follows the plate in translation
// only (rigid link 123): its rotations have mass but no stiffness, K_ii is
// singular exactly there and the message names that node and component
TEST(CraigBampton, MechanismWithoutStiffnessIsNamed) {
  PlateModel p = Plate();
  const int hub = AddNode(p.model.mesh, fe::Vec3(0.3, 0.2, 0.1));
  AddPointMass(p.model.mesh, hub, 2.0, fe::Vec3::Zero(), fe::Mat3::Identity() * 0.01);
  AddRigidLink(p.model.mesh, 9, p.grid[17], {hub}, 0b000111);
  const std::string msg = MessageOf<NumericalError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("K_ii"), std::string::npos) << msg;
  const std::string id = std::to_string(hub + 1);
  EXPECT_NE(msg.find("node " + id + " (test.bdf:" + std::to_string(101 + hub) + ") component r"), std::string::npos)
      << msg;
}

// a second plate hanging on the first by a single translational rigid link
// (a spherical joint): it can swing freely with the interface held; the
// failing pivot lies on the hanging plate or its joint
TEST(CraigBampton, SwingingPlateIsAMechanism) {
  PlateModel p = Plate();
  const std::vector<int> second = AddPlate(p.model.mesh, 3, 3, 0.3, 0.3, 0.004, fe::Vec3(0.7, 0.0, 0.0));
  AddRigidLink(p.model.mesh, 9, p.grid[6], {second[0]}, 0b000111);
  const std::string msg = MessageOf<NumericalError>([&] { ReduceCraigBampton(p.model, p.options); });
  EXPECT_NE(msg.find("K_ii"), std::string::npos) << msg;
  bool named = false;
  for (int n : second) named = named || msg.find("node " + std::to_string(n + 1) + " (") != std::string::npos;
  named = named || msg.find("node " + std::to_string(p.grid[6] + 1) + " (") != std::string::npos;
  EXPECT_TRUE(named) << msg;
}

// a dependent node (rigid link) as interface node: its independent node's
// DOF become boundary DOF, and its mode rows follow the link exactly
TEST(CraigBampton, DependentNodeAsInterface) {
  PlateModel p = Plate();
  const int bracket = AddNode(p.model.mesh, fe::Vec3(0.3, 0.2, 0.15));
  AddPointMass(p.model.mesh, bracket, 0.5, fe::Vec3::Zero(), fe::Mat3::Identity() * 1e-3);
  AddRigidLink(p.model.mesh, 3, p.grid[17], {bracket});
  p.options.interface_nodes = {p.grid[0], bracket};
  const ReducedBody body = ReduceCraigBampton(p.model, p.options);
  EXPECT_EQ(body.static_modes, 12);
  const fe::Vec3 r = p.model.mesh.nodes[bracket].x - p.model.mesh.nodes[p.grid[17]].x;
  for (int j = 0; j < body.modes.cols(); ++j) {
    const fe::Vec3 ua = body.modes.block(6 * p.grid[17], j, 3, 1);
    const fe::Vec3 ta = body.modes.block(6 * p.grid[17] + 3, j, 3, 1);
    const fe::Vec3 ud = body.modes.block(6 * bracket, j, 3, 1);
    const fe::Vec3 td = body.modes.block(6 * bracket + 3, j, 3, 1);
    EXPECT_LT((ud - (ua + ta.cross(r))).norm(), 1e-12 * (ua.norm() + ta.norm() * r.norm())) << "mode " << j;
    EXPECT_LT((td - ta).norm(), 1e-12 * ta.norm()) << "mode " << j;
  }
}

}  // namespace
}  // namespace flexmb::reduction
