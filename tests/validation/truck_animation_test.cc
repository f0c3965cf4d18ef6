// The lane change's ParaView animation (results/truck_animation.h): a short
// elastic-frame run of examples/truck_lane_change/truck.yaml (a coarser
// frame mesh, reduced to few modes, keeps it fast) writes one frame per
// 1/fps of simulated time and a .pvd listing them; in every frame the
// frame's mesh points equal the flexible body's node positions
// r + R (rho_k + s H_k w), computed here from the body's coordinates and
// the reduced body's mode matrix, to 1e-9 m; the loaded frame's von Mises
// stress is non-zero; the rigid-frame run draws the undeformed frame mesh.
// The frames are binary (base64) and read back by an independent decoder
// (tests/unit/results/vtu_test_reader.h); the rods (drag link, tie rod, extra
// arm) are line cells ending at their joints' marker origins to 1e-9 m, and
// the axle hub, contact patches and steering column have cells.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>  // getpid: ctest -j runs each test in its own process

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/joints/joint.h"
#include "flexmb/model/model.h"
#include "tests/unit/results/vtu_test_reader.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_animation_test {

namespace fs = std::filesystem;

// the numbers of the DataArray named `name` (or the Points array) of a
// .vtu, decoded by the tests' own reader; `format` gets its encoding
std::vector<double> TruckAnimVtuArray(const std::string& path, const std::string& name,
                                      std::string* format = nullptr) {
  return vtu_test::VtuTestArray(path, name, format);
}

// origins of markers i and j of joint `name` in world (empty if no such joint)
std::vector<Vec3> TruckAnimLinkEnds(const Model& m, const State& st, const char* name) {
  const int j = m.FindJoint(name);
  if (j < 0) return {};
  std::vector<Vec3> ends;
  for (int k : {m.joints[j]->marker_i, m.joints[j]->marker_j}) {
    const Marker& mk = m.markers[static_cast<size_t>(k)];
    const Body& b = *m.bodies[mk.body];
    MarkerState ms;
    b.EvaluateMarker(st.q.data() + b.q_offset, st.v.data() + b.v_offset, mk, ms);
    ends.push_back(ms.p_WM);
  }
  return ends;
}

int TruckAnimPvdEntries(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  int n = 0;
  bool closed = false;
  while (std::getline(in, line)) {
    if (line.find("<DataSet") != std::string::npos) ++n;
    if (line.find("</VTKFile>") != std::string::npos) closed = true;
  }
  return closed ? n : -1;
}

std::shared_ptr<const reduction::ReducedBody> TruckAnimCoarseFrame() {
  static const std::shared_ptr<const reduction::ReducedBody> body = [] {
    TruckData d = LoadLaneChangeTruck(TruckFile());
    d.ladder.element_size = 0.08;
    SetFrameMesh(d);
    return std::shared_ptr<const reduction::ReducedBody>(ReduceTruckFrame(d, FrameReductionData{4, 0.02, 12}));
  }();
  return body;
}

TEST(TruckAnimation, ElasticFrameFramesShowTheFlexibleBodyNodes) {
  const fs::path dir = fs::temp_directory_path() / ("flexmb_truck_animation_elastic_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto body = TruckAnimCoarseFrame();
  const int nodes = static_cast<int>(body->mesh.nodes.size());
  LaneChangeOptions o;
  o.file = TruckFile();
  o.out_dir = dir.string();
  o.speed_kmh = 55.0;
  o.frame = "elastic";
  o.frame_body = body;
  o.stop_distance = 6.0;
  o.animation_fps = 25.0;
  // expected node positions of every frame, from the body's coordinates
  std::vector<std::vector<Vec3>> expected;
  std::vector<std::vector<std::vector<Vec3>>> link_ends;  // per frame, per rod: its two ends
  std::vector<int> shaped_bodies;
  double scale = -1;
  o.on_animation_frame = [&](const Model& m, const State& st) {
    const FlexibleBody* flex = nullptr;
    for (const auto& b : m.bodies)
      if (const auto* f = dynamic_cast<const FlexibleBody*>(b.get())) flex = f;
    ASSERT_NE(flex, nullptr);
    scale = m.output.deformation_scale;
    const double* q = st.q.data() + flex->q_offset;
    const Vec3 r(q[0], q[1], q[2]);
    const Mat3 R = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
    const reduction::ReducedBody& rb = flex->reduced();
    std::vector<Vec3> p(static_cast<size_t>(nodes));
    for (int k = 0; k < nodes; ++k) {
      Vec3 u = Vec3::Zero();
      for (int j = 0; j < flex->modes(); ++j) u += rb.modes.block<3, 1>(6 * k, j) * q[7 + j];
      p[static_cast<size_t>(k)] = r + R * (rb.mesh.nodes[static_cast<size_t>(k)].x + scale * u);
    }
    expected.push_back(std::move(p));
    std::vector<std::vector<Vec3>> links;
    for (const char* name : {"drag_link", "tie_rod", "rear_extra_arm"}) {
      links.push_back(TruckAnimLinkEnds(m, st, name));
      ASSERT_EQ(links.back().size(), 2u) << name;
    }
    link_ends.push_back(std::move(links));
    if (shaped_bodies.empty())
      for (const char* name : {"rear_axle_hub", "wheel_fl_patch", "wheel_fr_patch", "wheel_rl_patch",
                               "wheel_rr_patch", "steering_column", "pitman_arm"})
        for (size_t b = 0; b < m.bodies.size(); ++b)
          if (m.bodies[b]->name() == name) shaped_bodies.push_back(static_cast<int>(b));
  };
  const LaneChangeResult res = RunLaneChange(o);
  ASSERT_TRUE(res.completed) << res.message;
  // one frame at t = 0 and one per 1/25 s after it
  const int n_frames = static_cast<int>(std::floor(res.t_end * 25.0 + 1e-6)) + 1;
  EXPECT_EQ(res.animation_frames, n_frames);
  ASSERT_EQ(static_cast<int>(expected.size()), n_frames);
  EXPECT_EQ(TruckAnimPvdEntries((dir / "animation" / "anim.pvd").string()), n_frames);
  EXPECT_GE(scale, 0.0);
  double max_vm = 0, max_u = 0;
  for (int i = 0; i < n_frames; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%05d.vtu", i);
    const std::string path = (dir / "animation" / "frames" / name).string();
    std::string format;
    const std::vector<double> pts = TruckAnimVtuArray(path, "Points", &format);
    EXPECT_EQ(format, "binary");
    ASSERT_GE(static_cast<int>(pts.size()), 3 * nodes) << path;
    // the frame's mesh is the last block of points
    const size_t base = pts.size() - 3 * static_cast<size_t>(nodes);
    double err = 0;
    for (int k = 0; k < nodes; ++k)
      for (int c = 0; c < 3; ++c)
        err = std::max(err, std::abs(pts[base + 3 * static_cast<size_t>(k) + static_cast<size_t>(c)] -
                                     expected[static_cast<size_t>(i)][static_cast<size_t>(k)](c)));
    EXPECT_LT(err, 1e-9) << path;
    // more points than the frame: the parts' shapes and the corridor
    EXPECT_GT(pts.size(), 3 * static_cast<size_t>(nodes) + 100);
    // every rod is a line cell between its joint's marker origins
    const std::vector<double> conn = TruckAnimVtuArray(path, "connectivity"),
                              offsets = TruckAnimVtuArray(path, "offsets"),
                              types = TruckAnimVtuArray(path, "types"), body_id = TruckAnimVtuArray(path, "body_id");
    ASSERT_EQ(types.size(), offsets.size());
    ASSERT_EQ(types.size(), body_id.size());
    for (const std::vector<Vec3>& ends : link_ends[static_cast<size_t>(i)]) {
      double best = 1e300;
      for (size_t c = 0; c < types.size(); ++c) {
        if (types[c] != 3) continue;
        const auto end = static_cast<size_t>(offsets[c]);
        const auto a = static_cast<size_t>(conn[end - 2]), b = static_cast<size_t>(conn[end - 1]);
        const Vec3 pa(pts[3 * a], pts[3 * a + 1], pts[3 * a + 2]), pb(pts[3 * b], pts[3 * b + 1], pts[3 * b + 2]);
        best = std::min(best, std::max((pa - ends[0]).norm(), (pb - ends[1]).norm()));
      }
      EXPECT_LT(best, 1e-9) << path;
    }
    // the parts that got shapes in this session draw cells
    for (int b : shaped_bodies)
      EXPECT_GT(std::count(body_id.begin(), body_id.end(), static_cast<double>(b)), 0) << "body " << b;
    const std::vector<double> vm = TruckAnimVtuArray(path, "von_mises");
    for (double v : vm) max_vm = std::max(max_vm, v);
    const std::vector<double> u = TruckAnimVtuArray(path, "displacement");
    for (double v : u) max_u = std::max(max_u, std::abs(v));
  }
  // the frame carries the cab, powertrain and cargo: MPa, not zero, not GPa
  EXPECT_GT(max_vm, 1e6);
  EXPECT_LT(max_vm, 1e9);
  EXPECT_GT(max_u, 1e-5);
  EXPECT_EQ(shaped_bodies.size(), 7u);
  std::printf("%d frames to t = %.3f s, %d frame nodes, deformation scale %g, max von Mises %.1f MPa, max "
              "displacement %.3f mm; writing took %.3f s\n",
              n_frames, res.t_end, nodes, scale, max_vm / 1e6, max_u * 1e3, res.animation_wall_time_s);
  fs::remove_all(dir);
}

TEST(TruckAnimation, RigidFrameRunDrawsTheUndeformedMesh) {
  const fs::path dir = fs::temp_directory_path() / ("flexmb_truck_animation_rigid_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  LaneChangeOptions o;
  o.file = TruckFile();
  o.out_dir = dir.string();
  o.speed_kmh = 30.0;
  o.frame = "rigid";
  o.stop_distance = 2.0;
  o.animation = true;
  int calls = 0;
  o.on_animation_frame = [&](const Model&, const State&) { ++calls; };
  const LaneChangeResult res = RunLaneChange(o);
  ASSERT_TRUE(res.completed) << res.message;
  EXPECT_EQ(res.animation_frames, calls);
  EXPECT_EQ(res.animation_frames, static_cast<int>(std::floor(res.t_end * 25.0 + 1e-6)) + 1);
  const TruckData d = LoadLaneChangeTruck(TruckFile());
  const std::string first = (dir / "animation" / "frames" / "frame_00000.vtu").string();
  // every frame node drawn (the rigid frame's mesh), zero stress everywhere
  EXPECT_GT(TruckAnimVtuArray(first, "Points").size(), 3 * d.frame_mesh->nodes.size());
  for (double v : TruckAnimVtuArray(first, "von_mises")) EXPECT_EQ(v, 0.0);
  fs::remove_all(dir);
}

}  // namespace truck_animation_test
}  // namespace flexmb::vehicle::testing
