#include "flexmb/vehicle/single_track.h"

#include <cmath>
#include <numeric>

#include <Eigen/Dense>

#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {

double SingleTrack::YawRateGain(double v, double g) const {
  return v / (wheelbase + understeer_gradient * v * v / g) / steering_ratio;
}

double SingleTrack::SteeringWheelAngleFor(double ay, double v, double g) const {
  return ay / (v * YawRateGain(v, g));
}

SingleTrack::Response SingleTrack::FrequencyResponse(double f, double v, double x_point) const {
  using C = std::complex<double>;
  const double W = axle_load[0] + axle_load[1];
  const double a = wheelbase * axle_load[1] / W, b = wheelbase * axle_load[0] / W;
  const C s(0.0, 2.0 * 3.14159265358979323846 * f);
  // unknowns (v_y, r, F_f, F_r) for a road-wheel angle of 1 rad
  Eigen::Matrix<C, 4, 4> A = Eigen::Matrix<C, 4, 4>::Zero();
  Eigen::Matrix<C, 4, 1> rhs = Eigen::Matrix<C, 4, 1>::Zero();
  A(0, 0) = mass * s;
  A(0, 1) = mass * v;
  A(0, 2) = -1.0;
  A(0, 3) = -1.0;
  A(1, 1) = yaw_inertia * s;
  A(1, 2) = -(a - trail[0]);
  A(1, 3) = b + trail[1];
  A(2, 0) = cornering_stiffness[0] / v;
  A(2, 1) = cornering_stiffness[0] * a / v;
  A(2, 2) = relaxation_length[0] / v * s + 1.0;
  rhs(2) = cornering_stiffness[0];
  A(3, 0) = cornering_stiffness[1] / v;
  A(3, 1) = -cornering_stiffness[1] * b / v;
  A(3, 3) = relaxation_length[1] / v * s + 1.0;
  const Eigen::Matrix<C, 4, 1> x = A.partialPivLu().solve(rhs);
  // per steering-wheel angle; a_y at the point: centre of mass plus r' times the lever
  const C r = x(1) / steering_ratio, vy = x(0) / steering_ratio;
  return {r, s * vy + v * r + s * r * (x_point + a)};
}

SingleTrack TruckSingleTrack(const TruckData& d, double g) {
  SingleTrack s;
  const double L = Wheelbase(d);
  s.wheelbase = L;
  s.steering_ratio = d.steering_ratio;
  // axle 0 the front, the others one rear axle at x = -L (a bogie's trunnion)
  const std::vector<double> loads = StaticAxleLoads(d, g);
  const std::array<double, 2> w{loads[0], std::accumulate(loads.begin() + 1, loads.end(), 0.0)};
  double trail_rear = 0, relax_rear = 0;
  for (size_t i = 0; i < d.axles.size(); ++i) {
    const TireData& td = d.axles[i].tire;
    const Tire tire("reference", td, 1.0);
    // per side: a set of td.count tires sharing the wheel's load
    const double c = 2.0 * td.count * tire.CorneringStiffness(0.5 * loads[i] / td.count);
    // relaxation length at the static load: C(F_z) / k with k = C(F_z0) / sigma_0
    const double sigma = td.relaxation_length * tire.CorneringStiffness(0.5 * loads[i] / td.count) /
                         tire.CorneringStiffness(td.nominal_load);
    const int a = i == 0 ? 0 : 1;
    s.cornering_stiffness[a] += c;
    if (a == 0) {
      s.trail[0] = td.trail;
      s.relaxation_length[0] = sigma;
    } else {
      // the rear group's trail and relaxation length weighted by cornering stiffness
      trail_rear += c * td.trail;
      relax_rear += c * sigma;
    }
  }
  s.trail[1] = trail_rear / s.cornering_stiffness[1];
  s.relaxation_length[1] = relax_rear / s.cornering_stiffness[1];
  s.axle_load[0] = w[0];
  s.axle_load[1] = w[1];
  // centre of mass: a behind the front axle, b ahead of the rear one
  const double weight = w[0] + w[1], a = L * w[1] / weight, b = L * w[0] / weight;
  const double arm = L - s.trail[0] + s.trail[1];
  const double front = weight * (b + s.trail[1]) / arm, rear = weight * (a - s.trail[0]) / arm;
  s.understeer_gradient = front / s.cornering_stiffness[0] - rear / s.cornering_stiffness[1];

  // mass and yaw inertia about the centre of mass at x = -a: every part's
  // own moment plus m (dx^2 + dy^2)
  s.mass = weight / g;
  const double xc = -a;
  double inertia = 0;
  auto add = [&](double mass, double x, double y, double own) {
    inertia += own + mass * ((x - xc) * (x - xc) + y * y);
  };
  for (const PartData* p : {&d.frame, &d.cab, &d.powertrain, &d.cargo}) add(p->mass, p->cg.x(), p->cg.y(), p->inertia.z());
  for (const AxleData& ax : d.axles) {
    const TireData& t = ax.tire;
    const double patch = t.relaxation_length > 0 ? t.count * t.patch_mass : 0.0;
    add(ax.axle.mass + (ax.suspension.extra_arm_height > 0 ? kAxleHubMass : 0.0), ax.x, 0.0, ax.axle.inertia.z());
    for (double side : {1.0, -1.0}) {
      add(ax.wheel.mass + patch, ax.x, side * 0.5 * ax.track, ax.wheel.inertia.z());
      if (ax.steered) add(d.knuckle.mass, ax.x, side * (0.5 * ax.track - 0.5 * d.kingpin_offset), d.knuckle.inertia.z());
    }
    add(d.arm.mass, ax.x + 0.5 * ax.suspension.arm_length, 0.0, 0.0);
  }
  for (const BogieData& bg : d.bogies)
    for (double side : {1.0, -1.0})
      add(bg.beam.mass, bg.x, side * d.axles.back().suspension.spring_half_spacing, bg.beam.inertia.z());
  if (d.steering_linkage) add(d.pitman_arm_mass, d.drag_link_length, 0.0, 0.0);
  if (d.steering_linkage && d.steering_column)
    add(d.column_mass, d.drag_link_length - 0.5 * d.column_length * std::sin(d.column_inclination), 0.0, 0.0);
  s.yaw_inertia = inertia;
  return s;
}

}  // namespace flexmb::vehicle
