// The integrator's accepted-step path allocates nothing (docs/design.md, hot
// paths). Reference: a count of heap allocations, by replacing the global
// operator new/delete in this translation unit and, on glibc, interposing
// malloc/calloc/realloc (Eigen's dynamic matrices and KLU allocate through
// malloc, not operator new). The replacements live in the whole unit-test
// binary, so they count only while `g_counting` is set.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "flexmb/ancf/ancf_cable3d_body.h"
#include "flexmb/bodies/flexible_body.h"
#include "flexmb/bodies/rigid_body.h"
#include "flexmb/forces/spring_damper.h"
#include "flexmb/joints/revolute.h"
#include "flexmb/joints/spherical.h"
#include "flexmb/solver/generalized_alpha.h"
#include "flexmb/solver/initial_conditions.h"
#include "flexmb/solver/simulator.h"
#include "flexmb/solver/sparse_lu.h"
#include "tests/unit/bodies/flexible_test_bodies.h"

#if defined(__SANITIZE_ADDRESS__)
#define FLEXMB_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FLEXMB_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef FLEXMB_COUNT_ALLOCATIONS
#define FLEXMB_COUNT_ALLOCATIONS 1
#endif

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_new_calls{0};     // operator new (all forms)
std::atomic<long> g_malloc_calls{0};  // malloc, calloc, realloc (glibc only)

void* CountedNew(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_new_calls.fetch_add(1, std::memory_order_relaxed);
  void* p = std::malloc(n ? n : 1);
  if (!p) throw std::bad_alloc();
  return p;
}

void* CountedAlignedNew(std::size_t n, std::align_val_t al) {
  if (g_counting.load(std::memory_order_relaxed)) g_new_calls.fetch_add(1, std::memory_order_relaxed);
  const std::size_t a = static_cast<std::size_t>(al);
  void* p = std::aligned_alloc(a, ((n ? n : 1) + a - 1) / a * a);
  if (!p) throw std::bad_alloc();
  return p;
}

}  // namespace

#if FLEXMB_COUNT_ALLOCATIONS
void* operator new(std::size_t n) { return CountedNew(n); }
void* operator new[](std::size_t n) { return CountedNew(n); }
void* operator new(std::size_t n, std::align_val_t a) { return CountedAlignedNew(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return CountedAlignedNew(n, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

#if defined(__GLIBC__)
#define FLEXMB_COUNT_MALLOC 1
// glibc's documented way to replace malloc: define malloc, calloc, realloc
// (forwarding to the glibc allocator, so free and memalign stay compatible)
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);

void* malloc(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_malloc_calls.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t s) {
  if (g_counting.load(std::memory_order_relaxed)) g_malloc_calls.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, s);
}
void* realloc(void* p, std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_malloc_calls.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, n);
}
}
#endif
#endif

#ifndef FLEXMB_COUNT_MALLOC
#define FLEXMB_COUNT_MALLOC 0
#endif

namespace flexmb {
namespace {

/// Counts the allocations made between construction and stop().
class AllocationCount {
 public:
  AllocationCount() {
    news_ = g_new_calls.load();
    mallocs_ = g_malloc_calls.load();
    g_counting.store(true);
  }
  ~AllocationCount() { g_counting.store(false); }
  void stop() {
    g_counting.store(false);
    news_ = g_new_calls.load() - news_;
    mallocs_ = g_malloc_calls.load() - mallocs_;
  }
  long news() const { return news_; }
  long mallocs() const { return mallocs_; }

 private:
  long news_ = 0, mallocs_ = 0;
};

// keeps the optimizer from removing an allocation whose result is unused
void Escape(const void* p) { asm volatile("" : : "g"(p) : "memory"); }

// A revolute pendulum (rod pinned at (0, 0, 2)), a 3-link spherical chain
// pinned at the origin, and a spring-damper from the chain tip to the ground,
// released horizontal under gravity -y.
std::unique_ptr<Model> MakeModel() {
  auto m = std::make_unique<Model>();
  m->gravity_W = Vec3(0, -9.81, 0);
  auto rod = [](const Vec3& p_WB) {
    RigidBodyData d;
    d.mass = 1.0;
    d.inertia_C = Vec3(1e-4, 1.0 / 12, 1.0 / 12).asDiagonal();
    d.c_B = Vec3(0.5, 0, 0);
    d.p_WB = p_WB;
    return d;
  };
  const int p = m->AddBody(std::make_unique<RigidBody>("pendulum", rod(Vec3(0, 0, 2))));
  m->AddJoint(std::make_unique<RevoluteJoint>("hinge"), m->AddMarker(0, "hinge", Vec3(0, 0, 2), Mat3::Identity()),
              m->AddMarker(p, "a", Vec3::Zero(), Mat3::Identity()));
  int prev = m->AddMarker(0, "pin", Vec3::Zero(), Mat3::Identity());
  for (int k = 0; k < 3; ++k) {
    const int b = m->AddBody(std::make_unique<RigidBody>("link" + std::to_string(k), rod(Vec3(k, 0, 0))));
    m->AddJoint(std::make_unique<SphericalJoint>("ball" + std::to_string(k)), prev,
                m->AddMarker(b, "a", Vec3::Zero(), Mat3::Identity()));
    prev = m->AddMarker(b, "b", Vec3(1, 0, 0), Mat3::Identity());
  }
  SpringDamperLaw law;
  law.free_length = 3.0;
  law.stiffness = 20.0;
  law.damping = 0.5;
  m->AddForce(std::make_unique<SpringDamper>("spring", law), m->AddMarker(0, "anchor", Vec3(3, 1, 0.5), Mat3::Identity()),
              prev);
  m->solver.dt = 1e-3;
  m->solver.rho_inf = 0.8;
  m->Finalize();
  return m;
}

TEST(NoAllocation, CounterSeesAllocations) {
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  AllocationCount c;
  {
    std::vector<double> v(100, 1.0);
    Escape(v.data());
    VecX x = VecX::Ones(100);
    Escape(x.data());
  }
  c.stop();
  EXPECT_GE(c.news(), 1);
  if (FLEXMB_COUNT_MALLOC) EXPECT_GE(c.mallocs(), 2);  // the vector's (through new) and Eigen's

  // KLU (a shared library) allocates its analysis and factors through malloc
  SparseMat A(2, 2);
  A.insert(0, 0) = 2.0;
  A.insert(1, 1) = 3.0;
  A.makeCompressed();
  SparseLu lu;
  AllocationCount k;
  ASSERT_TRUE(lu.Factorize(A));
  k.stop();
  if (FLEXMB_COUNT_MALLOC) EXPECT_GE(k.mallocs(), 1);
}

// SparseLu's dense path on an n x n matrix: refactorizations and solves
// after the first factorization count no allocation
void ExpectDenseLuAllocatesNothing(int n) {
  SparseMat A(n, n);
  A.reserve(Eigen::VectorXi::Constant(n, n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) A.insert(i, j) = (i == j ? 3.0 * n : 0.0) + std::sin(1.0 + i + 7.0 * j);
  A.makeCompressed();
  SparseLu lu;
  ASSERT_TRUE(lu.Factorize(A));
  ASSERT_TRUE(lu.dense());
  VecX b = VecX::Ones(n);
  AllocationCount c;
  for (int k = 0; k < 3; ++k) {
    A.valuePtr()[k] += 0.5;
    ASSERT_TRUE(lu.Factorize(A));
    lu.Solve(b);
  }
  c.stop();
  EXPECT_GT(b.norm(), 0.0);
  EXPECT_EQ(c.news(), 0) << "operator new calls in dense refactorizations and solves";
  EXPECT_EQ(c.mallocs(), 0) << "malloc/calloc/realloc calls in dense refactorizations and solves";
}

TEST(NoAllocation, DenseLuRefactorAndSolve) {
  // SparseLu's dense path (large, mostly dense matrix): after the first
  // factorization sizes it, refactorizations and solves allocate nothing, also
  // above ~450 rows where a blocked LU's products outgrow Eigen's stack buffers
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  for (const int n : {2 * SparseLu::kDenseMinRows, 600}) {
    SCOPED_TRACE(n);
    ExpectDenseLuAllocatesNothing(n);
  }
}

TEST(NoAllocation, GeneralizedAlphaAcceptedSteps) {
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  auto model = MakeModel();
  const Model& m = *model;
  State s = m.InitialState();
  Workspace ws;
  AllocationCount init;
  MakeConsistent(m, s, ws);
  init.stop();
  EXPECT_GT(init.news() + init.mallocs(), 0) << "the counter must see the engine sizing its workspace";
  GeneralizedAlpha ga(m, ws, m.solver.rho_inf);
  ga.Start(s);
  for (int k = 0; k < 5; ++k) {
    ASSERT_EQ(ga.TryStep(s, m.solver.dt), StepStatus::kConverged);
    ga.Accept(s);
  }
  const VecX q5 = s.q;
  const long its0 = ga.stats.newton_iterations;
  int converged = 0;
  AllocationCount c;
  for (int k = 0; k < 200; ++k) {
    if (ga.TryStep(s, m.solver.dt) != StepStatus::kConverged) break;
    ga.Accept(s);
    ++converged;
  }
  c.stop();
  EXPECT_EQ(converged, 200);
  EXPECT_GT(ga.stats.newton_iterations - its0, 200);  // at least one iteration per step
  EXPECT_GT((s.q - q5).norm(), 0.1);                  // the bodies did move
  EXPECT_EQ(c.news(), 0) << "operator new calls in 200 accepted steps";
  EXPECT_EQ(c.mallocs(), 0) << "malloc/calloc/realloc calls in 200 accepted steps";
}

TEST(NoAllocation, SimulatorRunWithoutObserver) {
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  auto model = MakeModel();
  Simulator sim(*model);
  sim.Initialize();
  sim.Run(0.005, 0.0, nullptr);
  const long steps0 = sim.stats().steps;
  const Observer none;
  AllocationCount c;
  sim.Run(0.205, 0.0, none);
  c.stop();
  EXPECT_EQ(sim.stats().steps - steps0, 200);
  EXPECT_EQ(sim.stats().rejected, 0);
  EXPECT_EQ(c.news(), 0) << "operator new calls in Simulator::Run over 200 steps";
  EXPECT_EQ(c.mallocs(), 0) << "malloc/calloc/realloc calls in Simulator::Run over 200 steps";
}

// body b of m pinned by a spherical joint at its node 0 to the ground, a
// spring-damper from the ground to a point offset from node 6: 100 steps of
// 1 ms after a start-up allocate nothing
void ExpectNoAllocationPinnedAndDamped(Model& m, int b, const Vec3& tip_offset, const std::string& what) {
  m.AddJoint(std::make_unique<SphericalJoint>("pivot"), m.AddMarker(0, "pivot", Vec3::Zero(), Mat3::Identity()),
             m.AddMarker(b, "pivot", Vec3::Zero(), Mat3::Identity(), 0));
  SpringDamperLaw law;
  law.free_length = 0.5;
  law.stiffness = 50.0;
  law.damping = 0.5;
  m.AddForce(std::make_unique<SpringDamper>("spring", law), m.AddMarker(0, "anchor", Vec3(0.8, 0.5, 1.0), Mat3::Identity()),
             m.AddMarker(b, "tip", tip_offset, Mat3::Identity(), 6));
  m.solver.dt = 1e-3;
  m.Finalize();
  Simulator sim(m);
  sim.Initialize();
  sim.Run(0.005, 0.0, nullptr);
  const long steps0 = sim.stats().steps;
  AllocationCount c;
  sim.Run(0.105, 0.0, Observer());
  c.stop();
  EXPECT_EQ(sim.stats().steps - steps0, 100);
  EXPECT_EQ(c.news(), 0) << "operator new calls in 100 steps with " << what;
  EXPECT_EQ(c.mallocs(), 0) << "malloc/calloc/realloc calls in 100 steps with " << what;
}

// a free bent bar of 9 modes (testing::FreeBentBar(3, 3)), spinning at
// w_WB = (0.5, 1, 3) rad/s, added to m; returns its body index
int NoAllocSpinningBentBar(Model& m) {
  FlexibleBodyData d;
  d.reduced = testing::FreeBentBar(3, 3);
  d.w_WB = Vec3(0.5, 1.0, 3.0);
  return m.AddBody(std::make_unique<FlexibleBody>("bar", d));
}

TEST(NoAllocation, FlexibleBodySteps) {
  // a floating-frame flexible body (9 modes) hanging from a spherical joint
  // at a node, a damper on another node: body forces, tangents and markers
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  Model m;
  const int b = NoAllocSpinningBentBar(m);
  ExpectNoAllocationPinnedAndDamped(m, b, Vec3(0, 0, 0.01), "a flexible body");
}

TEST(NoAllocation, FlexibleBodyStepsWithJacobianReuse) {
  // the same with modified Newton: iterations without force derivatives
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  Model m;
  const int b = NoAllocSpinningBentBar(m);
  m.solver.jacobian_reuse = true;
  ExpectNoAllocationPinnedAndDamped(m, b, Vec3(0, 0, 0.01), "a flexible body and Jacobian reuse");
}

TEST(NoAllocation, AncfCableSteps) {
  // a 3D ANCF cable (sparse body blocks, node markers) on a spherical pin,
  // a damper on its end node
  if (!FLEXMB_COUNT_ALLOCATIONS) GTEST_SKIP() << "allocation counting is off under AddressSanitizer";
  Model m;
  ancf::AncfCable3dData d;
  d.length = 1.2;
  d.elements = 6;
  d.section.E = 0.7e6;
  d.section.A = 0.0018;
  d.section.I = 1.215e-8;
  d.section.rho = 5540.0;
  d.section.damping = 0.01;
  m.gravity_W = Vec3(0, -9.81, 0);
  const int b = m.AddBody(std::make_unique<ancf::AncfCable3dBody>("cable", d));
  ExpectNoAllocationPinnedAndDamped(m, b, Vec3(0, 0.01, 0), "an ANCF cable");
}

}  // namespace
}  // namespace flexmb
