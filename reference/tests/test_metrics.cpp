// Number model, error metrics and verdicts (NUM-1, METRIC-1 .. METRIC-7, TOL-1, TOL-2).
#include <cfloat>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/tolerance.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace {

using namespace rotorcert::ref;
using namespace rotorcert::ref::clause;
using rotorcert::testing::eps_class_bars;
using rotorcert::testing::ref_class_bar;

/// Rotation by theta about the unit axis (ux, uy, uz): (cos(theta/2), sin(theta/2) u).
template <class T>
Quaternion<T> about(const T& theta, const T& ux, const T& uy, const T& uz) {
  using std::cos;
  using std::sin;
  const T h = theta / T(2);
  return {cos(h), sin(h) * ux, sin(h) * uy, sin(h) * uz};
}

TEST(NumberModel, FormatEpsilons) {
  RC_CLAUSE("NUM-1");
  EXPECT_EQ(format_epsilon<double>(Format::binary32), double(FLT_EPSILON));
  EXPECT_EQ(format_epsilon<double>(Format::binary64), DBL_EPSILON);
  EXPECT_EQ(format_epsilon<Real>(Format::binary32), Real(FLT_EPSILON));
}

TEST(NumberModel, SubnormalsAreNotFlushed) {
  RC_CLAUSE("NUM-1");
  // The suite itself must see subnormals as values, or it could not judge EDGE-8.
  volatile float tiny = 0x1p-149f;
  volatile double tinier = 0x1p-1074;
  EXPECT_NE(tiny * 1.0f, 0.0f);
  EXPECT_NE(tinier * 1.0, 0.0);
  EXPECT_EQ(std::fpclassify(tiny), FP_SUBNORMAL);
#if defined(__x86_64__) || defined(__i386__)
  const unsigned csr = _mm_getcsr();
  EXPECT_EQ(csr & 0x8000u, 0u) << "flush-to-zero is on";
  EXPECT_EQ(csr & 0x0040u, 0u) << "denormals-are-zero is on";
#endif
}

TEST(Metric, RotationDistanceOfKnownRotations) {
  RC_CLAUSE("METRIC-1");
  const Real pi = ScalarTraits<Real>::pi();
  const auto id = Quaternion<Real>::identity();
  for (int k = 0; k <= 24; ++k) {
    const Real theta = Real(2) * pi * Real(k) / Real(24);  // 0 .. 2 pi
    const Real expected = theta <= pi ? theta : Real(2) * pi - theta;
    const auto q = about(theta, Real(0), Real(0), Real(1));
    EXPECT_LE(abs(METRIC_1_rotation_distance(id, q) - expected), ref_class_bar()) << k;
    EXPECT_LE(abs(METRIC_1_rotation_distance(q, id) - expected), ref_class_bar()) << k;
  }
}

RC_GTEST_PROP(Metric, RotationDistanceIsAMetricOnRotations, ()) {
  RC_CLAUSE("METRIC-1");
  using rotorcert::testing::quaternion;
  const auto a = *quaternion(), b = *quaternion(), c = *quaternion();
  const Real dab = METRIC_1_rotation_distance(a, b);
  RC_ASSERT(dab >= 0);
  RC_ASSERT(dab <= ScalarTraits<Real>::pi() + ref_class_bar());
  RC_ASSERT(abs(dab - METRIC_1_rotation_distance(b, a)) <= ref_class_bar());
  RC_ASSERT(abs(dab - METRIC_1_rotation_distance(a, -b)) <= ref_class_bar());   // q ~ -q
  RC_ASSERT(abs(dab - METRIC_1_rotation_distance(Real(3) * a, b)) <= ref_class_bar());  // scale
  RC_ASSERT(METRIC_1_rotation_distance(a, c) <= dab + METRIC_1_rotation_distance(b, c) + ref_class_bar());
  // It is the angle of the relative rotation a* b: 2 atan2(|v|, |w|) of that product.
  const auto rel = conj(a) * b;
  const Real angle = Real(2) * atan2(sqrt(rel.x * rel.x + rel.y * rel.y + rel.z * rel.z), abs(rel.w));
  RC_ASSERT(abs(dab - angle) <= ref_class_bar());
}

TEST(Metric, RotationDistanceStaysAccurateAtTinyAnglesWhereAcosFails) {
  RC_CLAUSE("METRIC-1");
  // In binary64, a rotation of 1e-9 rad: the chord formula keeps full relative accuracy,
  // while acos of the dot product returns exactly 0 (cos(5e-10) rounds to 1).
  const auto bars = eps_class_bars("eps4");
  for (double theta : {1e-9, 3e-7, 1e-4, 0.5}) {
    const auto a = Quaternion<double>::identity();
    const auto b = about(theta, 0.0, 0.6, 0.8);
    const double measured = METRIC_1_rotation_distance(a, b);
    EXPECT_LE(std::abs(measured - theta) / theta / DBL_EPSILON, bars.strict) << theta;
  }
  const auto b = about(1e-9, 0.0, 0.6, 0.8);
  const double acos_of_dot = 2.0 * std::acos(std::min(1.0, std::abs(dot(Quaternion<double>::identity(), b))));
  EXPECT_EQ(acos_of_dot, 0.0) << "the failure mode METRIC-1 exists to avoid";
}

TEST(Metric, RotationDistanceOfInvalidInputIsNaN) {
  RC_CLAUSE("METRIC-1");
  const auto id = Quaternion<double>::identity();
  EXPECT_TRUE(std::isnan(METRIC_1_rotation_distance(id, Quaternion<double>{0, 0, 0, 0})));
  EXPECT_TRUE(std::isnan(METRIC_1_rotation_distance(id, Quaternion<double>{NAN, 0, 0, 1})));
  EXPECT_TRUE(std::isnan(METRIC_1_rotation_distance(Quaternion<double>{INFINITY, 0, 0, 0}, id)));
}

TEST(Metric, EpsUnits) {
  RC_CLAUSE("METRIC-2");
  EXPECT_EQ(METRIC_2_eps_units(std::ldexp(1.0, -23), Format::binary32), 1.0);
  EXPECT_EQ(METRIC_2_eps_units(std::ldexp(3.0, -52), Format::binary64), 3.0);
  EXPECT_EQ(METRIC_2_eps_units(Real(1), Format::binary32), Real(8388608));
}

TEST(Metric, VectorErrorIsRelativeUnlessTheReferenceIsZero) {
  RC_CLAUSE("METRIC-3");
  EXPECT_EQ(METRIC_3_vector_error<double>({3, 4, 5}, {0, 0, 5}), 1.0);
  EXPECT_EQ(METRIC_3_vector_error<double>({1e-30, 0, 0}, {2e-30, 0, 0}), 0.5);  // scale-free
  EXPECT_EQ(METRIC_3_vector_error<double>({0, 3, 4}, {0, 0, 0}), 5.0);        // absolute at 0
}

TEST(Metric, MatrixErrorIsTheLargestEntryDifference) {
  RC_CLAUSE("METRIC-4");
  Mat3<double> a{}, b{};
  a[7] = 0.25;
  b[2] = -0.5;
  EXPECT_EQ(METRIC_4_matrix_error(a, b), 0.5);
  a[4] = NAN;
  EXPECT_TRUE(std::isnan(METRIC_4_matrix_error(a, b)));
}

TEST(Metric, BivectorErrorIsEuclidean) {
  RC_CLAUSE("METRIC-5");
  EXPECT_EQ(METRIC_5_bivector_error<double>({1, 2, 2}, {0, 0, 0}), 3.0);
}

TEST(Metric, NormDefect) {
  RC_CLAUSE("METRIC-6");
  EXPECT_EQ(METRIC_6_norm_defect(Quaternion<double>{0, 0, 0.6, 0.8}), 0.0);
  EXPECT_EQ(METRIC_6_norm_defect(Quaternion<double>{0, 0, 3, 4}), 4.0);
}

TEST(Metric, RigidErrorSeparatesRotationAndTranslation) {
  RC_CLAUSE("METRIC-7");
  const Real pi = ScalarTraits<Real>::pi();
  const auto r = about(pi / Real(3), Real(0), Real(0), Real(1));
  const auto make = [&](const Quaternion<Real>& rot, Real tx, Real ty, Real tz) {
    const Quaternion<Real> t{Real(0), tx, ty, tz};
    return DualQuaternion<Real>{rot, Real("0.5") * (t * rot)};
  };
  const auto d = make(r, Real(1), Real(2), Real(3));
  const auto t = dual_quaternion_translation(d);
  EXPECT_LE(abs(t[0] - 1) + abs(t[1] - 2) + abs(t[2] - 3), ref_class_bar());
  const auto same = METRIC_7_rigid_error(d, d);
  EXPECT_EQ(same.rotation, 0);
  EXPECT_EQ(same.translation, 0);
  // Off by 1e-3 along z from a reference of length sqrt(14) > 1: relative error 1e-3/sqrt(14).
  const auto moved = METRIC_7_rigid_error(make(r, Real(1), Real(2), Real("3.001")), d);
  EXPECT_LE(abs(moved.translation - Real("0.001") / sqrt(Real(14))), ref_class_bar());
  EXPECT_LE(moved.rotation, ref_class_bar());
  // Reference shorter than 1: the error is absolute.
  const auto small = METRIC_7_rigid_error(make(r, Real(0), Real(0), Real("0.002")), make(r, Real(0), Real(0), Real("0.001")));
  EXPECT_LE(abs(small.translation - Real("0.001")), ref_class_bar());
  // Rotation error reported in radians of the real parts, sign-insensitive.
  const auto turned = METRIC_7_rigid_error(DualQuaternion<Real>{-about(pi / Real(2), Real(0), Real(0), Real(1)), {}},
                                           DualQuaternion<Real>{r, {}});
  EXPECT_LE(abs(turned.rotation - pi / Real(6)), ref_class_bar());
}

TEST(Verdict, BarsSplitPassWarningFail) {
  RC_CLAUSE("TOL-1");
  const Bars eps16 = eps_class_bars("eps16");
  EXPECT_EQ(TOL_1_verdict(0.0, eps16), Verdict::pass);
  EXPECT_EQ(TOL_1_verdict(eps16.strict, eps16), Verdict::pass);
  EXPECT_EQ(TOL_1_verdict(std::nextafter(eps16.strict, 1e9), eps16), Verdict::quality_warning);
  EXPECT_EQ(TOL_1_verdict(eps16.loose, eps16), Verdict::quality_warning);
  EXPECT_EQ(TOL_1_verdict(std::nextafter(eps16.loose, 1e9), eps16), Verdict::fail);
  EXPECT_EQ(TOL_1_verdict(NAN, eps16), Verdict::fail);
  EXPECT_EQ(TOL_1_verdict(INFINITY, eps16), Verdict::fail);
  const Bars exact{0, 0};
  EXPECT_EQ(TOL_1_verdict(0.0, exact), Verdict::pass);
  EXPECT_EQ(TOL_1_verdict(std::numeric_limits<double>::denorm_min(), exact), Verdict::fail);
}

TEST(Verdict, WorstCaseDecides) {
  RC_CLAUSE("TOL-1");
  EXPECT_EQ(TOL_1_worst(Verdict::pass, Verdict::quality_warning), Verdict::quality_warning);
  EXPECT_EQ(TOL_1_worst(Verdict::fail, Verdict::quality_warning), Verdict::fail);
  EXPECT_EQ(TOL_1_worst(Verdict::pass, Verdict::pass), Verdict::pass);
}

TEST(Verdict, EpsClassesAreOrderedAndLooseBarsAreLooser) {
  RC_CLAUSE("TOL-2");
  double previous = 0;
  for (const char* name : {"eps4", "eps8", "eps16", "eps32", "eps64"}) {
    const Bars b = eps_class_bars(name);
    EXPECT_GT(b.strict, previous) << name;
    EXPECT_GT(b.loose, b.strict) << name;
    previous = b.strict;
  }
  EXPECT_THROW(eps_class_bars("exact"), std::invalid_argument);
  EXPECT_GT(ref_class_bar(), 0);
  EXPECT_LT(ref_class_bar(), Real("1e-50"));  // far below any binary64 error the suite measures
}

}  // namespace
