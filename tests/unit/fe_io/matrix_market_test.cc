#include "flexmb/fe_io/matrix_market.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "matrix_test_util.h"

namespace flexmb::io {
namespace {

using testing::ExpectBitIdentical;
using testing::ExpectContains;
using testing::FeData;
using testing::InputErrorOf;
using testing::ReadText;
using testing::Replace;

// random sparse matrix with values of every magnitude and extremes
fe::SparseMat RandomMatrix(int n, unsigned seed, bool symmetric, bool specials = true) {
  if (!specials) return testing::RandomRoundTripMatrix(n, seed, symmetric, 300, 0.15, {});
  return testing::RandomRoundTripMatrix(n, seed, symmetric, 300, 0.15,
                                        {0.1 + 0.2, 1.0 / 3.0, std::nextafter(1.0, 0.0), 4.9406564584124654e-324,
                                         -0.0, 1.7976931348623157e308});
}

TEST(MatrixMarket, ReadsGeneralWithCommentsCaseInsensitiveBannerAndSumsDuplicates) {
  const MatrixMarketMatrix m = ReadMatrixMarket(FeData("mtx/general.mtx"));
  Eigen::Matrix<double, 3, 4> ref;
  ref << 1.5, 0, 0, 1e10, 0, 3.0, 0, 0, -7e-3, 0, -2, 0;
  EXPECT_FALSE(m.symmetric);
  EXPECT_EQ(m.duplicates, 1);
  ASSERT_EQ(m.A.rows(), 3);
  ASSERT_EQ(m.A.cols(), 4);
  EXPECT_EQ(m.A.nonZeros(), 5);
  EXPECT_EQ((Eigen::Matrix<double, 3, 4>(Eigen::MatrixXd(m.A))), ref);
}

TEST(MatrixMarket, ExpandsSymmetricLowerAndUpperTriangles) {
  const MatrixMarketMatrix m = ReadMatrixMarket(FeData("mtx/symmetric.mtx"));
  EXPECT_TRUE(m.symmetric);
  EXPECT_EQ(m.duplicates, 0);
  EXPECT_EQ(m.A.nonZeros(), 12);
  EXPECT_EQ(Eigen::Matrix4d(Eigen::MatrixXd(m.A)), testing::SymmetricTestMatrix());

  const MatrixMarketMatrix u = ReadMatrixMarket(FeData("mtx/integer_upper.mtx"));
  EXPECT_EQ(Eigen::Matrix3d(Eigen::MatrixXd(u.A)), testing::IntegerTestMatrix());
}

TEST(MatrixMarket, RoundTripIsBitForBit) {
  for (const bool symmetric : {true, false}) {
    const fe::SparseMat A = RandomMatrix(50, symmetric ? 1u : 2u, symmetric);
    const std::string path = testing::ScratchPath(symmetric ? "sym.mtx" : "gen.mtx");
    MatrixMarketWriteOptions o;
    o.symmetric = symmetric;
    WriteMatrixMarket(A, path, o);
    const std::string text = ReadText(path);
    EXPECT_EQ(text.rfind(symmetric ? "%%MatrixMarket matrix coordinate real symmetric\n"
                                   : "%%MatrixMarket matrix coordinate real general\n",
                         0),
              0u);
    EXPECT_NE(text.find("0.30000000000000004"), std::string::npos);
    const MatrixMarketMatrix m = ReadMatrixMarket(path);
    EXPECT_EQ(m.symmetric, symmetric);
    EXPECT_EQ(m.duplicates, 0);
    ExpectBitIdentical(m.A, A);
  }
}

TEST(MatrixMarket, WriteRejectsAsymmetricAndNonFinite) {
  fe::SparseMat A = RandomMatrix(8, 3, true, false);
  A.coeffRef(1, 6) += 0.5;
  const std::string path = testing::ScratchPath("bad_write.mtx");
  ExpectContains(InputErrorOf([&] { WriteMatrixMarket(A, path); }),
                 {"bad_write.mtx", "not symmetric: A(7,2) - A(2,7) = 0.5"}, "asymmetric");
  A.coeffRef(1, 6) = INFINITY;
  MatrixMarketWriteOptions o;
  o.symmetric = false;
  ExpectContains(InputErrorOf([&] { WriteMatrixMarket(A, path, o); }),
                 {"entry (row 2, column 7): value is not finite"}, "non-finite");
}

// each bad file: the message names the file, the line and the entry
TEST(MatrixMarket, BadInputNamesFileLineAndEntry) {
  const std::string good = ReadText(FeData("mtx/symmetric.mtx"));
  testing::ExpectBadFiles(
      {
          {"no_banner.mtx", Replace(good, "%%MatrixMarket", "%MatrixMarket"), ":1: banner",
           {"not a Matrix Market file"}},
          {"pattern.mtx", Replace(good, "real", "pattern"), ":1: banner", {"pattern matrices have no values"}},
          {"array.mtx", Replace(good, "coordinate", "array"), ":1: banner",
           {"array (dense) format is not supported"}},
          {"complex.mtx", Replace(good, "real", "complex"), ":1: banner", {"complex matrices are not supported"}},
          {"skew.mtx", Replace(good, "symmetric\n", "skew-symmetric\n"), ":1: banner",
           {"'skew-symmetric' is not supported"}},
          {"words.mtx", Replace(good, " symmetric\n", "\n"), ":1: banner", {"needs 4 words"}},
          {"size.mtx", Replace(good, "4 4 8", "4 4"), ":3: size line", {"expected the size line"}},
          {"square.mtx", Replace(good, "4 4 8", "4 5 8"), ":3: size line", {"must be square"}},
          {"range.mtx", Replace(good, "4 1 0.5", "5 1 0.5"), ":6: entry 3 (row 5, column 1)",
           {"row index out of range 1..4"}},
          {"nan.mtx", Replace(good, "3 2 -1", "3 2 NaN"), ":8: entry 5 (row 3, column 2)",
           {"value 'NaN' is not finite"}},
          {"inf.mtx", Replace(good, "3 2 -1", "3 2 -1e400"), ":8: entry 5 (row 3, column 2)", {"is not finite"}},
          {"number.mtx", Replace(good, "3 2 -1", "3 2 -1.0D+00"), ":8: entry 5 (row 3, column 2)",
           {"is not a number"}},
          {"fields.mtx", Replace(good, "3 2 -1", "3 2 -1 7"), ":8: entry 5",
           {"expected 'I J VALUE', found 4 fields"}},
          {"both_triangles.mtx", Replace(good, "3 2 -1", "2 3 -1"), ":8: entry 5 (row 2, column 3)",
           {"entry in the upper triangle, but line 5 has one in the lower"}},
          {"truncated.mtx", good.substr(0, good.find("3 3 4")), ":8: entry 6", {"file ends after 5 of 8 entries"}},
          {"too_many.mtx", good + "1 1 1\n", ":12: entry 9", {"more entries than the 8 of the size line"}},
          {"integer.mtx", Replace(good, "real", "integer"), ":6: entry 3 (row 4, column 1)", {"not an integer"}},
      },
      [](const std::string& path) { ReadMatrixMarket(path); });
}

}  // namespace
}  // namespace flexmb::io
