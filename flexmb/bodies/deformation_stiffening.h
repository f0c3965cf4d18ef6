#pragma once
/// \file deformation_stiffening.h
/// Run-time stiffening of a floating-frame flexible body by the stress of
/// its own deformation (reduction/deformation_stiffness.h): the geometric
/// stiffness of the current linear stress acting on the deformation,
///
///   Q_w = -G(w) w,   G(w) = sum_j w_j G_j,
///
/// and its tangent dQ_w/dw = -(G(w) + Y) with Y = [G_1 w, ..., G_n w] (not
/// symmetric). This is the second-order (P-delta) analysis of an FE
/// package in the modal basis: the stress is that of the linear strain,
/// and the force has no back-coupling onto the axial coordinates, which
/// without the quartic energy term would make a cantilever softer under a
/// pure transverse load (docs/design.md, "Stiffening by the body's own
/// deformation"). It is not the gradient of a potential; depends on w
/// only. Cost: n^3 for the force (Y), another n^3 for the tangent (G(w));
/// no allocation per call.

#include <memory>
#include <string>
#include <vector>

#include "flexmb/bodies/body.h"
#include "flexmb/bodies/geometric_stiffening.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb {

/// The deformation stiffening force of one body; see the file comment.
class DeformationStiffeningForce {
 public:
  /// Keeps a reference to the n matrices `g` (n x n each; must outlive this
  /// object); throws InputError if there are not n of size n x n.
  DeformationStiffeningForce(const std::vector<MatX>& g, int n);

  /// Adds -G(w) w to Qw (n) at the modal coordinates `w` (n).
  void Add(const double* w, Eigen::Ref<VecX> Qw) const;

  /// Adds -G(w) w to Qw (n) and its derivative -(G(w) + Y) to dQw_dw (n x n).
  void Add(const double* w, Eigen::Ref<VecX> Qw, Eigen::Ref<MatX> dQw_dw) const;

 private:
  const std::vector<MatX>& g_;
  int n_;
  mutable MatX y_;   // scratch: column m = G_m w
  mutable MatX gw_;  // scratch: G(w)
};

/// The deformation stiffening of the flexible body `body` (named in
/// errors) for `mode`: null for kOff or for kAuto when `reduced` has no
/// deformation stiffness; throws InputError for kOn without it.
std::unique_ptr<DeformationStiffeningForce> MakeDeformationStiffening(const std::string& body,
                                                                      const reduction::ReducedBody& reduced,
                                                                      GeometricStiffening mode);

}  // namespace flexmb
