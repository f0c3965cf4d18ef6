#include "flexmb/durability/stress_recovery.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "flexmb/common/error.h"

namespace flexmb::durability {

StressMeasure ParseStressMeasure(const std::string& name) {
  for (StressMeasure m : {StressMeasure::kVonMises, StressMeasure::kSignedVonMises, StressMeasure::kMaxPrincipal,
                          StressMeasure::kMinPrincipal, StressMeasure::kMaxAbsPrincipal})
    if (name == StressMeasureName(m)) return m;
  throw InputError("unknown stress measure '" + name +
                   "' (von_mises, signed_von_mises, max_principal, min_principal, max_abs_principal)");
}

const char* StressMeasureName(StressMeasure m) {
  switch (m) {
    case StressMeasure::kVonMises: return "von_mises";
    case StressMeasure::kSignedVonMises: return "signed_von_mises";
    case StressMeasure::kMaxPrincipal: return "max_principal";
    case StressMeasure::kMinPrincipal: return "min_principal";
    case StressMeasure::kMaxAbsPrincipal: return "max_abs_principal";
  }
  return "";
}

double PointStress::Get(StressMeasure m) const {
  switch (m) {
    case StressMeasure::kVonMises: return von_mises;
    case StressMeasure::kSignedVonMises: return signed_von_mises;
    case StressMeasure::kMaxPrincipal: return max_principal;
    case StressMeasure::kMinPrincipal: return min_principal;
    case StressMeasure::kMaxAbsPrincipal: return max_abs_principal;
  }
  return 0.0;
}

const Eigen::ArrayXd& PointHistory::Get(StressMeasure m) const {
  switch (m) {
    case StressMeasure::kVonMises: return von_mises;
    case StressMeasure::kSignedVonMises: return signed_von_mises;
    case StressMeasure::kMaxPrincipal: return max_principal;
    case StressMeasure::kMinPrincipal: return min_principal;
    case StressMeasure::kMaxAbsPrincipal: break;
  }
  return max_abs_principal;
}

PointStress PlaneStressMeasures(double sxx, double syy, double sxy) {
  PointStress p;
  const double c = 0.5 * (sxx + syy), d = 0.5 * (sxx - syy);
  const double r = std::sqrt(d * d + sxy * sxy);
  p.max_principal = c + r;
  p.min_principal = c - r;
  p.max_abs_principal = std::abs(p.max_principal) >= std::abs(p.min_principal) ? p.max_principal : p.min_principal;
  // von Mises of the plane state: s1^2 - s1 s2 + s2^2 = c^2 + 3 r^2
  p.von_mises = std::sqrt(c * c + 3.0 * (r * r));
  p.signed_von_mises = p.max_abs_principal < 0 ? -p.von_mises : p.von_mises;
  return p;
}

PointStress SolidStressMeasures(const double* s) {
  Eigen::Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d e = eig.eigenvalues();  // ascending
  PointStress p;
  p.max_principal = e(2);
  p.min_principal = e(0);
  p.max_abs_principal = std::abs(e(2)) >= std::abs(e(0)) ? e(2) : e(0);
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  p.von_mises = std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  p.signed_von_mises = p.max_abs_principal < 0 ? -p.von_mises : p.von_mises;
  return p;
}

PointStress UniaxialStressMeasures(double sxx) {
  PointStress p;
  p.von_mises = std::abs(sxx);
  p.signed_von_mises = sxx;
  p.max_principal = std::max(sxx, 0.0);
  p.min_principal = std::min(sxx, 0.0);
  p.max_abs_principal = sxx;
  return p;
}

StressRecovery::StressRecovery(const reduction::StressTable& table, const Eigen::MatrixXd& W) : table_(table) {
  const bool plane = table.Components() == 3 && table.components[0] == "sxx";
  const bool solid = table.Components() == 6 && table.components[0] == "sxx";
  uniaxial_ = table.Components() == 1 && table.components[0] == "sxx";
  if (!plane && !solid && !uniaxial_)
    throw InputError("stress recovery needs shell, solid or beam-fibre stress modes (stress components), not the " +
                         table.name + " table (section forces)",
                     {"", 0, "stress table '" + table.name + "'"});
  if (plane && table.Locations() != 2)
    throw InputError("shell stress modes without bottom and top surface", {"", 0, "stress table '" + table.name + "'"});
  shell_ = plane;
  if (W.rows() != table.modes.cols())
    throw InputError("modal coordinates of " + std::to_string(W.rows()) + " modes for stress modes of " +
                         std::to_string(table.modes.cols()), {"", 0, "stress table '" + table.name + "'"});
  wt_ = W.transpose();
}

const char* StressRecovery::PointName(int p) const {
  if (!shell_) return table_.locations[p].c_str();
  return p == 0 ? "bottom" : p == 1 ? "middle" : "top";
}

void StressRecovery::Recover(int k0, int count) {
  const Eigen::Index per = static_cast<Eigen::Index>(table_.Locations()) * table_.Components();
  values_.resize(wt_.rows(), per * count);
  values_.noalias() = wt_ * table_.modes.middleRows(table_.Row(k0, 0, 0), per * count).transpose();
  k0_ = k0;
  count_ = count;
}

const double* StressRecovery::Column(int k, int l, int c) const {
  const Eigen::Index col = (static_cast<Eigen::Index>(k - k0_) * table_.Locations() + l) * table_.Components() + c;
  return values_.data() + col * values_.rows();
}

PointStress StressRecovery::At(int k, int p, int r) const {
  if (shell_) {
    // bottom is location 0, top location 1; middle is their mean
    double s[3];
    for (int c = 0; c < 3; ++c) {
      if (p == 1) s[c] = 0.5 * (Column(k, 0, c)[r] + Column(k, 1, c)[r]);
      else s[c] = Column(k, p == 0 ? 0 : 1, c)[r];
    }
    return PlaneStressMeasures(s[0], s[1], s[2]);
  }
  if (uniaxial_) return UniaxialStressMeasures(Column(k, p, 0)[r]);
  double s[6];
  for (int c = 0; c < 6; ++c) s[c] = Column(k, p, c)[r];
  return SolidStressMeasures(s);
}

void StressRecovery::Histories(int k, int p, PointHistory& h) const {
  const Eigen::Index n = Instants();
  for (Eigen::ArrayXd* a : {&h.von_mises, &h.signed_von_mises, &h.max_principal, &h.min_principal,
                            &h.max_abs_principal})
    if (a->size() != n) a->resize(n);
  if (!shell_) {
    for (Eigen::Index r = 0; r < n; ++r) {
      const PointStress s = At(k, p, static_cast<int>(r));
      h.von_mises(r) = s.von_mises;
      h.signed_von_mises(r) = s.signed_von_mises;
      h.max_principal(r) = s.max_principal;
      h.min_principal(r) = s.min_principal;
      h.max_abs_principal(r) = s.max_abs_principal;
    }
    return;
  }
  // plane stress as array expressions over the instants
  using Map = Eigen::Map<const Eigen::ArrayXd>;
  Eigen::ArrayXd* comp[3] = {&sxx_, &syy_, &sxy_};
  for (int c = 0; c < 3; ++c) {
    if (p == 1) *comp[c] = 0.5 * (Map(Column(k, 0, c), n) + Map(Column(k, 1, c), n));
    else *comp[c] = Map(Column(k, p == 0 ? 0 : 1, c), n);
  }
  c_ = 0.5 * (sxx_ + syy_);
  r_ = ((0.5 * (sxx_ - syy_)).square() + sxy_.square()).sqrt();
  h.max_principal = c_ + r_;
  h.min_principal = c_ - r_;
  h.von_mises = (c_.square() + 3.0 * r_.square()).sqrt();
  h.max_abs_principal = (h.max_principal.abs() >= h.min_principal.abs()).select(h.max_principal, h.min_principal);
  h.signed_von_mises = (h.max_abs_principal < 0.0).select(-h.von_mises, h.von_mises);
}

void StressRecovery::History(int k, int p, StressMeasure m, double* out) const {
  const int n = Instants();
  for (int r = 0; r < n; ++r) out[r] = At(k, p, r).Get(m);
}

void StressRecovery::ComponentHistory(int k, int p, int c, double* out) const {
  const int n = Instants();
  if (shell_ && p == 1) {
    const double *a = Column(k, 0, c), *b = Column(k, 1, c);
    for (int r = 0; r < n; ++r) out[r] = 0.5 * (a[r] + b[r]);
    return;
  }
  const double* a = Column(k, shell_ ? (p == 2 ? 1 : 0) : p, c);
  for (int r = 0; r < n; ++r) out[r] = a[r];
}

}  // namespace flexmb::durability
