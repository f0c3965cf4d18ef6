#pragma once
/// \file flexible_test_bodies.h
/// Small FE models built in code and reduced by Craig-Bampton, for the
/// flexible body tests (unit and validation).

#include <memory>
#include <vector>

#include "flexmb/bodies/flexible_body.h"
#include "flexmb/fe/fe_model.h"
#include "flexmb/reduction/craig_bampton.h"
#include "tests/unit/fe/fe_test_models.h"

namespace flexmb::testing {

/// A steel round bar (radius r [m]) bent into an L in 3D: `per_leg` beam
/// elements from (0, 0, 0) to (a, 0, 0), then `per_leg` to (a, b, c), with a
/// point mass (offset, inertia) at the last node, so that every inertia
/// invariant is non-zero. Node indices 0 .. 2 per_leg.
inline fe::FeModel BentBar(int per_leg, double a = 0.8, double b = 0.5, double c = 0.2, double r = 0.01) {
  fe::FeModel model;
  fe::Mesh& mesh = model.mesh;
  mesh.source = "bent_bar.bdf";
  const int mat = fe::testing::AddMaterial(mesh, 2.1e11, 0.3, 7850.0);
  const int sec = fe::testing::AddRoundBar(mesh, mat, r);
  for (int k = 0; k <= per_leg; ++k) fe::testing::AddNode(mesh, fe::Vec3(a * k / per_leg, 0.0, 0.0));
  for (int k = 1; k <= per_leg; ++k)
    fe::testing::AddNode(mesh, fe::Vec3(a, b * k / per_leg, c * k / per_leg));
  for (int k = 0; k < 2 * per_leg; ++k)
    fe::testing::AddBeam(mesh, sec, k, k + 1, k < per_leg ? fe::Vec3(0, 1, 0) : fe::Vec3(0, 0, 1));
  fe::Mat3 inertia = fe::Mat3::Zero();
  inertia.diagonal() << 2e-3, 3e-3, 4e-3;
  fe::testing::AddPointMass(model.mesh, 2 * per_leg, 1.5, fe::Vec3(0.02, -0.03, 0.05), inertia);
  return model;
}

/// The free bent bar reduced with `normal` fixed-interface modes and its
/// two ends as interface (6 static modes remain after the 6 rigid modes
/// are removed): 6 + normal flexible modes, or the lowest `keep`.
inline std::shared_ptr<reduction::ReducedBody> FreeBentBar(int per_leg, int normal, int keep = -1) {
  const fe::FeModel model = BentBar(per_leg);
  reduction::ReductionOptions o;
  o.interface_nodes = {0, 2 * per_leg};
  o.normal_modes = normal;
  o.keep = keep;
  return std::make_shared<reduction::ReducedBody>(reduction::ReduceCraigBampton(model, o));
}

/// FreeBentBar(3, 3) as a flexible body in a general state, so that every
/// term of its mass matrix, forces and tangents is non-zero: tilted
/// (0.7 rad about (1, 2, 3)), spinning (w = (0.5, -1, 3) rad/s), moving
/// (v = (0.2, 0.1, -0.3) m/s) and deformed (w0, wd0 linear ramps).
inline FlexibleBodyData SpinningDeformedBentBar() {
  FlexibleBodyData d;
  d.reduced = FreeBentBar(3, 3);
  d.R_WB = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  d.w_WB = Vec3(0.5, -1.0, 3.0);
  d.v_WB = Vec3(0.2, 0.1, -0.3);
  const int n = static_cast<int>(d.reduced->invariants.n);
  d.w0 = VecX::LinSpaced(n, -0.02, 0.03);
  d.wd0 = VecX::LinSpaced(n, 0.5, -0.4);
  return d;
}

}  // namespace flexmb::testing
