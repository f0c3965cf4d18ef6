#pragma once
/// \file deformation_stiffening.h
/// Run-time stiffening of a floating-frame flexible body by the stress of
/// its own deformation (reduction/deformation_stiffness.h): the cubic strain
/// energy
///
///   U3(w) = 1/2 w^T G(w) w,   G(w) = sum_j w_j G_j,
///
/// its modal force Q_w = -dU3/dw, (dU3/dw)_m = 1/2 w^T G_m w + (G(w) w)_m,
/// and its tangent dQ_w/dw = -(Y + Y^T + G(w)) with Y = [G_1 w, ..., G_n w].
/// The force is conservative (U3 belongs to the body's elastic energy) and
/// depends on w only. Cost: n^3 for the force (Y), another n^3 for the
/// tangent (G(w)); no allocation per call.

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

  /// Adds -dU3/dw to Qw (n) at the modal coordinates `w` (n).
  void Add(const double* w, Eigen::Ref<VecX> Qw) const;

  /// Adds -dU3/dw to Qw (n) and -d^2U3/dw^2 to dQw_dw (n x n).
  void Add(const double* w, Eigen::Ref<VecX> Qw, Eigen::Ref<MatX> dQw_dw) const;

  /// The cubic strain energy U3(w) [J].
  double Energy(const double* w) const;

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
