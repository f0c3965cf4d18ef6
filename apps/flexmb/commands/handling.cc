#include "apps/flexmb/commands/handling.h"

#include <algorithm>
#include <chrono>
#include <complex>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>

#include <Eigen/Dense>

#include "apps/flexmb/commands/analysis_support.h"
#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/body_file/body_file.h"
#include "flexmb/common/error.h"
#include "flexmb/math/rotation.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/vehicle/single_track.h"
#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {
// file-scope names in a namespace of their own (unity builds, docs/design.md "Build time")
namespace handling_cc {

constexpr double kDeg = 180.0 / std::numbers::pi;

[[noreturn]] void Fail(const HandlingOptions& o, const std::string& option, const std::string& what) {
  throw InputError(option + " " + what, {o.file, 0, "truck handling " + o.test});
}

// the quantities of one output row
struct Row {
  double t = 0, speed = 0, delta_sw = 0, delta_road = 0, yaw_rate = 0, ay = 0, beta = 0, roll = 0;
  double x = 0, y = 0, yaw = 0, pitch = 0, ax = 0;
  double axle_load[2] = {0, 0};  // the front axle, the rear axles together [N]
};

// ECE R13 (Annex 4) braking measures from the rows from the brake onset
// t_brake: stopping distance and time (to 0.5 km/h), the mean fully
// developed deceleration d_m = (v_b^2 - v_e^2) / (25.92 (s_e - s_b)) with
// v_b = 0.8 v_1, v_e = 0.1 v_1 [km/h, m], the largest deceleration, pitch
// and front axle load, the smallest rear axle load
void BrakingMeasures(const std::vector<Row>& rows, double t_brake, std::vector<std::pair<std::string, double>>& m) {
  double s = 0, s_b = -1, s_e = -1, v1 = -1, stop_t = -1, ax_max = 0, pitch_max = 0, front_max = 0, rear_min = 1e300;
  const Row* prev = nullptr;
  for (const Row& r : rows) {
    if (r.t < t_brake) continue;
    if (prev) s += std::hypot(r.x - prev->x, r.y - prev->y);
    prev = &r;
    if (v1 < 0) v1 = r.speed * 3.6;
    const double v = r.speed * 3.6;
    if (s_b < 0 && v <= 0.8 * v1) s_b = s;
    if (s_e < 0 && v <= 0.1 * v1) s_e = s;
    ax_max = std::max(ax_max, -r.ax);
    pitch_max = std::max(pitch_max, std::abs(r.pitch));
    front_max = std::max(front_max, r.axle_load[0]);
    rear_min = std::min(rear_min, r.axle_load[1]);
    if (v <= 0.5) {
      stop_t = r.t - t_brake;
      break;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.emplace_back("brake_onset_speed_kmh", v1);
  m.emplace_back("stopping_distance", stop_t >= 0 ? s : nan);
  m.emplace_back("stopping_time", stop_t >= 0 ? stop_t : nan);
  m.emplace_back("mean_fully_developed_deceleration",
                 s_e > s_b && s_b >= 0 ? (0.64 - 0.01) * v1 * v1 / (25.92 * (s_e - s_b)) : nan);
  m.emplace_back("max_deceleration", ax_max);
  m.emplace_back("max_pitch_deg", pitch_max * 180.0 / std::numbers::pi);
  m.emplace_back("max_front_axle_load", front_max);
  m.emplace_back("min_rear_axle_load", rear_min);
}

// least-squares slope of y over x
double Slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxy = 0, sxx = 0;
  for (size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxx > 0 ? sxy / sxx : std::numeric_limits<double>::quiet_NaN();
}

// step-response values of one signal (ISO 7401 definitions): the steady
// state (mean of the last second), the response time (to 90 % of it) and
// the peak response time from t_ref (50 % of the steering input), and the
// overshoot of the peak over the steady state
struct StepResponse {
  double steady = 0, response_time = 0, peak_time = 0, overshoot = 0;
};

StepResponse Respond(const std::vector<Row>& rows, double Row::*x, double t_ref) {
  StepResponse s;
  const double t_end = rows.back().t;
  int n = 0;
  for (const Row& r : rows)
    if (r.t >= t_end - 1.0) s.steady += r.*x, ++n;
  s.steady /= n;
  const double sign = s.steady >= 0 ? 1.0 : -1.0;
  s.response_time = std::numeric_limits<double>::quiet_NaN();
  double peak = -1e300;
  const double level = 0.9 * std::abs(s.steady);
  const Row* prev = nullptr;
  for (const Row& r : rows) {
    if (r.t < t_ref) continue;
    // the 90 % crossing, interpolated between the output rows
    if (std::isnan(s.response_time) && sign * r.*x >= level) {
      const double before = prev ? sign * prev->*x : level;
      const double f = before < level ? (level - before) / (sign * r.*x - before) : 0.0;
      s.response_time = (prev ? prev->t + f * (r.t - prev->t) : r.t) - t_ref;
    }
    if (sign * r.*x > peak) peak = sign * r.*x, s.peak_time = r.t - t_ref;
    prev = &r;
  }
  s.overshoot = (peak - std::abs(s.steady)) / std::abs(s.steady);
  // no peak above the steady state (overshoot below 0.5 %): no peak time
  if (s.overshoot < 0.005) s.peak_time = std::numeric_limits<double>::quiet_NaN();
  return s;
}

// phasor c1 + i c2 of the least-squares fit y = c0 + c1 sin(w t) + c2 cos(w t)
// over the rows with t in [t0, t1] (w t from the input's start t_in), and
// the fit's rms residual relative to the amplitude
std::complex<double> SinePhasor(const std::vector<Row>& rows, double Row::*y, double t_in, double f, double t0,
                                double t1, double* misfit) {
  const double w = 2.0 * std::numbers::pi * f;
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const Row& r : rows) {
    if (r.t < t0 - 1e-9 || r.t > t1 + 1e-9) continue;
    const Eigen::Vector3d a(1.0, std::sin(w * (r.t - t_in)), std::cos(w * (r.t - t_in)));
    N += a * a.transpose();
    b += a * (r.*y);
  }
  const Eigen::Vector3d c = N.ldlt().solve(b);
  double sq = 0;
  int n = 0;
  for (const Row& r : rows) {
    if (r.t < t0 - 1e-9 || r.t > t1 + 1e-9) continue;
    const double e = r.*y - (c(0) + c(1) * std::sin(w * (r.t - t_in)) + c(2) * std::cos(w * (r.t - t_in)));
    sq += e * e, ++n;
  }
  const double amp = std::hypot(c(1), c(2));
  if (misfit) *misfit = n > 0 && amp > 0 ? std::sqrt(sq / n) / amp : std::numeric_limits<double>::quiet_NaN();
  return {c(1), c(2)};
}

struct HandlingEnd {};

}  // namespace handling_cc

double HandlingResult::Metric(const std::string& name) const {
  for (const auto& [key, value] : metrics)
    if (key == name) return value;
  return std::numeric_limits<double>::quiet_NaN();
}

std::string HandlingJson(const HandlingResult& r) {
  cli::JsonObjectText j;
  j.Text("test", r.test);
  j.Text("status", r.completed ? "ok" : "failed");
  j.Text("message", r.message);
  j.Text("frame", r.frame);
  for (const auto& [k, v] : r.metrics) j.Number(k, v);
  return j.str();
}

HandlingResult RunHandlingTest(const HandlingOptions& opt) {
  using namespace handling_cc;
  if (opt.test != "step-steer" && opt.test != "sine-steer" && opt.test != "constant-steer" && opt.test != "braking" &&
      opt.test != "brake-in-turn")
    Fail(opt, "--test",
         "must be step-steer, sine-steer, constant-steer, braking or brake-in-turn, got '" + opt.test + "'");
  const bool sine = opt.test == "sine-steer";
  const bool step = opt.test == "step-steer", circle = opt.test == "constant-steer";
  const bool braking = !step && !circle && !sine, in_turn = opt.test == "brake-in-turn";
  if (sine && (!(opt.frequency > 0) || !std::isfinite(opt.frequency) || opt.frequency > 5.0 || opt.periods < 2))
    Fail(opt, "--frequency/--periods", "need a frequency in (0, 5] Hz and at least 2 periods");
  TruckFileSettings f = LoadTruckFileSettings(opt.file);
  const std::string frame = opt.frame.value_or(f.frame);
  if (frame != "rigid" && frame != "elastic") Fail(opt, "--frame", "must be rigid or elastic, got '" + frame + "'");
  if (opt.dt) {
    if (!(*opt.dt > 0) || !std::isfinite(*opt.dt)) Fail(opt, "--dt", "must be a positive step [s]");
    f.solver.dt = *opt.dt;
  }
  if (!f.dt_min_given) f.solver.dt_min = 1e-6 * f.solver.dt;
  const double v0 = opt.speed_kmh.value_or(circle ? 10.0 : f.speed_kmh) / 3.6;
  if (!(v0 >= 1.0) || !std::isfinite(v0)) Fail(opt, "--speed", "must be at least 3.6 km/h");
  if (!(opt.step_time >= 0.5) || !(opt.rise_time > 0) || !(opt.hold_time >= 2.0))
    Fail(opt, "--step-time/--rise-time/--hold", "need a step time >= 0.5 s, a rise time > 0 and a hold >= 2 s");
  if (circle && (!(opt.speed_rate_kmh_s > 0) || !(opt.max_ay > 0) || !(opt.max_speed_kmh > v0 * 3.6)))
    Fail(opt, "--speed-rate/--max-ay/--max-speed", "need a positive speed rate and lateral acceleration, and a "
                                                    "top speed above the start speed");
  if (!(opt.target_ay > 0) || !(opt.radius > 0)) Fail(opt, "--ay/--radius", "must be positive");
  if (!(opt.decel > 0) || !(opt.brake_rise_time > 0) || (opt.brake_torque && !(*opt.brake_torque > 0)))
    Fail(opt, "--decel/--brake-torque/--brake-rise-time", "must be positive");

  Model model;
  const double g = -model.gravity_W.z();
  const SingleTrack ref = TruckSingleTrack(f.truck, g);
  double delta_sw = 0;
  if (opt.test == "braking") {
    if (opt.steer_deg) Fail(opt, "--steer", "does not apply to straight-line braking (brake-in-turn steers)");
  } else if (opt.steer_deg) {
    if (!std::isfinite(*opt.steer_deg) || *opt.steer_deg == 0) Fail(opt, "--steer", "must be a nonzero angle [deg]");
    delta_sw = *opt.steer_deg / kDeg;
  } else {
    delta_sw = circle ? ref.steering_ratio * ref.wheelbase / opt.radius : ref.SteeringWheelAngleFor(opt.target_ay, v0, g);
    // sine steer: the amplitude whose steady-state lateral acceleration is target_ay
  }
  if (!opt.out_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(opt.out_dir, ec);
  }
  if (frame == "elastic") {
    auto body = ReduceTruckFrame(f.truck, f.reduction, g);
    if (!opt.out_dir.empty() && !f.truck.frame_body)
      io::WriteBody(*body, (std::filesystem::path(opt.out_dir) / "frame.h5").string());
    f.truck.elastic_frame = std::move(body);
  }
  auto steer = std::make_shared<double>(0.0), torque = std::make_shared<double>(0.0);
  auto brake = std::make_shared<double>(0.0);
  const double brake_torque =
      opt.brake_torque.value_or(ref.mass * opt.decel * 0.5 *
                                (f.truck.axles.front().tire.unloaded_radius + f.truck.axles.back().tire.unloaded_radius));
  model.name = "truck_handling_" + opt.test;
  model.solver = f.solver;
  const TruckHandles h = BuildTruck(f.truck, v0, f.mu, steer, torque, model, brake);
  model.Finalize();
  const Body& frame_body = *model.bodies[h.frame_body];
  const Marker& frame_ref = model.markers[static_cast<size_t>(h.frame_ref)];
  const size_t n_axles = f.truck.axles.size(), n_wheels = 2 * n_axles;
  std::vector<double> fz(n_wheels), ltr(n_axles);  // per step, allocated once

  std::FILE* csv = nullptr;
  if (!opt.out_dir.empty()) {
    csv = std::fopen((std::filesystem::path(opt.out_dir) / "results.csv").string().c_str(), "w");
    if (!csv) throw InputError("cannot write results.csv", {opt.out_dir, 0, ""});
    // per wheel fz_fl_kN, ..., per axle ltr_front, ...
    std::string fz, ltr;
    for (const AxleData& a : f.truck.axles) {
      ltr += "ltr_" + a.name + ",";
      for (int k = 0; k < 2; ++k) fz += "fz_" + WheelName(a, k).substr(6) + "_kN,";
    }
    std::fprintf(csv, "time,x,y,speed_kmh,steering_wheel_angle_deg,road_wheel_angle_deg,yaw_rate_degps,"
                      "lateral_acceleration,sideslip_deg,roll_deg,curvature,%s%sdrive_torque_kNm,brake_torque_kNm,"
                      "yaw_deg,pitch_deg,longitudinal_acceleration\n",
                 fz.c_str(), ltr.c_str());
    std::fflush(csv);
  }
  // the steering input; constant steer: ramped in over 1 s, the speed rises
  // from 3 s after that
  // braking: from the step time (straight), 4 s after the turn-in (in a turn)
  const double t_speed = opt.step_time + 4.0;
  const double t_brake = in_turn ? opt.step_time + 4.0 : opt.step_time;
  const double t_sine_end = opt.step_time + opt.periods / opt.frequency;
  const double t_end = sine     ? t_sine_end
                       : step   ? opt.step_time + opt.rise_time + opt.hold_time
                       : circle ? t_speed + (opt.max_speed_kmh / 3.6 - v0) / (opt.speed_rate_kmh_s / 3.6) + 5.0
                                : t_brake + 3.0 * v0 / opt.decel + 10.0;
  const double ramp = step ? opt.rise_time : 1.0;
  auto steering = [&](double t) {
    if (sine)
      return t < opt.step_time ? 0.0 : delta_sw * std::sin(2.0 * std::numbers::pi * opt.frequency * (t - opt.step_time));
    return delta_sw * std::clamp((t - opt.step_time) / ramp, 0.0, 1.0);
  };
  auto target_speed = [&](double t) {
    return step || sine ? v0 : v0 + opt.speed_rate_kmh_s / 3.6 * std::max(0.0, t - t_speed);
  };

  HandlingResult r;
  std::vector<Row> rows;
  double integral = 0, t_last = 0, next_row = 0, max_ltr = 0;
  Simulator sim(model);
  const auto wall0 = std::chrono::steady_clock::now();
  try {
    sim.Initialize();
    if (f.solver.analysis == Analysis::kStaticsThenDynamics) sim.SettleStatics(TruckStaticsSettings(), true);
    sim.Run(t_end, 0.0, [&](const State& st, const Workspace& ws) {
      const MarkerState& fr = ws.markers[h.frame_ref];
      const Vec3 rpy = RollPitchYaw(fr.R_WM);
      const Vec3 ex(std::cos(rpy.z()), std::sin(rpy.z()), 0), ey(-std::sin(rpy.z()), std::cos(rpy.z()), 0);
      const Vec6 acc = fr.J * ws.vdot.segment(frame_body.v_offset, frame_body.nv()) +
                       frame_body.MarkerAccelerationBias(st.q.data() + frame_body.q_offset,
                                                         st.v.data() + frame_body.v_offset, frame_ref);
      Row row;
      row.t = st.t;
      row.speed = fr.v_WM.dot(ex);
      row.delta_sw = *steer;
      for (int k = 0; k < 2; ++k) {
        const Joint& j = *model.joints[h.kingpin_joint[k]];
        row.delta_road += 0.5 * j.Coordinate(0, ws.markers[j.marker_i], ws.markers[j.marker_j], nullptr);
      }
      row.yaw_rate = fr.w_WM.z();
      row.ay = acc.head<3>().dot(ey);
      row.beta = std::atan2(fr.v_WM.dot(ey), row.speed);
      row.roll = rpy.x();
      row.x = fr.p_WM.x();
      row.y = fr.p_WM.y();
      row.yaw = rpy.z();
      row.pitch = rpy.y();
      row.ax = acc.head<3>().dot(ex);
      for (size_t k = 0; k < n_wheels; ++k) {
        const MarkerState& wm = ws.markers[h.wheel_marker[k]];
        TireContact c;
        static_cast<const Tire&>(*model.forces[h.tire_force[k]]).Wrench(wm.p_WM, wm.R_WM, wm.v_WM, wm.w_WM, &c);
        fz[k] = std::max(c.fz, 0.0);
      }
      for (size_t a = 0; a < n_axles; ++a) {
        const double load = fz[2 * a] + fz[2 * a + 1];
        row.axle_load[a == 0 ? 0 : 1] += load;
        ltr[a] = load > 0 ? (fz[2 * a] - fz[2 * a + 1]) / load : 0.0;
        if (st.t >= opt.step_time) max_ltr = std::max(max_ltr, std::abs(ltr[a]));
      }
      // controls held over the next step: steering, PI speed control
      *steer = steering(st.t);
      const double err = target_speed(st.t) - row.speed;
      integral += err * (st.t - t_last);
      t_last = st.t;
      *torque = std::clamp(f.driver.speed_kp * err + f.driver.speed_ki * integral, -f.driver.max_drive_torque,
                           f.driver.max_drive_torque);
      if (braking && st.t >= t_brake) {  // the driver is off the throttle and on the brake
        *torque = 0.0;
        *brake = brake_torque * std::min(1.0, (st.t - t_brake) / opt.brake_rise_time);
      }
      const bool stopped = braking && st.t > t_brake && row.speed * 3.6 <= 0.5;
      r.completed = (!braking && st.t >= t_end - 1e-9) || stopped;
      if (st.t >= next_row - 1e-9 || r.completed) {
        next_row = st.t + f.output_interval;
        rows.push_back(row);
        const Vec3 p = fr.p_WM;
        if (csv) {
          std::fprintf(csv, "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g", st.t, p.x(), p.y(),
                       row.speed * 3.6, row.delta_sw * kDeg, row.delta_road * kDeg, row.yaw_rate * kDeg, row.ay,
                       row.beta * kDeg, row.roll * kDeg, row.yaw_rate / row.speed);
          for (size_t k = 0; k < n_wheels; ++k) std::fprintf(csv, ",%.6g", fz[k] / 1e3);
          for (size_t a = 0; a < n_axles; ++a) std::fprintf(csv, ",%.6g", ltr[a]);
          std::fprintf(csv, ",%.6g,%.6g,%.6g,%.6g,%.6g\n", *torque / 1e3, *brake / 1e3, row.yaw * kDeg,
                       row.pitch * kDeg, row.ax);
          std::fflush(csv);
        }
      }
      if (std::abs(rpy.x()) > std::numbers::pi / 4) {
        r.message = "the truck rolled over (|roll| > 45 deg)";
        throw HandlingEnd{};
      }
      if (stopped) throw HandlingEnd{};
      if (circle && st.t > t_speed && (std::abs(row.ay) >= opt.max_ay || row.speed * 3.6 >= opt.max_speed_kmh ||
                                      max_ltr >= 1.0)) {
        r.completed = true;
        throw HandlingEnd{};
      }
    });
  } catch (const HandlingEnd&) {
  } catch (const NumericalError& e) {
    r.completed = false;
    r.message = e.what();
  } catch (...) {
    if (csv) std::fclose(csv);
    throw;
  }
  if (csv) std::fclose(csv);
  if (braking && !r.completed && r.message.empty())
    r.message = "the truck did not stop within " + std::to_string(static_cast<int>(t_end)) + " s";
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

  auto add = [&](const std::string& k, double v) { r.metrics.emplace_back(k, v); };
  add("steering_wheel_angle_deg", delta_sw * kDeg);
  add("steering_ratio", ref.steering_ratio);
  add("wheelbase", ref.wheelbase);
  add("single_track_understeer_gradient_deg_per_g", ref.understeer_gradient * kDeg);
  // the front axle's, the other axles' together
  double rear_stiffness = 0;
  for (size_t i = 1; i < ref.axles.size(); ++i) rear_stiffness += ref.axles[i].cornering_stiffness;
  add("single_track_front_cornering_stiffness", ref.axles[0].cornering_stiffness);
  add("single_track_rear_cornering_stiffness", rear_stiffness);
  if (step && r.completed) {
    const double t_ref = opt.step_time + 0.5 * opt.rise_time;
    const StepResponse yr = Respond(rows, &Row::yaw_rate, t_ref), ay = Respond(rows, &Row::ay, t_ref);
    const StepResponse beta = Respond(rows, &Row::beta, t_ref), roll = Respond(rows, &Row::roll, t_ref);
    add("speed_kmh", v0 * 3.6);
    add("yaw_rate_gain", yr.steady / delta_sw);
    add("single_track_yaw_rate_gain", ref.YawRateGain(v0, g));
    add("lateral_acceleration_gain", ay.steady / delta_sw);
    add("steady_yaw_rate_degps", yr.steady * kDeg);
    add("steady_lateral_acceleration", ay.steady);
    add("steady_sideslip_deg", beta.steady * kDeg);
    add("steady_roll_deg", roll.steady * kDeg);
    add("yaw_rate_response_time", yr.response_time);
    add("yaw_rate_peak_response_time", yr.peak_time);
    add("yaw_rate_overshoot", yr.overshoot);
    add("lateral_acceleration_response_time", ay.response_time);
    add("lateral_acceleration_peak_response_time", ay.peak_time);
    add("lateral_acceleration_overshoot", ay.overshoot);
  }
  if (sine && r.completed) {
    // the periods after the first (the start's transient) at the input frequency
    const double t0 = opt.step_time + 1.0 / opt.frequency, t1 = t_sine_end;
    double misfit_sw = 0, misfit_r = 0, misfit_ay = 0;
    const std::complex<double> in = SinePhasor(rows, &Row::delta_sw, opt.step_time, opt.frequency, t0, t1, &misfit_sw);
    const std::complex<double> hr =
        SinePhasor(rows, &Row::yaw_rate, opt.step_time, opt.frequency, t0, t1, &misfit_r) / in;
    const std::complex<double> ha = SinePhasor(rows, &Row::ay, opt.step_time, opt.frequency, t0, t1, &misfit_ay) / in;
    const std::complex<double> hroll = SinePhasor(rows, &Row::roll, opt.step_time, opt.frequency, t0, t1, nullptr) / in;
    const SingleTrack::Response st = ref.FrequencyResponse(opt.frequency, v0, f.truck.frame.cg.x());
    // phase lag in (-180, 180] deg, time lag at the input frequency
    auto lag = [](std::complex<double> h) { return -std::arg(h) * kDeg; };
    const double period = 1.0 / opt.frequency;
    add("speed_kmh", v0 * 3.6);
    add("frequency_hz", opt.frequency);
    add("fitted_periods", opt.periods - 1.0);
    add("yaw_rate_gain", std::abs(hr));
    add("yaw_rate_phase_lag_deg", lag(hr));
    add("yaw_rate_time_lag", lag(hr) / 360.0 * period);
    add("lateral_acceleration_gain", std::abs(ha));
    add("lateral_acceleration_phase_lag_deg", lag(ha));
    add("lateral_acceleration_time_lag", lag(ha) / 360.0 * period);
    add("roll_gain", std::abs(hroll));
    add("roll_phase_lag_deg", lag(hroll));
    add("single_track_yaw_rate_gain", std::abs(st.yaw_rate));
    add("single_track_yaw_rate_phase_lag_deg", lag(st.yaw_rate));
    add("single_track_lateral_acceleration_gain", std::abs(st.lateral_acceleration));
    add("single_track_lateral_acceleration_phase_lag_deg", lag(st.lateral_acceleration));
    add("single_track_steady_yaw_rate_gain", ref.YawRateGain(v0, g));
    add("single_track_yaw_inertia", ref.yaw_inertia);
    add("yaw_rate_fit_residual", misfit_r);
    add("lateral_acceleration_fit_residual", misfit_ay);
  }
  if (braking && !rows.empty()) {
    add("brake_torque", brake_torque);
    add("brake_onset_time", t_brake);
    BrakingMeasures(rows, t_brake, r.metrics);
    // the state at the brake onset and 1 s later
    auto at = [&](double t) {
      return *std::min_element(rows.begin(), rows.end(),
                               [&](const Row& a, const Row& b) { return std::abs(a.t - t) < std::abs(b.t - t); });
    };
    const Row r0 = at(t_brake), r1 = at(t_brake + 1.0), last = rows.back();
    // heading and lateral position of the path against the line (straight)
    // or the turn (in a turn, heading only) held from the brake onset
    add("heading_change_deg", (last.yaw - r0.yaw) * kDeg);
    if (!in_turn) add("lateral_deviation", -std::sin(r0.yaw) * (last.x - r0.x) + std::cos(r0.yaw) * (last.y - r0.y));
    if (in_turn) {
      add("yaw_rate_before_degps", r0.yaw_rate * kDeg);
      add("lateral_acceleration_before", r0.ay);
      add("yaw_rate_ratio_1s", r1.yaw_rate / r0.yaw_rate);
      add("lateral_acceleration_ratio_1s", r1.ay / r0.ay);
      add("heading_deviation_1s_deg", (r1.yaw - r0.yaw - r0.yaw_rate * (r1.t - r0.t)) * kDeg);
    }
  }
  if (circle) {
    // quasi-steady states with the steering held and the speed rising,
    // 0.5 <= |a_y| <= min(2, max_ay) m/s^2 (the linear range):
    // delta / ratio = L kappa + K a_y / g, kappa = r / v
    std::vector<double> ay, lk, dk, roll, beta;
    for (const Row& w : rows)
      if (w.t > t_speed && std::abs(w.ay) >= 0.5 && std::abs(w.ay) <= std::min(2.0, opt.max_ay)) {
        ay.push_back(w.ay / g);
        lk.push_back(-ref.wheelbase * w.yaw_rate / w.speed);
        dk.push_back(w.delta_road - ref.wheelbase * w.yaw_rate / w.speed);
        roll.push_back(w.roll * kDeg);
        beta.push_back(w.beta * kDeg);
      }
    add("quasi_steady_from", t_speed);
    add("start_speed_kmh", v0 * 3.6);
    add("end_speed_kmh", rows.empty() ? 0.0 : rows.back().speed * 3.6);
    add("max_lateral_acceleration", rows.empty() ? 0.0 : std::abs(rows.back().ay));
    add("fit_points", static_cast<double>(ay.size()));
    if (ay.size() >= 10) {
      add("understeer_gradient_deg_per_g", Slope(ay, lk) * kDeg);
      add("understeer_gradient_road_wheels_deg_per_g", Slope(ay, dk) * kDeg);
      add("roll_gradient_deg_per_g", Slope(ay, roll));
      add("sideslip_gradient_deg_per_g", Slope(ay, beta));
    } else if (r.completed) {
      r.completed = false;
      r.message = "fewer than 10 rows with 0.5 <= |a_y| <= 2 m/s^2: raise --max-ay or --max-speed, or the angle";
    }
  }
  add("max_ltr", max_ltr);
  add("t_end", rows.empty() ? 0.0 : rows.back().t);
  add("steps", static_cast<double>(sim.stats().steps));
  add("wall_time_s", wall);
  r.test = opt.test;
  r.frame = frame;
  if (!opt.out_dir.empty())
    cli::WriteAnalysisFile((std::filesystem::path(opt.out_dir) / "summary.json").string(), HandlingJson(r));
  if (opt.info) {
    std::fprintf(opt.info, "%s (%s frame), steering wheel %.1f deg: %s", opt.test.c_str(), frame.c_str(),
                 delta_sw * kDeg, r.completed ? "completed" : ("stopped: " + r.message).c_str());
    if (step && r.completed)
      std::fprintf(opt.info, "; yaw-rate gain %.4f 1/s (single track %.4f), response time %.3f s, overshoot %.1f %%",
                   r.Metric("yaw_rate_gain"), r.Metric("single_track_yaw_rate_gain"),
                   r.Metric("yaw_rate_response_time"), 100 * r.Metric("yaw_rate_overshoot"));
    if (sine && r.completed)
      std::fprintf(opt.info, "; %.2f Hz: yaw-rate gain %.4f 1/s, phase lag %.1f deg (single track %.4f, %.1f deg), "
                             "lateral acceleration gain %.3f m/s^2/rad, phase lag %.1f deg (single track %.3f, %.1f deg)",
                   opt.frequency, r.Metric("yaw_rate_gain"), r.Metric("yaw_rate_phase_lag_deg"),
                   r.Metric("single_track_yaw_rate_gain"), r.Metric("single_track_yaw_rate_phase_lag_deg"),
                   r.Metric("lateral_acceleration_gain"), r.Metric("lateral_acceleration_phase_lag_deg"),
                   r.Metric("single_track_lateral_acceleration_gain"),
                   r.Metric("single_track_lateral_acceleration_phase_lag_deg"));
    if (braking && r.completed)
      std::fprintf(opt.info, "; stopping distance %.1f m from %.1f km/h, mean fully developed deceleration %.2f m/s^2",
                   r.Metric("stopping_distance"), r.Metric("brake_onset_speed_kmh"),
                   r.Metric("mean_fully_developed_deceleration"));
    if (in_turn && r.completed)
      std::fprintf(opt.info, "; yaw-rate ratio after 1 s %.3f, heading deviation %.2f deg", r.Metric("yaw_rate_ratio_1s"),
                   r.Metric("heading_deviation_1s_deg"));
    if (circle && !std::isnan(r.Metric("understeer_gradient_deg_per_g")))
      std::fprintf(opt.info, "; understeer gradient %.2f deg/g (at the road wheels %.2f, single track %.2f), roll "
                             "gradient %.2f deg/g",
                   r.Metric("understeer_gradient_deg_per_g"), r.Metric("understeer_gradient_road_wheels_deg_per_g"),
                   r.Metric("single_track_understeer_gradient_deg_per_g"), r.Metric("roll_gradient_deg_per_g"));
    std::fprintf(opt.info, "\n");
  }
  return r;
}

}  // namespace flexmb::vehicle
