#include "flexmb/fe/laminate.h"

#include <cmath>

namespace flexmb::fe {

Eigen::Matrix3d IsotropicPlaneStress(double E, double nu) {
  Eigen::Matrix3d q;
  q << 1.0, nu, 0.0, nu, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - nu);
  return q * (E / (1.0 - nu * nu));
}

Eigen::Matrix3d OrthotropicPlaneStress(double E1, double E2, double nu12, double G12) {
  const double nu21 = nu12 * E2 / E1, d = 1.0 - nu12 * nu21;
  Eigen::Matrix3d q = Eigen::Matrix3d::Zero();
  q(0, 0) = E1 / d;
  q(1, 1) = E2 / d;
  q(0, 1) = q(1, 0) = nu12 * E2 / d;
  q(2, 2) = G12;
  return q;
}

Eigen::Matrix3d RotatePlaneStress(const Eigen::Matrix3d& q, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  // strains in the rotated axes from (exx, eyy, gxy)
  Eigen::Matrix3d t;
  t << c * c, s * s, c * s, s * s, c * c, -c * s, -2.0 * c * s, 2.0 * c * s, c * c - s * s;
  return t.transpose() * q * t;
}

Eigen::Matrix2d RotateShear(const Eigen::Matrix2d& s, double theta) {
  const double c = std::cos(theta), sn = std::sin(theta);
  Eigen::Matrix2d r;
  r << c, sn, -sn, c;
  return r.transpose() * s * r;
}

ShellLaminate StackPlies(const std::vector<LaminatePly>& plies, double z0) {
  ShellLaminate l;
  double z = z0;
  l.z_bottom = z0;
  for (size_t k = 0; k < plies.size(); ++k) {
    const LaminatePly& p = plies[k];
    const double zb = z, zt = z + p.t;
    const Eigen::Matrix3d q = RotatePlaneStress(p.q, p.theta);
    l.A += q * (zt - zb);
    l.B += q * (0.5 * (zt * zt - zb * zb));
    l.D += q * ((zt * zt * zt - zb * zb * zb) / 3.0);
    Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
    g(0, 0) = p.g13;
    g(1, 1) = p.g23;
    l.S += RotateShear(g, p.theta) * (5.0 / 6.0 * p.t);
    l.mass += p.rho * p.t;
    l.rotary += p.rho * (zt * zt * zt - zb * zb * zb) / 3.0;
    l.thickness += p.t;
    if (k == 0) l.q_bottom = l.qb_bottom = q;
    if (k + 1 == plies.size()) l.q_top = l.qb_top = q;
    z = zt;
  }
  l.z_top = z;
  return l;
}

ShellLaminate MembraneLaminate(const Eigen::Matrix3d& q, double rho, double t, const std::string& card) {
  ShellLaminate l;
  l.A = q * t;
  l.mass = rho * t;
  l.thickness = t;
  l.z_bottom = -0.5 * t;
  l.z_top = 0.5 * t;
  l.q_bottom = l.q_top = q;
  l.card = card;
  l.membrane_only = true;
  return l;
}

ShellLaminate InElementAxes(const ShellLaminate& l, double theta) {
  ShellLaminate r = l;
  r.A = RotatePlaneStress(l.A, theta);
  r.B = RotatePlaneStress(l.B, theta);
  r.D = RotatePlaneStress(l.D, theta);
  r.S = RotateShear(l.S, theta);
  r.q_bottom = RotatePlaneStress(l.q_bottom, theta);
  r.q_top = RotatePlaneStress(l.q_top, theta);
  r.qb_bottom = RotatePlaneStress(l.qb_bottom, theta);
  r.qb_top = RotatePlaneStress(l.qb_top, theta);
  return r;
}

}  // namespace flexmb::fe
