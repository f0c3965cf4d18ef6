// Tire force element: analytic pure-slip and vertical values, lift-off,
// the tangents K, C against independent finite differences, and the
// longitudinal relaxation (step in slip ratio on a rig against the
// first-order lag in travelled distance).
#include "flexmb/vehicle/tire.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flexmb/common/error.h"
#include "tests/unit/vehicle/tire_rig.h"
#include "tests/unit/vehicle/tire_test_data.h"

namespace flexmb::vehicle {
namespace {

// a twin set of 11R22.5 tires
TireData Truck() {
  TireData d = Tire11R22();
  d.count = 2;
  d.pdy2 = -0.1;
  return d;
}

// wheel centre marker: spin axis (z of the marker) along world +y
MarkerState Wheel(double z, const Vec3& v, double omega) {
  MarkerState m;
  m.p_WM = Vec3(1.0, 2.0, z);
  m.R_WM << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  m.v_WM = v;
  m.w_WM = Vec3(0, omega, 0);
  return m;
}

TEST(Tire, VerticalSpringDamperAndLiftOff) {
  const TireData d = Truck();
  const Tire tire("t", d, 0.8);
  TireContact c;
  const MarkerState m = Wheel(0.517, Vec3(0, 0, -0.1), 0.0);
  const Vec6 w = tire.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &c);
  // Fz = n (k d - c vz), d = 10 mm
  EXPECT_NEAR(c.deflection, 0.010, 1e-12);
  EXPECT_NEAR(w[2], 2 * (9e5 * 0.010 + 1.5e3 * 0.1), 1e-6);
  // lifted: centre above R0, no force at all
  const MarkerState up = Wheel(0.53, Vec3(3, 0, 0), 5.0);
  EXPECT_EQ(tire.Wrench(up.p_WM, up.R_WM, up.v_WM, up.w_WM, nullptr).norm(), 0.0);
  // in contact but separating fast: damper would pull, force clamped to zero
  const MarkerState fast = Wheel(0.526, Vec3(0, 0, 5.0), 0.0);
  EXPECT_EQ(tire.Wrench(fast.p_WM, fast.R_WM, fast.v_WM, fast.w_WM, nullptr)[2], 0.0);
}

TEST(Tire, PureLateralSlipFollowsMagicFormula) {
  TireData d = Truck();
  d.rolling_resistance = 0.0;
  d.trail = 0.0;
  const double mu = 0.8, V = 15.0, alpha = 2.0 * M_PI / 180;
  const Tire tire("t", d, mu);
  const double z = 0.527 - 0.011;
  const double re = d.unloaded_radius - d.rolling_radius_factor * 0.011;
  // free rolling with the centre sliding to +y: alpha = atan(vy / sqrt(V^2 + vlow^2))
  const double vref = std::sqrt(V * V + 1.0);
  const MarkerState m = Wheel(z, Vec3(V, vref * std::tan(alpha), 0), V / re);
  TireContact c;
  tire.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &c);
  // hand computation of MF 2002 (no shifts, lambda = 1)
  const double fz1 = 9e5 * 0.011, dfz = (fz1 - 25e3) / 25e3;
  const double D = mu * 1.0 * (1 - 0.1 * dfz) * fz1;
  const double Ky = 8.5 * 25e3 * std::sin(2 * std::atan(fz1 / (2.0 * 25e3)));
  const double B = Ky / (1.3 * D), E = -0.2;
  const double fy1 = -D * std::sin(1.3 * std::atan(B * alpha - E * (B * alpha - std::atan(B * alpha))));
  EXPECT_NEAR(c.alpha, alpha, 1e-12);
  EXPECT_NEAR(c.kappa, 0.0, 1e-12);
  EXPECT_NEAR(c.fy, 2 * fy1, 1e-6 * std::abs(fy1));
  EXPECT_NEAR(c.fx, 0.0, 1e-9);
}

TEST(Tire, CombinedSlipReducesLateralForce) {
  const Tire tire("t", Truck(), 0.8);
  const double z = 0.516, V = 15.0, re = 0.527 - 0.011 / 3.0;
  TireContact pure, combined;
  MarkerState m = Wheel(z, Vec3(V, 0.5, 0), V / re);
  tire.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &pure);
  m.w_WM.y() = 1.1 * V / re;  // driving slip ~ 0.1
  tire.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &combined);
  EXPECT_GT(combined.kappa, 0.05);
  EXPECT_GT(combined.fx, 0.0);
  EXPECT_LT(std::abs(combined.fy), 0.9 * std::abs(pure.fy));
}

// A wheel of the Truck() tire at 14 m/s with a lateral velocity of 0.8 m/s,
// steered by 0.1 rad and cambered by 0.02 rad, spinning at `spin` times the
// free-rolling rate (longitudinal slip) with a small yaw and roll rate:
// combined slip, so that every term of the wrench acts.
MarkerState SteeredCamberedWheel(double spin) {
  const double re = 0.527 - 0.012 / 3.0;
  MarkerState m = Wheel(0.515, Vec3(14.0, 0.8, -0.05), spin * 14.0 / re);
  m.R_WM = (Eigen::AngleAxisd(0.1, Vec3::UnitZ()) * Eigen::AngleAxisd(0.02, Vec3::UnitX())).toRotationMatrix() * m.R_WM;
  m.w_WM = m.R_WM.col(2) * spin * 14.0 / re + Vec3(0.01, 0.0, 0.2);
  return m;
}

// independent finite differences of the wrench, forward-backward with a
// different step and the rotation applied as a quaternion product
TEST(Tire, TangentsMatchFiniteDifferences) {
  const Tire tire("t", Truck(), 0.8);
  const MarkerState m = SteeredCamberedWheel(1.05);
  ForceEval e;
  tire.Evaluate(m, MarkerState{}, 0.0, e);
  const double h = 1e-5;
  Eigen::Matrix<double, 6, 6> K, C;
  for (int k = 0; k < 6; ++k) {
    MarkerState p = m, q = m;
    if (k < 3) {
      p.p_WM[k] += h;
      q.p_WM[k] -= h;
    } else {
      Vec3 th = Vec3::Zero();
      th[k - 3] = h;
      p.R_WM = (Eigen::Quaterniond(Eigen::AngleAxisd(h, th.normalized())) * Eigen::Quaterniond(m.R_WM)).toRotationMatrix();
      q.R_WM = (Eigen::Quaterniond(Eigen::AngleAxisd(-h, th.normalized())) * Eigen::Quaterniond(m.R_WM)).toRotationMatrix();
    }
    K.col(k) = (tire.Wrench(p.p_WM, p.R_WM, p.v_WM, p.w_WM, nullptr) - tire.Wrench(q.p_WM, q.R_WM, q.v_WM, q.w_WM, nullptr)) / (2 * h);
    MarkerState a = m, b = m;
    if (k < 3) {
      a.v_WM[k] += 1e-4;
      b.v_WM[k] -= 1e-4;
    } else {
      a.w_WM[k - 3] += 1e-4;
      b.w_WM[k - 3] -= 1e-4;
    }
    C.col(k) = (tire.Wrench(a.p_WM, a.R_WM, a.v_WM, a.w_WM, nullptr) - tire.Wrench(b.p_WM, b.R_WM, b.v_WM, b.w_WM, nullptr)) / 2e-4;
  }
  const Eigen::Matrix<double, 6, 6> Ke = e.K.topLeftCorner<6, 6>(), Ce = e.C.topLeftCorner<6, 6>();
  EXPECT_LT((Ke - K).norm(), 1e-5 * K.norm()) << "K\n" << Ke << "\nFD\n" << K;
  EXPECT_LT((Ce - C).norm(), 1e-5 * C.norm()) << "C\n" << Ce << "\nFD\n" << C;
  // j blocks of a single-marker element stay zero
  EXPECT_EQ(e.K.rightCols<6>().norm() + e.K.bottomRows<6>().norm(), 0.0);
  // analytic vertical entries: dFz/dz = -n k / cos(gamma) (rho = z / cos), dFz/dvz = -n c / cos
  const double cg = std::sqrt(1 - std::pow(m.R_WM.col(2).z(), 2));
  EXPECT_NEAR(Ke(2, 2), -2 * 9e5 / cg, 1e-3 * 2 * 9e5);
  EXPECT_NEAR(Ce(2, 2), -2 * 1.5e3 / cg, 1e-3 * 2 * 1.5e3);
}

// The tangents are exact (forward-mode AD), not differences: Richardson
// extrapolation of central differences, (4 D(h/2) - D(h)) / 3 with an
// O(h^4) error (h = 1e-4 pose, 1e-3 twist), agrees with them to 1e-11 of
// the block's norm (measured 1.8e-12 and 9.7e-13; the former central
// differences of the element: 6e-11 and 5e-11), in combined slip with
// camber, steer and a yaw rate, so that every term of the wrench acts.
TEST(Tire, TangentsAreExactToRichardsonDifferences) {
  TireData d = Truck();
  d.rolling_resistance = 0.006;
  const Tire tire("t", d, 0.8);
  const MarkerState m = SteeredCamberedWheel(1.08);
  ForceEval e;
  tire.Evaluate(m, MarkerState{}, 0.0, e);
  // wrench with variation k (0-5 pose: dp, dtheta applied as a quaternion
  // product; 6-11 twist: v, w) of size h
  auto wrench = [&](int k, double h) {
    MarkerState x = m;
    if (k < 3) x.p_WM[k] += h;
    else if (k < 6) x.R_WM = (Eigen::Quaterniond(Eigen::AngleAxisd(h, Vec3::Unit(k - 3))) * Eigen::Quaterniond(m.R_WM)).toRotationMatrix();
    else if (k < 9) x.v_WM[k - 6] += h;
    else x.w_WM[k - 9] += h;
    return tire.Wrench(x.p_WM, x.R_WM, x.v_WM, x.w_WM, nullptr);
  };
  auto central = [&](int k, double h) -> Vec6 { return (wrench(k, h) - wrench(k, -h)) / (2 * h); };
  Eigen::Matrix<double, 6, 12> fd;
  for (int k = 0; k < 12; ++k) {
    const double h = k < 6 ? 1e-4 : 1e-3;
    fd.col(k) = (4 * central(k, 0.5 * h) - central(k, h)) / 3;
  }
  const Eigen::Matrix<double, 6, 6> K = e.K.topLeftCorner<6, 6>(), C = e.C.topLeftCorner<6, 6>();
  EXPECT_LT((K - fd.leftCols<6>()).norm(), 1e-11 * K.norm()) << "K\n" << K << "\nRichardson\n" << fd.leftCols<6>();
  EXPECT_LT((C - fd.rightCols<6>()).norm(), 1e-11 * C.norm()) << "C\n" << C << "\nRichardson\n" << fd.rightCols<6>();
}

// Rolling resistance is a moment against the spin, f_r Fz rho tanh(Vx / 0.5)
// (rho the loaded radius), with no force: a free-rolling wheel balances it by
// a retarding slip force f_r Fz.
TEST(Tire, RollingResistanceIsAMomentAgainstTheSpin) {
  TireData d = Truck();
  d.rolling_resistance = 0.006;
  d.vertical_damping = 0.0;
  const Tire tire("t", d, 0.8);
  const double rho = 0.515, re = 0.527 - 0.012 / 3.0;
  const MarkerState m = Wheel(rho, Vec3(10.0, 0, 0), 10.0 / re);
  TireContact c;
  const Vec6 w = tire.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &c);
  const double fz = 2 * 9e5 * 0.012;
  EXPECT_NEAR(c.fz, fz, 1e-6);
  EXPECT_NEAR(w[0], 0.0, 1e-9);
  EXPECT_NEAR(w.tail<3>().dot(m.R_WM.col(2)), -0.006 * fz * rho * std::tanh(10.0 / 0.5), 1e-9);
}

// Relaxed tire (contact-patch carcass model): with the patch not sliding
// (v_j = v) the slip is the wheel's, so the resultant force of the wheel and
// patch wrenches is the stateless tire's for any patch offset, and so is the
// sum of their moments (the patch's about its own marker: the slip force
// acts at the contact point carried along by the patch); the carcass spring is count * Ky(Fz0) / sigma0 with
// Ky(Fz0) = pky1 Fz0 sin(2 atan(1 / pky2)) = 8.5 * 25 kN * 0.8.
TEST(Tire, RelaxedPatchAtRestMatchesStatelessResultant) {
  TireData d = Truck();
  const Tire stateless("s", d, 0.8);
  d.relaxation_length = 0.6;
  const Tire relaxed("r", d, 0.8);
  EXPECT_NEAR(relaxed.carcass_stiffness(), 2 * 8.5 * 25e3 * 0.8 / 0.6, 1e-6);
  const double re = 0.527 - 0.012 / 3.0;
  MarkerState m = Wheel(0.515, Vec3(14.0, 0.8, -0.05), 1.02 * 14.0 / re);
  m.R_WM = Eigen::AngleAxisd(0.05, Vec3::UnitZ()).toRotationMatrix() * m.R_WM;
  m.w_WM = m.R_WM.col(2) * 1.02 * 14.0 / re;
  const Vec3 a = m.R_WM.col(2), pj = m.p_WM + 0.004 * a;
  TireContact cs, cr;
  const Vec6 ws = stateless.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &cs);
  const Vec12 wr = relaxed.RelaxedWrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, pj, m.v_WM, &cr);
  const Vec3 f = wr.segment<3>(0) + wr.segment<3>(6);
  const Vec3 mom = wr.segment<3>(3) + wr.segment<3>(9);
  EXPECT_LT((f - ws.head<3>()).norm(), 1e-9 * ws.head<3>().norm());
  EXPECT_LT((mom - ws.tail<3>()).norm(), 1e-9 * ws.tail<3>().norm());
  EXPECT_NEAR(cr.fy, cs.fy, 1e-9 * std::abs(cs.fy));
  // the wheel feels the carcass spring, not the slip force
  const Vec3 yt = Vec3::UnitZ().cross(a.cross(Vec3::UnitZ()).normalized());
  EXPECT_NEAR(cr.fy_wheel, relaxed.carcass_stiffness() * 0.004 * a.dot(yt), 1e-6);
  EXPECT_EQ(cs.fy_wheel, cs.fy);
  // a sliding patch slips less: v_j - v along -Vsy cancels the slip force
  const double vsy = m.v_WM.dot(yt);
  TireContact c0;
  relaxed.RelaxedWrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, pj, m.v_WM - vsy * yt, &c0);
  EXPECT_NEAR(c0.fy, 0.0, 1e-9 * std::abs(cs.fy));
  // wrong marker count for the element's kind
  ForceEval e;
  EXPECT_THROW(relaxed.Evaluate(m, MarkerState{}, 0.0, e), InputError);
  EXPECT_THROW(stateless.RelaxedWrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, pj, m.v_WM, nullptr), InputError);
}

// Tangents of the relaxed tire (two markers) against independent central
// differences of RelaxedWrench with another step; the patch's rotation does
// not enter. `pj_offset`: patch position relative to the wheel centre.
void TireCheckRelaxedTangents(const TireData& d, const Vec3& pj_offset, const Vec3& vj_offset, ForceEval& e) {
  Tire tire("t", d, 0.8);
  tire.marker_i = 0;
  tire.marker_j = 1;
  const double re = 0.527 - 0.012 / 3.0;
  MarkerState m = Wheel(0.515, Vec3(14.0, 0.8, -0.05), 1.05 * 14.0 / re);
  m.R_WM = (Eigen::AngleAxisd(0.1, Vec3::UnitZ()) * Eigen::AngleAxisd(0.02, Vec3::UnitX())).toRotationMatrix() * m.R_WM;
  m.w_WM = m.R_WM.col(2) * 1.05 * 14.0 / re + Vec3(0.01, 0.0, 0.2);
  MarkerState pm = m;
  pm.p_WM = m.p_WM + m.R_WM * pj_offset;
  pm.v_WM = m.v_WM + m.R_WM * vj_offset;
  tire.Evaluate(m, pm, 0.0, e);
  auto W = [&](const MarkerState& i, const MarkerState& j) {
    return tire.RelaxedWrench(i.p_WM, i.R_WM, i.v_WM, i.w_WM, j.p_WM, j.v_WM, nullptr);
  };
  EXPECT_EQ((e.wrench - W(m, pm)).norm(), 0.0);
  const double h = 1e-5, hv = 1e-4;
  Mat12 K = Mat12::Zero(), C = Mat12::Zero();
  for (int k = 0; k < 9; ++k) {
    MarkerState ip = m, im = m, jp = pm, jm = pm;
    if (k < 3) {
      ip.p_WM[k] += h;
      im.p_WM[k] -= h;
    } else if (k < 6) {
      Vec3 th = Vec3::Zero();
      th[k - 3] = 1.0;
      ip.R_WM = (Eigen::Quaterniond(Eigen::AngleAxisd(h, th)) * Eigen::Quaterniond(m.R_WM)).toRotationMatrix();
      im.R_WM = (Eigen::Quaterniond(Eigen::AngleAxisd(-h, th)) * Eigen::Quaterniond(m.R_WM)).toRotationMatrix();
    } else {
      jp.p_WM[k - 6] += h;
      jm.p_WM[k - 6] -= h;
    }
    K.col(k) = (W(ip, jp) - W(im, jm)) / (2 * h);
    MarkerState ia = m, ib = m, ja = pm, jb = pm;
    if (k < 3) {
      ia.v_WM[k] += hv;
      ib.v_WM[k] -= hv;
    } else if (k < 6) {
      ia.w_WM[k - 3] += hv;
      ib.w_WM[k - 3] -= hv;
    } else {
      ja.v_WM[k - 6] += hv;
      jb.v_WM[k - 6] -= hv;
    }
    C.col(k) = (W(ia, ja) - W(ib, jb)) / (2 * hv);
  }
  EXPECT_LT((e.K - K).norm(), 1e-5 * K.norm()) << "K\n" << e.K << "\nFD\n" << K;
  EXPECT_LT((e.C - C).norm(), 1e-5 * C.norm()) << "C\n" << e.C << "\nFD\n" << C;
  EXPECT_EQ(e.K.rightCols<3>().norm() + e.C.rightCols<3>().norm(), 0.0);
}

TEST(Tire, RelaxedTangentsMatchFiniteDifferences) {
  TireData d = Truck();
  d.relaxation_length = 0.6;
  ForceEval e;
  TireCheckRelaxedTangents(d, Vec3(0, 0, 0.003), Vec3(0, 0, -0.3), e);
  // the carcass spring's block: d f_j / d p_j = -k_y I
  const double ky = 2 * 8.5 * 25e3 * 0.8 / 0.6;
  EXPECT_NEAR(e.K(6, 6), -ky, 1e-4 * ky);
}

// Longitudinally relaxed tire: the patch displaced along x_t and y_t and
// sliding in both directions; the spring block d f_j / d p_j is
// -(k_y I + (k_x - k_y) x_t x_t^T), analytic.
TEST(Tire, LongitudinallyRelaxedTangentsMatchFiniteDifferences) {
  TireData d = Truck();
  d.relaxation_length = 0.6;
  d.longitudinal_relaxation_length = 0.3;
  ForceEval e;
  // marker frame of Wheel(): x forward, z the spin axis
  TireCheckRelaxedTangents(d, Vec3(-0.006, 0, 0.003), Vec3(0.2, 0, -0.3), e);
  const double ky = 2 * 8.5 * 25e3 * 0.8 / 0.6, kx = 2 * 15.0 * 25e3 / 0.3;
  const Vec3 a = (Eigen::AngleAxisd(0.1, Vec3::UnitZ()) * Eigen::AngleAxisd(0.02, Vec3::UnitX())) * Vec3::UnitY();
  const Vec3 xt = a.cross(Vec3::UnitZ()).normalized();
  const Mat3 Kjj = e.K.block<3, 3>(6, 6);
  const Mat3 ref = -(ky * Mat3::Identity() + (kx - ky) * xt * xt.transpose());
  EXPECT_LT((Kjj - ref).norm(), 1e-4 * kx) << Kjj << "\nref\n" << ref;
}

TEST(Tire, RejectsBadData) {
  TireData d = Truck();
  d.pky1 = -1;
  EXPECT_THROW(Tire("t", d, 0.8), InputError);
  EXPECT_THROW(Tire("t", Truck(), 0.0), InputError);
  d = Truck();
  d.relaxation_length = -0.1;
  EXPECT_THROW(Tire("t", d, 0.8), InputError);
  d.relaxation_length = 0.5;
  d.patch_mass = 0.0;
  EXPECT_THROW(Tire("t", d, 0.8), InputError);
  d = Truck();
  d.longitudinal_relaxation_length = -0.1;
  EXPECT_THROW(Tire("t", d, 0.8), InputError);
  // longitudinal relaxation needs the patch body of the lateral one
  d.longitudinal_relaxation_length = 0.3;
  EXPECT_THROW(Tire("t", d, 0.8), InputError);
  d.relaxation_length = 0.6;
  EXPECT_NO_THROW(Tire("t", d, 0.8));
}

// Longitudinally relaxed tire with the patch not sliding (v_j = v): the slip
// is the wheel's, so the resultant force of wheel and patch is the stateless
// tire's, and the moments about the wheel centre add up to the stateless
// moment plus u x (slip force) (the slip force acts at the contact point
// carried along by the patch, u = p_j - p). The wheel feels the carcass
// spring k_x (u . x_t) along x_t, k_x = count pkx1 Fz0 / sigma_kappa0, with
// the lever of the contact point (spin moment rho S_x, as for the slip force
// of the stateless tire); a patch sliding at (v_j - v) . x_t = -Vsx has no
// longitudinal slip.
TEST(Tire, LongitudinallyRelaxedPatchAtRestMatchesStatelessResultant) {
  TireData d = Truck();
  d.rolling_resistance = 0.0;
  const Tire stateless("s", d, 0.8);
  d.relaxation_length = 0.6;
  d.longitudinal_relaxation_length = 0.3;
  const Tire relaxed("r", d, 0.8);
  const double kx = 2 * 15.0 * 25e3 / 0.3;
  EXPECT_NEAR(relaxed.longitudinal_carcass_stiffness(), kx, 1e-6);
  const double re = 0.527 - 0.012 / 3.0;
  MarkerState m = Wheel(0.515, Vec3(14.0, 0.8, 0.0), 0.97 * 14.0 / re);
  m.R_WM = Eigen::AngleAxisd(0.05, Vec3::UnitZ()).toRotationMatrix() * m.R_WM;
  m.w_WM = m.R_WM.col(2) * 0.97 * 14.0 / re;
  const Vec3 a = m.R_WM.col(2);
  const Vec3 xt = a.cross(Vec3::UnitZ()).normalized(), yt = Vec3::UnitZ().cross(xt);
  const Vec3 u = -0.008 * xt + 0.004 * a;
  TireContact cs, cr;
  const Vec6 ws = stateless.Wrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, &cs);
  const Vec12 wr = relaxed.RelaxedWrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, m.p_WM + u, m.v_WM, &cr);
  ASSERT_LT(cs.kappa, -0.02);
  const Vec3 f = wr.segment<3>(0) + wr.segment<3>(6);
  const Vec3 mom = wr.segment<3>(3) + wr.segment<3>(9) + u.cross(wr.segment<3>(6));
  const Vec3 fs = cs.fx * xt + cs.fy * yt;
  EXPECT_LT((f - ws.head<3>()).norm(), 1e-9 * ws.head<3>().norm());
  EXPECT_LT((mom - ws.tail<3>() - u.cross(fs)).norm(), 1e-9 * ws.tail<3>().norm());
  EXPECT_NEAR(cr.fx, cs.fx, 1e-9 * std::abs(cs.fx));
  EXPECT_NEAR(cr.fy, cs.fy, 1e-9 * std::abs(cs.fy));
  // the wheel feels the spring: k_x u_x along x_t, spin moment rho k_x u_x
  EXPECT_NEAR(cr.fx_wheel, kx * -0.008, 1e-6);
  EXPECT_NEAR(cr.fy_wheel, relaxed.carcass_stiffness() * 0.004 * a.dot(yt), 1e-6);
  // (a backward force at the contact point drives the spin: moment +rho |S_x| a)
  EXPECT_NEAR(wr.segment<3>(3).dot(a), 0.515 * kx * 0.008, 1e-6 * 0.515 * kx * 0.008);
  EXPECT_EQ(cs.fx_wheel, cs.fx);
  // the spring pair alone conserves angular momentum: total moment about the
  // world origin of the wheel and patch wrenches equals that of the slip and
  // vertical forces at their points
  const Vec3 pj = m.p_WM + u;
  const Vec3 l_total =
      m.p_WM.cross(wr.segment<3>(0)) + wr.segment<3>(3) + pj.cross(wr.segment<3>(6)) + wr.segment<3>(9);
  const Vec3 c = cr.contact_W;
  const double trail = 0.04 * std::cos(std::atan(8.0 * cr.alpha));
  const Vec3 l_ref = c.cross(cr.fz * Vec3::UnitZ()) + (c + u).cross(fs) -
                     trail * cr.fy * std::tanh(m.v_WM.dot(xt) / 0.5) * Vec3::UnitZ();
  EXPECT_LT((l_total - l_ref).norm(), 1e-9 * l_ref.norm());
  // a patch sliding back at -Vsx cancels the longitudinal slip
  const double vsx = m.v_WM.dot(xt) - re * m.w_WM.dot(a);
  TireContact c0;
  relaxed.RelaxedWrench(m.p_WM, m.R_WM, m.v_WM, m.w_WM, pj, m.v_WM - vsx * xt, &c0);
  EXPECT_NEAR(c0.kappa, 0.0, 1e-12);
  EXPECT_NEAR(c0.fx, 0.0, 1e-9 * std::abs(cs.fx));
}

// one 11R22.5 tire on the rig (lateral relaxation 0.6 m), longitudinal
// pure-slip coefficients and relaxation length sigma_kappa
TireData TireLongRigData(double sigma_kappa) {
  TireData d = Tire11R22Rig(0.6);
  d.pdx1 = 1.0;
  d.pkx1 = 15.0;
  d.longitudinal_relaxation_length = sigma_kappa;
  return d;
}

// Step in slip ratio kappa0 = -0.002 (braking) at 10 m/s, sigma_kappa = 0.3 m.
// Reference: the single-contact-point transient model (Pacejka, Tire and
// Vehicle Dynamics, 3rd ed., sec. 7.2.1) in the longitudinal direction,
// patch mass neglected: sigma_kappa dFx/dx + Fx = Fx_ss with sigma_kappa =
// Kx / k_x, so Fx(x) = Fx_ss (1 - exp(-x / sigma_kappa)). Deviations: the patch
// mass (relative m V^2 / (Kx sigma_kappa) = 4e-4), the Magic Formula's
// curvature at Bx kappa = 0.018 (~2e-4), the slip regularisation (5e-5) and
// the time step (1 ms against sigma_kappa / V = 30 ms). Tolerance 3e-3 of
// Fx_ss; an error of 2 % in sigma_kappa would show as 7e-3.
TEST(Tire, LongitudinalSlipStepFollowsFirstOrderLagInDistance) {
  const double sigma = 0.3, V = 10.0, kappa0 = -0.002;
  // straight ahead (psi = 0), spin prescribed at the slip ratio kappa0
  const TireRigRun run = RunTireStepRig(TireLongRigData(sigma), V, 0.0, kappa0, 5 * sigma / V, 1e-3);
  const double fss = run.fx_steady;
  const std::vector<TireRigSample>& s = run.samples;
  ASSERT_LT(fss, -500.0);
  ASSERT_GT(s.size(), 140u);
  EXPECT_NEAR(s.front().fx_wheel, 0.0, 1e-9 * std::abs(fss));
  double worst = 0.0, x63 = 0.0;
  const double target = 1.0 - std::exp(-1.0);
  for (size_t k = 0; k < s.size(); ++k) {
    const double ref = fss * (1.0 - std::exp(-s[k].x / sigma));
    worst = std::max(worst, std::abs(s[k].fx_wheel - ref) / std::abs(fss));
    if (k == 0) continue;
    const double f0 = s[k - 1].fx_wheel / fss, f1 = s[k].fx_wheel / fss;
    if (f0 < target && f1 >= target) x63 = s[k - 1].x + (target - f0) / (f1 - f0) * (s[k].x - s[k - 1].x);
  }
  EXPECT_LT(worst, 3e-3);
  // the distance to 63.2 % of the steady force is sigma_kappa (2 %)
  EXPECT_NEAR(x63, sigma, 0.02 * sigma);
}

// asked for the wrench only (ForceEval::tangents false, residual
// evaluations with a kept iteration matrix): the same wrench as with
// tangents, K and C left as they were
TEST(TireWrenchOnly, SameWrenchAsWithTangentsAndTangentsUntouched) {
  const Tire tire("t", Truck(), 0.8);
  // rolling at 15 m/s with 3 degrees of slip angle and some longitudinal slip
  MarkerState m;
  m.p_WM = Vec3(1.0, 2.0, 0.515);
  m.R_WM << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  m.v_WM = Vec3(15.0, 15.0 * std::tan(3.0 * M_PI / 180), 0.0);
  m.w_WM = Vec3(0, 15.0 / 0.51, 0);
  ForceEval full;
  tire.Evaluate(m, MarkerState{}, 0.0, full);
  ASSERT_GT(full.wrench.head<3>().norm(), 1e3);
  ASSERT_GT(full.K.norm(), 0.0);
  ForceEval only;
  only.tangents = false;
  only.K.setConstant(7.0);
  only.C.setConstant(-3.0);
  tire.Evaluate(m, MarkerState{}, 0.0, only);
  EXPECT_EQ((only.wrench - full.wrench).norm(), 0.0);
  EXPECT_EQ(only.K, Mat12::Constant(7.0));
  EXPECT_EQ(only.C, Mat12::Constant(-3.0));
}

}  // namespace
}  // namespace flexmb::vehicle
