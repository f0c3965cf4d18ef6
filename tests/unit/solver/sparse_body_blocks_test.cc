// Sparse body blocks (Body::BlockPattern, Body::MarkerColumns): the
// iteration matrix, constraint Jacobian, forces and mass products assembled
// with the banded pattern of an ANCF body equal those assembled with the
// dense default (the same body behind a wrapper that does not declare a
// pattern), and the non-zero count of S grows by exactly one element block
// minus the shared node block per element. A body writing outside its
// declared pattern is refused when the workspace is sized.

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "flexmb/ancf/ancf_beam2d_body.h"
#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/forces/bushing.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/common/error.h"
#include "flexmb/solver/assembler.h"
#include "tests/unit/ancf/ancf_test_util.h"

namespace flexmb {
namespace {

using ancf::AncfBeam2dBody;
using ancf::AncfBeam2dData;
using ancf::AncfCable3dBody;
using ancf::AncfCable3dData;

// the body T with the dense defaults of BlockPattern and MarkerColumns, or
// (leaky) with T's pattern but one force derivative entry written outside it
template <class T>
class Dense final : public Body {
 public:
  explicit Dense(std::unique_ptr<T> b, bool leaky = false) : Body(b->name()), b_(std::move(b)), leaky_(leaky) {}
  bool BlockPattern(std::vector<std::pair<int, int>>& entries) const override {
    return leaky_ && b_->BlockPattern(entries);
  }
  int nq() const override { return b_->nq(); }
  int nv() const override { return b_->nv(); }
  void InitialCoordinates(double* q, double* v) const override { b_->InitialCoordinates(q, v); }
  void Retract(const double* q, const double* dx, double* out) const override { b_->Retract(q, dx, out); }
  void MassMatrix(const double* q, MatX& M) const override { b_->MassMatrix(q, M); }
  bool HasConstantMass() const override { return b_->HasConstantMass(); }
  bool MarkerJacobianFullRank() const override { return b_->MarkerJacobianFullRank(); }
  void AddForces(const double* q, const double* v, const Vec3& g, Eigen::Ref<VecX> Q, Eigen::Ref<MatX> Kq,
                 Eigen::Ref<MatX> Kv) const override {
    b_->AddForces(q, v, g, Q, Kq, Kv);
    if (leaky_) Kv(0, nv() - 1) += 1e-3;
  }
  void EvaluateMarker(const double* q, const double* v, const Marker& m, MarkerState& out) const override {
    b_->EvaluateMarker(q, v, m, out);
    out.v_offset = v_offset;
  }
  Vec6 MarkerAccelerationBias(const double* q, const double* v, const Marker& m) const override {
    return b_->MarkerAccelerationBias(q, v, m);
  }
  void AddMarkerWrenchTangent(const double* q, const Marker& m, const Vec6& w,
                              Eigen::Ref<MatX> K) const override {
    b_->AddMarkerWrenchTangent(q, m, w, K);
  }
  void MarkerTwistTangent(const double* q, const double* v, const Marker& m,
                          Eigen::Ref<MatX> out) const override {
    b_->MarkerTwistTangent(q, v, m, out);
  }
  double KineticEnergy(const double* q, const double* v) const override { return b_->KineticEnergy(q, v); }
  double GravityPotential(const double* q, const Vec3& g) const override { return b_->GravityPotential(q, g); }
  Vec6 Momentum(const double* q, const double* v) const override { return b_->Momentum(q, v); }
  void BodyFramePose(const double* q, Vec3& p, Mat3& R) const override { b_->BodyFramePose(q, p, R); }

 private:
  std::unique_ptr<T> b_;
  bool leaky_ = false;
};

ancf::BeamSection Section() { return ancf::test_util::MakeSection(0.7e6, 0.0018, 1.215e-8, 5540, 0.02); }

std::unique_ptr<AncfCable3dBody> Cable(int n) {
  AncfCable3dData d;
  d.length = 1.2;
  d.elements = n;
  d.section = Section();
  d.direction_W = Vec3(1.0, 0.2, -0.1);
  return std::make_unique<AncfCable3dBody>("beam", d);
}

std::unique_ptr<AncfBeam2dBody> Beam(int n) {
  AncfBeam2dData d;
  d.length = 1.2;
  d.elements = n;
  d.section = Section();
  return std::make_unique<AncfBeam2dBody>("beam", d);
}

// pin at node 0 (spherical joint to ground), a bushing between the middle
// and the end node of the body, and a spring-damper from ground to the end
void AddLinks(Model& m, int body, int n) {
  const int pivot = m.AddMarker(0, "pivot", Vec3::Zero(), Mat3::Identity());
  const int anchor = m.AddMarker(0, "anchor", Vec3(0.5, 0.8, 0.1), Mat3::Identity());
  const int pin = m.AddMarker(body, "pin", Vec3::Zero(), Mat3::Identity(), 0);
  const int mid = m.AddMarker(body, "mid", Vec3(0.01, 0.02, 0.0), Mat3::Identity(), n / 2);
  const int tip = m.AddMarker(body, "tip", Vec3(0.0, 0.03, 0.0), Mat3::Identity(), n);
  m.AddJoint(std::make_unique<SphericalJoint>("pin"), pivot, pin);
  BushingData bd;
  bd.translational_stiffness = Vec3(1e3, 2e3, 1.5e3);
  bd.rotational_stiffness = Vec3(5, 8, 3);
  bd.translational_damping = Vec3(10, 20, 15);
  bd.rotational_damping = Vec3(0.1, 0.2, 0.3);
  m.AddForce(std::make_unique<Bushing>("bushing", bd), mid, tip);
  SpringDamperLaw sl;
  sl.stiffness = 800.0;
  sl.damping = 12.0;
  sl.free_length = 0.2;
  m.AddForce(std::make_unique<SpringDamper>("hang", sl), anchor, tip);
}

struct Assembled {
  MatX S, B;
  VecX Q, Ma;
  int nnz = 0;
};

// assembles at a perturbed state (random coordinates, velocities and
// multipliers from a fixed seed, so both models see the same state)
Assembled Assemble(std::unique_ptr<Body> body, int n) {
  Model m;
  const int b = m.AddBody(std::move(body));
  AddLinks(m, b, n);
  m.Finalize();
  State s = m.InitialState();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < m.nv; ++k) {
    s.q(k) += 0.02 * u(rng);
    s.v(k) = 0.5 * u(rng);
  }
  for (int k = 0; k < m.nc; ++k) s.lambda(k) = 10.0 * u(rng);
  Workspace ws;
  InitWorkspace(m, ws);
  EvaluateMarkers(m, s, ws);
  EvaluateConstraints(m, s, ws);
  EvaluateForces(m, s, ws, true);
  MatrixCoefficients c;
  c.mass = 1.3;
  c.damping = 0.7;
  c.stiffness = 2.1;
  AssembleIterationMatrix(m, s, ws, c);
  Assembled out;
  out.S = MatX(ws.S);
  out.B = MatX(ws.B);
  out.Q = ws.Q;
  VecX a(m.nv);
  for (int k = 0; k < m.nv; ++k) a(k) = u(rng);
  out.Ma.setZero(m.nv);
  MassTimes(m, ws, a, out.Ma);
  out.nnz = static_cast<int>(ws.S.nonZeros());
  return out;
}

void ExpectSame(const Assembled& sparse, const Assembled& dense) {
  ASSERT_EQ(sparse.S.rows(), dense.S.rows());
  const double tol = 1e-13 * dense.S.cwiseAbs().maxCoeff();
  EXPECT_LE((sparse.S - dense.S).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((sparse.B - dense.B).cwiseAbs().maxCoeff(), 1e-13 * dense.B.cwiseAbs().maxCoeff());
  EXPECT_LE((sparse.Q - dense.Q).cwiseAbs().maxCoeff(), 1e-13 * dense.Q.cwiseAbs().maxCoeff());
  EXPECT_LE((sparse.Ma - dense.Ma).cwiseAbs().maxCoeff(), 1e-13 * dense.Ma.cwiseAbs().maxCoeff());
  EXPECT_LT(sparse.nnz, dense.nnz);
}

TEST(SparseBodyBlocks, CableMatrixEqualsDenseAssembly) {
  const int n = 8;
  ExpectSame(Assemble(Cable(n), n), Assemble(std::make_unique<Dense<AncfCable3dBody>>(Cable(n)), n));
}

TEST(SparseBodyBlocks, BeamMatrixEqualsDenseAssembly) {
  const int n = 8;
  ExpectSame(Assemble(Beam(n), n), Assemble(std::make_unique<Dense<AncfBeam2dBody>>(Beam(n)), n));
}

TEST(SparseBodyBlocks, NonZerosGrowLinearlyWithElements) {
  // each element adds its 12 x 12 (3D) or 8 x 8 (2D) block less the 6 x 6
  // (4 x 4) block of the node it shares; the links add a fixed count
  const int c8 = Assemble(Cable(8), 8).nnz, c16 = Assemble(Cable(16), 16).nnz;
  const int c32 = Assemble(Cable(32), 32).nnz;
  EXPECT_EQ(c16 - c8, 8 * (144 - 36));
  EXPECT_EQ(c32 - c16, 16 * (144 - 36));
  const int b8 = Assemble(Beam(8), 8).nnz, b16 = Assemble(Beam(16), 16).nnz;
  const int b32 = Assemble(Beam(32), 32).nnz;
  EXPECT_EQ(b16 - b8, 8 * (64 - 16));
  EXPECT_EQ(b32 - b16, 16 * (64 - 16));
}

TEST(SparseBodyBlocks, WritingOutsideThePatternIsAnError) {
  // a body that writes dQ/dv outside its declared pattern (the first node's
  // row, the last node's column, far outside the band): the workspace refuses
  // it, naming the body; the same body keeping to its pattern is accepted
  for (const bool leaky : {false, true}) {
    Model m;
    if (leaky)
      m.AddBody(std::make_unique<Dense<AncfCable3dBody>>(Cable(4), true));
    else
      m.AddBody(Cable(4));
    m.Finalize();
    Workspace ws;
    if (!leaky) {
      EXPECT_NO_THROW(InitWorkspace(m, ws));
      continue;
    }
    try {
      InitWorkspace(m, ws);
      ADD_FAILURE() << "no error for a body writing outside its pattern";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("body 'beam'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("outside its declared block pattern"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace flexmb
