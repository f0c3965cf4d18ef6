#include "flexmb/forces/bushing.h"

#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb {

Bushing::Bushing(std::string name, const BushingData& data) : ForceElement(std::move(name)), data_(data) {
  const ErrorContext ctx{"", 0, "force '" + this->name() + "'"};
  auto check = [&](const Vec3& v, const char* what) {
    if (!v.allFinite() || v.minCoeff() < 0.0)
      throw InputError(std::string(what) + " entries must be finite and >= 0", ctx);
  };
  check(data_.translational_stiffness, "translational_stiffness");
  check(data_.rotational_stiffness, "rotational_stiffness");
  check(data_.translational_damping, "translational_damping");
  check(data_.rotational_damping, "rotational_damping");
  if (!data_.preload_force.allFinite() || !data_.preload_torque.allFinite())
    throw InputError("preload entries must be finite", ctx);
}

void Bushing::Evaluate(const MarkerState& mi, const MarkerState& mj, double, ForceEval& e) const {
  const Mat3& Ri = mi.R_WM;
  const Mat3 Rit = Ri.transpose();
  const Vec3 d = mj.p_WM - mi.p_WM;
  const Vec3 di = Rit * d;
  const Vec3 s = mj.v_WM - mi.v_WM - mi.w_WM.cross(d);
  const Vec3 di_dot = Rit * s;
  const Vec3 phi = LogSO3(Rit * mj.R_WM);
  const Vec3 wrel = mj.w_WM - mi.w_WM;
  const Vec3 wrel_i = Rit * wrel;
  const auto Kt = data_.translational_stiffness.asDiagonal();
  const auto Ct = data_.translational_damping.asDiagonal();
  const auto Kr = data_.rotational_stiffness.asDiagonal();
  const auto Cr = data_.rotational_damping.asDiagonal();

  const Vec3 fj = Ri * (data_.preload_force - Kt * di - Ct * di_dot);
  const Vec3 mj_ = Ri * (data_.preload_torque - Kr * phi - Cr * wrel_i);
  const Mat3 Sd = Skew(d), Sf = Skew(fj);
  e.wrench.segment<3>(0) = -fj;
  e.wrench.segment<3>(3) = -mj_ - d.cross(fj);
  e.wrench.segment<3>(6) = fj;
  e.wrench.segment<3>(9) = mj_;

  // dphi = Gamma (dth_j - dth_i) with Gamma = T(phi)^-1 R_j^T
  const Mat3 Gamma = TangentSO3(phi).inverse() * mj.R_WM.transpose();
  const Mat3 RKt = Ri * Kt, RCt = Ri * Ct, RKr = Ri * Kr, RCr = Ri * Cr;
  // rows of f_j and m_j; columns dp_i, dth_i, dp_j, dth_j. d(R_i a) = -skew(R_i a) dth_i
  auto Fj = e.K.block<3, 12>(6, 0);
  auto Mj = e.K.block<3, 12>(9, 0);
  Fj.block<3, 3>(0, 0) = RKt * Rit - RCt * Rit * Skew(mi.w_WM);
  Fj.block<3, 3>(0, 3) = -RKt * Rit * Sd - RCt * Rit * Skew(s) - Sf;
  Fj.block<3, 3>(0, 6) = -Fj.block<3, 3>(0, 0);
  Fj.block<3, 3>(0, 9).setZero();
  Mj.block<3, 3>(0, 0).setZero();
  Mj.block<3, 3>(0, 3) = RKr * Gamma - RCr * Rit * Skew(wrel) - Skew(mj_);
  Mj.block<3, 3>(0, 6).setZero();
  Mj.block<3, 3>(0, 9) = -RKr * Gamma;
  // reactions: f_i = -f_j, m_i = -m_j - skew(d) f_j, with d(d) = dp_j - dp_i
  e.K.block<3, 12>(0, 0) = -Fj;
  e.K.block<3, 12>(3, 0) = -Mj - Sd * Fj;
  e.K.block<3, 3>(3, 0) -= Sf;
  e.K.block<3, 3>(3, 6) += Sf;

  auto Fc = e.C.block<3, 12>(6, 0);
  auto Mc = e.C.block<3, 12>(9, 0);
  const Mat3 Ctw = RCt * Rit;
  Fc.block<3, 3>(0, 0) = Ctw;
  Fc.block<3, 3>(0, 3) = -Ctw * Sd;
  Fc.block<3, 3>(0, 6) = -Ctw;
  Fc.block<3, 3>(0, 9).setZero();
  const Mat3 Crw = RCr * Rit;
  Mc.block<3, 3>(0, 0).setZero();
  Mc.block<3, 3>(0, 3) = Crw;
  Mc.block<3, 3>(0, 6).setZero();
  Mc.block<3, 3>(0, 9) = -Crw;
  e.C.block<3, 12>(0, 0) = -Fc;
  e.C.block<3, 12>(3, 0) = -Mc - Sd * Fc;
}

double Bushing::PotentialEnergy(const MarkerState& mi, const MarkerState& mj, double) const {
  const Mat3 Rit = mi.R_WM.transpose();
  const Vec3 di = Rit * (mj.p_WM - mi.p_WM);
  const Vec3 phi = LogSO3(Rit * mj.R_WM);
  return 0.5 * di.dot(data_.translational_stiffness.cwiseProduct(di)) +
         0.5 * phi.dot(data_.rotational_stiffness.cwiseProduct(phi)) - data_.preload_force.dot(di) -
         data_.preload_torque.dot(phi);
}

}  // namespace flexmb
