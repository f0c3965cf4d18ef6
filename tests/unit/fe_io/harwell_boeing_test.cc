#include "flexmb/fe_io/harwell_boeing.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "matrix_test_util.h"

namespace flexmb::io {
namespace {

using testing::ExpectBitIdentical;
using testing::ExpectContains;
using testing::FeData;
using testing::InputErrorOf;
using testing::ReadText;
using testing::Replace;
using testing::ScratchPath;

// the first n lines of text
std::string Head(const std::string& text, int n) {
  size_t p = 0;
  for (int i = 0; i < n; ++i) p = text.find('\n', p) + 1;
  return text.substr(0, p);
}

// random sparse symmetric matrix with values of every magnitude and full
// 17-digit mantissas, plus values that need exactly 17 significant digits
fe::SparseMat RandomSymmetric(int n, unsigned seed, bool with_specials = true) {
  if (!with_specials) return testing::RandomRoundTripMatrix(n, seed, true, 30, 0.1, {});
  return testing::RandomRoundTripMatrix(n, seed, true, 30, 0.1,
                                        {0.1 + 0.2, 1.0 / 3.0, std::nextafter(1.0, 2.0), 2.0 / 3.0 * 1e-300,
                                         1.7976931348623157e308, 4.9406564584124654e-324, -0.0, 123456789.12345678});
}

TEST(HarwellBoeing, ReadsClassicHeaderWithRightHandSide) {
  // classic Harwell-Boeing: five card counts, an RHS header line, Fortran
  // E20.12 values; the lower triangle of the matrix below
  const HarwellBoeingMatrix m = ReadHarwellBoeing(FeData("hb/classic_rsa.hb"));
  EXPECT_EQ(m.type, "RSA");
  EXPECT_EQ(m.key, "TESTHB01");
  EXPECT_EQ(m.title, "Test matrix: classic Harwell-Boeing header with a right-hand side");
  EXPECT_TRUE(m.symmetric);
  EXPECT_FALSE(m.pattern);
  EXPECT_EQ(m.A.nonZeros(), 12);  // 8 stored, 4 of them mirrored
  EXPECT_EQ(Eigen::Matrix4d(Eigen::MatrixXd(m.A)), testing::SymmetricTestMatrix());
}

TEST(HarwellBoeing, ReadsRutherfordBoeingUnsymmetric) {
  const HarwellBoeingMatrix m = ReadHarwellBoeing(FeData("hb/rb_rua.rb"));
  Eigen::Matrix3d ref;
  ref << 1.5, 0, -2, 0.25, 3, 0, 0, 7e-3, 1e10;
  EXPECT_EQ(m.type, "RUA");
  EXPECT_EQ(m.key, "TESTRB01");
  EXPECT_EQ(m.title, "Test matrix: Rutherford-Boeing header, unsymmetric");
  EXPECT_FALSE(m.symmetric);
  EXPECT_EQ(m.A.nonZeros(), 6);
  EXPECT_EQ(Eigen::Matrix3d(Eigen::MatrixXd(m.A)), ref);
}

TEST(HarwellBoeing, SymmetricRoundTripIsBitForBit) {
  const fe::SparseMat A = RandomSymmetric(60, 7);
  // premise: 0.1 + 0.2 needs 17 significant digits
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.16g", 0.1 + 0.2);
  ASSERT_NE(std::strtod(buf, nullptr), 0.1 + 0.2);

  const std::string path = ScratchPath("sym.hb");
  HarwellBoeingWriteOptions o;
  o.title = "random symmetric";
  o.key = "RAND60";
  WriteHarwellBoeing(A, path, o);
  const std::string text = ReadText(path);
  EXPECT_NE(text.find("rsa"), std::string::npos) << text.substr(0, 400);
  const HarwellBoeingMatrix m = ReadHarwellBoeing(path);
  EXPECT_EQ(m.type, "RSA");
  EXPECT_TRUE(m.symmetric);
  EXPECT_EQ(m.title, "random symmetric");
  EXPECT_EQ(m.key, "RAND60");
  ExpectBitIdentical(m.A, A);
  const auto [i, j] = testing::RoundTripSpecialPosition(60, 6);  // -0.0, the seventh special value
  ASSERT_TRUE(A.coeff(i, j) == 0.0 && std::signbit(A.coeff(i, j)));  // the input has it
  EXPECT_TRUE(std::signbit(m.A.coeff(i, j)));  // -0.0 kept
}

TEST(HarwellBoeing, SeventeenDigitValuesAreWrittenWithSeventeenDigits) {
  // without huge or tiny values RBio picks the narrowest exact format: here
  // the 17-digit one, since 0.1 + 0.2 and 1/3 need 17 significant digits
  fe::SparseMat A(2, 2);
  A.insert(0, 0) = 0.1 + 0.2;
  A.insert(1, 0) = 1.0 / 3.0;
  A.insert(0, 1) = 1.0 / 3.0;
  A.insert(1, 1) = 2.0 / 3.0;
  A.makeCompressed();
  const std::string path = ScratchPath("digits17.hb");
  WriteHarwellBoeing(A, path);
  const std::string text = ReadText(path);
  EXPECT_NE(text.find("3.0000000000000004"), std::string::npos) << text;
  ExpectBitIdentical(ReadHarwellBoeing(path).A, A);
}

TEST(HarwellBoeing, WritesTheLowerTriangleOfARoundOffAsymmetricMatrix) {
  fe::SparseMat A = RandomSymmetric(20, 3, false);
  A.coeffRef(19, 0) = 0.25;
  A.coeffRef(0, 19) = 0.25;
  const double lower = A.coeff(19, 0);
  A.coeffRef(0, 19) = lower * (1.0 + 1e-14);
  const std::string path = ScratchPath("roundoff.hb");
  WriteHarwellBoeing(A, path);
  const HarwellBoeingMatrix m = ReadHarwellBoeing(path);
  EXPECT_EQ(m.A.coeff(0, 19), lower);
  EXPECT_EQ(m.A.coeff(19, 0), lower);
}

TEST(HarwellBoeing, UnsymmetricRoundTripIsBitForBit) {
  fe::SparseMat A = RandomSymmetric(30, 11);
  A.coeffRef(3, 17) = 0.7;
  A.coeffRef(25, 2) = -1e-7 / 3.0;
  A.makeCompressed();
  const std::string path = ScratchPath("unsym.rua");
  HarwellBoeingWriteOptions o;
  o.symmetric = false;
  WriteHarwellBoeing(A, path, o);
  const HarwellBoeingMatrix m = ReadHarwellBoeing(path);
  EXPECT_EQ(m.type, "RUA");
  EXPECT_FALSE(m.symmetric);
  ExpectBitIdentical(m.A, A);
}

TEST(HarwellBoeing, RbioWritesUnitAndIntegerMatricesAsPatternAndInteger) {
  fe::SparseMat I(5, 5);
  I.setIdentity();
  I.makeCompressed();
  const std::string p1 = ScratchPath("identity.hb");
  WriteHarwellBoeing(I, p1);
  const HarwellBoeingMatrix a = ReadHarwellBoeing(p1);
  EXPECT_EQ(a.type, "PSA");
  EXPECT_TRUE(a.pattern);
  ExpectBitIdentical(a.A, I);

  fe::SparseMat K = testing::IntegerTestMatrix().sparseView();
  K.makeCompressed();
  const std::string p2 = ScratchPath("integer.hb");
  WriteHarwellBoeing(K, p2);
  const HarwellBoeingMatrix b = ReadHarwellBoeing(p2);
  EXPECT_EQ(b.type, "ISA");
  ExpectBitIdentical(b.A, K);
}

// RBio's integer format has no negative zero (found by the fuzzer): an
// integer-valued matrix with -0.0 is written as ISA and reads back with +0.0,
// equal in value; a real matrix keeps its -0.0 bit for bit
TEST(HarwellBoeing, NegativeZeroOfAnIntegerMatrixReadsBackAsPositiveZero) {
  fe::SparseMat K = testing::IntegerTestMatrix().sparseView();
  K.makeCompressed();
  K.coeffRef(1, 0) = -0.0;
  K.coeffRef(0, 1) = -0.0;
  const std::string p1 = ScratchPath("negative_zero_integer.hb");
  WriteHarwellBoeing(K, p1);
  const HarwellBoeingMatrix a = ReadHarwellBoeing(p1);
  EXPECT_EQ(a.type, "ISA");
  EXPECT_EQ(a.A.coeff(1, 0), 0.0);
  EXPECT_FALSE(std::signbit(a.A.coeff(1, 0)));
  EXPECT_EQ(a.A.nonZeros(), K.nonZeros());
  EXPECT_EQ(Eigen::MatrixXd(a.A), Eigen::MatrixXd(K));

  K.coeffRef(2, 2) = 0.5;
  const std::string p2 = ScratchPath("negative_zero_real.hb");
  WriteHarwellBoeing(K, p2);
  const HarwellBoeingMatrix b = ReadHarwellBoeing(p2);
  EXPECT_EQ(b.type, "RSA");
  EXPECT_TRUE(std::signbit(b.A.coeff(1, 0)));
  ExpectBitIdentical(b.A, K);
}

TEST(HarwellBoeing, WriteRejectsAsymmetricNonFiniteAndEmpty) {
  Eigen::MatrixXd dense = Eigen::MatrixXd::Identity(10, 10) * 4.0;
  dense(2, 7) = dense(7, 2) = -1.5;
  fe::SparseMat A = dense.sparseView();
  A.coeffRef(2, 7) += 1.0;
  const std::string path = ScratchPath("bad_write.hb");
  ExpectContains(InputErrorOf([&] { WriteHarwellBoeing(A, path); }),
                 {"bad_write.hb", "not symmetric: A(8,3) - A(3,8) = 1"}, "asymmetric");
  A.coeffRef(2, 7) = std::nan("");
  ExpectContains(InputErrorOf([&] { WriteHarwellBoeing(A, path); }), {"entry (row 3, column 8)", "not finite"},
                 "non-finite");
  ExpectContains(InputErrorOf([&] { WriteHarwellBoeing(fe::SparseMat(4, 4), path); }), {"no stored entries"}, "empty");
  EXPECT_FALSE(std::filesystem::exists(path));
}

// each bad file: the message names the file, the line and the entry
TEST(HarwellBoeing, BadInputNamesFileLineAndEntry) {
  const std::string good = ReadText(FeData("hb/classic_rsa.hb"));
  testing::ExpectBadFiles(
      {
          {"complex.hb", Replace(good, "RSA", "CSA"), ":3: matrix type 'CSA'", {"complex matrices are not supported"}},
          {"rectangular.hb", Replace(good, "RSA", "RRA"), ":3: matrix type 'RRA'", {"rectangular"}},
          {"elemental.hb", Replace(good, "RSA", "RSE"), ":3: matrix type 'RSE'", {"elemental"}},
          {"short_header.hb", Head(good, 3), ":3: header", {"file ends inside the header"}},
          {"dims.hb", Replace(good, "  4             4", "  4             5"), ":3: header", {"must be square"}},
          {"nan.hb", Replace(good, "  0.400000000000E+01 -0.1", "                 nan -0.1"),
           ":8: entry 1 (row 1, column 1)", {"value 'nan' is not finite"}},
          {"inf.hb", Replace(good, "0.300000000000E+01", "0.300000000000E+999"), ":9: entry 8 (row 4, column 4)",
           {"is not finite"}},
          {"fortran_d.hb",
           Replace(good, "-0.100000000000E+01  0.500000000000E+00", "-0.100000000000D+01  0.500000000000E+00"),
           ":8: entry 2 (row 2, column 1)", {"is not a number"}},
          {"range.hb", Replace(good, "    1    2    4    2", "    1    2    9    2"), ":7: entry 3 (row 9, column 1)",
           {"row index out of range 1..4"}},
          {"upper.hb", Replace(good, "    1    2    4    2    3", "    1    2    4    1    3"),
           ":7: entry 4 (row 1, column 2)", {"entry above the diagonal"}},
          {"unsorted.hb", Replace(good, "    1    2    4    2", "    1    4    2    2"),
           ":7: entry 3 (row 2, column 1)", {"not increasing"}},
          {"duplicate.hb", Replace(good, "    1    2    4    2", "    1    2    2    2"),
           ":7: entry 3 (row 2, column 1)", {"duplicate entry"}},
          {"pointer.hb", Replace(good, "    1    4    6    8    9", "    1    4    3    8    9"),
           ":6: column pointer 3", {"column pointers decrease"}},
          {"nnz.hb", Replace(good, "8             0", "9             0"), ":6: column pointer 5",
           {"must be NNZERO + 1 = 10"}},
          {"truncated.hb", Head(good, 8), ":8:", {"file ends early: 4 of 8 values read"}},
          {"blank.hb",
           Replace(good, "    1    2    4    2    3    3    4    4\n",
                   "    1    2    4    2\n\n    3    3    4    4\n"),
           ":8:", {"blank line inside the row indices"}},
          {"extra.hb", Replace(good, "    1    4    6    8    9", "    1    4    6    8    9   10"), ":6:",
           {"more column pointers than the header's 5"}},
          {"token.hb", Replace(good, "    1    4    6", "    1    4x   6"), ":6: column pointer 2",
           {"is not an integer"}},
          {"rhs.hb", Replace(good, "F                          1", "X                          1"), ":5: header",
           {"RHSCRD is 1"}},
      },
      [](const std::string& path) { ReadHarwellBoeing(path); });
}

TEST(HarwellBoeing, MissingFileIsAnInputError) {
  const std::string path = ScratchPath("does_not_exist.hb");
  ExpectContains(InputErrorOf([&] { ReadHarwellBoeing(path); }), {path + ": cannot open"}, "does_not_exist.hb");
}

}  // namespace
}  // namespace flexmb::io
