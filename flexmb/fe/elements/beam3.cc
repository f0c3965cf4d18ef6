#include "flexmb/fe/elements/beam3.h"

#include <array>
#include <cmath>
#include <string>

#include "flexmb/common/error.h"
#include "flexmb/fe/elements/beam2.h"
#include "flexmb/fe/elements/element_common.h"

namespace flexmb::fe {
namespace {

// a half of the 3-node beam as a 2-node beam: the element's copy with two
// nodes (its id, type and origin name it in messages) and their coordinates
struct Beam3Half {
  Element element;
  std::array<Vec3, 2> x;
  ElementInput input;
};

// position of half h's nodes in the 3-node element (A, mid, B)
constexpr int kBeam3HalfNodes[2][2] = {{0, 1}, {1, 2}};

// fills the halves of the element of `in` (their inputs point into them)
void Beam3Halves(const ElementInput& in, std::array<Beam3Half, 2>& halves) {
  const Element& e = CheckElementNodes(in, 3, "beam");
  const ErrorContext ctx = ElementContext(e);
  if (!(e.offset_a - e.offset_b).isZero(0.0) || !e.offset_a.allFinite())
    throw InputError("different end offsets are not supported on the 3-node beam (only one offset of its axis)", ctx);
  const Vec3 &xa = in.x[0], &xm = in.x[1], &xb = in.x[2];
  const double L = (xb - xa).norm();
  if (!(L > 1e-10 * std::max(xa.norm(), xb.norm())) || !(L > 0.0))
    throw InputError("zero length (ends A and B coincide)", ctx);
  const Vec3 ex = (xb - xa) / L;
  const double s = (xm - xa).dot(ex);           // mid node's place along the chord
  const double off = (xm - xa - s * ex).norm();  // and its distance from it
  if (!(off <= 1e-4 * L))
    throw InputError("curved 3-node beam: the mid node lies " + std::to_string(off) +
                         " m off the chord A-B (more than 1e-4 of its length " + std::to_string(L) +
                         " m); flexmb reads straight 3-node beams only: mesh an arc with straight "
                         "elements",
                     ctx);
  if (!(s >= 0.01 * L && s <= 0.99 * L))
    throw InputError("the mid node of the 3-node beam lies at " + std::to_string(s / L) +
                         " of its length from end A, not between its ends",
                     ctx);
  for (int h = 0; h < 2; ++h) {
    Beam3Half& half = halves[h];
    half.element = e;
    half.element.nodes = {e.nodes[kBeam3HalfNodes[h][0]], e.nodes[kBeam3HalfNodes[h][1]]};
    half.element.offset_a = half.element.offset_b = e.offset_a;  // the axis offset from the node line
    half.x = {in.x[kBeam3HalfNodes[h][0]], in.x[kBeam3HalfNodes[h][1]]};
    half.input = in;
    half.input.element = &half.element;
    half.input.x = half.x.data();
  }
}

// adds the half's 12 x 12 block to the element's 18 x 18 one
void AddHalf(int h, const MatX& block, MatX& out) {
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      out.block<6, 6>(6 * kBeam3HalfNodes[h][i], 6 * kBeam3HalfNodes[h][j]) += block.block<6, 6>(6 * i, 6 * j);
}

}  // namespace

void Beam3Matrices(const ElementInput& in, MatX& K, MatX& M) {
  std::array<Beam3Half, 2> halves;
  Beam3Halves(in, halves);
  K = MatX::Zero(18, 18);
  M = MatX::Zero(18, 18);
  MatX k, m;
  for (int h = 0; h < 2; ++h) {
    Beam2Matrices(halves[h].input, k, m);
    AddHalf(h, k, K);
    AddHalf(h, m, M);
  }
}

void Beam3SectionForces(const ElementInput& in, MatX& S, Eigen::Matrix3d& axes) {
  std::array<Beam3Half, 2> halves;
  Beam3Halves(in, halves);
  S = MatX::Zero(12, 18);
  MatX s;
  Eigen::Matrix3d half_axes;
  for (int h = 0; h < 2; ++h) {
    Beam2SectionForces(halves[h].input, s, half_axes);
    if (h == 0) axes = half_axes;
    // end A from the first half's rows 0-5, end B from the second's rows 6-11
    for (int j = 0; j < 2; ++j)
      S.block<6, 6>(6 * h, 6 * kBeam3HalfNodes[h][j]) = s.block<6, 6>(6 * h, 6 * j);
  }
}

void Beam3GeometricStiffness(const ElementInput& in, const Eigen::VectorXd& u, MatX& KG,
                             double* axial_force) {
  std::array<Beam3Half, 2> halves;
  Beam3Halves(in, halves);
  KG = MatX::Zero(18, 18);
  MatX kg;
  double mean = 0.0;
  for (int h = 0; h < 2; ++h) {
    Eigen::VectorXd uh(12);
    for (int j = 0; j < 2; ++j) uh.segment<6>(6 * j) = u.segment<6>(6 * kBeam3HalfNodes[h][j]);
    double N = 0.0;
    Beam2GeometricStiffnessUnder(halves[h].input, uh, kg, &N);
    mean += 0.5 * N;
    AddHalf(h, kg, KG);
  }
  if (axial_force != nullptr) *axial_force = mean;
}

}  // namespace flexmb::fe
