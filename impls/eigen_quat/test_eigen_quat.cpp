// eigen_quat: facts about Eigen 3.4 that the suite relies on or reports, as executable checks,
// and a short smoke test of the adapter against the reference. The systematic clause-by-clause
// run is the conformance engine's job, not this file's.
#include <Eigen/Geometry>

#include <array>
#include <cstdint>

#include <gtest/gtest.h>

#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/quat_library_checks.hpp>

extern "C" const rc_impl* rotorcert_impl_entry_eigen_quat(std::uint32_t abi, std::uint32_t index);

namespace {

// Conversions, verdicts and the checks shared with glm_quat's test: rotorcert/testing/quat_library_checks.hpp.
using namespace rotorcert::testing::quat_library;
namespace clause = rotorcert::ref::clause;

const rc_impl* find_table(std::uint32_t scalar) {
  return rotorcert::testing::quat_library::find_table(&rotorcert_impl_entry_eigen_quat, "eigen_quat", scalar);
}
template <class S> const Ops<S>* ops() { return ops_of<S>(&rotorcert_impl_entry_eigen_quat, "eigen_quat"); }

// ---- QUAT-3: storage order --------------------------------------------------------------------

TEST(EigenQuat, ConstructorTakesWxyzAndMemoryHoldsXyzw) {
  RC_CLAUSE("QUAT-3");
  const Eigen::Quaternionf q(1.0f, 2.0f, 3.0f, 4.0f);  // w, x, y, z
  expect_memory_holds_xyzw(q, Eigen::Quaterniond(1.0, 2.0, 3.0, 4.0));
  EXPECT_EQ(q.coeffs()[0], 2.0f);  // coeffs() is [x, y, z, w]
  EXPECT_EQ(q.coeffs()[3], 1.0f);
  const float xyzw[4] = {2.0f, 3.0f, 4.0f, 1.0f};
  const Eigen::Map<const Eigen::Quaternionf> mapped(xyzw);  // Map reads x, y, z, w
  EXPECT_EQ(mapped.w(), 1.0f);
  EXPECT_EQ(mapped.x(), 2.0f);
}

TEST(EigenQuat, AdapterKeepsTheAbiOrder) {
  RC_CLAUSE("QUAT-3");
  adapter_keeps_the_abi_order(*ops<float>(), *ops<double>());
}

// ---- AXANG-1: AngleAxis canonicalises to [0, pi] ---------------------------------------------

TEST(EigenQuat, AngleAxisCanonicalisesTheAngleToAtMostPi) {
  RC_CLAUSE("AXANG-1");
  // 6.0 rad about z: Eigen returns 2 pi - 6 about -z (the same rotation), AXANG-1 defines
  // theta = 2 atan2(|v|, w) = 6.0 about +z. A defined-form difference, reported as FAIL.
  const Q<float> q6{0, 0, 0x1.210386p-3f, -0x1.fae04cp-1f};
  float angle = 0;
  V<float> axis;
  std::uint8_t st = 0xff;
  ops<float>()->to_axis_angle(1, q6.data(), &angle, axis.data(), &st);
  EXPECT_EQ(angle, 0x1.21fb54p-2f);
  EXPECT_EQ(axis, (V<float>{0, 0, -1}));
  const auto r = clause::AXANG_1_to_axis_angle(exact(q6));
  EXPECT_EQ(verdict<float>(abs(Real(angle) - r.value.angle), "eps16"), Verdict::fail);
  // q = -1: Eigen gives angle 0 about (1, 0, 0); AXANG-1 gives 2 pi about (0, 0, 1).
  const Q<float> minus_one{0, 0, 0, -1};
  ops<float>()->to_axis_angle(1, minus_one.data(), &angle, axis.data(), &st);
  EXPECT_EQ(angle, 0.0f);
  EXPECT_EQ(axis, (V<float>{1, 0, 0}));
}

// ---- EDGE-6 / EDGE-8: normalized() -----------------------------------------------------------

TEST(EigenQuat, NormalizedOfZeroIsZeroNotDomainError) {
  RC_CLAUSE("EDGE-6");
  const Q<float> zero{0, 0, 0, 0};
  Q<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->normalize(1, zero.data(), out.data(), &st);
  EXPECT_EQ(st, RC_OK);                     // not DOMAIN_ERROR, but the all-zero sentinel of ACC-1
  EXPECT_EQ(out, (Q<float>{0, 0, 0, 0}));  // (zero_sentinel, spec 2.2.0); inverse() likewise returns 0
  ops<float>()->inverse(1, zero.data(), out.data(), &st);
  EXPECT_EQ(out, (Q<float>{0, 0, 0, 0}));
}

TEST(EigenQuat, NormalizedOfSubnormalIsUnchanged) {
  RC_CLAUSE("EDGE-8");
  // squaredNorm() underflows to 0, so normalized() returns its input: not unit.
  const Q<float> tiny{0x1p-149f, 0, 0, 0};
  Q<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->normalize(1, tiny.data(), out.data(), &st);
  EXPECT_EQ(out, tiny);
  EXPECT_EQ(verdict<float>(clause::METRIC_6_norm_defect(exact(out)), "eps4"), Verdict::fail);
}

// ---- SLERP-1 / EDGE-3: Eigen's slerp flips ------------------------------------------------------

TEST(EigenQuat, SlerpFlipsObtusePairsAndIsConstantOnAntipodes) {
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("EDGE-3");
  const Q<float> a{0, 0, 0, 1}, minus_a{0, 0, 0, -1}, b{0, 0, -0x1.eaee88p-2f, -0x1.c1528p-1f};  // b = -(1 rad about z)
  const float half = 0.5f, quarter = 0.25f;
  Q<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->slerp(1, a.data(), b.data(), &half, out.data(), &st);
  const auto r = clause::SLERP_1_slerp(exact(a), exact(b), Real(half));
  EXPECT_EQ(verdict<float>(clause::METRIC_1_rotation_distance(exact(out), r.value), "eps16"), Verdict::pass);
  EXPECT_GT(out[3], 0.0f);  // on a's side
  ops<float>()->slerp(1, a.data(), minus_a.data(), &quarter, out.data(), &st);
  EXPECT_EQ(out, a);
}

// ---- smoke test against the reference ---------------------------------------------------------

/// The smoke test shared with glm_quat on Eigen's rounding of its inputs, and NLERP-1.
template <class S> class EigenQuatSmoke : public ::testing::Test {};
TYPED_TEST_SUITE(EigenQuatSmoke, Formats);

TYPED_TEST(EigenQuatSmoke, AgainstReference) {
  using S = TypeParam;
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("NLERP-1");
  // Unit quaternions rounded to S (2 rad about (1,2,2)/3 and 0.7 rad about (0,0.6,0.8)).
  const Eigen::Quaternion<S> ea(Eigen::AngleAxis<S>(S(2), Eigen::Matrix<S, 3, 1>(S(1) / S(3), S(2) / S(3), S(2) / S(3))));
  const Eigen::Quaternion<S> eb(Eigen::AngleAxis<S>(S(0.7), Eigen::Matrix<S, 3, 1>(S(0), S(0.6), S(0.8))));
  const Q<S> a{ea.x(), ea.y(), ea.z(), ea.w()}, b{eb.x(), eb.y(), eb.z(), eb.w()};
  smoke_against_reference<S>(*ops<S>(), a, b);
  const S t = S(0.3);
  Q<S> q;
  std::uint8_t st = 0xff;
  ops<S>()->nlerp(1, a.data(), b.data(), &t, q.data(), &st);
  const auto rn = clause::NLERP_1_nlerp(exact(a), exact(b), Real(t)).value;
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), rn), "eps16"), Verdict::pass);
}

TEST(EigenQuat, TablesDeclareWhatTheyClaim) {
  // NOT_SUPPORTED is declared by a NULL slot, before any run (RESULT-1, judged by the certify tool)
  const rc_impl* f = find_table(RC_SCALAR_FLOAT32);
  const rc_impl* d = find_table(RC_SCALAR_FLOAT64);
  ASSERT_TRUE(f && d);
  EXPECT_EQ(f->f32->log, nullptr);  // Eigen has no quaternion log/exp
  EXPECT_EQ(f->f32->exp, nullptr);
  EXPECT_EQ(f->f32->blend_log, nullptr);
  EXPECT_EQ(d->f64->dq_compose, nullptr);  // nor dual quaternions
  EXPECT_NE(d->f64->blend_qlb, nullptr);
}

}  // namespace
