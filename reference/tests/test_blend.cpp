// Blending several rotations (QLB-1, LOGBLEND-1, KARCHER-1, KARCHER-2, BLENDQ-1) and the
// weight rules (EDGE-9).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "prelude.hpp"

namespace {

/// The strict bar of an eps class (spec/clauses.json, tolerance_classes), in binary64 units.
Real binary64_bar(const std::string& cls) {
  return Real(rotorcert::testing::eps_class_bars(cls).strict) * format_epsilon<Real>(Format::binary64);
}

Real diff(const Q& a, const Q& b) {
  return std::max({Real(abs(a.w - b.w)), Real(abs(a.x - b.x)), Real(abs(a.y - b.y)), Real(abs(a.z - b.z))});
}
Real vnorm(const Vec3<Real>& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
Q unit(const Q& q) { return (Real(1) / norm(q)) * q; }
Q to_real(const QD& q) { return {Real(q.w), Real(q.x), Real(q.y), Real(q.z)}; }
QD to_double(const Q& q) { return {q.w.toDouble(), q.x.toDouble(), q.y.toDouble(), q.z.toDouble()}; }

struct Influences {
  std::vector<Q> q;
  std::vector<Real> w;
};

/// 1 to 5 quaternions (any scale) with weights k/8, k in 0..16, at least one positive.
rc::Gen<Influences> influences(int max_count = 5) {
  return rc::gen::suchThat(
      rc::gen::mapcat(rc::gen::inRange(1, max_count + 1),
                      [](int n) {
                        return rc::gen::map(
                            rc::gen::pair(rc::gen::container<std::vector<Q>>(n, quaternion()),
                                          rc::gen::container<std::vector<Real>>(
                                              n, rc::gen::map(rc::gen::inRange(0, 17), [](int k) { return Real(k) / 8; }))),
                            [](const std::pair<std::vector<Q>, std::vector<Real>>& p) { return Influences{p.first, p.second}; });
                      }),
      [](const Influences& in) {
        for (const Real& w : in.w)
          if (w > 0) return true;
        return false;
      });
}

/// Rotations within about 0.9 rad of a random centre, where the Karcher mean is unique and the
/// fixed-point iteration converges quickly.
rc::Gen<Influences> clustered_influences() {
  return rc::gen::map(rc::gen::pair(unit_quaternion(), influences(4)), [](const std::pair<Q, Influences>& p) {
    Influences in = p.second;
    for (Q& q : in.q) {
      const Q u = unit(q);
      // Shrink each rotation's log to a quarter: |log| <= pi/4, rotation angle <= pi/2.
      const Vec3<Real> l = LOG_1_log(u).value;
      q = p.first * EXP_1_exp(Vec3<Real>{l[0] / 4, l[1] / 4, l[2] / 4}).value;
    }
    return in;
  });
}

std::size_t pivot_of(const Influences& in) {
  for (std::size_t i = 0; i < in.w.size(); ++i)
    if (in.w[i] > 0) return i;
  return in.w.size();
}

/// sum w_i log(align(m^-1 q_i)): the gradient direction of the Karcher cost at m.
Vec3<Real> karcher_gradient(const Q& m, const Influences& in) {
  Vec3<Real> g{0, 0, 0};
  for (std::size_t i = 0; i < in.q.size(); ++i) {
    Q d = conj(m) * unit(in.q[i]);
    if (d.w < 0) d = -d;
    const Vec3<Real> l = LOG_1_log(d).value;
    for (int k = 0; k < 3; ++k) g[k] += in.w[i] * l[k];
  }
  return g;
}

// ---- QLB-1 -------------------------------------------------------------------------------

RC_GTEST_PROP(Blend, QlbIsNormalisedAlignedSum, ()) {
  RC_CLAUSE("QLB-1");
  const Influences in = *influences();
  const std::size_t p = pivot_of(in);
  const Q pivot = unit(in.q[p]);
  Q sum{0, 0, 0, 0};
  for (std::size_t i = 0; i < in.q.size(); ++i) {
    const Q qi = unit(in.q[i]);
    sum = sum + (dot(qi, pivot) < 0 ? Real(-in.w[i]) : in.w[i]) * qi;
  }
  const Result<Q> r = QLB_1_blend<Real>(in.q, in.w);
  RC_ASSERT(r.status == Status::ok);
  RC_ASSERT(diff(r.value, unit(sum)) <= ref_class_bar());
  // Weights need not sum to 1: scaling them changes nothing.
  std::vector<Real> w7 = in.w;
  for (Real& w : w7) w *= 7;
  RC_ASSERT(diff(QLB_1_blend<Real>(in.q, w7).value, r.value) <= ref_class_bar());
  // Negating a non-pivot influence changes nothing (hemisphere rule).
  if (in.q.size() > 1) {
    std::vector<Q> flipped = in.q;
    const std::size_t i = (p + 1) % in.q.size();
    flipped[i] = -flipped[i];
    RC_ASSERT(diff(QLB_1_blend<Real>(flipped, in.w).value, r.value) <= ref_class_bar());
  }
}

TEST(Blend, QlbPivotIsTheFirstPositiveWeight) {
  RC_CLAUSE("QLB-1");
  // a, b, c on one great circle at 0, 50 and 100 degrees (rotor angles): b.a > 0, c.a < 0, c.b > 0.
  const Real deg = ScalarTraits<Real>::pi() / 180;
  const Q a{1, 0, 0, 0}, b{cos(50 * deg), sin(50 * deg), 0, 0}, c{cos(100 * deg), sin(100 * deg), 0, 0};
  const std::vector<Q> q{a, b, c};
  const std::vector<Real> w{0, 1, 1};
  // Pivot b (a has weight 0): c is kept, the blend is halfway between b and c (75 degrees).
  const Q expected{cos(75 * deg), sin(75 * deg), 0, 0};
  EXPECT_LE(METRIC_1_rotation_distance(QLB_1_blend<Real>(q, w).value, expected), ref_class_bar());
  // With a as pivot (weight > 0 but tiny), c would be flipped: a different rotation.
  const std::vector<Real> w_a{Real("1e-40"), 1, 1};
  EXPECT_GT(METRIC_1_rotation_distance(QLB_1_blend<Real>(q, w_a).value, expected), Real(1));
  // Exact antipodes of the pivot are aligned, not cancelled.
  const std::vector<Q> antipodes{b, -b};
  const std::vector<Real> half{Real("0.5"), Real("0.5")};
  EXPECT_LE(diff(QLB_1_blend<Real>(antipodes, half).value, b), ref_class_bar());
}

TEST(Blend, QlbHugeWeightsInDouble) {
  RC_CLAUSE("QLB-1");
  const std::vector<QD> q{QD{1, 0, 0, 0}, QD{0.6, 0.8, 0, 0}};
  const std::vector<double> w{1e308, 1.5e308};
  const Result<QD> r = QLB_1_blend<double>(q, w);
  ASSERT_EQ(r.status, Status::ok);
  const Q expected = QLB_1_blend<Real>(std::vector<Q>{to_real(q[0]), to_real(q[1])}, std::vector<Real>{2, 3}).value;
  EXPECT_LE(METRIC_1_rotation_distance(to_real(r.value), expected), binary64_bar("eps32"));
}

// ---- LOGBLEND-1 ---------------------------------------------------------------------------

RC_GTEST_PROP(Blend, LogBlendAboutThePivot, ()) {
  RC_CLAUSE("LOGBLEND-1");
  const Influences in = *influences();
  const std::size_t p = pivot_of(in);
  const Q qp = unit(in.q[p]);
  Real total(0);
  for (const Real& w : in.w) total += w;
  Vec3<Real> sum{0, 0, 0};
  for (std::size_t i = 0; i < in.q.size(); ++i) {
    Q d = conj(qp) * unit(in.q[i]);
    if (d.w < 0) d = -d;
    const Vec3<Real> l = LOG_1_log(d).value;
    for (int k = 0; k < 3; ++k) sum[k] += in.w[i] / total * l[k];
  }
  const Q expected = qp * EXP_1_exp(sum).value;
  RC_ASSERT(diff(LOGBLEND_1_blend<Real>(in.q, in.w).value, expected) <= ref_class_bar());
}

RC_GTEST_PROP(Blend, LogBlendOfTwoIsSlerp, ()) {
  RC_CLAUSE("LOGBLEND-1");
  const Q a = *quaternion(), b = *quaternion();
  const Real w0 = Real(*rc::gen::inRange(1, 17)) / 8, w1 = Real(*rc::gen::inRange(0, 17)) / 8;
  const std::vector<Q> q{a, b};
  const std::vector<Real> w{w0, w1};
  RC_ASSERT(diff(LOGBLEND_1_blend<Real>(q, w).value, SLERP_1_slerp(a, b, w1 / (w0 + w1)).value) <= ref_class_bar());
}

// ---- KARCHER-1, KARCHER-2 -------------------------------------------------------------

TEST(Blend, KarcherGradientVanishesAtTheMean) {
  RC_CLAUSE("KARCHER-1");
  rc::check("the weighted mean of the logs about m is zero", [] {
    const Influences in = *clustered_influences();
    const Result<Q> m = KARCHER_1_mean<Real>(in.q, in.w);
    RC_ASSERT(m.status == Status::ok);
    RC_ASSERT(METRIC_6_norm_defect(m.value) <= ref_class_bar());
    RC_ASSERT(vnorm(karcher_gradient(m.value, in)) <= ref_class_bar());
    // Invariant under q_i -> -q_i and under scaling the weights (as a rotation).
    Influences other = in;
    for (Q& q : other.q) q = Real(-3) * q;
    for (Real& w : other.w) w *= 5;
    RC_ASSERT(METRIC_1_rotation_distance(KARCHER_1_mean<Real>(other.q, other.w).value, m.value) <= ref_class_bar());
  });
}

TEST(Blend, KarcherMeanMinimisesTheCost) {
  RC_CLAUSE("KARCHER-1");
  // sum w_i dist(m, q_i)^2 grows when m moves a little in any of six directions.
  const Real deg = ScalarTraits<Real>::pi() / 180;
  const std::vector<Q> q{AXANG_2_from_axis_angle(20 * deg, Vec3<Real>{1, 0, 0}).value,
                         AXANG_2_from_axis_angle(40 * deg, Vec3<Real>{0, 1, 0}).value,
                         AXANG_2_from_axis_angle(-30 * deg, Vec3<Real>{1, 1, 1}).value};
  const std::vector<Real> w{1, 2, Real("0.5")};
  const Q m = KARCHER_1_mean<Real>(q, w).value;
  auto cost = [&](const Q& x) {
    Real c(0);
    for (std::size_t i = 0; i < q.size(); ++i) c += w[i] * pow(METRIC_1_rotation_distance(x, q[i]), 2);
    return c;
  };
  const Real c0 = cost(m);
  for (int k = 0; k < 3; ++k)
    for (const Real& h : {Real("1e-6"), Real("-1e-6")}) {
      Vec3<Real> d{0, 0, 0};
      d[k] = h;
      EXPECT_GT(cost(m * EXP_1_exp(d).value), c0);
    }
}

RC_GTEST_PROP(Blend, KarcherOfTwoIsSlerp, ()) {
  RC_CLAUSE("KARCHER-2");
  const Q a = *quaternion(), b = *quaternion();
  const Real w0 = Real(*rc::gen::inRange(0, 17)) / 8, w1 = Real(*rc::gen::inRange(1, 17)) / 8;
  const std::vector<Q> q{a, b};
  const std::vector<Real> w{w0, w1};
  RC_ASSERT(METRIC_1_rotation_distance(KARCHER_1_mean<Real>(q, w).value, SLERP_1_slerp(a, b, w1 / (w0 + w1)).value) <=
            ref_class_bar());
}

TEST(Blend, KarcherInDoubleIsCloseToReal) {
  RC_CLAUSE("KARCHER-1");
  const std::vector<Q> q{Q{1, Real("0.1"), 0, 0}, Q{1, 0, Real("0.3"), 0}, Q{1, 0, 0, Real("-0.2")}, Q{1, Real("0.2"), Real("0.2"), 0}};
  const std::vector<Real> w{1, 2, 3, 4};
  std::vector<QD> qd;
  for (const Q& x : q) qd.push_back(to_double(x));
  const std::vector<double> wd{1, 2, 3, 4};
  std::vector<Q> qr;
  for (const QD& x : qd) qr.push_back(to_real(x));
  const Result<QD> md = KARCHER_1_mean<double>(qd, wd);
  ASSERT_EQ(md.status, Status::ok);
  EXPECT_LE(METRIC_1_rotation_distance(to_real(md.value), KARCHER_1_mean<Real>(qr, w).value), binary64_bar("eps32"));
}

// ---- BLENDQ-1 -----------------------------------------------------------------------------

TEST(Blend, DeviationFromTheKarcherMean) {
  RC_CLAUSE("BLENDQ-1");
  rc::check("deviation is the distance of the blend from the Karcher mean", [] {
    const Influences in = *clustered_influences();
    const Q mean = KARCHER_1_mean<Real>(in.q, in.w).value;
    for (BlendMethod method : {BlendMethod::qlb, BlendMethod::log_blend}) {
      const Result<Real> d = BLENDQ_1_deviation<Real>(in.q, in.w, method);
      RC_ASSERT(d.status == Status::ok);
      const Q blend = method == BlendMethod::qlb ? QLB_1_blend<Real>(in.q, in.w).value : LOGBLEND_1_blend<Real>(in.q, in.w).value;
      RC_ASSERT(abs(d.value - METRIC_1_rotation_distance(blend, mean)) <= ref_class_bar());
      RC_ASSERT(d.value >= 0);
    }
  });
}

TEST(Blend, DeviationKnownCases) {
  RC_CLAUSE("BLENDQ-1");
  const Real deg = ScalarTraits<Real>::pi() / 180;
  const Q a{1, 0, 0, 0}, b = AXANG_2_from_axis_angle(120 * deg, Vec3<Real>{0, 0, 1}).value;
  const std::vector<Q> q{a, b};
  // Two influences: log blend = slerp = Karcher mean; QLB = nlerp = slerp only at equal weights.
  const std::vector<Real> equal{1, 1}, unequal{1, 3};
  EXPECT_LE(BLENDQ_1_deviation<Real>(q, unequal, BlendMethod::log_blend).value, ref_class_bar());
  EXPECT_LE(BLENDQ_1_deviation<Real>(q, equal, BlendMethod::qlb).value, ref_class_bar());
  EXPECT_GT(BLENDQ_1_deviation<Real>(q, unequal, BlendMethod::qlb).value, Real("1e-3"));
  // In double, close to the reference (informative: the bar here is only a sanity check).
  const std::vector<QD> qd{to_double(a), to_double(b)};
  const std::vector<double> wd{1, 3};
  const std::vector<Q> qr{to_real(qd[0]), to_real(qd[1])};
  EXPECT_LE(abs(Real(BLENDQ_1_deviation<double>(qd, wd, BlendMethod::qlb).value) -
                BLENDQ_1_deviation<Real>(qr, unequal, BlendMethod::qlb).value),
            binary64_bar("eps64"));
}

// ---- EDGE-9 -------------------------------------------------------------------------------

template <class T>
void expect_weights_rejected() {
  using Qt = Quaternion<T>;
  const std::vector<Qt> two{Qt{T(1), T(0), T(0), T(0)}, Qt{T(0), T(1), T(0), T(0)}};
  const T nan = ScalarTraits<T>::nan(), inf = T(1) / T(0);
  const std::vector<std::pair<std::vector<Qt>, std::vector<T>>> bad{
      {two, {nan, T(1)}},        {two, {T(1), inf}},          {two, {T(-inf), T(1)}}, {two, {T(1), T(-1)}},
      {two, {T(0), T(0)}},       {two, {T(-0.0), T(-0.0)}},   {{}, {}},               {two, {T(1)}},
      {two, {T(1), T(1), T(1)}}, {{two[0]}, {T(1), T(1)}},
  };
  for (std::size_t k = 0; k < bad.size(); ++k) {
    const auto& [q, w] = bad[k];
    for (const auto& r : {QLB_1_blend<T>(q, w), LOGBLEND_1_blend<T>(q, w), KARCHER_1_mean<T>(q, w)}) {
      EXPECT_EQ(r.status, Status::domain_error) << k;
      EXPECT_TRUE(ScalarTraits<T>::is_nan(r.value.w) && ScalarTraits<T>::is_nan(r.value.x) &&
                  ScalarTraits<T>::is_nan(r.value.y) && ScalarTraits<T>::is_nan(r.value.z))
          << k;
    }
    for (BlendMethod m : {BlendMethod::qlb, BlendMethod::log_blend}) {
      const Result<T> d = BLENDQ_1_deviation<T>(q, w, m);
      EXPECT_EQ(d.status, Status::domain_error) << k;
      EXPECT_TRUE(ScalarTraits<T>::is_nan(d.value)) << k;
    }
  }
  // -0 counts as 0, not negative: the pivot is the first positive weight.
  const std::vector<T> minus_zero_first{T(-0.0), T(2)};
  for (const auto& r : {QLB_1_blend<T>(two, minus_zero_first), LOGBLEND_1_blend<T>(two, minus_zero_first),
                        KARCHER_1_mean<T>(two, minus_zero_first)}) {
    EXPECT_EQ(r.status, Status::ok);
    EXPECT_EQ(r.value.x, T(1));
  }
}

TEST(Blend, BadWeightsAreADomainError) {
  RC_CLAUSE("EDGE-9");
  expect_weights_rejected<Real>();
  expect_weights_rejected<double>();
}

}  // namespace
