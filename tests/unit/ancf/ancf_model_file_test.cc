// Unit tests of the model-file entry `type: ancf_beam`: a valid beam with
// node markers, and bad input (non-positive length, element count, section,
// material; a marker on a node that does not exist; a joint on a marker the
// beam does not have) as InputError naming file, line and entity; the same
// for `type: ancf_cable`.
#include <gtest/gtest.h>

#include <string>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb::ancf {
namespace {

const char* kModel =
    "name: rope\n"                                            // 1
    "ground:\n"                                               // 2
    "  markers:\n"                                            // 3
    "    - {name: hook, position: [0, 0, 0]}\n"               // 4
    "bodies:\n"                                               // 5
    "  - name: beam\n"                                        // 6
    "    type: ancf_beam\n"                                   // 7
    "    length: 2.0\n"                                       // 8
    "    elements: 4\n"                                       // 9
    "    section: {diameter: 0.01}\n"                         // 10
    "    material: {E: 2.0e11, rho: 7850}\n"                  // 11
    "    start: [0, 0, 0]\n"                                  // 12
    "    direction: [0, 0, -1]\n"                             // 13
    "    normal: [0, 1, 0]\n"                                 // 14
    "    damping: 0.001\n"                                    // 15
    "    markers:\n"                                          // 16
    "      - {name: top, end: start}\n"                       // 17
    "      - {name: mid, node: 2}\n"                          // 18
    "      - {name: bottom, end: end}\n"                      // 19
    "joints:\n"                                               // 20
    "  - {name: pin, type: revolute, i: ground.hook, j: beam.top}\n";

TEST(AncfModelFile, BeamWithNodeMarkers) {
  auto model = LoadModelString(kModel, "rope.yaml");
  const int b = model->FindBody("beam");
  ASSERT_GT(b, 0);
  const auto& beam = dynamic_cast<const AncfBeam2dBody&>(*model->bodies[b]);
  EXPECT_EQ(beam.elements(), 4);
  EXPECT_NEAR(beam.element().section().A, 3.14159265358979 * 0.01 * 0.01 / 4.0, 1e-15);
  EXPECT_NEAR(beam.element().section().I, 3.14159265358979 * 1e-8 / 64.0, 1e-20);
  EXPECT_DOUBLE_EQ(beam.element().section().damping, 0.001);
  const int mid = model->FindMarker("beam.mid");
  const int bottom = model->FindMarker("beam.bottom");
  EXPECT_EQ(model->markers[mid].node, 2);
  EXPECT_EQ(model->markers[bottom].node, 4);
  // the beam hangs down along -z: the bottom marker is 2 m below the hook
  VecX q(beam.nq()), v(beam.nv());
  beam.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  beam.EvaluateMarker(q.data(), v.data(), model->markers[bottom], ms);
  EXPECT_LT((ms.p_WM - Vec3(0, 0, -2.0)).norm(), 1e-14);
  EXPECT_LT((ms.R_WM.col(0) - Vec3(0, 0, -1)).norm(), 1e-14);
}

TEST(AncfModelFile, BadInputNamesFileLineAndEntity) {
  const test_util::ModelFileErrorCase cases[] = {
      {"{name: mid, node: 2}", "{name: mid, node: 5}", "rope.yaml:18", "marker 'beam.mid'"},
      {"{name: mid, node: 2}", "{name: mid, node: -1}", "rope.yaml:18", "marker 'beam.mid'"},
      {"length: 2.0", "length: 0", "rope.yaml:8", "body 'beam'"},
      {"length: 2.0", "length: -2.0", "rope.yaml:8", "body 'beam'"},
      {"elements: 4", "elements: 0", "rope.yaml:9", "body 'beam'"},
      {"elements: 4", "elements: 2.5", "rope.yaml:9", "body 'beam'"},
      {"elements: 4", "elements: -3", "rope.yaml:9", "body 'beam'"},
      {"{diameter: 0.01}", "{diameter: 0}", "rope.yaml:10", "body 'beam'"},
      {"{diameter: 0.01}", "{area: 0, inertia: 1.0e-9}", "rope.yaml:10", "body 'beam'"},
      {"{diameter: 0.01}", "{area: -1.0e-4, inertia: 1.0e-9}", "rope.yaml:10", "body 'beam'"},
      {"{diameter: 0.01}", "{area: 1.0e-4, inertia: -1.0e-9}", "rope.yaml:10", "body 'beam'"},
      {"j: beam.top}", "j: beam.tip}", "rope.yaml:21", "joint 'pin'"},
      {"{diameter: 0.01}", "{diameter: -0.01}", "rope.yaml:10", "body 'beam'"},
      {"{diameter: 0.01}", "{area: 1.0e-4, inertia: 0}", "rope.yaml:10", "body 'beam'"},
      {"{E: 2.0e11, rho: 7850}", "{E: 2.0e11, rho: 0}", "rope.yaml:11", "body 'beam'"},
      {"damping: 0.001", "damping: -1", "rope.yaml:15", "body 'beam'"},
      {"direction: [0, 0, -1]", "direction: [0, 1, 0]", "rope.yaml:", "body 'beam'"},
      {"{name: bottom, end: end}", "{name: bottom, end: middle}", "rope.yaml:19", "marker 'beam.bottom'"},
      {"{name: bottom, end: end}", "{name: bottom}", "rope.yaml:19", "marker 'beam.bottom'"},
  };
  test_util::ExpectModelFileErrorsNameLineAndEntity(kModel, "rope.yaml", cases);
  EXPECT_NE(test_util::ModelFileErrorOf(kModel, "rope.yaml", "{name: mid, node: 2}", "{name: mid, node: 5}")
                .find("node 5 does not exist"),
            std::string::npos);
}

const char* kCable =
    "name: rope3d\n"                                          // 1
    "ground:\n"                                               // 2
    "  markers:\n"                                            // 3
    "    - {name: hook, position: [1, 2, 3]}\n"               // 4
    "bodies:\n"                                               // 5
    "  - name: rope\n"                                        // 6
    "    type: ancf_cable\n"                                  // 7
    "    start: [1, 2, 3]\n"                                  // 8
    "    end: [3, 4, 2]\n"                                    // 9
    "    elements: 6\n"                                       // 10
    "    section: {area: 1.0e-4, inertia: 1.0e-9}\n"          // 11
    "    material: {E: 1.0e10, rho: 1500}\n"                  // 12
    "    markers:\n"                                          // 13
    "      - {name: top, end: start}\n"                       // 14
    "      - {name: mid, node: 3, position: [0, 0.1, 0]}\n"   // 15
    "joints:\n"                                               // 16
    "  - {name: pin, type: spherical, i: ground.hook, j: rope.top}\n";

TEST(AncfModelFile, CableFromEndPointsWithNodeMarkers) {
  auto model = LoadModelString(kCable, "rope3d.yaml");
  const int b = model->FindBody("rope");
  ASSERT_GT(b, 0);
  const auto& rope = dynamic_cast<const AncfCable3dBody&>(*model->bodies[b]);
  EXPECT_EQ(rope.elements(), 6);
  EXPECT_NEAR(rope.element().length() * 6, 3.0, 1e-14);  // |(2, 2, -1)| = 3
  const int mid = model->FindMarker("rope.mid");
  EXPECT_EQ(model->markers[mid].node, 3);
  VecX q(rope.nq()), v(rope.nv());
  rope.InitialCoordinates(q.data(), v.data());
  MarkerState ms;
  rope.EvaluateMarker(q.data(), v.data(), model->markers[mid], ms);
  // node 3 halfway; the offset along the reference y axis z0 x t0
  const Vec3 t0 = Vec3(2, 2, -1) / 3.0;
  EXPECT_LT((ms.p_WM - (Vec3(2, 3, 2.5) + 0.1 * rope.R_W0().col(1))).norm(), 1e-14);
  EXPECT_LT((ms.R_WM.col(0) - t0).norm(), 1e-14);
}

TEST(AncfModelFile, BadCableInputNamesFileLineAndEntity) {
  const test_util::ModelFileErrorCase cases[] = {
      {"{name: mid, node: 3,", "{name: mid, node: 7,", "rope.yaml:15", "marker 'rope.mid'"},
      {"end: [3, 4, 2]", "end: [1, 2, 3]", "rope.yaml:9", "body 'rope'"},
      {"end: [3, 4, 2]", "length: -1.0", "rope.yaml:9", "body 'rope'"},
      {"end: [3, 4, 2]", "length: 0", "rope.yaml:9", "body 'rope'"},
      {"elements: 6", "elements: -2", "rope.yaml:10", "body 'rope'"},
      {"elements: 6", "elements: 0", "rope.yaml:10", "body 'rope'"},
      {"{name: mid, node: 3,", "{name: mid, node: -1,", "rope.yaml:15", "marker 'rope.mid'"},
      {"{area: 1.0e-4, inertia: 1.0e-9}", "{diameter: -0.01}", "rope.yaml:11", "body 'rope'"},
      {"area: 1.0e-4", "area: 0", "rope.yaml:11", "body 'rope'"},
      {"inertia: 1.0e-9", "inertia: -1.0e-9", "rope.yaml:11", "body 'rope'"},
      {"j: rope.top}", "j: rope.bottom}", "rope.yaml:17", "joint 'pin'"},
      {"inertia: 1.0e-9", "inertia: 0", "rope.yaml:11", "body 'rope'"},
      {"area: 1.0e-4", "area: -1.0e-4", "rope.yaml:11", "body 'rope'"},
      {"    elements: 6\n", "    elements: 6\n    length: 3\n", "rope.yaml:9", "body 'rope'"},
      {"end: [3, 4, 2]", "length: 2\n    direction: [0, 0, 1]\n    normal: [0, 0, 2]", "rope.yaml:", "body 'rope'"},
  };
  test_util::ExpectModelFileErrorsNameLineAndEntity(kCable, "rope.yaml", cases);
  EXPECT_NE(test_util::ModelFileErrorOf(kCable, "rope.yaml", "{name: mid, node: 3,", "{name: mid, node: 7,")
                .find("node 7 does not exist"),
            std::string::npos);
}

}  // namespace
}  // namespace flexmb::ancf
