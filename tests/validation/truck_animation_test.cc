// The lane change's ParaView animation (vehicle/truck_animation.h): a short
// elastic-frame run of examples/truck_lane_change/truck.yaml (a coarser
// frame mesh, reduced to few modes, keeps it fast) writes one frame per
// 1/fps of simulated time and a .pvd listing them; in every frame the
// frame's mesh points equal the flexible body's node positions
// r + R (rho_k + s H_k w), computed here from the body's coordinates and
// the reduced body's mode matrix, to 1e-9 m; the loaded frame's von Mises
// stress is non-zero; the rigid-frame run draws the undeformed frame mesh.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/model/model.h"
#include "truck_harness.h"

namespace flexmb::vehicle::testing {
namespace truck_animation_test {

namespace fs = std::filesystem;

// the numbers of the DataArray named `name` (or the Points array) of a .vtu
std::vector<double> TruckAnimVtuArray(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string s = buf.str();
  size_t at = name == "Points" ? s.find("<Points>") : s.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  at = s.find('>', s.find("<DataArray", name == "Points" ? at : s.rfind("<DataArray", at))) + 1;
  const size_t end = s.find("</DataArray>", at);
  std::istringstream values(s.substr(at, end - at));
  std::vector<double> out;
  double v = 0;
  while (values >> v) out.push_back(v);
  return out;
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
  const fs::path dir = fs::temp_directory_path() / "flexmb_truck_animation_elastic";
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
    const std::vector<double> pts = TruckAnimVtuArray(path, "Points");
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
    const std::vector<double> vm = TruckAnimVtuArray(path, "von_mises");
    for (double v : vm) max_vm = std::max(max_vm, v);
    const std::vector<double> u = TruckAnimVtuArray(path, "displacement");
    for (double v : u) max_u = std::max(max_u, std::abs(v));
  }
  // the frame carries the cab, powertrain and cargo: MPa, not zero, not GPa
  EXPECT_GT(max_vm, 1e6);
  EXPECT_LT(max_vm, 1e9);
  EXPECT_GT(max_u, 1e-5);
  std::printf("%d frames to t = %.3f s, %d frame nodes, deformation scale %g, max von Mises %.1f MPa, max "
              "displacement %.3f mm; writing took %.3f s\n",
              n_frames, res.t_end, nodes, scale, max_vm / 1e6, max_u * 1e3, res.animation_wall_time_s);
  fs::remove_all(dir);
}

TEST(TruckAnimation, RigidFrameRunDrawsTheUndeformedMesh) {
  const fs::path dir = fs::temp_directory_path() / "flexmb_truck_animation_rigid";
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
