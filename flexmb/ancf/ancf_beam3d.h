#pragma once
/// \file ancf_beam3d.h
/// 3D ANCF beam element with torsion (after Dombrowski 2002): per node the
/// position r, the slope r' and a twist angle phi; 14 coordinates
/// e = (r_0, r'_0, phi_0, r_1, r'_1, phi_1) in world components [m, -, rad].
/// The centre line is the cubic Hermite curve of the cable (line_element.h);
/// phi is interpolated linearly.
///
/// Cross-section (material) frame at a point: t = r'/|r'|, and
///   [t, d2m, d3m] = Rmin(t0 -> t) R_0,   d2 = cos(phi) d2m + sin(phi) d3m,
///   d3 = -sin(phi) d2m + cos(phi) d3m,
/// where R_0 = [t0, y0, z0] is a reference frame fixed in world (the body's
/// start frame) and Rmin(t0 -> t) the rotation by the smallest angle about
/// t0 x t that takes t0 into t (singular only at t = -t0).
/// Strains (line strains, per reference length):
///   axial   eps = |r'| - 1, or (|r'|^2 - 1) / 2 (Beam3dSection::axial_strain)
///   bending kappa_2 = d2 . kv, kappa_3 = d3 . kv with kv = (r' x r'') / |r'|^2
///   torsion kappa_1 = phi' + tau_min, tau_min = -t0 . kv / (1 + t0 . t)
///           (the twist rate of the minimal-rotation frame along s, so that
///           kappa_1 = d3 . d2').
/// W = 1/2 int (EA (eps - eps_0)^2 + GJ (k1 - k1_0)^2 + E Iy (k2 - k2_0)^2
///   + E Iz (k3 - k3_0)^2) ds; the reference strains (initial curvature and
/// twist) are those of the reference coordinates given to SetReference. The
/// axial energy uses the cable's reduced integration with hourglass control
/// (QuadratureOrder, docs/design.md "ANCF beams"). Strains and their first
/// and second derivatives come from second-order forward-mode automatic
/// differentiation in the 8 local variables (r', r'', phi, phi'), exact.

#include <Eigen/Core>

#include "flexmb/ancf/ancf_cable3d.h"
#include "flexmb/ancf/line_element.h"

namespace flexmb::ancf {

/// Section and material of the 3D beam (SI units). Axis y is the section's
/// d2 axis, z its d3 axis.
struct Beam3dSection {
  double E = 0.0;        ///< Young's modulus [Pa]
  double G = 0.0;        ///< shear modulus [Pa]
  double A = 0.0;        ///< area [m^2]
  double Iy = 0.0;       ///< second moment of area about the section y axis (d2) [m^4]
  double Iz = 0.0;       ///< second moment of area about the section z axis (d3) [m^4]
  double J = 0.0;        ///< torsion constant [m^4]
  double rho = 0.0;      ///< density [kg/m^3]
  double damping = 0.0;  ///< stiffness-proportional damping time beta [s]
  AxialStrainMeasure axial_strain = AxialStrainMeasure::kEngineering;  ///< measure of the axial strain eps
};

/// 3D ANCF beam element with torsion; see the file comment.
class AncfBeam3d {
 public:
  /// Number of nodal coordinates.
  static constexpr int kDof = 14;
  /// Element coordinates or generalized forces (14).
  using Vec = Eigen::Matrix<double, kDof, 1>;
  /// Element matrices (14 x 14).
  using Mat = Eigen::Matrix<double, kDof, kDof>;
  /// A 3-vector in world components.
  using Vec3d = Eigen::Matrix<double, 3, 1>;
  /// A rotation or 3 x 3 matrix in world components.
  using Mat3d = Eigen::Matrix<double, 3, 3>;
  /// Strain components (eps, kappa_1, kappa_2, kappa_3).
  using Strains = Eigen::Matrix<double, 4, 1>;

  /// Element of reference length `length` [m]; R_0 = [t0, y0, z0] is the
  /// reference frame of the cross-section rule (orthonormal columns). Throws
  /// InputError if length, E, G, A, Iy, Iz, J or rho is not positive or
  /// damping < 0. The reference (stress-free) state is straight along t0
  /// with no twist until SetReference is called.
  AncfBeam3d(double length, const Beam3dSection& section, const Mat3d& R_0,
             const QuadratureOrder& order = {});

  /// Makes the configuration e0 stress-free (initial curvature and twist).
  void SetReference(const Vec& e0);

  /// Reference length [m].
  double length() const { return length_; }
  /// Section and material.
  const Beam3dSection& section() const { return section_; }
  /// Constant consistent mass matrix [kg, kg m^2]: int rho A S^T S ds for the
  /// centre line plus rho (Iy + Iz) int N^T N ds for the twist angles (rotary
  /// inertia of the spin about the tangent; the part of the spin due to the
  /// slope rates and the rotary inertia of bending are neglected).
  const Mat& MassMatrix() const { return mass_; }

  /// Position r(xi) [m] at xi = s / L.
  Vec3d Position(const Vec& e, double xi) const;
  /// Cross-section frame [t, d2, d3] at xi (see the file comment).
  Mat3d SectionFrame(const Vec& e, double xi) const;
  /// Strains (eps, kappa_1, kappa_2, kappa_3) [-, 1/m] at xi (eps in the section's measure).
  Strains StrainsAt(const Vec& e, double xi) const;

  /// Strain energy [J] at e.
  double StrainEnergy(const Vec& e) const;

  /// Adds the elastic and structural damping generalized forces at (e, edot)
  /// to Q (the elastic part is -dW/de) and their derivatives to dQde, dQdedot.
  void AddInternalForces(const Vec& e, const Vec& edot, Vec& Q, Mat& dQde, Mat& dQdedot) const;
  /// The generalized force of AddInternalForces without its derivatives
  /// (for Newton iterations that keep an earlier iteration matrix).
  void AddInternalForceVector(const Vec& e, const Vec& edot, Vec& Q) const;

  /// Generalized force of a constant force per reference length f [N/m]
  /// (gravity: rho A g): int S^T f ds (exact; nothing on the twist angles).
  Vec DistributedLoad(const Vec3d& f) const;

  /// Rotation Rmin(t0 -> a/|a|) R_0 of the untwisted section frame for the
  /// slope a (first column t = a/|a|); throws NumericalError if a vanishes
  /// or points against t0 (t0 . t < -1 + 1e-8).
  static Mat3d MinimalFrame(const Mat3d& R_0, const Vec3d& a);
  /// Angular velocity matrix G(a) of that frame: w = G(a) adot [rad/s per
  /// 1/s], G = (I - t t0^T / (1 + t0.t)) [t]x / |a|.
  static Mat3d FrameRate(const Vec3d& t0, const Vec3d& a);
  /// d(G(a) u)/da at fixed u (3 x 3).
  static Mat3d FrameRateDerivative(const Vec3d& t0, const Vec3d& a, const Vec3d& u);
  /// d(G(a)^T y)/da at fixed y (3 x 3).
  static Mat3d FrameRateTransposeDerivative(const Vec3d& t0, const Vec3d& a, const Vec3d& y);

 private:
  // axial strain at xi with its gradient and Hessian in e
  double AxialTerms(const Vec& e, double xi, Vec& d1, Mat& d2) const;
  // torsion and bending strains (k1, k2, k3) at xi with their gradients and Hessians in e
  Vec3d CurvatureTerms(const Vec& e, double xi, Eigen::Matrix<double, kDof, 3>& d1, Mat (&d2)[3]) const {
    return CurvatureTerms(e, xi, d1, &d2);
  }
  // the same; the second derivatives only if d2 is not null
  Vec3d CurvatureTerms(const Vec& e, double xi, Eigen::Matrix<double, kDof, 3>& d1, Mat (*d2)[3]) const;
  // calls f(xi, EA w, eps0) at every point of the axial rules (weights
  // include the length and the split between reduced and full integration;
  // eps0 the reference axial strain at the point)
  template <class F>
  void ForEachAxialPoint(F&& f) const;
  // adds -k (s - s0) ds/de and the damping terms of one strain component
  void AddStrainTerm(double stiffness, double strain, const Vec& d1, const Mat& d2, const Vec& edot,
                     Vec& Q, Mat& dQde, Mat& dQdedot) const;

  double length_;
  Beam3dSection section_;
  QuadratureOrder order_;
  AncfCable3d line_;  // hermite shapes, translational mass and loads
  Mat3d R_0_;
  double axial_full_ = 0.0;
  // reference strains at the axial points (reduced rule, then full rule) and at the bending points
  double eps0_[2][6] = {};
  double kap0_[6][3] = {};
  Mat mass_;
};

}  // namespace flexmb::ancf
