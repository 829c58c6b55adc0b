// eigen_quat: facts about Eigen 3.4 that the suite relies on or reports, as executable checks,
// and a short smoke test of the adapter against the reference. The systematic clause-by-clause
// run is the conformance engine's job, not this file's.
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/tolerance.hpp>

extern "C" const rc_impl* rotorcert_impl_entry_eigen_quat(std::uint32_t abi, std::uint32_t index);

namespace {

using rotorcert::ref::Format;
using rotorcert::ref::Real;
using rotorcert::ref::Verdict;
namespace clause = rotorcert::ref::clause;
using RQ = rotorcert::ref::Quaternion<Real>;
using rotorcert::testing::eps_class_bars;

const rc_impl* find_table(std::uint32_t scalar) {
  for (std::uint32_t i = 0;; ++i) {
    const rc_impl* t = rotorcert_impl_entry_eigen_quat(RC_ABI_VERSION, i);
    if (t == nullptr) return nullptr;
    if (std::string(t->name) == "eigen_quat" && t->scalar == scalar) return t;
  }
}
template <class S> const auto* ops() {
  if constexpr (sizeof(S) == 4) return find_table(RC_SCALAR_FLOAT32)->f32;
  else return find_table(RC_SCALAR_FLOAT64)->f64;
}
template <class S> constexpr Format format() { return sizeof(S) == 4 ? Format::binary32 : Format::binary64; }

template <class S> using Q = std::array<S, 4>;  // ABI order [x, y, z, w]
template <class S> using V = std::array<S, 3>;

/// The exact value of an input or output at the reference precision (NUM-2).
template <class S> RQ exact(const Q<S>& q) { return RQ::from_xyzw({Real(q[0]), Real(q[1]), Real(q[2]), Real(q[3])}); }
template <class S> rotorcert::ref::Vec3<Real> exact(const V<S>& v) { return {Real(v[0]), Real(v[1]), Real(v[2])}; }

template <class S> Verdict verdict(const Real& err, const char* cls) {
  return clause::TOL_1_verdict(clause::METRIC_2_eps_units(err, format<S>()).toDouble(), eps_class_bars(cls));
}

// ---- QUAT-3: storage order --------------------------------------------------------------------

TEST(EigenQuat, ConstructorTakesWxyzAndMemoryHoldsXyzw) {
  RC_CLAUSE("QUAT-3");
  static_assert(sizeof(Eigen::Quaternionf) == 4 * sizeof(float) && sizeof(Eigen::Quaterniond) == 4 * sizeof(double));
  const Eigen::Quaternionf q(1.0f, 2.0f, 3.0f, 4.0f);  // w, x, y, z
  float mem[4];
  std::memcpy(mem, &q, sizeof mem);
  EXPECT_EQ(mem[0], 2.0f);
  EXPECT_EQ(mem[1], 3.0f);
  EXPECT_EQ(mem[2], 4.0f);
  EXPECT_EQ(mem[3], 1.0f);
  EXPECT_EQ(q.coeffs()[0], 2.0f);  // coeffs() is [x, y, z, w]
  EXPECT_EQ(q.coeffs()[3], 1.0f);
  const float xyzw[4] = {2.0f, 3.0f, 4.0f, 1.0f};
  const Eigen::Map<const Eigen::Quaternionf> mapped(xyzw);  // Map reads x, y, z, w
  EXPECT_EQ(mapped.w(), 1.0f);
  EXPECT_EQ(mapped.x(), 2.0f);
  const Eigen::Quaterniond d(1.0, 2.0, 3.0, 4.0);
  double dmem[4];
  std::memcpy(dmem, &d, sizeof dmem);
  EXPECT_EQ(dmem[0], 2.0);
  EXPECT_EQ(dmem[3], 1.0);
}

TEST(EigenQuat, AdapterKeepsTheAbiOrder) {
  RC_CLAUSE("QUAT-3");
  // i j = k (Hamilton) and normalize((0,0,0,2)) = 1: exact results that a swapped w would break.
  const Q<float> i{1, 0, 0, 0}, j{0, 1, 0, 0}, two{0, 0, 0, 2};
  Q<float> out;
  std::uint8_t st = 0xff;
  ops<float>()->compose(1, i.data(), j.data(), out.data(), &st);
  EXPECT_EQ(out, (Q<float>{0, 0, 1, 0}));
  ops<float>()->normalize(1, two.data(), out.data(), &st);
  EXPECT_EQ(out, (Q<float>{0, 0, 0, 1}));
  const Q<double> id{1, 0, 0, 0}, jd{0, 1, 0, 0};
  Q<double> outd;
  ops<double>()->compose(1, id.data(), jd.data(), outd.data(), &st);
  EXPECT_EQ(outd, (Q<double>{0, 0, 1, 0}));
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

template <class S>
void smoke() {
  const auto* o = ops<S>();
  // Unit quaternions rounded to S (2 rad about (1,2,2)/3 and 0.7 rad about (0,0.6,0.8)).
  const Eigen::Quaternion<S> ea(Eigen::AngleAxis<S>(S(2), Eigen::Matrix<S, 3, 1>(S(1) / S(3), S(2) / S(3), S(2) / S(3))));
  const Eigen::Quaternion<S> eb(Eigen::AngleAxis<S>(S(0.7), Eigen::Matrix<S, 3, 1>(S(0), S(0.6), S(0.8))));
  const Q<S> a{ea.x(), ea.y(), ea.z(), ea.w()}, b{eb.x(), eb.y(), eb.z(), eb.w()};
  const Q<S> raw{S(0.25), S(-1.5), S(3), S(0.5)};
  const V<S> v{S(1), S(-2), S(0.5)};
  const S t = S(0.3);
  Q<S> q;
  V<S> w;
  std::array<S, 9> m;
  std::uint8_t st = 0xff;

  o->normalize(1, raw.data(), q.data(), &st);
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), clause::NORM_1_normalize(exact(raw)).value), "eps4"),
            Verdict::pass);
  o->compose(1, a.data(), b.data(), q.data(), &st);
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), clause::COMPOSE_1_compose(exact(a), exact(b)).value),
                       "eps8"),
            Verdict::pass);
  o->apply_vector(1, a.data(), v.data(), w.data(), &st);
  EXPECT_EQ(verdict<S>(clause::METRIC_3_vector_error(exact(w), clause::APPLY_1_apply_vector(exact(a), exact(v)).value),
                       "eps8"),
            Verdict::pass);
  o->to_matrix(1, a.data(), m.data(), &st);
  rotorcert::ref::Mat3<Real> mm;
  for (std::size_t k = 0; k < 9; ++k) mm[k] = Real(m[k]);
  EXPECT_EQ(verdict<S>(clause::METRIC_4_matrix_error(mm, clause::MAT_1_to_matrix(exact(a)).value), "eps8"), Verdict::pass);
  o->slerp(1, a.data(), b.data(), &t, q.data(), &st);
  const auto rs = clause::SLERP_1_slerp(exact(a), exact(b), Real(t)).value;
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), rs), "eps16"), Verdict::pass);
  EXPECT_EQ(verdict<S>(clause::METRIC_6_norm_defect(exact(q)), "eps16"), Verdict::pass);
  o->nlerp(1, a.data(), b.data(), &t, q.data(), &st);
  const auto rn = clause::NLERP_1_nlerp(exact(a), exact(b), Real(t)).value;
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), rn), "eps16"), Verdict::pass);
}

TEST(EigenQuat, SmokeFloat) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("NLERP-1");
  smoke<float>();
}

TEST(EigenQuat, SmokeDouble) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("NLERP-1");
  smoke<double>();
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
