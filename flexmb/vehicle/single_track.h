#pragma once
/// \file single_track.h
/// The linear single-track ("bicycle") model of a vehicle with two or more
/// axles in steady state (Wong, Theory of Ground Vehicles, 4th ed., sec. 5.2; Gillespie,
/// Fundamentals of Vehicle Dynamics, ch. 6): the reference the handling
/// tests (apps/flexmb/commands/handling.h) print beside the truck's results,
/// so that a user sees how much of the response is the axles' tires and
/// load split and how much the rest of the truck (steering compliance, roll
/// and load transfer).

#include <complex>
#include <vector>

#include "flexmb/vehicle/truck.h"

namespace flexmb::vehicle {

/// The linear single-track model of a vehicle with any number of axles.
struct SingleTrack {
  /// One axle (both sides lumped on the centre line).
  struct Axle {
    double x = 0.0;                ///< position along the vehicle's x, the first axle at 0 [m]
    double load = 0.0;             ///< static axle load W [N]
    double cornering_stiffness = 0.0;  ///< C of both sides [N/rad]
    double trail = 0.0;            ///< pneumatic trail t at zero slip [m]
    /// Relaxation length of the axle's tires at their static load [m]
    /// (sigma = C / k, the lateral carcass stiffness k set at the nominal
    /// load: Tire); 0: the lateral force follows the slip angle at once.
    double relaxation_length = 0.0;
    /// Road-wheel angle per the first axle's (SteerRatio): 1 for the first
    /// axle, 0 for an unsteered one.
    double steer = 0.0;
  };
  std::vector<Axle> axles;         ///< front to rear
  /// Equivalent wheelbase L [m] and understeer gradient K [rad per g of
  /// lateral acceleration] of the steady turn, delta = L / R + K a_y / g
  /// (SetSteadyState). Two axles: L the wheelbase and K = F_yf' / C_f -
  /// F_yr' / C_r, the tires' aligning moments -t F_y acting on the vehicle
  /// so that the lateral forces balance about points t behind the axles,
  /// F_yf (a - t_f) = F_yr (b + t_r), F_yf + F_yr = m a_y (Pacejka, Tire and
  /// Vehicle Dynamics, 3rd ed., sec. 1.3; t = 0 gives W_f / C_f - W_r /
  /// C_r). More axles: the same two balances with every axle's force and
  /// steer ratio; an unsteered tandem makes L longer than the distance to
  /// its centre (it resists the turn), a second axle steered at the
  /// Ackermann ratio keeps it (docs/validation.md, "Trucks with any number
  /// of axles").
  double wheelbase = 0.0;
  double understeer_gradient = 0.0;
  double steering_ratio = 1.0;     ///< steering-wheel / road-wheel angle [-]
  double mass = 0.0;               ///< total mass m [kg]
  /// Yaw moment of inertia about the vertical through the centre of mass
  /// [kg m^2] (all parts' own moments plus their masses' offsets).
  double yaw_inertia = 0.0;

  /// Sets wheelbase and understeer_gradient from the axles and the mass:
  /// with p_i the axles' positions from the centre of mass (x_c = sum W_i
  /// x_i / W), the lateral balance sum F_i = m v^2 / R and the yaw balance
  /// sum F_i (p_i - t_i) = 0 with F_i = C_i (r_i delta - beta - p_i / R)
  /// (r_i the axle's steer ratio) give delta R = (m v^2 Q0 + S1 Q0 - S0 Q1)
  /// / (R0 Q0 - S0 R1) with S0 = sum C, S1 = sum C p, Q0 = sum C (p - t), Q1
  /// = sum C p (p - t), R0 = sum C r, R1 = sum C r (p - t). Throws
  /// std::invalid_argument without a steered axle.
  void SetSteadyState(double g = 9.81);
  /// Centre of mass along the vehicle's x from the axle loads [m].
  double CentreOfMassX() const;

  /// Linear response to a sinusoidal steering-wheel angle of frequency f
  /// [Hz] at speed v [m/s], per unit angle: yaw rate [1/s] and lateral
  /// acceleration [m/s^2] at the point x_point of the vehicle frame (x
  /// forward from the front axle). The dynamic single-track model (Mitschke
  /// and Wallentowitz, Dynamik der Kraftfahrzeuge, ch. 30; Pacejka, sec.
  /// 1.3): lateral and yaw balance m (dv/dt + v r) = sum F_i, I r' = sum
  /// (p_i - t_i) F_i with each axle's force lagging its slip angle, (sigma_i
  /// / v) dF_i/dt + F_i = C_i alpha_i, alpha_i = delta_i - (v_y + p_i r) / v
  /// (two axles: p = a, -b). At f -> 0 it is YawRateGain.
  struct Response {
    std::complex<double> yaw_rate;              ///< [1/s per rad]
    std::complex<double> lateral_acceleration;  ///< [m/s^2 per rad]
  };
  Response FrequencyResponse(double f, double v, double x_point) const;

  /// Yaw rate per steering-wheel angle at speed v [m/s] in steady state
  /// [1/s]: v / (L + K v^2 / g) / ratio.
  double YawRateGain(double v, double g = 9.81) const;
  /// Steering-wheel angle [rad] that gives lateral acceleration a_y [m/s^2]
  /// at speed v [m/s] in steady state.
  double SteeringWheelAngleFor(double ay, double v, double g = 9.81) const;
};

/// The single-track model of the truck `d`: every axle with its static load
/// (StaticAxleLoads) and its cornering stiffness at that load
/// (Tire::CorneringStiffness of its tire set, both sides); mass and
/// yaw inertia summed by hand over the truck's parts (sprung parts with
/// their own moments, wheels and knuckles at their track positions).
SingleTrack TruckSingleTrack(const TruckData& d, double g = 9.81);

/// The wheelbase the driver steers by (VehicleView::steering_wheelbase)
/// [m]: for more than two axles the single-track model's equivalent
/// wheelbase (a tandem resists the turn: the same curvature needs more
/// road-wheel angle than the distance to its trunnion gives); 0 (the
/// geometric wheelbase) for two.
double DriverWheelbase(const TruckData& d, double g = 9.81);

}  // namespace flexmb::vehicle
