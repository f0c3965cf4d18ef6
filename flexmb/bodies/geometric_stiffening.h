#pragma once
/// \file geometric_stiffening.h
/// Run-time geometric stiffening of a floating-frame flexible body: the
/// modal force of the centrifugal geometric stiffness stored in the reduced
/// body (reduction/geometric_stiffness.h),
///
///   Q_w = -G(om) w,   G(om) = sum_c p_c(om) Kg_c,
///
/// p_c the six products om_i om_j of the angular velocity (body axes), and
/// its analytic derivatives dQ_w/dw = -G(om), dQ_w/dom = -sum_c (Kg_c w)
/// dp_c/dom. Only the centrifugal load cases are included (not the frame's
/// translational or angular acceleration, nor gravity): the force depends on
/// positions and velocities only, so it enters the residual like any other
/// force and the tangent stays as it is (docs/design.md, "Geometric
/// stiffening", states the consequences). Cost 6 n^2 per call, no
/// allocation.

#include <memory>
#include <string>
#include <vector>

#include "flexmb/bodies/body.h"
#include "flexmb/common/error.h"
#include "flexmb/reduction/reduced_body.h"

namespace flexmb {

/// Whether a flexible body uses the geometric stiffness of its body file.
enum class GeometricStiffening {
  kAuto,  ///< if the body file has it
  kOn,    ///< required: InputError if the body file has none
  kOff,   ///< never
};

/// The stiffening force of one body; see the file comment.
class GeometricStiffeningForce {
 public:
  /// Keeps a reference to the six n x n matrices `kg` (must outlive this
  /// object); throws InputError if there are not six of size n x n.
  GeometricStiffeningForce(const std::vector<MatX>& kg, int n);

  /// Adds -G(om) w to Qw (n), -G(om) to dQw_dw (n x n) and the partials with
  /// respect to om (body axes) to dQw_dom (n x 3).
  void Add(const Vec3& om, const double* w, Eigen::Ref<VecX> Qw, Eigen::Ref<MatX> dQw_dom,
           Eigen::Ref<MatX> dQw_dw) const;

  /// G(om) = sum_c p_c(om) Kg_c into `out` (n x n, sized by the caller).
  void Matrix(const Vec3& om, Eigen::Ref<MatX> out) const;

 private:
  const std::vector<MatX>& kg_;
  int n_;
  mutable Eigen::Matrix<double, Eigen::Dynamic, 6> y_;  // scratch: Kg_c w
};

/// A body's stiffening force of type Force, made from its body-file matrices
/// `matrices` (Force(matrices, n)) under `mode`: null for kOff, or for kAuto
/// when `matrices` is empty; for kOn without them an InputError naming the
/// body, `what` (e.g. "geometric stiffness") and the reduce `option` that
/// makes them. Errors of Force's constructor are rethrown naming the body.
template <class Force>
std::unique_ptr<Force> MakeStiffening(const std::string& body, const std::vector<MatX>& matrices, int n,
                                      GeometricStiffening mode, const std::string& what, const std::string& option) {
  const ErrorContext ctx{"", 0, "flexible body '" + body + "'"};
  if (mode == GeometricStiffening::kOff) return nullptr;
  if (matrices.empty()) {
    if (mode == GeometricStiffening::kAuto) return nullptr;
    throw InputError(what + " asked for, but the body file has none (reduce with " + option + ")", ctx);
  }
  try {
    return std::make_unique<Force>(matrices, n);
  } catch (const InputError& e) {
    throw InputError(e.what(), ctx);
  }
}

/// The stiffening force of the flexible body `body` (named in errors) for
/// `mode`: null for kOff or for kAuto without geometric stiffness in
/// `reduced`; throws InputError for kOn without it.
std::unique_ptr<GeometricStiffeningForce> MakeGeometricStiffening(const std::string& body,
                                                                  const reduction::ReducedBody& reduced,
                                                                  GeometricStiffening mode);

}  // namespace flexmb
