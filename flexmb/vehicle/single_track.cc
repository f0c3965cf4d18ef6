#include "flexmb/vehicle/single_track.h"

#include "flexmb/vehicle/tire.h"

namespace flexmb::vehicle {

double SingleTrack::YawRateGain(double v, double g) const {
  return v / (wheelbase + understeer_gradient * v * v / g) / steering_ratio;
}

double SingleTrack::SteeringWheelAngleFor(double ay, double v, double g) const {
  return ay / (v * YawRateGain(v, g));
}

SingleTrack TruckSingleTrack(const TruckData& d, double g) {
  SingleTrack s;
  s.wheelbase = d.wheelbase;
  s.steering_ratio = d.steering_ratio;
  const std::array<double, 2> w = StaticAxleLoads(d, g);
  for (int a = 0; a < 2; ++a) {
    const TireData& td = a == 0 ? d.front_tire : d.rear_tire;
    const Tire tire("reference", td, 1.0);
    // per side: a set of td.count tires sharing the wheel's load
    s.axle_load[a] = w[a];
    s.cornering_stiffness[a] = 2.0 * td.count * tire.CorneringStiffness(0.5 * w[a] / td.count);
    s.trail[a] = td.trail;
  }
  // centre of mass: a behind the front axle, b ahead of the rear one
  const double weight = w[0] + w[1], a = d.wheelbase * w[1] / weight, b = d.wheelbase * w[0] / weight;
  const double arm = d.wheelbase - s.trail[0] + s.trail[1];
  const double front = weight * (b + s.trail[1]) / arm, rear = weight * (a - s.trail[0]) / arm;
  s.understeer_gradient = front / s.cornering_stiffness[0] - rear / s.cornering_stiffness[1];
  return s;
}

}  // namespace flexmb::vehicle
