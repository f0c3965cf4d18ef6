#include "apps/flexmb/commands/straight_run.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>

#include "apps/flexmb/commands/analysis_support.h"
#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/common/error.h"
#include "flexmb/common/json_text.h"
#include "flexmb/durability/modal_history.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/vehicle/driver.h"
#include "flexmb/vehicle/lane_change_course.h"
#include "flexmb/vehicle/road_surface.h"
#include "flexmb/vehicle/single_track.h"
#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {
namespace {

/// Thrown by the observer when the front axle has driven the distance.
struct StraightRunEnd {};

// running mean, variance and extremes of one force (Welford)
struct StraightRunMoments {
  long n = 0;
  double mean = 0.0, m2 = 0.0, min = 1e300, max = -1e300;
  void Add(double v) {
    ++n;
    const double d = v - mean;
    mean += d / static_cast<double>(n);
    m2 += d * (v - mean);
    min = std::min(min, v);
    max = std::max(max, v);
  }
  ForceStatistics Result(const std::string& name) const {
    if (n == 0) return {name, 0, 0, 0, 0};
    return {name, mean, std::sqrt(m2 / static_cast<double>(n)), min, max};
  }
};

// an option error naming the file and the option
[[noreturn]] void StraightRunFail(const StraightRunOptions& o, const std::string& option, const std::string& what) {
  throw InputError(what, {o.file, 0, "straight run option " + option});
}

}  // namespace

RoadProfile StraightRunRoad(const StraightRunOptions& o, double track_width) {
  if (!(o.fade_in >= 0) || !std::isfinite(o.fade_in)) StraightRunFail(o, "--fade-in", "must be a length >= 0 [m]");
  RoadProfile p;
  if (o.road == "flat") {
    if (!(o.road_length > 0) || !std::isfinite(o.road_length))
      StraightRunFail(o, "--road-length", "must be a positive length [m]");
    p.x = {0.0, o.road_length};
    p.z_left = p.z_right = {0.0, 0.0};
    return p;
  }
  if (o.road == "iso8608") {
    if (o.road_class.size() != 1)
      StraightRunFail(o, "--road-class", "expected one letter A to H, got '" + o.road_class + "'");
    if (!(o.road_length > 0) || !std::isfinite(o.road_length))
      StraightRunFail(o, "--road-length", "must be a positive length [m]");
    Iso8608Options g;
    g.road_class = o.road_class[0];
    g.length = o.road_length;
    g.seed = o.seed;
    g.track_width = track_width;
    try {
      p = GenerateIso8608(g);
    } catch (const InputError& e) {
      StraightRunFail(o, "--road-class", std::string("'") + o.road_class + "': " + e.what());
    }
    // the generated grid is a power of two long: keep the requested length
    const auto end = std::upper_bound(p.x.begin(), p.x.end(), o.road_length + 1e-9);
    const size_t keep = std::max<size_t>(2, static_cast<size_t>(end - p.x.begin()));
    p.x.resize(keep);
    p.z_left.resize(keep);
    p.z_right.resize(keep);
  } else if (o.road == "csv") {
    if (o.road_csv.empty()) StraightRunFail(o, "--road-csv", "no road file given");
    p = ReadRoadCsv(o.road_csv);
    const double x0 = p.x.front();
    for (double& x : p.x) x -= x0;
  } else {
    StraightRunFail(o, "--road", "expected flat, iso8608 or csv, got '" + o.road + "'");
  }
  // fade-in: the road starts level
  for (size_t i = 0; i < p.x.size() && p.x[i] < o.fade_in; ++i) {
    const double w = 0.5 * (1.0 - std::cos(std::numbers::pi * p.x[i] / o.fade_in));
    p.z_left[i] *= w;
    p.z_right[i] *= w;
  }
  return p;
}

StraightRunResult RunStraight(const StraightRunOptions& opt) {
  TruckFileSettings f = LoadTruckFileSettings(opt.file);
  if (opt.speed_kmh) f.speed_kmh = *opt.speed_kmh;
  if (opt.frame) f.frame = *opt.frame;
  if (!std::isfinite(f.speed_kmh) || !(f.speed_kmh > 0))
    StraightRunFail(opt, "--speed", "the speed must be a positive number [km/h]");
  if (f.frame != "rigid" && f.frame != "elastic")
    StraightRunFail(opt, "--frame", "expected rigid or elastic, got '" + f.frame + "'");
  SolverOverrides overrides;
  overrides.dt = opt.dt;
  ApplySolverOverrides(overrides, f.solver);
  if (!f.dt_min_given) f.solver.dt_min = 1e-6 * f.solver.dt;
  const double v0 = f.speed_kmh / 3.6;
  TruckData& truck = f.truck;

  // the road: its x = 0 lies where the front axle is after the run-up
  if (!(opt.run_up_time >= 0) || !std::isfinite(opt.run_up_time))
    StraightRunFail(opt, "--run-up", "must be a time >= 0 [s]");
  f.run_up_time = opt.run_up_time;
  const double run_up = v0 * f.run_up_time;
  auto profile = std::make_shared<RoadProfile>(StraightRunRoad(opt, 0.5 * (truck.axles.front().track + truck.axles.back().track)));
  const double road_length = profile->x.back();
  const double distance = opt.distance.value_or(road_length);
  if (!(distance > 0) || !std::isfinite(distance))
    StraightRunFail(opt, "--distance", "must be a positive length [m]");
  if (distance > road_length + 1e-9)
    StraightRunFail(opt, "--distance", "the run of " + io::JsonNumber(distance) + " m is longer than the road (" +
                                           io::JsonNumber(road_length) + " m)");
  for (double& x : profile->x) x += run_up;

  StraightRunResult r;
  r.frame = f.frame;
  r.speed_kmh = f.speed_kmh;
  r.road_length = road_length;
  r.run_up = run_up;
  r.road = opt.road == "iso8608" ? "iso8608 class " + opt.road_class + ", seed " + std::to_string(opt.seed)
           : opt.road == "csv"   ? opt.road_csv
                                 : "flat";

  // the driver holds the speed and the straight line y = 0
  LaneChangeCourseData cd;
  cd.offset = 0.0;
  cd.start_x = 0.0;
  const LaneChangeCourse course(cd);
  Driver driver(f.driver, course, v0);
  if (!opt.out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(opt.out_dir, ec);
  }
  Model model;
  if (f.frame == "elastic") {
    const auto t0 = std::chrono::steady_clock::now();
    std::shared_ptr<const reduction::ReducedBody> body = opt.frame_body;
    if (!body) {
      auto reduced = ReduceTruckFrame(truck, f.reduction, -model.gravity_W.z());
      if (!opt.out_dir.empty()) io::WriteBody(*reduced, (std::filesystem::path(opt.out_dir) / "frame.h5").string());
      body = std::move(reduced);
    }
    truck.elastic_frame = body;
    r.reduction_wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  model.name = "truck_straight_run";
  model.solver = f.solver;
  const TruckHandles h = BuildTruck(truck, v0, f.mu, driver.steering_wheel_angle(), driver.drive_torque(), model,
                                    driver.brake_torque());
  // the tires follow the left (FL, RL, ...) and right (FR, RR, ...) tracks
  const std::array<std::shared_ptr<const RoadSurface>, 2> surface = {std::make_shared<RoadSurface>(profile, 0),
                                                                      std::make_shared<RoadSurface>(profile, 1)};
  const size_t n_axles = truck.axles.size(), n_wheels = 2 * n_axles;
  for (size_t k = 0; k < n_wheels; ++k) static_cast<Tire&>(*model.forces[h.tire_force[k]]).SetRoad(surface[k % 2]);
  // the mounts and springs on the frame: bushings and spring-dampers with
  // marker i on it (and a bogie's springs with marker i on its beams)
  std::vector<int> mounts;
  for (size_t i = 0; i < model.forces.size(); ++i) {
    const ForceElement& fe = *model.forces[i];
    const std::string type = fe.type();
    const int body = model.markers[static_cast<size_t>(fe.marker_i)].body;
    // on the frame, or a bogie's spring on its balancer beam
    const bool on_beam = body >= 0 && model.bodies[static_cast<size_t>(body)]->name().starts_with("bogie_");
    if ((type == "bushing" || type == "spring_damper") && (body == h.frame_body || on_beam))
      mounts.push_back(static_cast<int>(i));
  }
  model.Finalize();

  std::FILE* csv = nullptr;
  if (!opt.out_dir.empty()) {
    csv = std::fopen((std::filesystem::path(opt.out_dir) / "results.csv").string().c_str(), "w");
    if (!csv) throw InputError("cannot write results.csv", {opt.out_dir, 0, ""});
    std::fprintf(csv, "time,x,y,speed_kmh,steering_wheel_angle_deg,drive_torque_kNm");
    for (const char* what : {"road_%s_mm", "fz_%s_kN"})
      for (const AxleData& a : truck.axles)
        for (int k = 0; k < 2; ++k) {
          std::fprintf(csv, ",");
          std::fprintf(csv, what, WheelName(a, k).substr(6).c_str());
        }
    for (const AxleData& a : truck.axles) std::fprintf(csv, ",%s_axle_load_kN", a.name.c_str());
    for (int i : mounts) std::fprintf(csv, ",%s_fz_kN", model.forces[static_cast<size_t>(i)]->name().c_str());
    std::fprintf(csv, "\n");
  }
  std::unique_ptr<durability::ModelModalHistory> modal;
  if (!opt.out_dir.empty() && h.elastic) {
    std::map<std::string, std::string> written;
    if (!opt.frame_body) written.emplace("frame", "frame.h5");
    modal = std::make_unique<durability::ModelModalHistory>(opt.out_dir, model, written);
  }

  std::vector<StraightRunMoments> tire_moments(n_wheels);
  std::vector<double> fz(n_wheels), road(n_wheels);  // per step, allocated once
  std::vector<StraightRunMoments> mount_moments(mounts.size());
  StraightRunMoments speed_moments;
  ForceEval fe;
  fe.tangents = false;
  const double driver_wheelbase = DriverWheelbase(truck, -model.gravity_W.z());
  Simulator sim(model);
  const auto wall0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  const double t_limit = f.run_up_time + 1.5 * distance / v0 + 5.0;
  double next_row = 0.0;
  try {
    sim.Initialize();
    if (f.solver.analysis == Analysis::kStaticsThenDynamics) sim.SettleStatics(TruckStaticsSettings(), true);
    sim.Run(t_limit, 0.0, [&](const State& st, const Workspace& ws) {
      const MarkerState& fr = ws.markers[h.frame_ref];
      const double yaw = std::atan2(fr.R_WM(1, 0), fr.R_WM(0, 0));
      const Vec3 pf = ws.markers[h.front_axle_ref].p_WM, pr = ws.markers[h.rear_axle_ref].p_WM;
      const double speed = fr.v_WM.dot(Vec3(std::cos(yaw), std::sin(yaw), 0));
      driver.Update(VehicleView{st.t, pf.x(), pr.x(), pr.y(), yaw, speed, Wheelbase(truck), pf.y(), fr.w_WM.z(),
                                driver_wheelbase});
      r.t_end = st.t;
      // recorded: from the front axle's arrival on the road
      const double x = pf.x() - run_up;
      if (x < 0) return;
      const bool done = x >= distance;
      if (st.t < next_row - 1e-9 && !done) return;
      next_row = st.t + f.output_interval;
      r.distance = x;
      ++r.rows;
      speed_moments.Add(speed * 3.6);
      for (size_t k = 0; k < n_wheels; ++k) {
        const MarkerState& wm = ws.markers[h.wheel_marker[k]];
        TireContact c;
        const Tire& tire = static_cast<const Tire&>(*model.forces[h.tire_force[k]]);
        tire.Wrench(wm.p_WM, wm.R_WM, wm.v_WM, wm.w_WM, &c);
        fz[k] = c.fz;
        double slope = 0.0;
        surface[k % 2]->Evaluate(wm.p_WM.x(), &road[k], &slope);
        road[k] += 0.0;  // -0 (the faded-in start) written as 0
        tire_moments[k].Add(c.fz);
      }
      if (csv) {
        std::fprintf(csv, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", st.t, x, pf.y(), speed * 3.6,
                     *driver.steering_wheel_angle() * 180.0 / std::numbers::pi, *driver.drive_torque() / 1e3);
        for (size_t k = 0; k < n_wheels; ++k) std::fprintf(csv, ",%.6g", road[k] * 1e3);
        for (size_t k = 0; k < n_wheels; ++k) std::fprintf(csv, ",%.6g", fz[k] / 1e3);
        for (size_t a = 0; a < n_axles; ++a) std::fprintf(csv, ",%.6g", (fz[2 * a] + fz[2 * a + 1]) / 1e3);
      }
      for (size_t m = 0; m < mounts.size(); ++m) {
        const ForceElement& el = *model.forces[static_cast<size_t>(mounts[m])];
        el.Evaluate(ws.markers[el.marker_i], ws.markers[el.marker_j], st.t, fe);
        // the force on the frame (marker i), world z
        const double fz_frame = fe.wrench[2];
        mount_moments[m].Add(fz_frame);
        if (csv) std::fprintf(csv, ",%.6g", fz_frame / 1e3);
      }
      if (csv) std::fprintf(csv, "\n");
      if (modal) modal->Write(st);
      if (done) throw StraightRunEnd{};
    });
    r.message = "the time limit was reached before the front axle drove the distance";
  } catch (const StraightRunEnd&) {
    r.completed = true;
  } catch (const NumericalError& e) {
    r.message = e.what();
  } catch (...) {
    if (csv) std::fclose(csv);
    throw;
  }
  if (csv) std::fclose(csv);
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.cpu_time_s = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  r.steps = sim.stats().steps;
  r.mean_speed_kmh = speed_moments.mean;
  for (size_t k = 0; k < n_wheels; ++k) {
    const AxleData& a = truck.axles[k / 2];
    r.tires.push_back(tire_moments[k].Result("tire_" + WheelName(a, static_cast<int>(k % 2)).substr(6)));
  }
  for (size_t m = 0; m < mounts.size(); ++m)
    r.mounts.push_back(mount_moments[m].Result(model.forces[static_cast<size_t>(mounts[m])]->name()));
  if (!opt.out_dir.empty()) {
    std::ofstream js(std::filesystem::path(opt.out_dir) / "summary.json");
    js << StraightRunJson(r);
  }
  if (opt.info)
    std::fprintf(opt.info,
                 "straight run at %.1f km/h (%s frame) on %s: %s after %.1f m of %.1f m road (%.4f km), t = %.2f s; "
                 "%d rows; %.2f s wall time, %.2f s CPU\n",
                 r.speed_kmh, r.frame.c_str(), r.road.c_str(), r.completed ? "completed" : "stopped", r.distance,
                 r.road_length, r.distance / 1e3, r.t_end, r.rows, r.wall_time_s, r.cpu_time_s);
  return r;
}

std::string StraightRunJson(const StraightRunResult& r) {
  using io::JsonNumber;
  using io::JsonString;
  auto forces = [](const std::vector<ForceStatistics>& v) {
    std::string s = "[";
    for (size_t i = 0; i < v.size(); ++i)
      s += std::string(i ? ",\n    " : "\n    ") + "{\"name\": " + JsonString(v[i].name) +
           ", \"mean\": " + JsonNumber(v[i].mean) + ", \"std\": " + JsonNumber(v[i].std) +
           ", \"min\": " + JsonNumber(v[i].min) + ", \"max\": " + JsonNumber(v[i].max) + "}";
    return s + "]";
  };
  cli::JsonObjectText j;
  j.Text("status", r.completed ? "ok" : "failed");
  j.Text("message", r.message);
  j.Text("frame", r.frame);
  j.Number("speed_kmh", r.speed_kmh);
  j.Number("mean_speed_kmh", r.mean_speed_kmh);
  j.Text("road", r.road);
  j.Number("road_length", r.road_length);
  j.Number("run_up", r.run_up);
  j.Number("distance", r.distance);
  j.Number("distance_km", r.distance / 1e3);
  j.Number("t_end", r.t_end);
  j.Raw("rows", std::to_string(r.rows));
  j.Raw("steps", std::to_string(r.steps));
  j.Number("wall_time_s", r.wall_time_s);
  j.Number("cpu_time_s", r.cpu_time_s);
  j.Number("reduction_wall_time_s", r.reduction_wall_time_s);
  j.Raw("tire_fz_N", forces(r.tires));
  j.Raw("mount_fz_N", forces(r.mounts));
  return j.str();
}

}  // namespace flexmb::vehicle
