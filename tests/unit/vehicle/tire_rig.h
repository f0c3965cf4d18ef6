// Step rig shared by the tire transient tests: a step in slip ratio
// (tests/unit/vehicle/tire_test.cc) and a step steer
// (tests/validation/tire_relaxation_test.cc), both against the first-order
// lag in travelled distance.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "flexmb/bodies/rigid_body.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/prismatic.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/vehicle/contact_patch_joint.h"
#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {

/// One sample of the tire step rig (RunTireStepRig).
struct TireRigSample {
  double x = 0.0;         ///< travelled distance V t [m]
  double fx_wheel = 0.0;  ///< longitudinal force on the wheel (TireContact::fx_wheel) [N]
  double fy_wheel = 0.0;  ///< lateral force on the wheel (TireContact::fy_wheel) [N]
};

/// What RunTireStepRig returns.
struct TireRigRun {
  std::vector<TireRigSample> samples;  ///< one every dt, from t = 0
  double fx_steady = 0.0;  ///< stateless tire's longitudinal slip force at the rig's slip [N]
  double fy_steady = 0.0;  ///< stateless tire's lateral slip force at the rig's slip [N]
};

/// Tire step rig: a carrier driven along world x at speed V [m/s] (prismatic
/// joint on the ground with a motion driver), the wheel centre at the height
/// of the nominal load, the wheel steered by psi [rad] about z from t = 0 (a
/// step in slip angle). With slip_ratio, the wheel's spin is prescribed (a
/// motion driver on its bearing) at Omega = V cos(psi) (1 + slip_ratio) / Re
/// from t = 0 (a step in slip ratio); without, it rolls freely on the
/// bearing, starting at V cos(psi) / Re. With relaxation the contact-patch
/// body slides on the carrier: on a ContactPatchJoint when the tire also
/// relaxes longitudinally, else on a prismatic joint along the spin axis. The
/// patch starts with the velocity that makes its slip zero (force-free start
/// of the massless carcass). No gravity, generalized-alpha rho_inf 0.8, time
/// step dt [s], run to t_end [s]. The steady forces are those of the
/// stateless tire (Tire::Wrench, no patch) at the wheel's initial motion.
inline TireRigRun RunTireStepRig(const TireData& td, double V, double psi, std::optional<double> slip_ratio,
                                 double t_end, double dt) {
  Model m;
  m.gravity_W.setZero();
  m.solver.dt = dt;
  m.solver.rho_inf = 0.8;
  const double zc = td.unloaded_radius - td.nominal_load / (td.count * td.vertical_stiffness);
  const Vec3 c(0, 0, zc);
  Mat3 axis_x;  // z along world x
  axis_x << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  Mat3 spin;  // z along the steered spin axis a = (-sin psi, cos psi, 0), x forward
  spin << std::cos(psi), 0, -std::sin(psi), std::sin(psi), 0, std::cos(psi), 0, -1, 0;
  const Vec3 a = spin.col(2);
  const Vec3 xt = a.cross(Vec3::UnitZ());
  const Vec3 v(V, 0, 0);
  const double vx = V * xt.x();
  const double kappa0 = slip_ratio.value_or(0.0);
  const double re = td.unloaded_radius - td.rolling_radius_factor * (td.unloaded_radius - zc);
  const double omega = vx * (1 + kappa0) / re;
  const Vec3 w = omega * a;
  auto body = [&](const char* name, double mass, const Vec3& vel, const Vec3& om) {
    RigidBodyData b;
    b.mass = mass;
    b.inertia_C = Mat3::Identity() * (0.1 * mass);
    b.c_B = c;
    b.v_WB = vel - om.cross(c);
    b.w_WB = om;
    return m.AddBody(std::make_unique<RigidBody>(name, b));
  };
  auto ramp = [](double rate) {
    return std::make_shared<TableFunction>(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, rate},
                                           TableFunction::Interpolation::kLinear, true);
  };
  const int carrier = body("carrier", 100.0, v, Vec3::Zero());
  const int wheel = body("wheel", 50.0, v, w);
  const bool relaxed = td.relaxation_length > 0;
  // zero patch slip at t = 0: (v_patch - v) . a = -v . a, (v_patch - v) . x_t = kappa0 Vx
  const int patch = relaxed ? body("patch", td.patch_mass, v - v.dot(a) * a + (kappa0 * vx) * xt, Vec3::Zero()) : -1;
  const int slide = m.AddJoint(std::make_unique<PrismaticJoint>("slide"), m.AddMarker(0, "rail", c, axis_x),
                               m.AddMarker(carrier, "rail", c, axis_x));
  m.AddJoint(std::make_unique<MotionDriver>("drive", m.joints[slide].get(), 0, ramp(V)), m.joints[slide]->marker_i,
             m.joints[slide]->marker_j);
  const int bearing = m.AddJoint(std::make_unique<RevoluteJoint>("bearing"), m.AddMarker(carrier, "bearing", c, spin),
                                 m.AddMarker(wheel, "bearing", c, spin));
  if (slip_ratio) {
    m.AddJoint(std::make_unique<MotionDriver>("spin", m.joints[bearing].get(), 0, ramp(omega)),
               m.joints[bearing]->marker_i, m.joints[bearing]->marker_j);
  }
  const int wm = m.AddMarker(wheel, "centre", c, spin);
  int pm = -1;
  if (relaxed) {
    pm = m.AddMarker(patch, "centre", c, spin);
    if (td.longitudinal_relaxation_length > 0) {
      m.AddJoint(std::make_unique<ContactPatchJoint>("carcass"), m.AddMarker(carrier, "carcass", c, spin), pm);
    } else {
      m.AddJoint(std::make_unique<PrismaticJoint>("carcass"), m.AddMarker(carrier, "carcass", c, spin), pm);
    }
  }
  const int tire = m.AddForce(std::make_unique<Tire>("tire", td, 1.0), wm, pm);
  TireRigRun run;
  TireContact ss;
  Tire("probe", td, 1.0).Wrench(c, spin, v, w, &ss);
  run.fx_steady = ss.fx;
  run.fy_steady = ss.fy;
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  sim.Run(t_end, dt, [&](const State& st, const Workspace& ws) {
    const MarkerState& wc = ws.markers[wm];
    const Tire& t = static_cast<const Tire&>(*m.forces[tire]);
    TireContact tc;
    if (pm >= 0) {
      const MarkerState& pc = ws.markers[pm];
      t.RelaxedWrench(wc.p_WM, wc.R_WM, wc.v_WM, wc.w_WM, pc.p_WM, pc.v_WM, &tc);
    } else {
      t.Wrench(wc.p_WM, wc.R_WM, wc.v_WM, wc.w_WM, &tc);
    }
    run.samples.push_back({V * st.t, tc.fx_wheel, tc.fy_wheel});
  });
  return run;
}

}  // namespace flexmb::vehicle
