#pragma once
/// \file line_force.h
/// Wrench and tangents of a force acting along the line between two marker
/// origins (spring-damper, rope): the shared kinematics of such elements.

#include "flexmb/forces/force_element.h"

namespace flexmb {

/// Fills e (all of wrench, K and C) for a tension F [N] acting along the
/// unit direction u = d / l, d = p_j - p_i, l = |d| [m]: +F u on marker i,
/// -F u on marker j, no moments. dFdl [N/m] and dFdv [N s/m] are the
/// derivatives of F with respect to the length l and its rate
/// ldot = u . vrel, vrel = v_j - v_i [m/s].
inline void SetLineForce(const Vec3& u, double l, const Vec3& vrel, double F, double dFdl, double dFdv,
                         ForceEval& e) {
  e.wrench.setZero();
  e.wrench.segment<3>(0) = F * u;
  e.wrench.segment<3>(6) = -F * u;
  // d(F u)/dd with du/dd = P / l and dldot/dd = P vrel / l, P = I - u u^T
  const Mat3 P = (Mat3::Identity() - u * u.transpose()) / l;
  const Vec3 dFdd = dFdl * u + dFdv * (P * vrel);
  const Mat3 A = u * dFdd.transpose() + F * P;
  const Mat3 Cv = dFdv * u * u.transpose();  // d(F u)/dvrel
  e.K.setZero();
  e.K.block<3, 3>(0, 0) = -A;
  e.K.block<3, 3>(0, 6) = A;
  e.K.block<3, 3>(6, 0) = A;
  e.K.block<3, 3>(6, 6) = -A;
  e.C.setZero();
  e.C.block<3, 3>(0, 0) = -Cv;
  e.C.block<3, 3>(0, 6) = Cv;
  e.C.block<3, 3>(6, 0) = Cv;
  e.C.block<3, 3>(6, 6) = -Cv;
}

}  // namespace flexmb
