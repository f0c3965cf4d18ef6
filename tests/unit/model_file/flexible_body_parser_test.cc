// Model-file bodies of type flexible: body file relative to the model file,
// initial state, damping override, markers by node id (warning off the
// interface, error naming file, line, body and node for a missing node; a
// joint off the interface is an error at the joint).

#include "flexmb/model_file/flexible_body_parser.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/common/log.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/model/model.h"
#include "flexmb/model/workspace.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

namespace flexmb {
namespace {

namespace fs = std::filesystem;

// a folder with bar.h5 (the free bent bar: nodes 1..7, interface 1 and 7)
struct Folder {
  fs::path dir;
  Folder() {
    dir = fs::temp_directory_path() / ("flexmb_flexparse_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    io::WriteBody(*testing::FreeBentBar(3, 3), (dir / "bar.h5").string());
  }
  ~Folder() { fs::remove_all(dir); }
  std::string Write(const std::string& yaml) const {
    const fs::path p = dir / "model.yaml";
    std::ofstream(p) << yaml;
    return p.string();
  }
};

const Folder& Shared() {
  static const Folder f;
  return f;
}

std::string ModelText(const std::string& body_extra, const std::string& markers) {
  return "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  - name: bar\n"
         "    type: flexible\n"
         "    file: bar.h5\n"
         "    position: [1, 2, 3]\n"
         "    angular_velocity: [0, 0, 2]\n" +
         body_extra + "    markers:\n" + markers;
}

std::string ErrorOf(const std::string& yaml) {
  try {
    LoadModelFile(Shared().Write(yaml));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FlexibleBodyParser, LoadsBodyAndMarkers) {
  std::vector<std::string> warnings;
  const LogSink old = SetWarningSink([&](const std::string& w) { warnings.push_back(w); });
  auto m = LoadModelFile(Shared().Write(ModelText("    modal_coordinates: [0.01, 0, 0, 0, 0, 0, 0, 0, 0]\n"
                                              "    damping: {rayleigh: [0.5, 0.001]}\n",
                                              "      - {name: a, node: 1}\n"
                                              "      - {name: b, node: 4, position: [0, 0, 0.1]}\n"
                                              "      - {name: c, position: [0.1, 0, 0]}\n")));
  SetWarningSink(old);
  ASSERT_EQ(m->bodies.size(), 2u);
  const auto* body = dynamic_cast<const FlexibleBody*>(m->bodies[1].get());
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(body->nq(), 16);
  EXPECT_EQ(body->nv(), 15);
  const reduction::ReducedBody& r = body->reduced();
  EXPECT_LT((body->damping() - (0.5 * r.mass + 0.001 * r.stiffness)).norm(), 1e-12 * r.stiffness.norm());
  const int a = m->FindMarker("bar.a"), b = m->FindMarker("bar.b"), c = m->FindMarker("bar.c");
  ASSERT_GE(a, 0);
  EXPECT_EQ(m->markers[a].node, 0);
  EXPECT_EQ(m->markers[b].node, 3);
  EXPECT_EQ(m->markers[c].node, -1);
  // only node 4 is off the interface
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("node 4 is not an interface node"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("bar.b"), std::string::npos) << warnings[0];
  // initial state
  VecX q(body->nq()), v(body->nv());
  body->InitialCoordinates(q.data(), v.data());
  EXPECT_DOUBLE_EQ(q(0), 1.0);
  EXPECT_DOUBLE_EQ(q(7), 0.01);
  EXPECT_DOUBLE_EQ(v(5), 2.0);
}

TEST(FlexibleBodyParser, FlexibleSensors) {
  const LogSink old = SetWarningSink([](const std::string&) {});
  auto m = LoadModelFile(Shared().Write(
      ModelText("    modal_coordinates: [0.01, 0, 0, 0, 0, 0, 0, 0, -0.02]\n", "      - {name: a, node: 1}\n") +
      "sensors:\n"
      "  - {name: w, type: modal_coordinates, body: bar}\n"
      "  - {name: u, type: node_displacement, body: bar, node: 5}\n"
      "  - {name: e, type: strain_energy, body: bar}\n"));
  SetWarningSink(old);
  const auto& body = dynamic_cast<const FlexibleBody&>(*m->bodies[1]);
  const State s = m->InitialState();
  Workspace ws;
  ASSERT_EQ(m->sensors.size(), 3u);
  std::vector<double> w(9), u(3), e(1);
  EXPECT_EQ(m->sensors[0]->Components().size(), 9u);
  EXPECT_EQ(m->sensors[0]->Components()[8], "w9");
  m->sensors[0]->Evaluate(*m, s, ws, w.data());
  m->sensors[1]->Evaluate(*m, s, ws, u.data());
  m->sensors[2]->Evaluate(*m, s, ws, e.data());
  const int n = 9;
  VecX wq = VecX::Zero(n);
  wq(0) = 0.01;
  wq(8) = -0.02;
  EXPECT_DOUBLE_EQ(w[0], 0.01);
  EXPECT_DOUBLE_EQ(w[8], -0.02);
  const Vec3 ref = body.reduced().modes.block(6 * 4, 0, 3, n) * wq;  // node id 5 = index 4
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(u[k], ref(k), 1e-15);
  EXPECT_NEAR(e[0], 0.5 * wq.dot(body.reduced().stiffness * wq), 1e-12);
  EXPECT_NE(ErrorOf(ModelText("", "      - {name: a, node: 1}\n") +
                    "sensors:\n  - {name: u, type: node_displacement, body: bar, node: 77}\n")
                .find("node 77 does not exist"),
            std::string::npos);
}

TEST(FlexibleBodyParser, NodeAndStressSensors) {
  const LogSink old = SetWarningSink([](const std::string&) {});
  auto m = LoadModelFile(Shared().Write(
      ModelText("    modal_coordinates: [0.01, 0, 0, 0, 0, 0, 0, 0, -0.02]\n", "      - {name: a, node: 1}\n") +
      "sensors:\n"
      "  - {name: p, type: node_position, body: bar, node: 5}\n"
      "  - {name: v, type: node_velocity, body: bar, node: 5}\n"
      "  - {name: s, type: element_stress, body: bar, element: 3}\n"));
  SetWarningSink(old);
  const auto& body = dynamic_cast<const FlexibleBody&>(*m->bodies[1]);
  ASSERT_EQ(m->sensors.size(), 3u);
  const State s = m->InitialState();
  const Workspace ws;
  double p[3], v[3], st[12];
  m->sensors[0]->Evaluate(*m, s, ws, p);
  m->sensors[1]->Evaluate(*m, s, ws, v);
  m->sensors[2]->Evaluate(*m, s, ws, st);
  const double* q = s.q.data() + body.q_offset;
  // node id 5 = index 4, element id 3 = index 2 (the bar is beams only)
  const Vec3 pr = body.NodePosition(q, 4), vr = body.NodeVelocity(q, s.v.data() + body.v_offset, 4);
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(p[k], pr(k));
    EXPECT_DOUBLE_EQ(v[k], vr(k));
  }
  EXPECT_EQ(m->sensors[2]->Components()[4], "end_a_My");
  const reduction::StressTable& t = body.reduced().stress.beam;
  const VecX ref = t.modes.middleRows(t.Row(2, 0, 0), 12) * Eigen::Map<const VecX>(q + 7, body.modes());
  for (int k = 0; k < 12; ++k) EXPECT_NEAR(st[k], ref(k), 1e-12 * ref.norm());
  const std::string base = ModelText("", "      - {name: a, node: 1}\n") + "sensors:\n";
  EXPECT_NE(ErrorOf(base + "  - {name: s, type: element_stress, body: bar, element: 40}\n").find("element 40 does not exist"),
            std::string::npos);
  EXPECT_NE(ErrorOf(base + "  - {name: s, type: node_stress, body: bar, node: 2}\n")
                .find("node 2 of body 'bar' has no shell or solid element"),
            std::string::npos);
  EXPECT_NE(ErrorOf(base + "  - {name: s, type: node_velocity, body: bar}\n").find("missing key 'node'"),
            std::string::npos);
}

TEST(FlexibleBodyParser, MissingNodeNamesFileLineBodyAndNode) {
  const std::string e = ErrorOf(ModelText("", "      - {name: a, node: 1}\n      - {name: z, node: 99}\n"));
  EXPECT_NE(e.find("model.yaml:10:"), std::string::npos) << e;
  EXPECT_NE(e.find("node 99 does not exist"), std::string::npos) << e;
  EXPECT_NE(e.find("'bar'"), std::string::npos) << e;
  EXPECT_NE(e.find("bar.z"), std::string::npos) << e;
}

// a joint may attach only at an interface node (nodes 1 and 7 of the bar);
// a sensor or force elsewhere only warns (LoadsBodyAndMarkers)
TEST(FlexibleBodyParser, JointOffTheInterfaceIsAnErrorAtTheJoint) {
  const std::string markers = "      - {name: a, node: 1}\n      - {name: b, node: 4}\n";
  const std::string joints = "ground:\n  markers: [{name: o, position: [1, 2, 3]}]\njoints:\n";
  const std::string ok = ModelText("", markers) + joints + "  - {name: pin, type: spherical, i: ground.o, j: bar.a}\n";
  EXPECT_EQ(ErrorOf(ok), "no error");
  const std::string bad = ModelText("", markers) + joints + "  - {name: pin, type: spherical, i: ground.o, j: bar.b}\n";
  const std::string e = ErrorOf(bad);
  EXPECT_NE(e.find("model.yaml:14:"), std::string::npos) << e;
  EXPECT_NE(e.find("joint 'pin'"), std::string::npos) << e;
  EXPECT_NE(e.find("marker 'bar.b' sits on node 4 of flexible body 'bar', which is not an interface node"),
            std::string::npos)
      << e;
}

TEST(FlexibleBodyParser, JointOnANodeFixedInTheReductionIsExact) {
  // the bar reduced with node 1 clamped (--fix 1, the frame attached to it)
  // and node 7 as interface: node 1 is the floating frame, a joint there is
  // as exact as on an interface node
  reduction::ReductionOptions o;
  o.fixed_nodes = {0};
  o.interface_nodes = {6};
  o.normal_modes = 3;
  io::WriteBody(reduction::ReduceCraigBampton(testing::BentBar(3), o), (Shared().dir / "fixed.h5").string());
  std::string text = ModelText("", "      - {name: a, node: 1}\n      - {name: b, node: 4}\n") +
                     "ground:\n  markers: [{name: o, position: [1, 2, 3]}]\njoints:\n"
                     "  - {name: pin, type: spherical, i: ground.o, j: bar.a}\n";
  text.replace(text.find("bar.h5"), 6, "fixed.h5");
  EXPECT_EQ(ErrorOf(text), "no error");
  auto m = LoadModelFile(Shared().Write(text));
  const auto& bar = dynamic_cast<const FlexibleBody&>(*m->bodies[1]);
  EXPECT_TRUE(bar.IsInterfaceNode(0));   // fixed: no modal motion
  EXPECT_TRUE(bar.IsInterfaceNode(6));   // interface
  EXPECT_FALSE(bar.IsInterfaceNode(3));  // interior
}

TEST(FlexibleBodyParser, BadInput) {
  std::string yaml = ModelText("", "      - {name: a, node: 1}\n");
  const std::string missing = ErrorOf(yaml.replace(yaml.find("bar.h5"), 6, "nope.h5"));
  EXPECT_NE(missing.find("model.yaml:5"), std::string::npos) << missing;
  EXPECT_NE(missing.find("nope.h5"), std::string::npos) << missing;
  const std::string len = ErrorOf(ModelText("    modal_coordinates: [0, 0]\n", "      - {name: a, node: 1}\n"));
  EXPECT_NE(len.find("9 numbers"), std::string::npos) << len;
  const std::string damp = ErrorOf(ModelText("    damping: {rayleigh: [1]}\n", "      - {name: a, node: 1}\n"));
  EXPECT_NE(damp.find("rayleigh"), std::string::npos) << damp;
}

}  // namespace
}  // namespace flexmb
