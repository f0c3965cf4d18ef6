#include "flexmb/ancf/ancf_beam3d.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"

namespace flexmb::ancf {
namespace {

// second-order forward-mode number in the 8 local variables (r', r'', phi, phi')
struct Beam3dJet {
  double v = 0.0;
  Eigen::Matrix<double, 8, 1> g = Eigen::Matrix<double, 8, 1>::Zero();
  Eigen::Matrix<double, 8, 8> h = Eigen::Matrix<double, 8, 8>::Zero();
};

Beam3dJet Beam3dVar(double v, int k) {
  Beam3dJet x;
  x.v = v;
  x.g(k) = 1.0;
  return x;
}

Beam3dJet operator+(const Beam3dJet& a, const Beam3dJet& b) {
  Beam3dJet r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  r.h = a.h + b.h;
  return r;
}

Beam3dJet operator-(const Beam3dJet& a, const Beam3dJet& b) {
  Beam3dJet r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  r.h = a.h - b.h;
  return r;
}

Beam3dJet operator*(const Beam3dJet& a, const Beam3dJet& b) {
  Beam3dJet r;
  r.v = a.v * b.v;
  r.g = a.g * b.v + b.g * a.v;
  r.h = a.h * b.v + b.h * a.v + a.g * b.g.transpose() + b.g * a.g.transpose();
  return r;
}

Beam3dJet operator*(double s, const Beam3dJet& a) {
  Beam3dJet r;
  r.v = s * a.v;
  r.g = s * a.g;
  r.h = s * a.h;
  return r;
}

// f(a) for a scalar function with value f0 and derivatives f1, f2 at a.v
Beam3dJet Beam3dChain(const Beam3dJet& a, double f0, double f1, double f2) {
  Beam3dJet r;
  r.v = f0;
  r.g = f1 * a.g;
  r.h = f1 * a.h + f2 * a.g * a.g.transpose();
  return r;
}

Beam3dJet B3Inverse(const Beam3dJet& a) {
  const double i = 1.0 / a.v;
  return Beam3dChain(a, i, -i * i, 2.0 * i * i * i);
}

Beam3dJet B3Sqrt(const Beam3dJet& a) {
  const double s = std::sqrt(a.v);
  return Beam3dChain(a, s, 0.5 / s, -0.25 / (s * a.v));
}

struct Beam3dJetVec {
  Beam3dJet c[3];
};

Beam3dJet B3Dot(const Beam3dJetVec& a, const Beam3dJetVec& b) {
  return a.c[0] * b.c[0] + a.c[1] * b.c[1] + a.c[2] * b.c[2];
}

// dot with a constant vector
Beam3dJet B3Dot(const Eigen::Vector3d& a, const Beam3dJetVec& b) {
  return a(0) * b.c[0] + a(1) * b.c[1] + a(2) * b.c[2];
}

Beam3dJetVec B3Cross(const Beam3dJetVec& a, const Beam3dJetVec& b) {
  Beam3dJetVec r;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    r.c[k] = a.c[i] * b.c[j] - a.c[j] * b.c[i];
  }
  return r;
}

// cross product of a constant vector with a jet vector
Beam3dJetVec B3Cross(const Eigen::Vector3d& a, const Beam3dJetVec& b) {
  Beam3dJetVec r;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    r.c[k] = a(i) * b.c[j] - a(j) * b.c[i];
  }
  return r;
}

Beam3dJetVec B3Scale(const Beam3dJet& s, const Beam3dJetVec& a) {
  return {{s * a.c[0], s * a.c[1], s * a.c[2]}};
}

Beam3dJetVec B3Add(const Beam3dJetVec& a, const Beam3dJetVec& b) {
  return {{a.c[0] + b.c[0], a.c[1] + b.c[1], a.c[2] + b.c[2]}};
}

Beam3dJetVec B3Sub(const Beam3dJetVec& a, const Beam3dJetVec& b) {
  return {{a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2]}};
}

// torsion and bending strains (k1, k2, k3) of the local variables z = (a, b, phi, phi')
void Beam3dCurvatureJets(const Eigen::Matrix<double, 8, 1>& z, const Eigen::Matrix3d& R0,
                         Beam3dJet (&k)[3]) {
  const Eigen::Vector3d t0 = R0.col(0), y0 = R0.col(1), z0 = R0.col(2);
  Beam3dJetVec a, b;
  for (int i = 0; i < 3; ++i) {
    a.c[i] = Beam3dVar(z(i), i);
    b.c[i] = Beam3dVar(z(3 + i), 3 + i);
  }
  const Beam3dJet phi = Beam3dVar(z(6), 6);
  const Beam3dJet phid = Beam3dVar(z(7), 7);
  const Beam3dJet aa = B3Dot(a, a);
  if (!(aa.v > 0.0)) throw NumericalError("ANCF beam slope r' vanished (element collapsed)");
  const Beam3dJetVec t = B3Scale(B3Inverse(B3Sqrt(aa)), a);
  const Beam3dJetVec kv = B3Scale(B3Inverse(aa), B3Cross(a, b));
  Beam3dJet w = B3Dot(t0, t);
  w.v += 1.0;
  if (!(w.v > 1e-8))
    throw NumericalError("ANCF beam slope turned against the reference direction (section frame singular)");
  const Beam3dJet iw = B3Inverse(w);
  // u = Rmin^T kv: its components along y0, z0 are those of kv along d2m, d3m
  const Beam3dJetVec c = B3Cross(t0, t);
  const Beam3dJetVec ckv = B3Cross(c, kv);
  const Beam3dJetVec u = B3Add(B3Sub(kv, ckv), B3Scale(iw, B3Cross(c, ckv)));
  const Beam3dJet py = B3Dot(y0, u), pz = B3Dot(z0, u);
  const Beam3dJet cp = Beam3dChain(phi, std::cos(phi.v), -std::sin(phi.v), -std::cos(phi.v));
  const Beam3dJet sp = Beam3dChain(phi, std::sin(phi.v), std::cos(phi.v), -std::sin(phi.v));
  k[0] = phid - B3Dot(t0, kv) * iw;
  k[1] = cp * py + sp * pz;
  k[2] = cp * pz - sp * py;
}

// G(a) u and G(a)^T y as jets in a (variables 0..2)
Beam3dJetVec Beam3dRateJet(const Eigen::Vector3d& t0, const Eigen::Vector3d& av, const Eigen::Vector3d& vec,
                           bool transpose) {
  Beam3dJetVec a;
  for (int i = 0; i < 3; ++i) a.c[i] = Beam3dVar(av(i), i);
  const Beam3dJet ila = B3Inverse(B3Sqrt(B3Dot(a, a)));
  const Beam3dJetVec t = B3Scale(ila, a);
  Beam3dJet w = B3Dot(t0, t);
  w.v += 1.0;
  const Beam3dJet iw = B3Inverse(w);
  Beam3dJetVec y;
  for (int i = 0; i < 3; ++i) y.c[i].v = vec(i);
  if (!transpose) {
    // (I - t t0^T / w) (t x u) / |a|
    const Beam3dJetVec tu = B3Cross(t, y);
    return B3Scale(ila, B3Sub(tu, B3Scale(B3Dot(t0, tu) * iw, t)));
  }
  // -(t x (y - t0 (t.y) / w)) / |a|
  Beam3dJetVec t0j;
  for (int i = 0; i < 3; ++i) t0j.c[i].v = t0(i);
  const Beam3dJetVec r = B3Sub(y, B3Scale(B3Dot(t, y) * iw, t0j));
  return B3Scale(-1.0 * ila, B3Cross(t, r));
}

Eigen::Matrix3d Beam3dJetGradient(const Beam3dJetVec& v) {
  Eigen::Matrix3d D;
  for (int i = 0; i < 3; ++i) D.row(i) = v.c[i].g.head<3>().transpose();
  return D;
}

// column of each cable coordinate (r0, r'0, r1, r'1) among the 14 beam coordinates
constexpr int kBeam3dCableIndex[12] = {0, 1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12};

BeamSection Beam3dLineSection(const Beam3dSection& s) {
  BeamSection b;
  b.E = s.E;
  b.A = s.A;
  b.I = s.Iy;
  b.rho = s.rho;
  b.damping = s.damping;
  b.axial_strain = s.axial_strain;
  return b;
}

}  // namespace

AncfBeam3d::AncfBeam3d(double length, const Beam3dSection& section, const Mat3d& R_0,
                       const QuadratureOrder& order)
    : length_(length), section_(section), order_(order), line_(length, Beam3dLineSection(section), order),
      R_0_(R_0) {
  if (!(section.G > 0.0)) throw InputError("ANCF beam shear modulus G must be positive");
  if (!(section.Iz > 0.0)) throw InputError("ANCF beam second moment of area Iz must be positive");
  if (!(section.J > 0.0)) throw InputError("ANCF beam torsion constant J must be positive");
  axial_full_ = std::min(1.0, order.hourglass * std::min(section.Iy, section.Iz) / (section.A * length * length));
  if (order.axial == order.axial_full_points) axial_full_ = 0.0;
  mass_.setZero();
  const auto& Mc = line_.MassMatrix();
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) mass_(kBeam3dCableIndex[i], kBeam3dCableIndex[j]) = Mc(i, j);
  const double mr = section.rho * (section.Iy + section.Iz) * length;
  mass_(6, 6) = mass_(13, 13) = mr / 3.0;
  mass_(6, 13) = mass_(13, 6) = mr / 6.0;
}

void AncfBeam3d::SetReference(const Vec& e0) {
  const double* xi = nullptr;
  const double* w = nullptr;
  Vec d1;
  Mat d2;
  for (int rule = 0; rule < 2; ++rule) {
    const int np = rule == 0 ? order_.axial : order_.axial_full_points;
    GaussPoints01(np, xi, w);
    for (int g = 0; g < np; ++g) eps0_[rule][g] = AxialTerms(e0, xi[g], d1, d2);
  }
  GaussPoints01(order_.bending, xi, w);
  for (int g = 0; g < order_.bending; ++g) {
    const Strains s = StrainsAt(e0, xi[g]);
    for (int k = 0; k < 3; ++k) kap0_[g][k] = s(1 + k);
  }
}

AncfBeam3d::Vec3d AncfBeam3d::Position(const Vec& e, double xi) const {
  const auto S = line_.Shape(xi);
  Vec3d r = Vec3d::Zero();
  for (int i = 0; i < 12; ++i) r += S.col(i) * e(kBeam3dCableIndex[i]);
  return r;
}

AncfBeam3d::Mat3d AncfBeam3d::MinimalFrame(const Mat3d& R_0, const Vec3d& a) {
  const double la = a.norm();
  const Vec3d t0 = R_0.col(0);
  if (!(la > 0.0)) throw NumericalError("ANCF beam slope r' vanished");
  const Vec3d t = a / la;
  const double w = 1.0 + t0.dot(t);
  if (!(w > 1e-8)) throw NumericalError("ANCF beam slope turned against the reference direction");
  const Vec3d c = t0.cross(t);
  Mat3d C;
  C << 0.0, -c.z(), c.y(), c.z(), 0.0, -c.x(), -c.y(), c.x(), 0.0;
  return (Mat3d::Identity() + C + C * C / w) * R_0;
}

AncfBeam3d::Mat3d AncfBeam3d::FrameRate(const Vec3d& t0, const Vec3d& a) {
  const double la = a.norm();
  const Vec3d t = a / la;
  Mat3d T;
  T << 0.0, -t.z(), t.y(), t.z(), 0.0, -t.x(), -t.y(), t.x(), 0.0;
  return (Mat3d::Identity() - t * t0.transpose() / (1.0 + t0.dot(t))) * T / la;
}

AncfBeam3d::Mat3d AncfBeam3d::FrameRateDerivative(const Vec3d& t0, const Vec3d& a, const Vec3d& u) {
  return Beam3dJetGradient(Beam3dRateJet(t0, a, u, false));
}

AncfBeam3d::Mat3d AncfBeam3d::FrameRateTransposeDerivative(const Vec3d& t0, const Vec3d& a, const Vec3d& y) {
  return Beam3dJetGradient(Beam3dRateJet(t0, a, y, true));
}

AncfBeam3d::Mat3d AncfBeam3d::SectionFrame(const Vec& e, double xi) const {
  const auto Sx = line_.ShapeSlope(xi);
  Vec3d a = Vec3d::Zero();
  for (int i = 0; i < 12; ++i) a += Sx.col(i) * e(kBeam3dCableIndex[i]);
  const Mat3d D = MinimalFrame(R_0_, a);
  const double phi = (1.0 - xi) * e(6) + xi * e(13);
  const double c = std::cos(phi), s = std::sin(phi);
  Mat3d F;
  F.col(0) = D.col(0);
  F.col(1) = c * D.col(1) + s * D.col(2);
  F.col(2) = c * D.col(2) - s * D.col(1);
  return F;
}

AncfBeam3d::Strains AncfBeam3d::StrainsAt(const Vec& e, double xi) const {
  Vec d1;
  Mat d2;
  Strains s;
  s(0) = AxialTerms(e, xi, d1, d2);
  Eigen::Matrix<double, kDof, 3> g;
  Mat h[3];
  s.tail<3>() = CurvatureTerms(e, xi, g, h);
  return s;
}

double AncfBeam3d::AxialTerms(const Vec& e, double xi, Vec& d1, Mat& d2) const {
  const auto Sx = line_.ShapeSlope(xi);
  Eigen::Matrix<double, 3, kDof> B = Eigen::Matrix<double, 3, kDof>::Zero();
  for (int i = 0; i < 12; ++i) B.col(kBeam3dCableIndex[i]) = Sx.col(i);
  return AncfAxialStrainTerms<3, kDof>(section_.axial_strain, B, e, d1, d2);
}

AncfBeam3d::Vec3d AncfBeam3d::CurvatureTerms(const Vec& e, double xi, Eigen::Matrix<double, kDof, 3>& d1,
                                             Mat (*d2)[3]) const {
  const auto Sx = line_.ShapeSlope(xi);
  const auto Sxx = line_.ShapeCurvature(xi);
  Eigen::Matrix<double, 8, kDof> B = Eigen::Matrix<double, 8, kDof>::Zero();
  for (int i = 0; i < 12; ++i) {
    B.block<3, 1>(0, kBeam3dCableIndex[i]) = Sx.col(i);
    B.block<3, 1>(3, kBeam3dCableIndex[i]) = Sxx.col(i);
  }
  B(6, 6) = 1.0 - xi;
  B(6, 13) = xi;
  B(7, 6) = -1.0 / length_;
  B(7, 13) = 1.0 / length_;
  const Eigen::Matrix<double, 8, 1> z = B * e;
  Beam3dJet k[3];
  Beam3dCurvatureJets(z, R_0_, k);
  Vec3d out;
  for (int c = 0; c < 3; ++c) {
    out(c) = k[c].v;
    d1.col(c).noalias() = B.transpose() * k[c].g;
    if (d2) (*d2)[c].noalias() = B.transpose() * k[c].h * B;
  }
  return out;
}

void AncfBeam3d::AddStrainTerm(double stiffness, double strain, const Vec& d1, const Mat& d2, const Vec& edot,
                               Vec& Q, Mat& dQde, Mat& dQdedot) const {
  AddAncfStrainTerm<kDof>(stiffness, section_.damping, strain, d1, d2, edot, Q, dQde, dQdedot);
}

template <class F>
void AncfBeam3d::ForEachAxialPoint(F&& f) const {
  const double* xi = nullptr;
  const double* w = nullptr;
  const double EA = section_.E * section_.A * length_;
  for (int rule = 0; rule < 2; ++rule) {
    const int np = rule == 0 ? order_.axial : order_.axial_full_points;
    const double frac = rule == 0 ? 1.0 - axial_full_ : axial_full_;
    if (frac == 0.0) continue;
    GaussPoints01(np, xi, w);
    for (int g = 0; g < np; ++g) f(xi[g], frac * w[g] * EA, eps0_[rule][g]);
  }
}

double AncfBeam3d::StrainEnergy(const Vec& e) const {
  const double* xi = nullptr;
  const double* w = nullptr;
  Vec d1;
  Mat d2;
  double W = 0.0;
  ForEachAxialPoint([&](double x, double EAw, double eps0) {
    const double eps = AxialTerms(e, x, d1, d2) - eps0;
    W += 0.5 * EAw * eps * eps;
  });
  const double stiff[3] = {section_.G * section_.J, section_.E * section_.Iy, section_.E * section_.Iz};
  GaussPoints01(order_.bending, xi, w);
  for (int g = 0; g < order_.bending; ++g) {
    const Strains s = StrainsAt(e, xi[g]);
    for (int k = 0; k < 3; ++k) {
      const double d = s(1 + k) - kap0_[g][k];
      W += 0.5 * w[g] * length_ * stiff[k] * d * d;
    }
  }
  return W;
}

void AncfBeam3d::AddInternalForces(const Vec& e, const Vec& edot, Vec& Q, Mat& dQde, Mat& dQdedot) const {
  const double* xi = nullptr;
  const double* w = nullptr;
  Vec d1;
  Mat d2;
  ForEachAxialPoint([&](double x, double EAw, double eps0) {
    const double eps = AxialTerms(e, x, d1, d2) - eps0;
    AddStrainTerm(EAw, eps, d1, d2, edot, Q, dQde, dQdedot);
  });
  const double stiff[3] = {section_.G * section_.J, section_.E * section_.Iy, section_.E * section_.Iz};
  Eigen::Matrix<double, kDof, 3> g1;
  Mat g2[3];
  GaussPoints01(order_.bending, xi, w);
  for (int g = 0; g < order_.bending; ++g) {
    const Vec3d k = CurvatureTerms(e, xi[g], g1, g2);
    for (int c = 0; c < 3; ++c)
      AddStrainTerm(w[g] * length_ * stiff[c], k(c) - kap0_[g][c], g1.col(c), g2[c], edot, Q, dQde, dQdedot);
  }
}

void AncfBeam3d::AddInternalForceVector(const Vec& e, const Vec& edot, Vec& Q) const {
  const double beta = section_.damping;
  // Q -= k s ds/de (+ the Kelvin-Voigt term), as AddAncfStrainTerm without tangents
  auto add = [&](double k, double s, const auto& d1) {
    Q.noalias() -= (k * s) * d1;
    if (beta > 0.0) Q.noalias() -= (beta * k * d1.dot(edot)) * d1;
  };
  Vec d1;
  Mat d2;
  ForEachAxialPoint([&](double x, double EAw, double eps0) { add(EAw, AxialTerms(e, x, d1, d2) - eps0, d1); });
  const double stiff[3] = {section_.G * section_.J, section_.E * section_.Iy, section_.E * section_.Iz};
  const double* xi = nullptr;
  const double* w = nullptr;
  Eigen::Matrix<double, kDof, 3> g1;
  GaussPoints01(order_.bending, xi, w);
  for (int g = 0; g < order_.bending; ++g) {
    const Vec3d k = CurvatureTerms(e, xi[g], g1, nullptr);
    for (int c = 0; c < 3; ++c) add(w[g] * length_ * stiff[c], k(c) - kap0_[g][c], g1.col(c));
  }
}

AncfBeam3d::Vec AncfBeam3d::DistributedLoad(const Vec3d& f) const {
  const auto Qc = line_.DistributedLoad(f);
  Vec Q = Vec::Zero();
  for (int i = 0; i < 12; ++i) Q(kBeam3dCableIndex[i]) = Qc(i);
  return Q;
}

}  // namespace flexmb::ancf
