#pragma once
/// \file line_element.h
/// Shared kernel of the ANCF line elements (2D planar Euler-Bernoulli beam,
/// 3D cable): cubic Hermite interpolation of the centre line in reference arc
/// length s, nodal coordinates e = (r_0, r'_0, r_1, r'_1) in world components
/// (D = 2 or 3 per vector, 4 D in all). Structural ("line") strain measures:
///   axial   eps   = |r'| - 1                     (engineering (Biot), per reference
///                                                 length; the default) or
///           eps   = (|r'|^2 - 1) / 2             (Green-Lagrange), AxialStrainMeasure
///   bending kappa = (r' x r'') / |r'|^2          (rate of turn of the tangent per
///                                                 reference length; a scalar in 2D,
///                                                 a vector in 3D)
/// Strain energy W = 1/2 int (EA eps^2 + EI |kappa - kappa_0|^2) ds, integrated
/// by Gauss quadrature. Because the strains are those of a line, no Poisson or
/// shear (thickness) locking arises; membrane locking is avoided by reduced
/// integration of the axial term with hourglass control (QuadratureOrder);
/// see docs/design.md "ANCF beams".
/// Not for direct use: the element classes AncfBeam2d and AncfCable3d derive
/// from LineElement<2> and LineElement<3>.

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::ancf {

/// Measure eps of the axial strain of the ANCF elements, in the stretch
/// lambda = |r'| of the centre line (reference arc length s). The axial
/// energy is 1/2 EA eps^2 per reference length with either, so the two are
/// two materials that agree to first order in lambda - 1: the axial force
/// EA eps deps/dlambda is EA (lambda - 1) resp. EA lambda (lambda^2 - 1) / 2.
enum class AxialStrainMeasure {
  kEngineering,    ///< eps = lambda - 1 (Biot; the default)
  kGreenLagrange,  ///< eps = (lambda^2 - 1) / 2 (Berzeri and Shabana 2000)
};

/// Cross section and material of a line element (SI units).
struct BeamSection {
  double E = 0.0;        ///< Young's modulus [Pa]
  double A = 0.0;        ///< cross-section area [m^2]
  double I = 0.0;        ///< second moment of area for bending [m^4]
  double rho = 0.0;      ///< density [kg/m^3]
  double damping = 0.0;  ///< stiffness-proportional damping time beta [s]: stress += beta E * strain rate
  AxialStrainMeasure axial_strain = AxialStrainMeasure::kEngineering;  ///< measure of the axial strain
};

/// Axial strain eps of the slope a = B e (B = dr'/de, D x N) in the given
/// measure, its gradient d1 = deps/de and Hessian d2 = d^2 eps/de^2 (exact;
/// Green-Lagrange: d1 = B^T a, d2 = B^T B). Throws NumericalError if the
/// slope vanishes under the engineering measure (not differentiable there).
template <int D, int N>
double AncfAxialStrainTerms(AxialStrainMeasure measure, const Eigen::Matrix<double, D, N>& B,
                            const Eigen::Matrix<double, N, 1>& e, Eigen::Matrix<double, N, 1>& d1,
                            Eigen::Matrix<double, N, N>& d2) {
  const Eigen::Matrix<double, D, 1> a = B * e;
  d1.noalias() = B.transpose() * a;
  d2.noalias() = B.transpose() * B;
  const double g = a.squaredNorm();
  if (measure == AxialStrainMeasure::kGreenLagrange) return 0.5 * (g - 1.0);
  const double l = std::sqrt(g);
  if (!(l > 0.0)) throw NumericalError("ANCF element slope r' vanished (element collapsed)");
  d2 /= l;
  d2.noalias() -= d1 * d1.transpose() / (l * l * l);
  d1 /= l;
  return l - 1.0;
}

/// Points per element of an ANCF body's centre line in animations
/// (Body::CentreLinePoints): enough to show a cubic element's bend.
constexpr int kLinePointsPerElement = 4;

/// Quadrature orders of the element integrals (Gauss-Legendre points, 1..6).
/// The default integrates the axial energy with 2 points (selective reduced
/// integration): with full integration the cubic element locks in bending
/// of slender beams (membrane locking; docs/design.md "ANCF beams" shows the
/// convergence of both).
/// The 2-point rule alone leaves one axial hourglass mode (r' varying along
/// the tangent as (xi - g1)(xi - g2), zero at both Gauss points, continuous
/// across elements). A fraction alpha = min(1, hourglass * I / (A h^2)) of
/// the axial energy (h the element length) is integrated with
/// `axial_full_points` to give that mode a stiffness of the order of the
/// bending stiffness (hourglass control scaled by EI, so that it does not
/// bring the locking back for slender elements).
struct QuadratureOrder {
  int axial = 2;              ///< points for the (reduced) axial energy
  int bending = 4;            ///< points for the bending energy (the integrand is rational: 4 is near exact)
  double hourglass = 0.1;     ///< hourglass control factor, >= 0 (0: none)
  int axial_full_points = 5;  ///< points of the fully integrated fraction
};

/// Finds the element i (0..n_el-1) and the element coordinate xi in [0, 1]
/// of arc length s [m] along a line of n_el elements of length h [m];
/// s outside [0, n_el h] is clamped to the end elements.
inline void LocateOnAncfLine(double s, double h, int n_el, int& i, double& xi) {
  i = std::min(n_el - 1, std::max(0, static_cast<int>(std::floor(s / h))));
  xi = std::min(1.0, std::max(0.0, (s - i * h) / h));
}

/// Adds the linear momentum p [kg m/s] and the angular momentum about the
/// world origin L [kg m^2/s] of one 3D ANCF element whose position vectors
/// (r0, r0', r1, r1', world) start at slots slot[0..3] of its coordinates qe
/// and velocities ve; M its mass matrix, m (x) I3 on those slots.
template <class MassMat>
void AddAncfElementMomentum(const MassMat& M, const double* qe, const double* ve, const int (&slot)[4],
                            Eigen::Matrix<double, 3, 1>& p, Eigen::Matrix<double, 3, 1>& L) {
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      const double mab = M(slot[a], slot[b]);
      const Eigen::Map<const Eigen::Matrix<double, 3, 1>> ra(qe + slot[a]), vb(ve + slot[b]);
      if (a % 2 == 0) p += mab * vb;
      L += mab * ra.cross(vb);
    }
  }
}

/// Adds the generalized force of one strain component s(e) of an ANCF
/// element with weighted stiffness k (stiffness times quadrature weight and
/// length): Q -= k s ds/de, its tangent to dQde, and with damping time
/// beta > 0 [s] the Kelvin-Voigt terms Q -= beta k (ds/de . edot) ds/de and
/// their tangents to dQde and dQdedot. d1 = ds/de, d2 = d^2 s/de^2.
template <int N>
void AddAncfStrainTerm(double stiffness, double beta, double strain, const Eigen::Matrix<double, N, 1>& d1,
                       const Eigen::Matrix<double, N, N>& d2, const Eigen::Matrix<double, N, 1>& edot,
                       Eigen::Matrix<double, N, 1>& Q, Eigen::Matrix<double, N, N>& dQde,
                       Eigen::Matrix<double, N, N>& dQdedot) {
  Q.noalias() -= (stiffness * strain) * d1;
  dQde.noalias() -= stiffness * (d1 * d1.transpose() + strain * d2);
  if (beta > 0.0) {
    const double rate = d1.dot(edot);
    Q.noalias() -= (beta * stiffness * rate) * d1;
    dQdedot.noalias() -= (beta * stiffness) * d1 * d1.transpose();
    dQde.noalias() -= (beta * stiffness) * (rate * d2 + d1 * (d2 * edot).transpose());
  }
}

/// Gauss-Legendre points on [0, 1] and their weights (sum 1), n = 1..6.
/// Throws InputError for other n.
void GaussPoints01(int n, const double*& xi, const double*& w);

/// ANCF line element in D dimensions (D = 2 or 3). All quantities in world
/// components; s is the reference arc length [m] from node 0.
template <int D>
class LineElement {
 public:
  /// Number of nodal coordinates (r, r' at two nodes).
  static constexpr int kDof = 4 * D;
  /// Number of bending-strain components (1 in 2D, 3 in 3D).
  static constexpr int kCurv = D == 2 ? 1 : 3;
  using VecD = Eigen::Matrix<double, D, 1>;
  using Vec = Eigen::Matrix<double, kDof, 1>;
  using Mat = Eigen::Matrix<double, kDof, kDof>;
  using ShapeMat = Eigen::Matrix<double, D, kDof>;
  using VecK = Eigen::Matrix<double, kCurv, 1>;

  /// Element of reference length `length` [m] with the given section; throws
  /// InputError if length, E, A, I or rho is not positive, or damping < 0.
  LineElement(double length, const BeamSection& section, const QuadratureOrder& order = {});

  /// Reference length [m].
  double length() const { return length_; }
  /// Section and material.
  const BeamSection& section() const { return section_; }
  /// Constant consistent mass matrix int rho A S^T S ds [kg].
  const Mat& MassMatrix() const { return mass_; }

  /// Shape matrix S(xi) (D x kDof) at xi = s / L in [0, 1]: r = S e.
  ShapeMat Shape(double xi) const;
  /// dS/ds [1/m] at xi: r' = S' e.
  ShapeMat ShapeSlope(double xi) const;
  /// d2S/ds2 [1/m^2] at xi: r'' = S'' e.
  ShapeMat ShapeCurvature(double xi) const;

  /// Position r(xi) [m].
  VecD Position(const Vec& e, double xi) const { return Shape(xi) * e; }
  /// Slope r'(xi) (dimensionless).
  VecD Slope(const Vec& e, double xi) const { return ShapeSlope(xi) * e; }

  /// Axial strain at xi in the section's measure: |r'| - 1 or (|r'|^2 - 1) / 2.
  double AxialStrain(const Vec& e, double xi) const;
  /// Bending strain (r' x r'') / |r'|^2 at xi [1/m].
  VecK Curvature(const Vec& e, double xi) const;

  /// Strain energy [J] at e.
  double StrainEnergy(const Vec& e) const;

  /// Adds the elastic and structural damping generalized forces at (e, edot)
  /// to Q (positive = applied to the coordinates; the elastic part is
  /// -dW/de) and their derivatives dQ/de and dQ/dedot to dQde, dQdedot.
  void AddInternalForces(const Vec& e, const Vec& edot, Vec& Q, Mat& dQde, Mat& dQdedot) const;

  /// The generalized force of AddInternalForces without its derivatives
  /// (for Newton iterations that keep an earlier iteration matrix).
  void AddInternalForceVector(const Vec& e, const Vec& edot, Vec& Q) const;

  /// Generalized force of a constant load per unit reference length f [N/m]
  /// (gravity: f = rho A g): int S^T f ds (exact).
  Vec DistributedLoad(const VecD& f) const;

  /// Nodal coordinates of a straight, unstrained element from p0 along the
  /// unit direction `dir`.
  Vec StraightCoordinates(const VecD& p0, const VecD& dir) const;

 protected:
  /// Reference bending strain (initial curvature) kappa_0 [1/m]; zero unless set.
  VecK kappa0_ = VecK::Zero();

 private:
  // calls f(xi, EA w) at every point of the axial rules (weights include
  // the length and the split between reduced and full integration)
  template <class F>
  void ForEachAxialPoint(F&& f) const;
  // calls f(xi, EI w) at every bending quadrature point
  template <class F>
  void ForEachBendingPoint(F&& f) const;
  double length_;
  BeamSection section_;
  QuadratureOrder order_;
  double axial_full_ = 0.0;  // fraction of the axial energy integrated fully
  Mat mass_;
  // quadrature points of the kernels: weighted stiffness k (EA resp. EI
  // times weight and length) and the scalar Hermite slopes s' [1/m] and
  // curvatures s'' [1/m^2] of the 4 nodal vectors
  struct AxialPoint {
    double k;
    double sx[4];
  };
  struct BendingPoint {
    double k;
    double sx[4];
    double sxx[4];
  };
  std::array<AxialPoint, 12> axial_pts_{};
  int n_axial_ = 0;
  std::array<BendingPoint, 6> bending_pts_{};
  int n_bending_ = 0;
};

extern template class LineElement<2>;
extern template class LineElement<3>;

}  // namespace flexmb::ancf
