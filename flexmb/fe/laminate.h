#pragma once
/// \file laminate.h
/// Laminated shells (Nastran PCOMP / PCOMPG, a generalized PSHELL): the equivalent single-layer
/// section of a stack of plies (classical lamination theory), its rotation
/// into an element's axes, and the plane-stress stiffness of an isotropic
/// or orthotropic ply. Formulation and what is approximated: docs/design.md,
/// "Laminated shells".

#include <string>
#include <vector>

#include <Eigen/Core>

namespace flexmb::fe {

/// One ply, listed bottom (most negative z) to top.
struct LaminatePly {
  Eigen::Matrix3d q = Eigen::Matrix3d::Zero();  ///< plane stress (s11 s22 s12) = q (e11 e22 g12), ply axes [Pa]
  double g13 = 0.0, g23 = 0.0;                  ///< transverse shear moduli, ply axes [Pa]
  double rho = 0.0;                             ///< density [kg/m^3]
  double t = 0.0;                               ///< thickness [m]
  double theta = 0.0;                           ///< ply axis 1 from the laminate x axis [rad]
};

/// The equivalent section of a laminate in its own axes (x the laminate's
/// material axis): N = A eps0 + B kappa, M = B eps0 + D kappa, transverse
/// shear Q = S gamma; z from the reference (mid-)surface.
struct ShellLaminate {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();  ///< membrane [N/m]
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();  ///< membrane-bending coupling [N]
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();  ///< bending [N m]
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();  ///< transverse shear, 5/6 sum G t [N/m] (xz, yz)
  double mass = 0.0;                            ///< sum rho t [kg/m^2]
  double rotary = 0.0;                          ///< sum rho (z_top^3 - z_bottom^3) / 3 [kg]
  double thickness = 0.0;                       ///< sum t [m]
  double z_bottom = 0.0, z_top = 0.0;           ///< outer surfaces from the reference surface [m]
  Eigen::Matrix3d q_bottom = Eigen::Matrix3d::Zero();  ///< q of the bottom ply in laminate axes [Pa]
  Eigen::Matrix3d q_top = Eigen::Matrix3d::Zero();     ///< q of the top ply in laminate axes [Pa]
  /// The stiffness of the bending part of the surface stresses, sigma = q
  /// eps0 + z qb kappa at z_bottom and z_top: the outer plies' q for a
  /// stack; a PSHELL's MID2 where it differs from MID1 [Pa].
  Eigen::Matrix3d qb_bottom = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d qb_top = Eigen::Matrix3d::Zero();  ///< as qb_bottom, at z_top [Pa]
  std::string card;                             ///< where it came from, for messages ("PCOMP 7")
  /// A membrane (a PSHELL without MID2): only A and the mass act; the
  /// section has no bending, transverse shear or drilling stiffness and no
  /// rotary inertia, and its elements act on their nodes' translations only
  /// (the rotations stay free unless another element uses them).
  bool membrane_only = false;
};

/// q of an isotropic ply: E / (1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu) / 2].
Eigen::Matrix3d IsotropicPlaneStress(double E, double nu);

/// q of an orthotropic ply (Nastran MAT8): nu21 = nu12 E2 / E1, q11 = E1 /
/// (1 - nu12 nu21), q22 = E2 / (1 - nu12 nu21), q12 = nu12 q22, q66 = G12.
Eigen::Matrix3d OrthotropicPlaneStress(double E1, double E2, double nu12, double G12);

/// A plane-stress stiffness (Voigt, engineering shear strain) given in axes
/// at angle `theta` [rad] from x, expressed in the x-y axes: T^T q T with T
/// the map of x-y strains to the rotated axes' strains.
Eigen::Matrix3d RotatePlaneStress(const Eigen::Matrix3d& q, double theta);

/// A transverse shear stiffness (xz, yz) given in axes at angle `theta`
/// from x, expressed in the x-y axes: R^T s R.
Eigen::Matrix2d RotateShear(const Eigen::Matrix2d& s, double theta);

/// The laminate of `plies` stacked from z = `z0` (the bottom surface from
/// the reference surface) up: A = sum q_k (z_k - z_k-1), B = sum q_k (z_k^2
/// - z_k-1^2) / 2, D = sum q_k (z_k^3 - z_k-1^3) / 3 with q_k the plies'
/// stiffness in laminate axes; S = 5/6 sum t_k [g13, g23] rotated.
ShellLaminate StackPlies(const std::vector<LaminatePly>& plies, double z0);

/// A membrane (ShellLaminate::membrane_only) of plane-stress stiffness `q`
/// [Pa], density `rho` [kg/m^3] and thickness `t` [m]: A = q t, mass rho t,
/// nothing else; `card` names its source for messages.
ShellLaminate MembraneLaminate(const Eigen::Matrix3d& q, double rho, double t, const std::string& card);

/// The laminate `l` in axes whose x axis is at angle -`theta` from the
/// laminate's material axis, i.e. the material axis at `theta` from the new
/// x: every stiffness rotated by RotatePlaneStress / RotateShear.
ShellLaminate InElementAxes(const ShellLaminate& l, double theta);

}  // namespace flexmb::fe
