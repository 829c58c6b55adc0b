// glm_quat: facts about GLM 0.9.9.8 that the suite relies on or reports, as executable checks,
// and a short smoke test of the adapter against the reference. The systematic clause-by-clause
// run is the conformance engine's job, not this file's.
//
// The defects below are GLM's and stay in the adapter on purpose: each test states what GLM
// returns and which clause that breaks (the expected verdict is FAIL).
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>  // glm::log, glm::exp of quaternions
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/dual_quaternion.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/quat_library_checks.hpp>
#include <rotorcert/testing/tolerance.hpp>

extern "C" const rc_impl* rotorcert_impl_entry_glm_quat(std::uint32_t abi, std::uint32_t index);

namespace {

// Conversions, verdicts and the checks shared with eigen_quat's test: rotorcert/testing/quat_library_checks.hpp.
using namespace rotorcert::testing::quat_library;
namespace clause = rotorcert::ref::clause;

// ---- access to the adapter's tables --------------------------------------------------------------

const rc_impl* find_table(const std::string& name, std::uint32_t scalar) {
  return rotorcert::testing::quat_library::find_table(&rotorcert_impl_entry_glm_quat, name, scalar);
}
template <class S> const Ops<S>* ops(const std::string& name = "glm_quat") {
  return ops_of<S>(&rotorcert_impl_entry_glm_quat, name);
}

template <class S> Q<S> slerp_via(const char* table, const Q<S>& a, const Q<S>& b, S t) {
  Q<S> out;
  std::uint8_t st = 0xff;
  ops<S>(table)->slerp(1, a.data(), b.data(), &t, out.data(), &st);
  EXPECT_EQ(st, RC_OK);
  return out;
}

// ---- QUAT-3: storage order --------------------------------------------------------------------

TEST(GlmQuat, ConstructorTakesWxyzAndMemoryHoldsXyzw) {
  RC_CLAUSE("QUAT-3");
  const glm::quat q(1.0f, 2.0f, 3.0f, 4.0f);  // w, x, y, z
  expect_memory_holds_xyzw(q, glm::dquat(1.0, 2.0, 3.0, 4.0));
  EXPECT_EQ(q[0], 2.0f);                   // operator[] follows memory order
  EXPECT_EQ(glm::value_ptr(q)[3], 1.0f);  // so does value_ptr
}

TEST(GlmQuat, AdapterKeepsTheAbiOrder) {
  RC_CLAUSE("QUAT-3");
  adapter_keeps_the_abi_order(*ops<float>(), *ops<double>());
}

// ---- AXANG-1: glm::angle above 2 pi - 1 -------------------------------------------------------

TEST(GlmQuat, AngleAboveTwoPiMinusOneReturnsTwoPiMinusTheta) {
  RC_CLAUSE("AXANG-1");
  // The quaternion of a 6.0 rad rotation about z. |w| > cos(1/2), so glm::angle takes the
  // 2 asin|v| branch, which is right only for w > 0: it returns 2 pi - 6 = 0.2832, a different
  // rotation (glm::axis still says +z).
  const Q<float> q6{0, 0, 0x1.210386p-3f, -0x1.fae04cp-1f};
  const glm::quat g = glm::angleAxis(6.0f, glm::vec3(0, 0, 1));
  ASSERT_EQ(g.z, q6[2]);
  ASSERT_EQ(g.w, q6[3]);
  float angle = 0;
  V<float> axis;
  std::uint8_t st = 0xff;
  ops<float>()->to_axis_angle(1, q6.data(), &angle, axis.data(), &st);
  EXPECT_EQ(angle, 0x1.21fb54p-2f);
  EXPECT_EQ(axis[0], 0.0f);  // axis +z: together with 2 pi - 6 a rotation by -6 rad
  EXPECT_EQ(axis[1], 0.0f);
  EXPECT_GT(axis[2], 0.0f);
  const auto r = clause::AXANG_1_to_axis_angle(exact(q6));
  EXPECT_EQ(verdict<float>(abs(Real(angle) - r.value.angle), "eps16"), Verdict::fail);

  const Q<double> q6d{0, 0, 0x1.210386db6d55bp-3, -0x1.fae04be85e5d2p-1};
  const glm::dquat gd = glm::angleAxis(6.0, glm::dvec3(0, 0, 1));
  ASSERT_EQ(gd.z, q6d[2]);
  ASSERT_EQ(gd.w, q6d[3]);
  EXPECT_EQ(glm::angle(gd), 0x1.21fb54442d184p-2);
  const auto rd = clause::AXANG_1_to_axis_angle(exact(q6d));
  EXPECT_EQ(verdict<double>(abs(Real(glm::angle(gd)) - rd.value.angle), "eps16"), Verdict::fail);

  // Below 2 pi - 1 (5.0 rad: |w| = 0.80 < cos(1/2)) the acos branch gives the right angle.
  const glm::quat g5 = glm::angleAxis(5.0f, glm::vec3(0, 0, 1));
  const auto r5 = clause::AXANG_1_to_axis_angle(exact(Q<float>{g5.x, g5.y, g5.z, g5.w}));
  EXPECT_NE(verdict<float>(abs(Real(glm::angle(g5)) - r5.value.angle), "eps16"), Verdict::fail);
}

// ---- LOG-2: glm::log of a negative real quaternion ---------------------------------------------

TEST(GlmQuat, LogOfMinusOneIsPiAboutX) {
  RC_CLAUSE("LOG-2");
  // glm::log, |v| < epsilon and w < 0: (w, x, y, z) = (log|w|, pi, 0, 0). The rotation is right
  // (exp gives -1 back) but LOG-2 defines (0, 0, pi): axis +z.
  const glm::quat l = glm::log(glm::quat(-1.0f, 0, 0, 0));
  EXPECT_EQ(l.w, 0.0f);
  EXPECT_EQ(l.x, 0x1.921fb6p+1f);
  const Q<float> minus_one{0, 0, 0, -1};
  V<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->log(1, minus_one.data(), out.data(), &st);
  EXPECT_EQ(out, (V<float>{0x1.921fb6p+1f, 0, 0}));
  const auto r = clause::LOG_1_log(exact(minus_one));
  EXPECT_EQ(verdict<float>(clause::METRIC_5_bivector_error(exact(out), r.value), "eps16"), Verdict::fail);
}

TEST(GlmQuat, LogScalarPartIsLogNormAndVectorPartIsScaleFree) {
  RC_CLAUSE("LOG-1");
  // glm::log is the full quaternion log: w = log|q|, (x, y, z) = atan(|v|, w) v/|v|, which
  // does not depend on |q|. The adapter drops w.
  const glm::quat q = glm::angleAxis(2.0f, glm::vec3(0, 0.6f, 0.8f));
  const glm::quat l1 = glm::log(q), l4 = glm::log(4.0f * q);
  const V<float> v1{l1.x, l1.y, l1.z}, v4{l4.x, l4.y, l4.z};
  EXPECT_EQ(verdict<float>(clause::METRIC_5_bivector_error(exact(v1), exact(v4)), "eps16"), Verdict::pass);
  EXPECT_EQ(verdict<float>(abs(Real(l4.w) - log(Real(4))), "eps16"), Verdict::pass);
  EXPECT_EQ(verdict<float>(abs(Real(l1.w)), "eps16"), Verdict::pass);
}

// ---- EDGE-1 / EXP-1: glm::exp near zero ---------------------------------------------------------

TEST(GlmQuat, ExpOfZeroIsTheZeroQuaternion) {
  RC_CLAUSE("EDGE-1");
  RC_CLAUSE("EXP-1");
  // glm::exp returns qua<T>() when |v| < epsilon; with the default configuration (no
  // GLM_FORCE_CTOR_INIT) that value-initialises to (0, 0, 0, 0), not the identity. So
  // exp(0) = 0 (EDGE-1 wants 1 exactly) and exp of any |v| < 2^-23 (float) is no rotation at all.
  for (const V<float> v : {V<float>{0, 0, 0}, V<float>{0x1p-24f, 0, 0}}) {
    Q<float> out;
    std::uint8_t st = 0xff;
    ops<float>()->exp(1, v.data(), out.data(), &st);
    EXPECT_EQ(out, (Q<float>{0, 0, 0, 0}));
  }
}

// ---- SLERP-1 / EDGE-3: glm::mix -----------------------------------------------------------------

TEST(GlmMix, ObtusePairTakesTheLongArc) {
  RC_CLAUSE("SLERP-1");
  // a = 1, b = -(1 rad about z): a . b = -cos(1/2) < 0. glm::mix does not flip b, so its
  // midpoint is the half-turn-away point of the long arc; glm::slerp flips and is right.
  const Q<float> a{0, 0, 0, 1}, b{0, 0, -0x1.eaee88p-2f, -0x1.c1528p-1f};
  const glm::quat g = -glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
  ASSERT_EQ(g.z, b[2]);
  ASSERT_EQ(g.w, b[3]);
  const auto r = clause::SLERP_1_slerp(exact(a), exact(b), Real(0.5));
  const Q<float> mixed = slerp_via<float>("glm_mix", a, b, 0.5f);
  EXPECT_GT(clause::METRIC_1_rotation_distance(exact(mixed), r.value), Real(3));  // about pi
  EXPECT_EQ(verdict<float>(clause::METRIC_1_rotation_distance(exact(mixed), r.value), "eps16"), Verdict::fail);
  const Q<float> slerped = slerp_via<float>("glm_quat", a, b, 0.5f);
  EXPECT_EQ(verdict<float>(clause::METRIC_1_rotation_distance(exact(slerped), r.value), "eps16"), Verdict::pass);
}

TEST(GlmMix, ObtusePairEndsAtMinusBPrime) {
  RC_CLAUSE("SLERP-3");
  // SLERP-3: slerp(a, b, 1) = b' = -b for an obtuse pair, and -b' is a FAIL. glm::mix(a, b, 1)
  // is b itself (sin(0) a + sin(W) b) / sin(W)).
  const Q<float> a{0, 0, 0, 1}, b{0, 0, -0x1.eaee88p-2f, -0x1.c1528p-1f};
  EXPECT_EQ(slerp_via<float>("glm_mix", a, b, 1.0f), b);
  const Q<float> slerped = slerp_via<float>("glm_quat", a, b, 1.0f);
  EXPECT_GT(slerped[3], 0.0f);  // glm::slerp ends at b' = -b
}

TEST(GlmMix, ExactAntipodeGivesZeroOrNonUnitGarbage) {
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("EDGE-3");
  // a = 1, b = -1: dot = -1, acos = pi, and mix divides sin((1-t) pi) - sin(t pi) by sin(pi).
  // EDGE-3: an exact antipode flips and the interpolation is the constant 1.
  const Q<float> a{0, 0, 0, 1}, b{0, 0, 0, -1};
  const Q<float> mid = slerp_via<float>("glm_mix", a, b, 0.5f);
  EXPECT_EQ(mid, (Q<float>{0, 0, 0, 0}));  // the zero quaternion, status OK
  const Q<float> early = slerp_via<float>("glm_mix", a, b, 0x1.333334p-3f);  // t = 0.15
  EXPECT_GT(clause::METRIC_6_norm_defect(exact(early)), Real(0.5));   // far from unit
  EXPECT_EQ(slerp_via<float>("glm_quat", a, b, 0.5f), a);                 // glm::slerp: constant 1
  // binary64: the same cancellation, non-unit garbage instead of zero.
  const Q<double> ad{0, 0, 0, 1}, bd{0, 0, 0, -1};
  const Q<double> md = slerp_via<double>("glm_quat", ad, bd, 0.25);
  EXPECT_EQ(md, ad);
  const glm::dquat gd = glm::mix(glm::dquat(1, 0, 0, 0), glm::dquat(-1, 0, 0, 0), 0.25);
  EXPECT_GT(clause::METRIC_6_norm_defect(exact(Q<double>{gd.x, gd.y, gd.z, gd.w})), Real(0.01));
}

TEST(GlmMix, RoundedAntipodeGivesNaN) {
  RC_CLAUSE("SLERP-1");
  // A normalised q whose float dot with -q rounds to -(1 + 2^-23): acos of it is NaN, so every
  // component of glm::mix(q, -q, t) is NaN for every t, even t = 0 (SLERP-3 wants q there).
  const Q<float> q{0x1.4264a8p-2f, 0x1.6bc1bp-1f, -0x1.e5ace2p-4f, 0x1.3c791ap-1f};
  const Q<float> mq{-q[0], -q[1], -q[2], -q[3]};
  const glm::quat g(q[3], q[0], q[1], q[2]);
  ASSERT_EQ(glm::dot(g, -g), -0x1.000002p+0f);
  for (const float t : {0.0f, 0.25f, 1.0f}) {
    const Q<float> m = slerp_via<float>("glm_mix", q, mq, t);
    for (const float c : m) EXPECT_TRUE(std::isnan(c)) << "t = " << t;
    EXPECT_EQ(slerp_via<float>("glm_quat", q, mq, t), q);  // glm::slerp flips: constant q
  }
}

// ---- EDGE-6 / EDGE-8: glm::normalize ---------------------------------------------------------

TEST(GlmQuat, NormalizeOfZeroIsIdentityNotDomainError) {
  RC_CLAUSE("EDGE-6");
  const Q<float> zero{0, 0, 0, 0};
  Q<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->normalize(1, zero.data(), out.data(), &st);
  EXPECT_EQ(st, RC_OK);                          // EDGE-6 wants DOMAIN_ERROR
  EXPECT_EQ(out, (Q<float>{0, 0, 0, 1}));       // and NaN, not the identity
}

TEST(GlmQuat, NormalizeOfSubnormalIsIdentity) {
  RC_CLAUSE("EDGE-8");
  // |q|^2 underflows to 0, and glm::normalize answers "no length" with the identity:
  // a half turn about x becomes no rotation at all.
  const Q<float> tiny{0x1p-149f, 0, 0, 0};
  Q<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->normalize(1, tiny.data(), out.data(), &st);
  EXPECT_EQ(out, (Q<float>{0, 0, 0, 1}));
  const auto r = clause::NORM_1_normalize(exact(tiny));
  EXPECT_EQ(verdict<float>(clause::METRIC_1_rotation_distance(exact(out), r.value), "eps4"), Verdict::fail);
}

// ---- DQ-4: glm::normalize(dualquat) -----------------------------------------------------------

TEST(GlmQuat, DualQuaternionNormalizeKeepsTheDualPartAlongTheReal) {
  RC_CLAUSE("DQ-4");
  // real 2, dual 1 (the dual part lies along the real part): DQ-4 gives (1, 0); GLM divides
  // both by |real| = 2 and returns (1, 1/2), so real . dual = 1/2, not 0.
  const std::array<float, 8> d{0, 0, 0, 2, 0, 0, 0, 1};
  std::array<float, 8> out;
  std::uint8_t st = 0xff;
  ops<float>()->dq_normalize(1, d.data(), out.data(), &st);
  EXPECT_EQ(out, (std::array<float, 8>{0, 0, 0, 1, 0, 0, 0, 0.5f}));
  const auto r = clause::DQ_4_normalize(rotorcert::ref::DualQuaternion<Real>{RQ{Real(2), 0, 0, 0}, RQ{Real(1), 0, 0, 0}});
  EXPECT_EQ(r.value.dual.w, Real(0));
}

// ---- smoke test against the reference ---------------------------------------------------------

/// The smoke test shared with eigen_quat, on GLM's rounding of its inputs.
template <class S> class GlmQuatSmoke : public ::testing::Test {};
TYPED_TEST_SUITE(GlmQuatSmoke, Formats);

TYPED_TEST(GlmQuatSmoke, AgainstReference) {
  using S = TypeParam;
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("SLERP-1");
  // Unit quaternions rounded to S (a 2 rad turn about (1,2,2)/3 and a 0.7 rad turn about (0,0.6,0.8)).
  const glm::qua<S> ga = glm::angleAxis(S(2), glm::vec<3, S>(S(1) / S(3), S(2) / S(3), S(2) / S(3)));
  const glm::qua<S> gb = glm::angleAxis(S(0.7), glm::vec<3, S>(S(0), S(0.6), S(0.8)));
  smoke_against_reference<S>(*ops<S>(), Q<S>{ga.x, ga.y, ga.z, ga.w}, Q<S>{gb.x, gb.y, gb.z, gb.w});
}

TEST(GlmQuat, TablesDeclareWhatTheyClaim) {
  // NOT_SUPPORTED is declared by a NULL slot, before any run (RESULT-1, judged by the certify tool)
  const rc_impl* f = find_table("glm_quat", RC_SCALAR_FLOAT32);
  const rc_impl* d = find_table("glm_quat", RC_SCALAR_FLOAT64);
  const rc_impl* m = find_table("glm_mix", RC_SCALAR_FLOAT32);
  ASSERT_TRUE(f && d && m);
  EXPECT_EQ(f->f32->dq_sclerp, nullptr);  // GLM has no ScLERP
  EXPECT_EQ(f->f32->blend_log, nullptr);  // nor a log-blend
  EXPECT_NE(f->f32->log, nullptr);
  EXPECT_EQ(m->levels, static_cast<std::uint32_t>(RC_LEVEL_INTERP));
  EXPECT_EQ(m->f32->normalize, nullptr);
}

}  // namespace
