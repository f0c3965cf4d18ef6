#pragma once
/// \file rotating_beam.h
/// Simo and Vu-Quoc's spin-up of a flexible beam (1986; docs/validation.md,
/// "Rotating beam: geometric stiffening"), shared by
/// tests/validation/rotating_beam_test.cc and bench/rotating_beam.cc: a beam
/// of L = 10 m, EA = 2.8e7 N, EI = 1.4e4 N m^2, rho A = 1.2 kg/m, clamped at
/// x = 0 to a hub turning about the world z axis by the prescribed angle
/// theta(t) (SpinUp), once as a Craig-Bampton reduced floating-frame body
/// (with or without geometric stiffening) and once as a planar ANCF beam
/// (geometrically exact strains: the independent reference). The hub is a
/// revolute joint of the beam's root to the ground, driven by a motion
/// driver, so the root is clamped to the turning hub frame.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/common/error.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/joints/motion_driver.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/math/scalar_function.h"
#include "flexmb/model/model.h"
#include "flexmb/reduction/craig_bampton.h"
#include "flexmb/solver/simulator.h"

namespace flexmb::rotating_beam {

constexpr double kL = 10.0, kEA = 2.8e7, kEI = 1.4e4, kRhoA = 1.2;

/// theta(t) = (Om/Ts) (t^2/2 + (Ts/(2 pi))^2 (cos(2 pi t/Ts) - 1)) for
/// t < Ts, Om (t - Ts/2) after [rad]; omega(t) = (Om/Ts) (t - Ts/(2 pi)
/// sin(2 pi t/Ts)) reaches Om at Ts with zero angular acceleration.
class SpinUp final : public ScalarFunction {
 public:
  SpinUp(double omega_s = 6.0, double t_s = 15.0) : om_(omega_s), ts_(t_s) {}
  double Value(double t) const override {
    if (t >= ts_) return om_ * (t - 0.5 * ts_);
    const double c = ts_ / (2.0 * M_PI);
    return om_ / ts_ * (0.5 * t * t + c * c * (std::cos(t / c) - 1.0));
  }
  double Derivative(double t) const override {
    if (t >= ts_) return om_;
    const double c = ts_ / (2.0 * M_PI);
    return om_ / ts_ * (t - c * std::sin(t / c));
  }
  double SecondDerivative(double t) const override {
    if (t >= ts_) return 0.0;
    const double c = ts_ / (2.0 * M_PI);
    return om_ / ts_ * (1.0 - std::cos(t / c));
  }

 private:
  double om_, ts_;
};

/// The beam as an FE model of `ne` Euler-Bernoulli beam elements along x
/// (a section with the given EA, EI, rho A; radius of gyration sqrt(EI/EA)).
inline fe::FeModel BeamModel(int ne) {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "rotating_beam";
  fe::Material mat;
  mat.id = 1;
  mat.E = kEA;  // A = 1 m^2
  mat.nu = 0.3;
  mat.G = mat.E / 2.6;
  mat.rho = kRhoA;
  mesh.materials.push_back(mat);
  fe::BeamSection s;
  s.id = 1;
  s.material = 0;
  s.A = 1.0;
  s.Iy = s.Iz = kEI / kEA;
  s.J = 2.0 * s.Iy;
  mesh.beam_sections.push_back(s);
  for (int k = 0; k <= ne; ++k) {
    fe::Node n;
    n.id = k + 1;
    n.x = fe::Vec3(kL * k / ne, 0.0, 0.0);
    mesh.nodes.push_back(n);
  }
  mesh.IndexNodes();
  for (int k = 0; k < ne; ++k) {
    fe::Element e;
    e.id = k + 1;
    e.type = fe::ElementType::kBeam2;
    e.property = 0;
    e.nodes = {k, k + 1};
    e.orientation = fe::Vec3(0.0, 1.0, 0.0);
    mesh.elements.push_back(e);
  }
  return model;
}

/// How the floating frame sits on the beam.
enum class Frame {
  /// The beam clamped at its root in the reduction (`fixed_nodes`): the
  /// modes are the cantilever modes and the frame is the hub frame, as in
  /// the "conventional" linear model of Kane, Ryan and Banerjee (1987).
  kRootAttached,
  /// The free beam with its root as interface node, rigid-body modes
  /// removed (the reduction's default): free-free modes M-orthogonal to the
  /// rigid motions, the frame follows the beam's mean rigid motion and the
  /// root node moves in the modes.
  kFree,
};

/// The beam reduced to the `modes` lowest normal modes (fixed-interface
/// modes for kFree), with the centrifugal geometric stiffness.
inline std::shared_ptr<reduction::ReducedBody> ReducedBeam(int ne, int modes, Frame frame) {
  reduction::ReductionOptions o;
  if (frame == Frame::kRootAttached) {
    o.fixed_nodes = {0};
  } else {
    o.interface_nodes = {0};
  }
  o.normal_modes = modes;
  o.geometric_stiffening = true;
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(BeamModel(ne), o));
}

/// A sample of the tip: time [s], transverse deflection in the hub frame
/// (along the hub's y axis) [m] and axial position in the hub frame [m].
struct TipSample {
  double t, deflection, axial;
};

/// Samples of one run; `failure` is the solver's message if it gave up
/// (the samples then end there), empty otherwise.
struct Result {
  std::vector<TipSample> samples;
  std::string failure;
};

/// Driven hub: revolute between a ground marker and the beam's root marker
/// `root`, and the motion driver theta(t).
inline void AddHub(Model& m, int root, const std::shared_ptr<const ScalarFunction>& theta) {
  const int g = m.AddMarker(0, "hub", Vec3::Zero(), Mat3::Identity());
  const int rev = m.AddJoint(std::make_unique<RevoluteJoint>("hub"), g, root);
  m.AddJoint(std::make_unique<MotionDriver>("spin", m.joints[rev].get(), 0, theta), g, root);
}

/// Runs a model to t_end with step dt (generalized-alpha, rho_inf = 0.8)
/// and returns the tip samples of every step.
inline Result Run(Model& m, int tip, double t_end, double dt) {
  const SpinUp theta;
  m.gravity_W = Vec3::Zero();
  m.solver.dt = dt;
  m.solver.rho_inf = 0.8;
  m.solver.newton_tol = 1e-10;
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  Result out;
  try {
    sim.Run(t_end, 0.0, [&](const State& s, const Workspace& ws) {
      const double a = theta.Value(s.t);
      const Vec3& p = ws.markers[tip].p_WM;
      out.samples.push_back(
          {s.t, -std::sin(a) * p.x() + std::cos(a) * p.y(), std::cos(a) * p.x() + std::sin(a) * p.y()});
    });
  } catch (const NumericalError& e) {
    out.failure = e.what();
  }
  return out;
}

/// The floating-frame beam; `stiffening` switches the geometric stiffening.
inline Result RunFloatingFrame(const std::shared_ptr<reduction::ReducedBody>& reduced,
                                               bool stiffening, double t_end, double dt) {
  Model m;
  FlexibleBodyData d;
  d.reduced = reduced;
  d.geometric_stiffening = stiffening ? GeometricStiffening::kOn : GeometricStiffening::kOff;
  const int b = m.AddBody(std::make_unique<FlexibleBody>("beam", d));
  const int root = m.AddMarker(b, "root", Vec3::Zero(), Mat3::Identity(), 0);
  const int tip = m.AddMarker(b, "tip", Vec3::Zero(), Mat3::Identity(),
                              static_cast<int>(reduced->mesh.nodes.size()) - 1);
  AddHub(m, root, std::make_shared<SpinUp>());
  return Run(m, tip, t_end, dt);
}

/// The planar ANCF beam of `ne` elements in the x-y plane.
inline Result RunAncf(int ne, double t_end, double dt) {
  Model m;
  ancf::AncfBeam2dData d;
  d.length = kL;
  d.elements = ne;
  d.section.E = kEA;  // A = 1 m^2
  d.section.A = 1.0;
  d.section.I = kEI / kEA;
  d.section.rho = kRhoA;
  const int b = m.AddBody(std::make_unique<ancf::AncfBeam2dBody>("beam", d));
  const int root = m.AddMarker(b, "root", Vec3::Zero(), Mat3::Identity(), 0);
  const int tip = m.AddMarker(b, "tip", Vec3::Zero(), Mat3::Identity(), ne);
  AddHub(m, root, std::make_shared<SpinUp>());
  return Run(m, tip, t_end, dt);
}

}  // namespace flexmb::rotating_beam
