#pragma once
// Test harness for the truck checks: builds the truck of
// examples/truck_lane_change/truck.yaml with a held steering-wheel angle and a
// PI speed controller (sampled per accepted step), and integrates it.
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/solver/simulator.h"
#include "apps/flexmb/commands/lane_change.h"
#include "flexmb/vehicle/tire.h"
#include "flexmb/vehicle/truck.h"

namespace flexmb::vehicle::testing {

inline std::string TruckFile() { return std::string(FLEXMB_SOURCE_DIR) + "/examples/truck_lane_change/truck.yaml"; }

/// Sampled vehicle quantities at one accepted step.
struct TruckSample {
  double t = 0, speed = 0, yaw_rate = 0, lateral_acceleration = 0, roll = 0;
  std::vector<double> axle_load;  ///< per axle, front to rear [N]
};

/// Runs the truck at `speed` [m/s] with the road-wheel angle ramped to
/// `road_angle` [rad] over 1 s, holding the speed by PI control of the
/// drive torque when `hold_speed`; calls `sample` after each accepted step.
inline void RunTruck(const TruckData& d, double speed, double road_angle, double t_end, bool hold_speed,
                     const std::function<void(const TruckSample&)>& sample) {
  auto steer = std::make_shared<double>(0.0);
  auto torque = std::make_shared<double>(0.0);
  Model m;
  m.solver.dt = 0.004;
  m.solver.dt_min = 1e-8;
  const TruckHandles h = BuildTruck(d, speed, 0.8, steer, torque, m);
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  double integral = 0, t_last = 0;
  const int vo = m.bodies[h.frame_body]->v_offset;
  sim.Run(t_end, 0.0, [&](const State& st, const Workspace& ws) {
    const MarkerState& fr = ws.markers[h.frame_ref];
    const double yaw = std::atan2(fr.R_WM(1, 0), fr.R_WM(0, 0));
    const Vec3 ex(std::cos(yaw), std::sin(yaw), 0), ey(-std::sin(yaw), std::cos(yaw), 0);
    TruckSample s;
    s.t = st.t;
    s.speed = fr.v_WM.dot(ex);
    s.yaw_rate = fr.w_WM.z();
    s.lateral_acceleration = ws.vdot.segment<3>(vo).dot(ey);
    s.roll = std::atan2(fr.R_WM(2, 1), fr.R_WM(2, 2));
    s.axle_load.assign(d.axles.size(), 0.0);
    for (size_t k = 0; k < h.wheel_marker.size(); ++k) {
      const MarkerState& w = ws.markers[h.wheel_marker[k]];
      TireContact c;
      static_cast<const Tire&>(*m.forces[h.tire_force[k]]).Wrench(w.p_WM, w.R_WM, w.v_WM, w.w_WM, &c);
      s.axle_load[k / 2] += c.fz;
    }
    sample(s);
    // controllers for the next step
    *steer = d.steering_ratio * road_angle * std::min(1.0, st.t);
    if (hold_speed) {
      const double err = speed - s.speed;
      integral += err * (st.t - t_last);
      *torque = 8000.0 * err + 2000.0 * integral;
    }
    t_last = st.t;
  });
}

}  // namespace flexmb::vehicle::testing
