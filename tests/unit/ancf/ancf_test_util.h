#pragma once
// Fixtures shared by the ANCF element and body unit tests: sections, the
// element force at a state, central-difference checks of the element
// tangents and of the force against the strain-energy gradient, and of a
// body's marker kinematics and force tangents; model-file error checks.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>

#include "flexmb/ancf/line_element.h"
#include "flexmb/bodies/body.h"
#include "flexmb/common/error.h"
#include "flexmb/model_file/model_file.h"
#include "flexmb/math/rotation.h"

namespace flexmb::ancf::test_util {

/// A section with the given E [Pa], A [m^2], I [m^4], rho [kg/m^3], damping [s].
inline BeamSection MakeSection(double E, double A, double I, double rho, double damping) {
  BeamSection s;
  s.E = E;
  s.A = A;
  s.I = I;
  s.rho = rho;
  s.damping = damping;
  return s;
}

/// Elastic and damping force of element `el` at (e, edot).
template <class El>
typename El::Vec Forces(const El& el, const typename El::Vec& e, const typename El::Vec& edot) {
  typename El::Vec Q = El::Vec::Zero();
  typename El::Mat K = El::Mat::Zero(), C = El::Mat::Zero();
  el.AddInternalForces(e, edot, Q, K, C);
  return Q;
}

/// Checks dQ/de and dQ/dedot of `el` at (e, edot) against central
/// differences (relative 1e-6); returns dQ/de.
template <class El>
typename El::Mat ExpectTangentsMatchCentralDifferences(const El& el, const typename El::Vec& e,
                                                       const typename El::Vec& edot) {
  using Vec = typename El::Vec;
  using Mat = typename El::Mat;
  Vec Q = Vec::Zero();
  Mat K = Mat::Zero(), C = Mat::Zero();
  el.AddInternalForces(e, edot, Q, K, C);
  const double h = 1e-6;
  Mat Kfd, Cfd;
  for (int j = 0; j < El::kDof; ++j) {
    Vec ep = e, em = e, vp = edot, vm = edot;
    ep(j) += h;
    em(j) -= h;
    vp(j) += h;
    vm(j) -= h;
    Kfd.col(j) = (Forces(el, ep, edot) - Forces(el, em, edot)) / (2 * h);
    Cfd.col(j) = (Forces(el, e, vp) - Forces(el, e, vm)) / (2 * h);
  }
  EXPECT_LT((K - Kfd).norm(), 1e-6 * K.norm());
  EXPECT_LT((C - Cfd).norm(), 1e-6 * C.norm());
  return K;
}

/// Checks that the elastic force (no velocity) of `el` at e is minus the
/// central-difference gradient of its strain energy (relative 1e-6).
template <class El>
void ExpectForceIsMinusEnergyGradient(const El& el, const typename El::Vec& e) {
  using Vec = typename El::Vec;
  const Vec Q = Forces(el, e, Vec::Zero());
  const double h = 1e-6;
  Vec g;
  for (int j = 0; j < El::kDof; ++j) {
    Vec ep = e, em = e;
    ep(j) += h;
    em(j) -= h;
    g(j) = (el.StrainEnergy(ep) - el.StrainEnergy(em)) / (2 * h);
  }
  EXPECT_LT((Q + g).norm(), 1e-6 * Q.norm());
}

/// Checks the marker Jacobian of `m` on `b` at (q, v): J v against the
/// marker twist, and its columns against central differences of the
/// marker position and orientation (absolute 1e-7).
inline void ExpectMarkerJacobianMatchesCentralDifferences(const Body& b, const VecX& q, const VecX& v,
                                                          const Marker& m) {
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), m, ms);
  EXPECT_LT((ms.J.topRows<3>() * v - ms.v_WM).norm(), 1e-12);
  EXPECT_LT((ms.J.bottomRows<3>() * v - ms.w_WM).norm(), 1e-12);
  const double h = 1e-6;
  MarkerState mp, mm;
  for (int j = 0; j < b.nv(); ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    b.EvaluateMarker(qp.data(), v.data(), m, mp);
    b.EvaluateMarker(qm.data(), v.data(), m, mm);
    const Vec3 dp = (mp.p_WM - mm.p_WM) / (2 * h);
    const Vec3 dth = LogSO3(mp.R_WM * mm.R_WM.transpose()) / (2 * h);
    EXPECT_LT((dp - ms.J.block<3, 1>(0, j)).norm(), 1e-7) << j;
    EXPECT_LT((dth - ms.J.block<3, 1>(3, j)).norm(), 1e-7) << j;
  }
}

/// Sets (q, v) of `b` to its initial coordinates with every coordinate
/// shifted by amplitude * sin(1.3 j + 0.2) and the velocity 0.4 cos(0.7 j).
inline void PerturbedBodyState(const Body& b, double amplitude, VecX& q, VecX& v) {
  q.resize(b.nq());
  v.resize(b.nv());
  b.InitialCoordinates(q.data(), v.data());
  for (int j = 0; j < b.nq(); ++j) {
    q(j) += amplitude * std::sin(1.3 * j + 0.2);
    v(j) = 0.4 * std::cos(0.7 * j);
  }
}

/// A marker named `name` on node `node`, offset and turned from the node frame.
inline Marker NodeTestMarker(const std::string& name, int node) {
  Marker m;
  m.name = name;
  m.node = node;
  m.p_BM = Vec3(0.1, -0.2, 0.05);
  m.R_BM = ExpSO3(Vec3(0.2, 0.1, -0.3));
  return m;
}

/// A fixed test acceleration of `b`: 0.3 sin(2.1 j).
inline VecX TestAcceleration(const Body& b) {
  VecX acc(b.nv());
  for (int j = 0; j < b.nv(); ++j) acc(j) = 0.3 * std::sin(2.1 * j);
  return acc;
}

/// A fixed test wrench (f, m) for the marker wrench tangent checks.
inline Vec6 TestWrench() {
  Vec6 w;
  w << 3.0, -1.0, 2.0, 0.5, 0.7, -0.4;
  return w;
}

/// Checks J acc + bias against the central-difference time derivative of
/// the marker twist along q + t v + t^2/2 acc (relative 1e-6).
inline void ExpectMarkerBiasMatchesCentralDifferences(const Body& b, const VecX& q, const VecX& v,
                                                      const VecX& acc, const Marker& m) {
  const double h = 1e-5;
  auto twist = [&](double t) {
    const VecX qt = q + t * v + 0.5 * t * t * acc;
    const VecX vt = v + t * acc;
    MarkerState ms;
    b.EvaluateMarker(qt.data(), vt.data(), m, ms);
    Vec6 tw;
    tw << ms.v_WM, ms.w_WM;
    return tw;
  };
  const Vec6 fd = (twist(h) - twist(-h)) / (2 * h);
  MarkerState ms;
  b.EvaluateMarker(q.data(), v.data(), m, ms);
  const Vec6 pred = ms.J * acc + b.MarkerAccelerationBias(q.data(), v.data(), m);
  EXPECT_LT((fd - pred).norm(), 1e-6 * pred.norm());
}

/// Checks the marker wrench tangent (for wrench w) and twist tangent against
/// central differences of J^T w and J v (relative 1e-6).
inline void ExpectMarkerTangentsMatchCentralDifferences(const Body& b, const VecX& q, const VecX& v,
                                                        const Marker& m, const Vec6& w) {
  MatX K = MatX::Zero(b.nv(), b.nv());
  b.AddMarkerWrenchTangent(q.data(), m, w, K);
  MatX T(6, b.nv());
  b.MarkerTwistTangent(q.data(), v.data(), m, T);
  const double h = 1e-6;
  MarkerState mp, mm;
  for (int j = 0; j < b.nv(); ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    b.EvaluateMarker(qp.data(), v.data(), m, mp);
    b.EvaluateMarker(qm.data(), v.data(), m, mm);
    const VecX dQ = (mp.J.transpose() * w - mm.J.transpose() * w) / (2 * h);
    const Vec6 dtw = (mp.J * v - mm.J * v) / (2 * h);
    EXPECT_LT((dQ - K.col(j)).norm(), 1e-6 * (1.0 + K.norm())) << j;
    EXPECT_LT((dtw - T.col(j)).norm(), 1e-6 * (1.0 + T.norm())) << j;
  }
}

/// Checks the body's dQ/dq and dQ/dv at (q, v) under gravity g against
/// central differences (relative 1e-6), and AddForceVector (where the body
/// has it) against the force of AddForces (relative 1e-12).
inline void ExpectBodyForceTangentsMatchCentralDifferences(const Body& b, const VecX& q, const VecX& v,
                                                           const Vec3& g) {
  const int n = b.nv();
  auto forces = [&](const VecX& qq, const VecX& vv) {
    VecX Q = VecX::Zero(n);
    MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
    b.AddForces(qq.data(), vv.data(), g, Q, K, C);
    return Q;
  };
  VecX Q = VecX::Zero(n);
  MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
  b.AddForces(q.data(), v.data(), g, Q, K, C);
  // the force-only path of kept iteration matrices gives the same force
  VecX Qv = VecX::Zero(n);
  if (b.AddForceVector(q.data(), v.data(), g, Qv)) EXPECT_LT((Qv - Q).norm(), 1e-12 * Q.norm());
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q, vp = v, vm = v;
    qp(j) += h;
    qm(j) -= h;
    vp(j) += h;
    vm(j) -= h;
    EXPECT_LT(((forces(qp, v) - forces(qm, v)) / (2 * h) - K.col(j)).norm(), 1e-6 * K.norm()) << j;
    EXPECT_LT(((forces(q, vp) - forces(q, vm)) / (2 * h) - C.col(j)).norm(), 1e-6 * C.norm()) << j;
  }
}

/// Checks that the gravity part of the body's force is minus the gradient of
/// GravityPotential and the rest minus that of ElasticEnergy (body without
/// damping or distributed load).
inline void ExpectBodyForcesArePotentialGradients(const Body& b, const VecX& q, const Vec3& g) {
  const int n = b.nv();
  const VecX v = VecX::Zero(n);
  VecX Qg = VecX::Zero(n), Qe = VecX::Zero(n);
  MatX K = MatX::Zero(n, n), C = MatX::Zero(n, n);
  b.AddForces(q.data(), v.data(), g, Qg, K, C);
  b.AddForces(q.data(), v.data(), Vec3::Zero(), Qe, K, C);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    VecX qp = q, qm = q;
    qp(j) += h;
    qm(j) -= h;
    const double dV = (b.GravityPotential(qp.data(), g) - b.GravityPotential(qm.data(), g)) / (2 * h);
    const double dW = (b.ElasticEnergy(qp.data()) - b.ElasticEnergy(qm.data())) / (2 * h);
    EXPECT_NEAR(Qg(j) - Qe(j), -dV, 1e-6 * (1.0 + Qg.norm())) << j;
    EXPECT_NEAR(Qe(j), -dW, 1e-6 * Qe.norm()) << j;
  }
}

/// Checks the Jacobian, acceleration bias and wrench and twist tangents of
/// a node test marker (NodeTestMarker) on each node in `nodes` at (q, v).
inline void ExpectNodeMarkerKinematicsMatchCentralDifferences(const Body& b, const VecX& q, const VecX& v,
                                                              std::initializer_list<int> nodes) {
  const VecX acc = TestAcceleration(b);
  for (int node : nodes) {
    SCOPED_TRACE("node " + std::to_string(node));
    const Marker m = NodeTestMarker(b.name() + ".m", node);
    ExpectMarkerJacobianMatchesCentralDifferences(b, q, v, m);
    ExpectMarkerBiasMatchesCentralDifferences(b, q, v, acc, m);
    ExpectMarkerTangentsMatchCentralDifferences(b, q, v, m, TestWrench());
  }
}

/// One bad-input case of a model file: the text `from` replaced by `to`
/// must give an InputError naming `where` (file:line) and `entity`.
struct ModelFileErrorCase {
  const char* from;
  const char* to;
  const char* where;
  const char* entity;
};

/// The InputError message of model text `text` (loaded as file `file`)
/// with the first `from` replaced by `to`; "" if it loads.
inline std::string ModelFileErrorOf(std::string text, const std::string& file, const std::string& from,
                                    const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  try {
    LoadModelString(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Checks every case of `cases` on model text `text` loaded as `file`.
template <class Cases>
void ExpectModelFileErrorsNameLineAndEntity(const std::string& text, const std::string& file, const Cases& cases) {
  for (const ModelFileErrorCase& c : cases) {
    const std::string what = ModelFileErrorOf(text, file, c.from, c.to);
    EXPECT_NE(what.find(c.where), std::string::npos) << c.to << ": " << what;
    EXPECT_NE(what.find(c.entity), std::string::npos) << c.to << ": " << what;
  }
}

}  // namespace flexmb::ancf::test_util
