#include "flexmb/vehicle/single_track.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {

double SingleTrack::YawRateGain(double v, double g) const {
  return v / (wheelbase + understeer_gradient * v * v / g) / steering_ratio;
}

double SingleTrack::SteeringWheelAngleFor(double ay, double v, double g) const {
  return ay / (v * YawRateGain(v, g));
}

double SingleTrack::CentreOfMassX() const {
  double w = 0, wx = 0;
  for (const Axle& a : axles) {
    w += a.load;
    wx += a.load * a.x;
  }
  return wx / w;
}

void SingleTrack::SetSteadyState(double g) {
  const double xc = CentreOfMassX();
  double s0 = 0, s1 = 0, q0 = 0, q1 = 0, r0 = 0, r1 = 0;
  for (const Axle& a : axles) {
    const double p = a.x - xc, c = a.cornering_stiffness;
    s0 += c;
    s1 += c * p;
    q0 += c * (p - a.trail);
    q1 += c * p * (p - a.trail);
    r0 += c * a.steer;
    r1 += c * a.steer * (p - a.trail);
  }
  if (r0 == 0) throw std::invalid_argument("single-track model: no axle is steered");
  const double den = r0 * q0 - s0 * r1;
  wheelbase = (s1 * q0 - s0 * q1) / den;
  understeer_gradient = g * mass * q0 / den;
}

SingleTrack::Response SingleTrack::FrequencyResponse(double f, double v, double x_point) const {
  using C = std::complex<double>;
  const double xc = CentreOfMassX();
  const C s(0.0, 2.0 * 3.14159265358979323846 * f);
  // unknowns (v_y, r, F_1, ..., F_n) for a road-wheel angle of 1 rad
  const int n = static_cast<int>(axles.size());
  Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic> A = Eigen::Matrix<C, Eigen::Dynamic, Eigen::Dynamic>::Zero(2 + n, 2 + n);
  Eigen::Matrix<C, Eigen::Dynamic, 1> rhs = Eigen::Matrix<C, Eigen::Dynamic, 1>::Zero(2 + n);
  A(0, 0) = mass * s;
  A(0, 1) = mass * v;
  A(1, 1) = yaw_inertia * s;
  for (int i = 0; i < n; ++i) {
    const Axle& a = axles[static_cast<size_t>(i)];
    const double p = a.x - xc;
    A(0, 2 + i) = -1.0;
    A(1, 2 + i) = -(p - a.trail);
    A(2 + i, 0) = a.cornering_stiffness / v;
    A(2 + i, 1) = a.cornering_stiffness * p / v;
    A(2 + i, 2 + i) = a.relaxation_length / v * s + 1.0;
    rhs(2 + i) = a.cornering_stiffness * a.steer;
  }
  const Eigen::Matrix<C, Eigen::Dynamic, 1> x = A.partialPivLu().solve(rhs);
  // per steering-wheel angle; a_y at the point: centre of mass plus r' times the lever
  const C r = x(1) / steering_ratio, vy = x(0) / steering_ratio;
  return {r, s * vy + v * r + s * r * (x_point - xc)};
}

SingleTrack TruckSingleTrack(const TruckData& d, double g) {
  SingleTrack s;
  s.steering_ratio = d.steering_ratio;
  const std::vector<double> loads = StaticAxleLoads(d, g);
  double weight = 0;
  for (size_t i = 0; i < d.axles.size(); ++i) {
    const AxleData& ax = d.axles[i];
    const TireData& td = ax.tire;
    const Tire tire("reference", td, 1.0);
    SingleTrack::Axle a;
    a.x = ax.x;
    a.load = loads[i];
    a.steer = SteerRatio(d, i);
    // per side: a set of td.count tires sharing the wheel's load
    a.cornering_stiffness = 2.0 * td.count * tire.CorneringStiffness(0.5 * loads[i] / td.count);
    a.trail = td.trail;
    // relaxation length at the static load: C(F_z) / k with k = C(F_z0) / sigma_0
    a.relaxation_length = td.relaxation_length * tire.CorneringStiffness(0.5 * loads[i] / td.count) /
                          tire.CorneringStiffness(td.nominal_load);
    s.axles.push_back(a);
    weight += loads[i];
  }
  s.mass = weight / g;

  // yaw inertia about the centre of mass: every part's own moment plus m (dx^2 + dy^2)
  const double xc = s.CentreOfMassX();
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
  if (d.steering_linkage && d.axles.size() > 1 && d.axles[1].steered)
    add(d.pitman_arm_mass, d.axles[1].x + d.drag_link_length, 0.0, 0.0);  // the relay arm
  if (d.steering_linkage && d.steering_column)
    add(d.column_mass, d.drag_link_length - 0.5 * d.column_length * std::sin(d.column_inclination), 0.0, 0.0);
  s.yaw_inertia = inertia;
  s.SetSteadyState(g);
  return s;
}

double DriverWheelbase(const TruckData& d, double g) {
  return d.axles.size() == 2 ? 0.0 : TruckSingleTrack(d, g).wheelbase;
}

}  // namespace flexmb::vehicle
