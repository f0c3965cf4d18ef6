#include "apps/flexmb/commands/lane_change.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/common/error.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/common/json_text.h"
#include "flexmb/durability/modal_history.h"
#include "flexmb/model_file/solver_section.h"
#include "flexmb/yaml/yaml_context.h"
#include "apps/flexmb/commands/frame_response.h"
#include "apps/flexmb/commands/run.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/reduction/stress_modes.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/vehicle/driver.h"
#include "flexmb/vehicle/lane_change_course.h"
#include "flexmb/vehicle/single_track.h"
#include "flexmb/vehicle/truck.h"
#include "flexmb/vehicle/truck_frame.h"
#include "flexmb/results/truck_animation.h"

namespace flexmb::vehicle {
namespace {

using io::JsonNumber;
using io::JsonString;
constexpr double kDeg = 180.0 / std::numbers::pi;

/// Thrown by the observer to end the run (test distance reached or failure).
struct EndOfTest {};

// the lane-change file's solver defaults: steps of 2 ms
SolverSettings LaneChangeSolverDefaults() {
  SolverSettings s;
  s.dt = 0.002;
  s.analysis = Analysis::kStaticsThenDynamics;
  return s;
}

/// Everything a lane-change file holds.
struct LaneChangeFile {
  double speed_kmh = 55.0;
  double run_up_time = 1.0;
  std::string frame = "rigid";
  FrameReductionData reduction;
  double mu = 0.8;
  LaneChangeCourseData course;
  DriverData driver;
  /// the `solver:` section (model/settings.h rules); dt 2 ms by default, and
  /// dt_min 1e-6 dt unless the file gives it
  SolverSettings solver = LaneChangeSolverDefaults();
  bool dt_min_given = false;
  double output_interval = 0.01;
  bool animation = false;
  TruckAnimationData animation_data;
  TruckData truck;
};

// an optional sub-map of the test (course, driver, solver): checked for its
// keys, the entity set for messages; an undefined node if absent
YAML::Node Section(const YAML::Node& t, const char* key, YamlContext& ctx, std::initializer_list<const char*> keys) {
  const YAML::Node n = t[key];
  if (n) {
    ctx.SetEntity(key);
    ctx.CheckKeys(n, keys);
  }
  return n;
}

LaneChangeFile ReadFile(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw InputError(std::string("cannot read the lane-change file: ") + e.what(), {path, 0, ""});
  }
  YamlContext ctx(path);
  LaneChangeFile f;
  ctx.SetEntity("lane-change file");
  ctx.CheckKeys(root, {"lane_change_test", "truck", "name", "note"});
  const YAML::Node t = root["lane_change_test"];
  ctx.SetEntity("lane_change_test");
  ctx.CheckKeys(t, {"entry_speed_kmh", "run_up_time", "frame", "frame_modes", "frame_damping", "frame_keep_modes",
                     "frame_acceleration_modes", "road_mu", "course", "driver", "solver",
                     "animation", "animation_fps", "animation_deformation_scale"});
  f.speed_kmh = ctx.Double(t, "entry_speed_kmh", f.speed_kmh);
  f.run_up_time = ctx.Double(t, "run_up_time", f.run_up_time);
  if (!(f.run_up_time >= 0)) ctx.Fail(t["run_up_time"], "run_up_time must be >= 0");
  f.frame = ctx.String(t, "frame", f.frame);
  FrameReductionData& fr = f.reduction;
  fr.normal_modes = ctx.Integer(t, "frame_modes", fr.normal_modes);
  if (fr.normal_modes < 0) ctx.Fail(t["frame_modes"], "frame_modes must be >= 0");
  fr.damping_ratio = ctx.Double(t, "frame_damping", fr.damping_ratio);
  if (!(fr.damping_ratio >= 0)) ctx.Fail(t["frame_damping"], "frame_damping must be >= 0");
  fr.keep = ctx.Integer(t, "frame_keep_modes", fr.keep);
  fr.acceleration_modes = ctx.Bool(t, "frame_acceleration_modes", fr.acceleration_modes);
  f.mu = ctx.Positive(t, "road_mu");
  f.animation = ctx.Bool(t, "animation", f.animation);
  f.animation_data.fps = ctx.Double(t, "animation_fps", f.animation_data.fps);
  if (!(f.animation_data.fps > 0)) ctx.Fail(t["animation_fps"], "animation_fps must be > 0");
  f.animation_data.deformation_scale =
      ctx.Double(t, "animation_deformation_scale", f.animation_data.deformation_scale);
  if (!(f.animation_data.deformation_scale >= 0))
    ctx.Fail(t["animation_deformation_scale"], "animation_deformation_scale must be >= 0");
  if (const YAML::Node c = Section(t, "course", ctx,
                                    {"section1_length", "section2_length", "section1_width", "section3_width", "offset"})) {
    LaneChangeCourseData& cd = f.course;
    cd.section1_length = ctx.Double(c, "section1_length", cd.section1_length);
    cd.section2_length = ctx.Double(c, "section2_length", cd.section2_length);
    cd.section1_width = ctx.Double(c, "section1_width", cd.section1_width);
    cd.section3_width = ctx.Double(c, "section3_width", cd.section3_width);
    cd.offset = ctx.Double(c, "offset", cd.offset);
  }
  if (const YAML::Node d = Section(t, "driver", ctx,
                                    {"steering_law", "preview_time", "min_preview", "lag_time", "understeer_gradient_deg",
                                     "steer_in_section1", "max_wheel_angle_deg", "max_wheel_rate_deg",
                                     "neutral_in_section3", "speed_kp", "speed_ki", "max_drive_torque", "hold_speed",
                                     "reaction_delay", "neuromuscular_lag"})) {
    DriverData& dd = f.driver;
    const std::string law = ctx.String(d, "steering_law", "preview");
    if (law != "preview" && law != "pure_pursuit")
      ctx.Fail(d["steering_law"], "steering_law must be 'preview' or 'pure_pursuit', got '" + law + "'");
    dd.steering_law = law == "preview" ? SteeringLaw::kPreview : SteeringLaw::kPurePursuit;
    dd.preview_time = ctx.Double(d, "preview_time", dd.preview_time);
    dd.lag_time = ctx.Double(d, "lag_time", dd.lag_time);
    if (!(dd.lag_time >= 0)) ctx.Fail(d["lag_time"], "lag_time must be >= 0");
    dd.understeer_gradient = ctx.Double(d, "understeer_gradient_deg", dd.understeer_gradient * kDeg) / kDeg;
    dd.steer_in_section1 = ctx.Bool(d, "steer_in_section1", dd.steer_in_section1);
    dd.min_preview = ctx.Double(d, "min_preview", dd.min_preview);
    dd.max_wheel_angle = ctx.Double(d, "max_wheel_angle_deg", dd.max_wheel_angle * kDeg) / kDeg;
    dd.max_wheel_rate = ctx.Double(d, "max_wheel_rate_deg", dd.max_wheel_rate * kDeg) / kDeg;
    dd.neutral_in_section3 = ctx.Bool(d, "neutral_in_section3", dd.neutral_in_section3);
    dd.speed_kp = ctx.Double(d, "speed_kp", dd.speed_kp);
    dd.speed_ki = ctx.Double(d, "speed_ki", dd.speed_ki);
    dd.max_drive_torque = ctx.Double(d, "max_drive_torque", dd.max_drive_torque);
    dd.reaction_delay = ctx.Double(d, "reaction_delay", dd.reaction_delay);
    if (!(dd.reaction_delay >= 0) || !std::isfinite(dd.reaction_delay))
      ctx.Fail(d["reaction_delay"], "reaction_delay must be >= 0 s");
    dd.neuromuscular_lag = ctx.Double(d, "neuromuscular_lag", dd.neuromuscular_lag);
    if (!(dd.neuromuscular_lag >= 0) || !std::isfinite(dd.neuromuscular_lag))
      ctx.Fail(d["neuromuscular_lag"], "neuromuscular_lag must be >= 0 s");
    dd.hold_speed = ctx.Bool(d, "hold_speed", dd.hold_speed);
  }
  if (const YAML::Node s = t["solver"]) {
    ctx.SetEntity("solver");
    ReadSolverSection(s, ctx, f.solver, {"output_interval"});
    if (f.solver.analysis == Analysis::kStatics)
      ctx.Fail(s["analysis"],
               "a lane-change test is a time integration: 'analysis' must be statics_then_dynamics (the default: "
               "rolling off from the static equilibrium) or dynamics (from the ride height of the lever rule)");
    f.dt_min_given = bool(s["dt_min"]);
    f.output_interval = ctx.Double(s, "output_interval", f.output_interval);
  }
  const YAML::Node tr = root["truck"];
  if (!tr) ctx.Fail(root, "missing the 'truck' map");
  f.truck = ParseTruck(tr, ctx, std::filesystem::path(path).parent_path().string());
  // the user's frame comes reduced: its modes and damping are the body file's
  if (f.truck.frame_body) {
    ctx.SetEntity("lane_change_test");
    for (const char* key : {"frame_modes", "frame_keep_modes", "frame_damping", "frame_acceleration_modes"})
      if (t[key])
        ctx.Fail(t[key], std::string("'") + key +
                             "' applies to the generated frame; the truck's frame is the body file " +
                             f.truck.frame_body_file + " (set modes and damping when reducing it: flexmb reduce "
                             "--modes, --keep, --damping-ratio, --acceleration-modes)");
  }
  f.driver.steering_ratio = f.truck.steering_ratio;
  return f;
}

// roll, pitch, yaw (z-y-x) of a rotation matrix [rad]
Vec3 RollPitchYaw(const Mat3& R) {
  return Vec3(std::atan2(R(2, 1), R(2, 2)), -std::asin(std::clamp(R(2, 0), -1.0, 1.0)), std::atan2(R(1, 0), R(0, 0)));
}

}  // namespace

bool IsLaneChangeFile(const std::string& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path);
    return root.IsMap() && root["lane_change_test"];
  } catch (const std::exception&) {
    return false;
  }
}

TruckData LoadLaneChangeTruck(const std::string& file) { return ReadFile(file).truck; }

TruckFileSettings LoadTruckFileSettings(const std::string& file) {
  const LaneChangeFile f = ReadFile(file);
  return {f.speed_kmh, f.run_up_time, f.frame, f.reduction, f.mu, f.driver, f.solver, f.dt_min_given,
          f.output_interval, f.truck};
}

FrameReductionData LaneChangeFrameReduction(const std::string& file) { return ReadFile(file).reduction; }

std::shared_ptr<const reduction::ReducedBody> ReduceTruckFrame(const TruckData& d, const FrameReductionData& r,
                                                               double g) {
  if (d.frame_body) return d.frame_body;  // the user's frame, reduced by them
  GeneratedFrameModel frame = BuildGeneratedFrameModel(d, g);
  fe::FeModel model;
  model.mesh = std::move(frame.mesh);
  reduction::ReductionOptions o;
  o.interface_nodes = std::move(frame.interface_nodes);
  o.normal_modes = r.normal_modes;
  o.keep = r.keep;
  o.acceleration_modes = r.acceleration_modes;
  o.damping_ratios = {r.damping_ratio};
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
}

namespace {

/// A run's set-up: the file with the caller's overrides, the course, the
/// driver and the finalized truck model (the elastic frame reduced, or the
/// caller's). Built in place: the driver refers to the course.
struct LaneChangeSetup {
  LaneChangeFile f;
  double v0 = 0.0;
  bool by_time = false;  // entry speed <= 0.1 m/s: the 10 s standing test
  std::unique_ptr<LaneChangeCourse> course;
  std::unique_ptr<Driver> driver;
  Model model;
  TruckHandles h;
  double reduction_wall_time_s = 0.0;
};

std::unique_ptr<LaneChangeSetup> SetUpLaneChange(const LaneChangeOptions& opt) {
  auto setup = std::make_unique<LaneChangeSetup>();
  LaneChangeFile& f = setup->f;
  f = ReadFile(opt.file);
  if (opt.speed_kmh) f.speed_kmh = *opt.speed_kmh;
  if (opt.frame) f.frame = *opt.frame;
  SolverOverrides overrides;
  overrides.dt = opt.dt;
  ApplySolverOverrides(overrides, f.solver);
  if (!f.dt_min_given) f.solver.dt_min = 1e-6 * f.solver.dt;
  for (const auto& [key, value] : opt.driver_settings) SetDriverSetting(f.driver, key, value);
  if (opt.run_up_time) f.run_up_time = *opt.run_up_time;
  if (!(f.run_up_time >= 0) || !std::isfinite(f.run_up_time)) throw InputError("run-up time must be >= 0 s");
  if (!std::isfinite(f.speed_kmh) || f.speed_kmh < 0) throw InputError("entry speed must be >= 0 km/h");
  if (f.frame != "rigid" && f.frame != "elastic") throw InputError("frame must be 'rigid' or 'elastic', got '" + f.frame + "'");
  if (opt.animation) f.animation = *opt.animation;
  if (opt.animation_fps) {
    f.animation_data.fps = *opt.animation_fps;
    f.animation = true;
  }
  if (f.animation && opt.out_dir.empty()) f.animation = false;

  setup->v0 = f.speed_kmh / 3.6;
  setup->by_time = setup->v0 <= 0.1;
  // the truck starts at x = 0 and reaches section 1 after the run-up
  f.course.start_x = setup->by_time ? 0.0 : setup->v0 * f.run_up_time;
  setup->course = std::make_unique<LaneChangeCourse>(f.course);
  setup->driver = std::make_unique<Driver>(f.driver, *setup->course, setup->v0);
  Model& model = setup->model;
  if (!opt.out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(opt.out_dir, ec);
  }
  if (f.frame == "elastic") {
    // reduce the generated frame (or take the caller's) and keep the body file
    const auto t0 = std::chrono::steady_clock::now();
    std::shared_ptr<const reduction::ReducedBody> body = opt.frame_body;
    if (!body) {
      auto reduced = ReduceTruckFrame(f.truck, f.reduction, -model.gravity_W.z());
      if (!opt.out_dir.empty()) io::WriteBody(*reduced, (std::filesystem::path(opt.out_dir) / "frame.h5").string());
      body = std::move(reduced);
    }
    f.truck.elastic_frame = body;
    setup->reduction_wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  model.name = "truck_lane_change";
  model.solver = f.solver;
  Driver& driver = *setup->driver;
  setup->h = BuildTruck(f.truck, setup->v0, f.mu, driver.steering_wheel_angle(), driver.drive_torque(), model,
                        driver.brake_torque());
  model.Finalize();
  return setup;
}

}  // namespace

void CheckLaneChange(const LaneChangeOptions& opt, std::FILE* out) {
  const std::unique_ptr<LaneChangeSetup> setup = SetUpLaneChange(opt);
  const LaneChangeFile& f = setup->f;
  ReportModel(setup->model, opt.file, out);
  const double g = -setup->model.gravity_W.z();
  const std::vector<double> axle = StaticAxleLoads(f.truck, g);
  std::fprintf(out, "lane-change test: entry speed %.1f km/h, run-up %.1f m (%.2f s), %s frame", f.speed_kmh,
               f.course.start_x, f.run_up_time, f.frame.c_str());
  if (f.truck.elastic_frame && f.truck.frame_body)
    std::fprintf(out, " (%d modal coordinates, from the body file)", f.truck.elastic_frame->invariants.n);
  else if (f.truck.elastic_frame)
    std::fprintf(out, " (%d modal coordinates, reduced in %.2f s)", f.truck.elastic_frame->invariants.n,
                 setup->reduction_wall_time_s);
  const LaneChangeCourseData& c = f.course;
  std::fprintf(out,
               "\ncourse: section 1 %.1f m wide %.2f m, section 2 %.1f m, section 3 wide %.2f m at offset %.2f m; "
               "test distance %.1f m\n",
               c.section1_length, c.section1_width, c.section2_length, c.section3_width, c.offset,
               setup->course->TestDistance());
  std::fprintf(out, "static axle loads:");
  double total = 0;
  for (size_t i = 0; i < axle.size(); ++i) {
    std::fprintf(out, "%s %s %.2f kN", i ? "," : "", f.truck.axles[i].name.c_str(), axle[i] / 1e3);
    total += axle[i];
  }
  std::fprintf(out, " (%.0f kg in all)\n", total / g);
  if (!f.truck.frame_body && f.truck.frame_mesh) {
    // the generated frame: its size, masses and the platform
    const LadderFrameData& lf = f.truck.ladder;
    std::fprintf(out, "frame: generated ladder frame, %zu shells, %.0f kg", f.truck.frame_mesh->elements.size(),
                 f.truck.frame.mass);
    if (lf.platform.present)
      std::fprintf(out,
                   " (rails and cross members %.0f kg, platform %.0f kg: x = %.2f to %.2f m, %.2f m wide, %zu "
                   "brackets per side; the cargo on its top at z = %.3f m)",
                   lf.total_mass, lf.platform.mass, lf.platform.front_x - lf.platform.length, lf.platform.front_x,
                   lf.platform.width, lf.platform.brackets.size(), PlatformTopZ(lf));
    std::fprintf(out, "\n");
  }
  if (f.truck.frame_body) {
    // the user's frame: its mounts and the largest lever from node to point
    double largest = 0;
    std::string where;
    for (const FrameAttachment& a : FrameAttachments(f.truck, g)) {
      const int node = FrameMountNode(f.truck, *f.truck.frame_body, a.name, a.point);
      const double dist = (f.truck.frame_body->mesh.nodes[static_cast<size_t>(node)].x - a.point).norm();
      if (dist >= largest) std::tie(largest, where) = std::make_pair(dist, a.name);
    }
    std::fprintf(out, "frame: body file %s, %.0f kg, %zu mounts on its interface nodes, largest offset %.3f m (%s)\n",
                 f.truck.frame_body_file.c_str(), f.truck.frame.mass, f.truck.frame_mounts.size(), largest,
                 where.c_str());
  }
  std::fprintf(out, "driver: %s, preview %.2f s (min %.1f m), reaction delay %.2f s, neuromuscular lag %.2f s, speed %s\n",
               f.driver.steering_law == SteeringLaw::kPreview ? "preview" : "pure pursuit", f.driver.preview_time,
               f.driver.min_preview, f.driver.reaction_delay, f.driver.neuromuscular_lag,
               f.driver.hold_speed ? "held" : "not held");
  std::fprintf(out, "solver: dt %g s, rho_inf %g, newton_tol %g, jacobian_reuse %s (rate %g)\n", f.solver.dt,
               f.solver.rho_inf, f.solver.newton_tol, f.solver.jacobian_reuse ? "on" : "off",
               f.solver.jacobian_reuse_rate);
  std::fflush(out);
}

LaneChangeResult RunLaneChange(const LaneChangeOptions& opt) {
  const std::unique_ptr<LaneChangeSetup> setup = SetUpLaneChange(opt);
  LaneChangeFile& f = setup->f;
  const double v0 = setup->v0;
  const bool by_time = setup->by_time;
  const double x_start = f.course.start_x;
  const LaneChangeCourse& course = *setup->course;
  Driver& driver = *setup->driver;
  Model& model = setup->model;
  const TruckHandles& h = setup->h;
  LaneChangeResult r;
  r.run_up = x_start;
  r.frame = f.frame;
  r.reduction_wall_time_s = setup->reduction_wall_time_s;
  r.entry_speed_kmh = f.speed_kmh;
  const size_t n_axles = f.truck.axles.size(), n_wheels = 2 * n_axles;
  r.static_axle_load = StaticAxleLoads(f.truck, -model.gravity_W.z());
  for (const AxleData& a : f.truck.axles) r.axle_names.push_back(a.name);
  r.min_axle_load.assign(n_axles, 1e300);
  r.max_abs_ltr.assign(n_axles, 0.0);
  r.min_corridor_margin = 1e300;
  const double distance = opt.stop_distance ? std::min(*opt.stop_distance, course.TestDistance()) : course.TestDistance();
  const double t_limit = by_time ? 10.0 : 1.5 * distance / v0 + f.run_up_time + 5.0;

  std::FILE* csv = nullptr;
  if (!opt.out_dir.empty()) {
    csv = std::fopen((std::filesystem::path(opt.out_dir) / "results.csv").string().c_str(), "w");
    if (!csv) throw InputError("cannot write results.csv", {opt.out_dir, 0, ""});
    // per axle and wheel: front_axle_load_kN, ..., fz_fl_kN, ..., liftoff_fl, ..., ltr_front, ...
    std::string axles, fz, lift, ltr;
    for (const AxleData& a : f.truck.axles) {
      axles += a.name + "_axle_load_kN,";
      ltr += ",ltr_" + a.name;
      for (int k = 0; k < 2; ++k) {
        fz += "fz_" + WheelName(a, k).substr(6) + "_kN,";
        lift += "liftoff_" + WheelName(a, k).substr(6) + ",";
      }
    }
    std::fprintf(csv,
                 "time,x,y,centre_line_y,speed_kmh,lateral_acceleration,steering_wheel_angle_deg,road_wheel_angle_deg,"
                 "roll_deg,pitch_deg,yaw_deg,yaw_rate_degps,%s%s%scorridor_margin,drive_torque_kNm,"
                 "wheel_angle_left_deg,wheel_angle_right_deg%s%s\n",
                 axles.c_str(), fz.c_str(), lift.c_str(), ltr.c_str(),
                 h.elastic ? ",frame_max_displacement_mm,frame_max_displacement_node,frame_max_displacement_x,"
                             "frame_max_stress_MPa,frame_max_stress_element,frame_max_stress_x"
                           : "");
  }

  std::unique_ptr<TruckAnimation> animation;
  if (f.animation)
    animation = std::make_unique<TruckAnimation>((std::filesystem::path(opt.out_dir) / "animation").string(), f.truck,
                                                 h, course, f.animation_data, model);

  Simulator sim(model);
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  double next_row = 0.0;
  const Body* frame_body = model.bodies[h.frame_body].get();
  const Marker& frame_ref = model.markers[static_cast<size_t>(h.frame_ref)];
  // elastic frame: its modal coordinates at every row, for "flexmb post"
  std::unique_ptr<durability::ModelModalHistory> modal;
  // the generated frame's body file is DIR/frame.h5 (written above), a
  // caller's frame is written to DIR/bodies/frame.h5
  if (!opt.out_dir.empty() && h.elastic) {
    std::map<std::string, std::string> written;
    if (!opt.frame_body) written.emplace("frame", "frame.h5");
    modal = std::make_unique<durability::ModelModalHistory>(opt.out_dir, model, written);
  }
  const size_t row_chars = FrameResponse::RowChars(n_axles);
  FrameResponse frame_response(h.elastic ? static_cast<const FlexibleBody*>(frame_body) : nullptr, csv, row_chars);
  const double wheelbase = Wheelbase(f.truck), steering_wheelbase = DriverWheelbase(f.truck, -model.gravity_W.z());
  std::vector<double> fz(n_wheels), axle_load(n_axles), ltr(n_axles);  // per step, allocated once
  std::vector<int> lift(n_wheels);
  std::vector<char> line_buffer(row_chars);  // the row, allocated once
  char* const line = line_buffer.data();
  r.frame_modal_coordinates = h.elastic ? f.truck.elastic_frame->invariants.n : 0;
  try {
    sim.Initialize();
    if (f.solver.analysis == Analysis::kStaticsThenDynamics) sim.SettleStatics(TruckStaticsSettings(), true);
    sim.Run(t_limit, 0.0, [&](const State& st, const Workspace& ws) {
      const MarkerState& fr = ws.markers[h.frame_ref];
      const Vec3 rpy = RollPitchYaw(fr.R_WM);
      const double yaw = rpy.z();
      const Vec3 ex(std::cos(yaw), std::sin(yaw), 0), ey(-std::sin(yaw), std::cos(yaw), 0);
      const Vec3 pf = ws.markers[h.front_axle_ref].p_WM, pr = ws.markers[h.rear_axle_ref].p_WM;
      const double speed = fr.v_WM.dot(ex);
      // acceleration of the frame's centre of mass (the ref marker)
      const Vec6 acc = fr.J * ws.vdot.segment(frame_body->v_offset, frame_body->nv()) +
                       frame_body->MarkerAccelerationBias(st.q.data() + frame_body->q_offset,
                                                          st.v.data() + frame_body->v_offset, frame_ref);
      const double ay = acc.head<3>().dot(ey);
      const double yaw_rate = fr.w_WM.z();

      // controllers, held over the next step
      driver.Update(VehicleView{st.t, pf.x(), pr.x(), pr.y(), yaw, speed, wheelbase, pf.y(), yaw_rate, steering_wheelbase});

      // tires, axle loads, lift-off
      bool lifted = false;
      for (size_t k = 0; k < n_wheels; ++k) {
        const MarkerState& wm = ws.markers[h.wheel_marker[k]];
        TireContact c;
        static_cast<const Tire&>(*model.forces[h.tire_force[k]]).Wrench(wm.p_WM, wm.R_WM, wm.v_WM, wm.w_WM, &c);
        fz[k] = c.fz;
        lift[k] = c.fz <= 0.0 ? 1 : 0;
        lifted = lifted || lift[k];
      }
      // axle load and load-transfer ratio per axle (a lifted wheel carries no load)
      for (size_t a = 0; a < n_axles; ++a) {
        axle_load[a] = fz[2 * a] + fz[2 * a + 1];
        const double left = std::max(fz[2 * a], 0.0), right = std::max(fz[2 * a + 1], 0.0);
        ltr[a] = left + right > 0 ? (left - right) / (left + right) : 0.0;
      }
      // corridor margin of the gauge points
      double margin = 1e300;
      for (int g : h.gauge) margin = std::min(margin, course.Margin(ws.markers[g].p_WM.x(), ws.markers[g].p_WM.y()));

      // actual road-wheel angles (kingpin joint coordinates)
      auto KingpinAngle = [&](int k) {
        const Joint& j = *model.joints[h.kingpin_joint[k]];
        return j.Coordinate(0, ws.markers[j.marker_i], ws.markers[j.marker_j], nullptr);
      };
      // the settling in the run-up is not part of the test
      const bool record = st.t > 0.0 && (by_time || pf.x() >= x_start);
      if (record) {
        r.min_corridor_margin = std::min(r.min_corridor_margin, margin);
        r.max_lateral_acceleration = std::max(r.max_lateral_acceleration, std::abs(ay));
        r.max_roll_deg = std::max(r.max_roll_deg, std::abs(rpy.x()) * kDeg);
        r.max_steering_wheel_deg = std::max(r.max_steering_wheel_deg, std::abs(*driver.steering_wheel_angle()) * kDeg);
        r.max_yaw_rate_deg = std::max(r.max_yaw_rate_deg, std::abs(yaw_rate) * kDeg);
        for (size_t a = 0; a < n_axles; ++a) {
          r.min_axle_load[a] = std::min(r.min_axle_load[a], axle_load[a]);
          r.max_abs_ltr[a] = std::max(r.max_abs_ltr[a], std::abs(ltr[a]));
        }
        if (margin < 0 && r.corridor_exit_time < 0) r.corridor_exit_time = st.t;
        if (lifted && r.lift_off_time < 0) r.lift_off_time = st.t;
      }
      r.t_end = st.t;
      r.distance = pf.x() - x_start;
      const bool done = by_time ? st.t >= 10.0 - 1e-9 : r.distance >= distance;
      const bool row = st.t >= next_row - 1e-9 || done;
      if (row) next_row = st.t + f.output_interval;
      if (csv && row) {
        size_t len = 0;
        auto put = [&](const char* format, auto... values) {
          const int n = std::snprintf(line + len, row_chars - len, format, values...);
          if (n < 0 || len + static_cast<size_t>(n) >= row_chars) throw std::logic_error("results.csv row too long");
          len += static_cast<size_t>(n);
        };
        put("%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", st.t, pf.x() - x_start, pf.y(),
            course.CentreLine(pf.x()), speed * 3.6, ay, *driver.steering_wheel_angle() * kDeg,
            driver.road_wheel_angle() * kDeg, rpy.x() * kDeg, rpy.y() * kDeg, yaw * kDeg, yaw_rate * kDeg);
        for (size_t a = 0; a < n_axles; ++a) put(",%.6g", axle_load[a] / 1e3);
        for (size_t k = 0; k < n_wheels; ++k) put(",%.6g", fz[k] / 1e3);
        for (size_t k = 0; k < n_wheels; ++k) put(",%d", lift[k]);
        put(",%.6g,%.6g,%.6g,%.6g", margin, *driver.drive_torque() / 1e3, KingpinAngle(0) * kDeg,
            KingpinAngle(1) * kDeg);
        for (size_t a = 0; a < n_axles; ++a) put(",%.6g", ltr[a]);
        if (!frame_response.active()) std::fprintf(csv, "%s\n", line);
      }
      // elastic frame: deflection and stress hot spot at the output times
      // (the row waits for its frame columns in the batch)
      if (row && modal) modal->Write(st);
      if (row && frame_response.active())
        frame_response.Add(st.t, st.q.data() + frame_body->q_offset, record, csv ? line : nullptr, r);
      if (animation) {
        const auto a0 = std::chrono::steady_clock::now();
        if (animation->Update(st)) {
          r.animation_wall_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - a0).count();
          if (opt.on_animation_frame) opt.on_animation_frame(model, st);
        }
      }
      if (done) throw EndOfTest{};
      // a truck rolled past 45 degrees is over: end the run as failed
      if (record && std::abs(rpy.x()) > std::numbers::pi / 4) {
        r.rolled_over = true;
        throw EndOfTest{};
      }
      if (opt.stop_on_failure && (r.corridor_exit_time >= 0 || r.lift_off_time >= 0)) throw EndOfTest{};
    });
    r.message = "the time limit was reached before the test distance";
  } catch (const EndOfTest&) {
    r.completed = !r.rolled_over && (by_time ? r.t_end >= 10.0 - 1e-9 : r.distance >= distance);
    if (r.rolled_over) r.message = "the truck rolled over (|roll| > 45 deg)";
  } catch (const NumericalError& e) {
    r.message = e.what();
  } catch (...) {
    // keep what was computed (rows waiting in the batch) before passing the error on
    frame_response.Flush(r);
    if (csv) std::fclose(csv);
    throw;
  }
  frame_response.Flush(r);
  if (csv) std::fclose(csv);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.animation_frames = animation ? animation->frames() : 0;
  r.steps = sim.stats().steps;
  r.newton_iterations = sim.stats().newton_iterations;
  r.factorizations = sim.stats().factorizations;
  r.cpu_time_s = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  r.wall_time_s = wall;
  r.real_time_factor = wall > 0 ? r.t_end / wall : 0.0;
  r.passed = r.completed && r.corridor_exit_time < 0 && r.lift_off_time < 0;
  if (r.min_corridor_margin > 1e299) r.min_corridor_margin = 0;
  if (!opt.out_dir.empty()) {
    std::ofstream js(std::filesystem::path(opt.out_dir) / "summary.json");
    js << LaneChangeJson(r);
  }
  if (opt.info)
    std::fprintf(opt.info,
                 "lane change at %.1f km/h (%s frame): %s; %s after %.1f m, t = %.2f s; max |a_y| %.2f m/s^2, "
                 "max |roll| %.2f deg, min corridor margin %.3f m; %.2f s wall time (real-time factor %.1f; %.1f on CPU time)\n",
                 r.entry_speed_kmh, r.frame.c_str(), r.passed ? "passed" : "failed", r.completed ? "completed" : "stopped", r.distance,
                 r.t_end, r.max_lateral_acceleration, r.max_roll_deg, r.min_corridor_margin, r.wall_time_s,
                 r.real_time_factor, r.cpu_time_s > 0 ? r.t_end / r.cpu_time_s : 0.0);
  if (opt.info && animation)
    std::fprintf(opt.info, "animation: %d frames at %g per second of simulated time in %s (%.2f s wall time)\n",
                 r.animation_frames, f.animation_data.fps, animation->writer().pvd_path().c_str(),
                 r.animation_wall_time_s);
  if (opt.info && r.frame == "elastic")
    std::fprintf(opt.info,
                 "elastic frame (%d modal coordinates, reduced in %.2f s): max elastic displacement %.2f mm at node %d "
                 "(x = %.2f m, t = %.2f s), max von Mises stress %.1f MPa in element %d (x = %.2f m, t = %.2f s)\n",
                 r.frame_modal_coordinates, r.reduction_wall_time_s, r.max_frame_displacement * 1e3,
                 r.max_displacement_node, r.max_displacement_position.x(), r.max_displacement_time,
                 r.max_frame_stress / 1e6, r.max_stress_element, r.max_stress_position.x(), r.max_stress_time);
  return r;
}

double MaxPassSpeed(const LaneChangeOptions& base, double low, double high, double tol, std::FILE* log,
                    bool* low_passed) {
  if (!(low > 0) || !(high > low) || !(tol > 0)) throw InputError("max-speed: need 0 < low < high and tol > 0");
  // an elastic frame is reduced once for all trials
  LaneChangeOptions shared = base;
  if (!shared.frame_body) {
    const LaneChangeFile f = ReadFile(base.file);
    if (base.frame.value_or(f.frame) == "elastic")
      shared.frame_body = ReduceTruckFrame(f.truck, f.reduction);
  }
  auto passes = [&](double v) {
    LaneChangeOptions o = shared;
    o.speed_kmh = v;
    o.out_dir.clear();
    o.stop_on_failure = true;
    o.info = nullptr;
    const LaneChangeResult r = RunLaneChange(o);
    if (log)
      std::fprintf(log, "  %.2f km/h: %s (corridor margin %.3f m%s%s)\n", v, r.passed ? "passed" : "failed",
                   r.min_corridor_margin, r.lift_off_time >= 0 ? ", wheel lift-off" : "",
                   r.rolled_over ? ", rolled over" : "");
    return r.passed;
  };
  *low_passed = passes(low);
  if (!*low_passed) return low;
  if (passes(high)) return high;
  while (high - low > tol) {
    const double mid = 0.5 * (low + high);
    (passes(mid) ? low : high) = mid;
  }
  return low;
}

std::string LaneChangeJson(const LaneChangeResult& r) {
  std::string j = "{\n";
  auto add = [&](const char* key, const std::string& value, bool last = false) {
    j += "  " + JsonString(key) + ": " + value + (last ? "\n" : ",\n");
  };
  auto b = [](bool v) { return std::string(v ? "true" : "false"); };
  add("status", JsonString(r.completed ? "ok" : "failed"));
  add("message", JsonString(r.message));
  add("frame", JsonString(r.frame));
  add("passed", b(r.passed));
  add("completed", b(r.completed));
  add("entry_speed_kmh", JsonNumber(r.entry_speed_kmh));
  add("distance", JsonNumber(r.distance));
  add("run_up", JsonNumber(r.run_up));
  add("t_end", JsonNumber(r.t_end));
  add("corridor_exit", b(r.corridor_exit_time >= 0));
  add("corridor_exit_time", JsonNumber(r.corridor_exit_time));
  add("rolled_over", b(r.rolled_over));
  add("lift_off", b(r.lift_off_time >= 0));
  add("lift_off_time", JsonNumber(r.lift_off_time));
  add("min_corridor_margin", JsonNumber(r.min_corridor_margin));
  add("max_lateral_acceleration", JsonNumber(r.max_lateral_acceleration));
  add("max_roll_deg", JsonNumber(r.max_roll_deg));
  add("max_steering_wheel_deg", JsonNumber(r.max_steering_wheel_deg));
  add("max_yaw_rate_degps", JsonNumber(r.max_yaw_rate_deg));
  // per axle: min_front_axle_load, ..., max_ltr_front, ..., static_front_axle_load, ...
  const size_t n_axles = r.axle_names.size();
  for (size_t a = 0; a < n_axles; ++a)
    add(("min_" + r.axle_names[a] + "_axle_load").c_str(), JsonNumber(r.min_axle_load[a]));
  double max_ltr = 0;
  for (size_t a = 0; a < n_axles; ++a) {
    add(("max_ltr_" + r.axle_names[a]).c_str(), JsonNumber(r.max_abs_ltr[a]));
    max_ltr = std::max(max_ltr, r.max_abs_ltr[a]);
  }
  add("rollover_margin", JsonNumber(1.0 - max_ltr));
  for (size_t a = 0; a < n_axles; ++a)
    add(("static_" + r.axle_names[a] + "_axle_load").c_str(), JsonNumber(r.static_axle_load[a]));
  add("steps", std::to_string(r.steps));
  add("newton_iterations", std::to_string(r.newton_iterations));
  add("factorizations", std::to_string(r.factorizations));
  add("wall_time_s", JsonNumber(r.wall_time_s));
  add("cpu_time_s", JsonNumber(r.cpu_time_s));
  add("animation_frames", std::to_string(r.animation_frames));
  add("animation_wall_time_s", JsonNumber(r.animation_wall_time_s));
  add("real_time_factor_cpu", JsonNumber(r.cpu_time_s > 0 ? r.t_end / r.cpu_time_s : 0.0));
  add("real_time_factor", JsonNumber(r.real_time_factor), r.frame != "elastic");
  if (r.frame == "elastic") {
    auto pos = [](const Vec3& x) {
      return "[" + JsonNumber(x.x()) + ", " + JsonNumber(x.y()) + ", " + JsonNumber(x.z()) + "]";
    };
    add("frame_modal_coordinates", std::to_string(r.frame_modal_coordinates));
    add("reduction_wall_time_s", JsonNumber(r.reduction_wall_time_s));
    add("max_frame_displacement_mm", JsonNumber(r.max_frame_displacement * 1e3));
    add("max_displacement_node", std::to_string(r.max_displacement_node));
    add("max_displacement_position", pos(r.max_displacement_position));
    add("max_displacement_time", JsonNumber(r.max_displacement_time));
    add("max_frame_stress_MPa", JsonNumber(r.max_frame_stress / 1e6));
    add("max_stress_element", std::to_string(r.max_stress_element));
    add("max_stress_position", pos(r.max_stress_position));
    add("max_stress_time", JsonNumber(r.max_stress_time), true);
  }
  return j + "}\n";
}

}  // namespace flexmb::vehicle
