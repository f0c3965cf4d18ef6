#pragma once
/// \file single_track.h
/// The linear single-track ("bicycle") model of a two-axle vehicle in steady
/// state (Wong, Theory of Ground Vehicles, 4th ed., sec. 5.2; Gillespie,
/// Fundamentals of Vehicle Dynamics, ch. 6): the reference the handling
/// tests (apps/flexmb/commands/handling.h) print beside the truck's results,
/// so that a user sees how much of the response is the axles' tires and
/// load split and how much the rest of the truck (steering compliance, roll
/// and load transfer).

#include <complex>

#include "flexmb/vehicle/truck.h"

namespace flexmb::vehicle {

/// Steady-state coefficients of the single-track model.
struct SingleTrack {
  double wheelbase = 0.0;          ///< L [m]
  double axle_load[2] = {0, 0};    ///< static front, rear axle load W [N]
  double cornering_stiffness[2] = {0, 0};  ///< front, rear axle C (both sides) [N/rad]
  double trail[2] = {0, 0};        ///< front, rear pneumatic trail t at zero slip [m]
  /// Understeer gradient K [rad] per g of lateral acceleration: delta = L /
  /// R + K a_y / g. The tires' aligning moments -t F_y act on the vehicle,
  /// so the lateral forces balance about points t behind the axles:
  /// F_yf (a - t_f) = F_yr (b + t_r), F_yf + F_yr = m a_y, and K = F_yf' /
  /// C_f - F_yr' / C_r with F' the axle forces per g (Pacejka, Tire and
  /// Vehicle Dynamics, 3rd ed., sec. 1.3; t = 0 gives W_f / C_f - W_r / C_r).
  double understeer_gradient = 0.0;
  double steering_ratio = 1.0;     ///< steering-wheel / road-wheel angle [-]
  double mass = 0.0;               ///< total mass m [kg]
  /// Yaw moment of inertia about the vertical through the centre of mass
  /// [kg m^2] (all parts' own moments plus their masses' offsets).
  double yaw_inertia = 0.0;
  /// Relaxation length of each axle's tires at their static load [m]
  /// (sigma = C / k, the lateral carcass stiffness k set at the nominal
  /// load: Tire); 0: the lateral force follows the slip angle at once.
  double relaxation_length[2] = {0, 0};

  /// Linear response to a sinusoidal steering-wheel angle of frequency f
  /// [Hz] at speed v [m/s], per unit angle: yaw rate [1/s] and lateral
  /// acceleration [m/s^2] at the point x_point of the vehicle frame (x
  /// forward from the front axle). The dynamic single-track model (Mitschke
  /// and Wallentowitz, Dynamik der Kraftfahrzeuge, ch. 30; Pacejka, sec.
  /// 1.3): lateral and yaw balance m (dv/dt + v r) = F_f + F_r, I r' =
  /// (a - t_f) F_f - (b + t_r) F_r with each axle's force lagging its slip
  /// angle, (sigma / v) dF/dt + F = C alpha, alpha_f = delta - (v_y + a r) /
  /// v, alpha_r = -(v_y - b r) / v. At f -> 0 it is YawRateGain.
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

/// The single-track model of the truck `d`: the static axle loads
/// (StaticAxleLoads) and each axle's cornering stiffness at its static tire
/// load (Tire::CorneringStiffness of its tire set, both sides); the axles
/// behind the first act as one rear axle at x = -Wheelbase(d) (a bogie's
/// trunnion) with their summed loads and cornering stiffnesses; mass and
/// yaw inertia summed by hand over the truck's parts (sprung parts with
/// their own moments, wheels and knuckles at their track positions).
SingleTrack TruckSingleTrack(const TruckData& d, double g = 9.81);

}  // namespace flexmb::vehicle
