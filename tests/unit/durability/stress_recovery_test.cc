#include "flexmb/durability/stress_recovery.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "flexmb/common/error.h"
#include "flexmb/durability/element_fatigue.h"
#include "flexmb/reduction/stress_modes.h"

namespace flexmb::durability {
namespace {

reduction::StressTable RecoveryTestTable(bool shell, int elements, int n) {
  reduction::StressTable t;
  t.name = shell ? "shell" : "solid";
  t.components = shell ? std::vector<std::string>{"sxx", "syy", "sxy"}
                       : std::vector<std::string>{"sxx", "syy", "szz", "sxy", "syz", "szx"};
  t.locations = shell ? std::vector<std::string>{"bottom", "top"} : std::vector<std::string>{"centroid"};
  for (int k = 0; k < elements; ++k) t.elements.push_back(2 * k);
  t.axes.assign(elements, Eigen::Matrix3d::Identity());
  t.modes = Eigen::MatrixXd::Random(elements * t.Locations() * t.Components(), n) * 1e8;
  return t;
}

// batched recovery against the per-instant product and reduction's von Mises
TEST(StressRecovery, BatchesMatchThePerInstantProduct) {
  for (bool shell : {true, false}) {
    const reduction::StressTable t = RecoveryTestTable(shell, 7, 4);
    const Eigen::MatrixXd W = Eigen::MatrixXd::Random(4, 9);
    StressRecovery rec(t, W);
    rec.Recover(2, 4);
    for (int r = 0; r < 9; ++r) {
      const Eigen::VectorXd v = t.modes * W.col(r);
      for (int k = 2; k < 6; ++k) {
        if (shell) {
          for (int p = 0; p < 3; ++p) {
            Eigen::Vector3d s;
            for (int c = 0; c < 3; ++c)
              s(c) = p == 1 ? 0.5 * (v(t.Row(k, 0, c)) + v(t.Row(k, 1, c))) : v(t.Row(k, p / 2, c));
            const PointStress ps = rec.At(k, p, r);
            EXPECT_NEAR(ps.von_mises, reduction::VonMises(s), 1e-6);
            // in-plane principal stresses: eigenvalues of [sxx sxy; sxy syy]
            Eigen::Matrix2d m;
            m << s(0), s(2), s(2), s(1);
            const Eigen::Vector2d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(m).eigenvalues();
            EXPECT_NEAR(ps.max_principal, e(1), 1e-6);
            EXPECT_NEAR(ps.min_principal, e(0), 1e-6);
            EXPECT_EQ(std::abs(ps.signed_von_mises), ps.von_mises);
            EXPECT_EQ(ps.signed_von_mises < 0, std::abs(e(0)) > std::abs(e(1)));
          }
        } else {
          Eigen::Matrix<double, 6, 1> s;
          for (int c = 0; c < 6; ++c) s(c) = v(t.Row(k, 0, c));
          const PointStress ps = rec.At(k, 0, r);
          EXPECT_NEAR(ps.von_mises, reduction::VonMises(s), 1e-6);
          Eigen::Matrix3d m;
          m << s(0), s(3), s(5), s(3), s(1), s(4), s(5), s(4), s(2);
          const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues();
          EXPECT_NEAR(ps.max_principal, e(2), 1e-4);
          EXPECT_NEAR(ps.min_principal, e(0), 1e-4);
        }
      }
    }
  }
}

TEST(StressRecovery, ElementExtremesAreIndependentOfTheBlockSize) {
  const reduction::StressTable t = RecoveryTestTable(true, 11, 3);
  const Eigen::MatrixXd W = Eigen::MatrixXd::Random(3, 50);
  StressRecovery rec(t, W);
  FatigueOptions a, b;
  a.curve = b.curve = SnCurve::Eurocode(80);
  a.block = 1;
  b.block = 4;
  const ElementResults ra = AnalyzeElements(rec, a), rb = AnalyzeElements(rec, b);
  EXPECT_EQ(ra.max_von_mises, rb.max_von_mises);
  EXPECT_EQ(ra.damage, rb.damage);
  // the maximum is where it is said to be
  rec.Recover(5, 1);
  EXPECT_DOUBLE_EQ(rec.At(5, ra.max_von_mises_point[5], ra.max_von_mises_instant[5]).von_mises, ra.max_von_mises[5]);
  // the arrays of Histories equal the per-instant measures (to round-off of 1e8 Pa stresses)
  PointHistory h;
  rec.Histories(5, 1, h);
  for (int r = 0; r < 50; ++r) {
    const PointStress s = rec.At(5, 1, r);
    EXPECT_NEAR(h.von_mises(r), s.von_mises, 1e-6);
    EXPECT_NEAR(h.max_abs_principal(r), s.max_abs_principal, 1e-6);
    EXPECT_NEAR(h.signed_von_mises(r), s.signed_von_mises, 1e-6);
    EXPECT_NEAR(h.min_principal(r), s.min_principal, 1e-6);
  }
  EXPECT_GT(ra.damage[5], 0.0);
}

TEST(StressRecovery, RejectsBeamTablesAndWrongSizes) {
  reduction::StressTable beam = RecoveryTestTable(true, 2, 3);
  beam.name = "beam";
  beam.components = {"N", "Vy", "Vz", "T", "My", "Mz"};
  EXPECT_THROW(StressRecovery(beam, Eigen::MatrixXd::Zero(3, 2)), InputError);
  const reduction::StressTable t = RecoveryTestTable(true, 2, 3);
  EXPECT_THROW(StressRecovery(t, Eigen::MatrixXd::Zero(4, 2)), InputError);
  EXPECT_THROW(ParseStressMeasure("tresca"), InputError);
}

}  // namespace
}  // namespace flexmb::durability
