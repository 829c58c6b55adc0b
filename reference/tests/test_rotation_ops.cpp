// The rotation operations (NORM-1 ... NLERP-1) and their edge cases (EDGE-1 ... EDGE-8).
//
// Reference-vs-reference identities at 256 bits use the spec's "ref" class. Where the double
// instantiation is checked against the Real one, the bar is the clause's eps class (read from
// spec/clauses.json) in binary64 eps units: the textbook code in double is expected to meet
// the same bars an implementation must.
#include <cfloat>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/cl3.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/reference/series.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "prelude.hpp"

namespace {

using MV = cl3::MV<Real>;


/// The strict bar of an eps class (spec/clauses.json, tolerance_classes), in binary64 units.
Real binary64_bar(const std::string& cls) {
  return Real(rotorcert::testing::eps_class_bars(cls).strict) * format_epsilon<Real>(Format::binary64);
}

Real diff(const Q& a, const Q& b) {
  return std::max({Real(abs(a.w - b.w)), Real(abs(a.x - b.x)), Real(abs(a.y - b.y)), Real(abs(a.z - b.z))});
}
template <std::size_t N>
Real diff(const std::array<Real, N>& a, const std::array<Real, N>& b) {
  Real m(0);
  for (std::size_t i = 0; i < N; ++i) m = std::max(m, Real(abs(a[i] - b[i])));
  return m;
}
Real diff(const MV& a, const MV& b) { return diff(a.c, b.c); }
Real vnorm(const Vec3<Real>& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
Q unit(const Q& q) { return (Real(1) / norm(q)) * q; }

Q to_real(const QD& q) { return {Real(q.w), Real(q.x), Real(q.y), Real(q.z)}; }
QD to_double(const Q& q) { return {q.w.toDouble(), q.x.toDouble(), q.y.toDouble(), q.z.toDouble()}; }
Vec3<Real> to_real(const Vec3<double>& v) { return {Real(v[0]), Real(v[1]), Real(v[2])}; }
Real diff(const Vec3<double>& a, const Vec3<double>& b) { return diff(to_real(a), to_real(b)); }
using std::signbit;

bool identical(const Q& a, const Q& b) {
  // Bit-exact, signs of zeros included.
  auto same = [](const Real& x, const Real& y) { return x == y && signbit(x) == signbit(y); };
  return same(a.w, b.w) && same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}
bool identical(const QD& a, const QD& b) {
  auto same = [](double x, double y) { return x == y && std::signbit(x) == std::signbit(y); };
  return same(a.w, b.w) && same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

/// a (a^-1 b)^t through the quaternion exp and log (the definition of SLERP-1), unit a, b.
Q power_form(const Q& a, const Q& b, const Real& t) {
  const Vec3<Real> l = LOG_1_log(conj(a) * b).value;
  return a * EXP_1_exp(Vec3<Real>{t * l[0], t * l[1], t * l[2]}).value;
}

/// Canonical sign of MAT-2: w > 0, or w == 0 and the first nonzero of x, y, z positive.
Q canonical(const Q& q) {
  const Real first = q.w != 0 ? q.w : (q.x != 0 ? q.x : (q.y != 0 ? q.y : q.z));
  return first < 0 ? -q : q;
}

Mat3<Real> matrix_formula(const Q& q) {  // MAT-1's printed formula, rows, for unit q
  const Real &w = q.w, &x = q.x, &y = q.y, &z = q.z;
  const Real rows[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  Mat3<Real> m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[c * 3 + r] = rows[r][c];
  return m;
}

Vec3<Real> times(const Mat3<Real>& m, const Vec3<Real>& v) {
  Vec3<Real> r{0, 0, 0};
  for (int row = 0; row < 3; ++row)
    for (int c = 0; c < 3; ++c) r[row] += m[c * 3 + row] * v[c];
  return r;
}

rc::Gen<Vec3<Real>> nonzero_vector3() {
  return rc::gen::suchThat(vector3(), [](const Vec3<Real>& v) { return v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > Real(1) / 1024; });
}

// ---- NORM-1, COMPOSE-1, INV-1 ---------------------------------------------------------------

TEST(Normalize, WorkedExample) {
  RC_CLAUSE("NORM-1");
  const Q n = NORM_1_normalize(Q{4, 0, 0, 3}).value;  // [x,y,z,w] = [0,0,3,4]
  EXPECT_LE(diff(n, Q{Real(4) / 5, 0, 0, Real(3) / 5}), ref_class_bar());
}

RC_GTEST_PROP(Normalize, DividesByTheNorm, ()) {
  RC_CLAUSE("NORM-1");
  const Q q = *quaternion();
  const Result<Q> n = NORM_1_normalize(q);
  RC_ASSERT(n.status == Status::ok);
  RC_ASSERT(diff(n.value, unit(q)) <= ref_class_bar());
  RC_ASSERT(METRIC_6_norm_defect(n.value) <= ref_class_bar());
}

RC_GTEST_PROP(Compose, IsTheHamiltonProductAppliedRightFirst, ()) {
  RC_CLAUSE("COMPOSE-1");
  const Q a = *quaternion(), b = *quaternion();
  const Vec3<Real> v = *vector3();
  const Q c = COMPOSE_1_compose(a, b).value;
  RC_ASSERT(diff(c, a * b) <= ref_class_bar());  // the plain product: no normalisation (EDGE-5 exception)
  // Phi(a) Phi(b) acts as "b first, then a".
  const Vec3<Real> two_steps = APPLY_1_apply_vector(a, APPLY_1_apply_vector(b, v).value).value;
  RC_ASSERT(diff(APPLY_1_apply_vector(c, v).value, two_steps) <= ref_class_bar());
}

RC_GTEST_PROP(Inverse, IsConjugateOverNormSquared, ()) {
  RC_CLAUSE("INV-1");
  const Q q = *quaternion();
  const Q inv = INV_1_inverse(q).value;
  RC_ASSERT(diff(inv, (Real(1) / dot(q, q)) * conj(q)) <= ref_class_bar());
  RC_ASSERT(diff(q * inv, Q{1, 0, 0, 0}) <= ref_class_bar());
}

TEST(Inverse, HugeAndTinyInDouble) {
  RC_CLAUSE("INV-1");
  RC_CLAUSE("EDGE-5");
  for (double s : {0x1p-1000, 1e-300, 1e-30, 1e30, 1e300, 0x1p1000}) {
    const QD q{s, 2 * s, -2 * s, 4 * s};  // |q| = 5 s
    const Result<QD> inv = INV_1_inverse(q);
    ASSERT_EQ(inv.status, Status::ok);
    const Q expected = (Real(1) / (Real(25) * Real(s))) * conj(Q{1, 2, -2, 4});
    EXPECT_LE(diff(to_real(inv.value), expected) / abs(expected.w), binary64_bar("eps4")) << s;
  }
}

// ---- APPLY-1 ... APPLY-3 ---------------------------------------------------------------------

TEST(Apply, QuarterTurnAboutZTakesE1ToE2) {
  RC_CLAUSE("APPLY-1");
  const Q q = AXANG_2_from_axis_angle(ScalarTraits<Real>::pi() / 2, Vec3<Real>{0, 0, 1}).value;
  EXPECT_LE(diff(APPLY_1_apply_vector(q, Vec3<Real>{1, 0, 0}).value, Vec3<Real>{0, 1, 0}), ref_class_bar());
}

RC_GTEST_PROP(Apply, VectorIsSandwichOfTheNormalisedRotor, ()) {
  RC_CLAUSE("APPLY-1");
  const Q q = *quaternion();
  const Vec3<Real> v = *vector3();
  const Vec3<Real> got = APPLY_1_apply_vector(q, v).value;
  const Q expected = unit(q) * Q{0, v[0], v[1], v[2]} * conj(unit(q));
  RC_ASSERT(diff(got, Vec3<Real>{expected.x, expected.y, expected.z}) <= ref_class_bar());
  RC_ASSERT(abs(vnorm(got) - vnorm(v)) <= ref_class_bar());
}

RC_GTEST_PROP(Apply, BivectorCoefficientsRotateLikeAVector, ()) {
  RC_CLAUSE("APPLY-2");
  // I is central: R (I n) ~R = I (R n ~R), and e23, e31, e12 = e1 I, e2 I, e3 I.
  const Q q = *quaternion();
  const Vec3<Real> b = *vector3();
  RC_ASSERT(diff(APPLY_2_apply_bivector(q, b).value, APPLY_1_apply_vector(q, b).value) <= ref_class_bar());
}

RC_GTEST_PROP(Apply, TrivectorIsInvariant, ()) {
  RC_CLAUSE("APPLY-3");
  const Q q = *quaternion();
  const Real s = *real_in(8);
  RC_ASSERT(abs(APPLY_3_apply_trivector(q, s).value - s) <= ref_class_bar());
}

// ---- MAT-1 ... MAT-3 ---------------------------------------------------------------------------

RC_GTEST_PROP(Matrix, ActsLikeTheSandwichAndMatchesTheFormula, ()) {
  RC_CLAUSE("MAT-1");
  const Q q = *quaternion();
  const Vec3<Real> v = *vector3();
  const Mat3<Real> m = MAT_1_to_matrix(q).value;
  RC_ASSERT(diff(times(m, v), APPLY_1_apply_vector(q, v).value) <= ref_class_bar());
  RC_ASSERT(diff(m, matrix_formula(unit(q))) <= ref_class_bar());
}

TEST(Matrix, ColumnMajorLayout) {
  RC_CLAUSE("MAT-1");
  // Quarter turn about z: e1 -> e2, so column 0 is (0, 1, 0): m[1] = 1, m[3] = -1.
  const Q q = AXANG_2_from_axis_angle(ScalarTraits<Real>::pi() / 2, Vec3<Real>{0, 0, 1}).value;
  const Mat3<Real> m = MAT_1_to_matrix(q).value;
  EXPECT_LE(abs(m[1] - 1), ref_class_bar());
  EXPECT_LE(abs(m[3] + 1), ref_class_bar());
}

RC_GTEST_PROP(Matrix, FromMatrixRoundTripsToTheCanonicalQuaternion, ()) {
  RC_CLAUSE("MAT-2");
  const Q q = unit(*quaternion());
  const Result<Q> back = MAT_2_from_matrix(MAT_1_to_matrix(q).value);
  RC_ASSERT(back.status == Status::ok);
  RC_ASSERT(diff(back.value, canonical(q)) <= ref_class_bar());
}

TEST(Matrix, FromMatrixSignCanonicalAtHalfTurns) {
  RC_CLAUSE("MAT-2");
  // Exact matrices (formula entries computed once each, so the matrix is exactly symmetric
  // where a half turn's is): w == 0 exactly, and the first nonzero of x, y, z is positive.
  const std::vector<Q> cases{Q{0, 1, 2, 2}, Q{0, -1, 2, 2}, Q{0, 0, -3, 4}, Q{0, 0, 0, -1}, Q{0, -1, 0, 0},
                             Q{1, 0, 0, 0}, Q{-1, 2, 2, 0}};
  for (const Q& raw : cases) {
    const Q q = unit(raw);
    const Result<Q> got = MAT_2_from_matrix(matrix_formula(q));
    ASSERT_EQ(got.status, Status::ok);
    EXPECT_LE(diff(got.value, canonical(q)), ref_class_bar()) << raw.x << " " << raw.y << " " << raw.z;
    if (raw.w == 0) {
      EXPECT_EQ(got.value.w, 0);
    }
  }
  // The identity and the axis half turns come out exactly.
  const Mat3<Real> identity{1, 0, 0, 0, 1, 0, 0, 0, 1}, half_x{1, 0, 0, 0, -1, 0, 0, 0, -1};
  EXPECT_TRUE(identical(MAT_2_from_matrix(identity).value, Q{1, 0, 0, 0}));
  EXPECT_TRUE(identical(MAT_2_from_matrix(half_x).value, Q{0, 1, 0, 0}));
}

TEST(Matrix, FromMatrixInDoubleMeetsItsClass) {
  RC_CLAUSE("MAT-2");
  for (const Q& raw : {Q{1, 2, 3, 4}, Q{0, 1, 2, 2}, Q{Real("0.001"), 1, -1, 1}, Q{-3, 0, 1, 0}}) {
    const Q q = unit(raw);
    Mat3<double> m;
    const Mat3<Real> mr = matrix_formula(q);
    for (int i = 0; i < 9; ++i) m[i] = mr[i].toDouble();
    const Result<QD> got = MAT_2_from_matrix(m);
    ASSERT_EQ(got.status, Status::ok);
    EXPECT_LE(METRIC_1_rotation_distance(to_real(got.value), q), binary64_bar("eps16"));
  }
}

RC_GTEST_PROP(Matrix, NearestRotationOfAPerturbedMatrix, ()) {
  RC_CLAUSE("MAT-3");
  // M = Q S with S symmetric positive definite (the polar decomposition) characterises the
  // nearest rotation Q in the Frobenius norm.
  const Q q = unit(*quaternion());
  const Mat3<Real> noise = *rc::gen::container<Mat3<Real>>(real_in(1));
  Mat3<Real> m = MAT_1_to_matrix(q).value;
  for (int i = 0; i < 9; ++i) m[i] += noise[i] / 8;
  const Real scale = *rc::gen::element(Real("0.25"), Real(1), Real(7));
  for (Real& e : m) e *= scale;
  const Result<Q> r = MAT_2_from_matrix(m);
  RC_ASSERT(r.status == Status::ok);
  const Mat3<Real> rm = MAT_1_to_matrix(r.value).value;
  Real s[3][3];  // S = R^T M
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      s[i][j] = 0;
      for (int k = 0; k < 3; ++k) s[i][j] += rm[i * 3 + k] * m[j * 3 + k];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) RC_ASSERT(abs(s[i][j] - s[j][i]) <= ref_class_bar());
  const Real minor2 = s[0][0] * s[1][1] - s[0][1] * s[1][0];
  const Real det = s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) - s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
                   s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
  RC_ASSERT(s[0][0] > 0 && minor2 > 0 && det > 0);
}

RC_GTEST_PROP(Matrix, NearestRotationOfColumnsScaledAcrossTheExponentRange, ()) {
  RC_CLAUSE("MAT-3");
  // M = R D, D = diag(2^a, 2^b, 2^c) (exact: powers of two), has the polar factor R whatever
  // the spread of a, b, c; K's eigen gap is then ~2^-(spread), far below 256 bits.
  const Q q = unit(*quaternion());
  Mat3<Real> m = MAT_1_to_matrix(q).value;
  for (int c = 0; c < 3; ++c) {
    const int e = *rc::gen::inRange(-1000, 1);
    for (int r = 0; r < 3; ++r) m[c * 3 + r] *= pow(Real(2), e);
  }
  const Result<Q> r = MAT_2_from_matrix(m);
  RC_ASSERT(r.status == Status::ok);
  RC_ASSERT(std::min(diff(r.value, q), diff(r.value, -q)) <= ref_class_bar());
}

TEST(Matrix, NonPositiveDeterminantIsADomainError) {
  RC_CLAUSE("MAT-3");
  const Real nan = ScalarTraits<Real>::nan(), inf = Real(1) / Real(0);
  const std::vector<Mat3<Real>> bad{
      {1, 0, 0, 0, 1, 0, 0, 0, -1},  // reflection, det -1
      {1, 0, 0, 0, 1, 0, 0, 0, 0},   // singular
      {0, 0, 0, 0, 0, 0, 0, 0, 0},   // zero
      {1, 0, 0, 0, 1, 0, 0, 0, nan},
      {1, 0, 0, 0, inf, 0, 0, 0, 1},
  };
  for (const Mat3<Real>& m : bad) {
    const Result<Q> r = MAT_2_from_matrix(m);
    EXPECT_EQ(r.status, Status::domain_error);
    EXPECT_TRUE(isnan(r.value.w) && isnan(r.value.x) && isnan(r.value.y) && isnan(r.value.z));
  }
  EXPECT_EQ(MAT_2_from_matrix(Mat3<double>{-1, 0, 0, 0, 1, 0, 0, 0, 1}).status, Status::domain_error);
}

// ---- AXANG-1, AXANG-2 ----------------------------------------------------------------------

RC_GTEST_PROP(AxisAngle, AngleInZeroTwoPiAndReconstructsQ, ()) {
  RC_CLAUSE("AXANG-1");
  const Q q = *quaternion();
  const AxisAngle<Real> aa = AXANG_1_to_axis_angle(q).value;
  RC_ASSERT(aa.angle >= 0 && aa.angle <= 2 * ScalarTraits<Real>::pi());
  RC_ASSERT(abs(vnorm(aa.axis) - 1) <= ref_class_bar());
  // theta in [0, 2 pi] covers both q and -q: the quaternion itself comes back, not just its rotation.
  RC_ASSERT(diff(AXANG_2_from_axis_angle(aa.angle, aa.axis).value, unit(q)) <= ref_class_bar());
}

TEST(AxisAngle, ZeroVectorPartGivesAxisZ) {
  RC_CLAUSE("AXANG-1");
  const AxisAngle<Real> one = AXANG_1_to_axis_angle(Q{3, 0, 0, 0}).value;
  EXPECT_EQ(one.angle, 0);
  EXPECT_TRUE(one.axis == (Vec3<Real>{0, 0, 1}));
  const AxisAngle<Real> minus_one = AXANG_1_to_axis_angle(Q{-2, 0, 0, 0}).value;
  EXPECT_EQ(minus_one.angle, 2 * ScalarTraits<Real>::pi());
  EXPECT_TRUE(minus_one.axis == (Vec3<Real>{0, 0, 1}));
  const AxisAngle<Real> half_x = AXANG_1_to_axis_angle(Q{0, 5, 0, 0}).value;
  EXPECT_LE(abs(half_x.angle - ScalarTraits<Real>::pi()), ref_class_bar());
  EXPECT_TRUE(half_x.axis == (Vec3<Real>{1, 0, 0}));
}

RC_GTEST_PROP(AxisAngle, FromAngleAndAnyNonzeroAxis, ()) {
  RC_CLAUSE("AXANG-2");
  const Real angle = *real_in(8);
  const Vec3<Real> axis = *nonzero_vector3();
  const Real n = vnorm(axis), s = sin(angle / 2) / n;
  const Q expected{cos(angle / 2), s * axis[0], s * axis[1], s * axis[2]};
  RC_ASSERT(diff(AXANG_2_from_axis_angle(angle, axis).value, expected) <= ref_class_bar());
  RC_ASSERT(diff(AXANG_2_from_axis_angle(angle, Vec3<Real>{5 * axis[0], 5 * axis[1], 5 * axis[2]}).value, expected) <=
            ref_class_bar());
}

TEST(AxisAngle, ZeroOrNonFiniteAxisIsADomainError) {
  RC_CLAUSE("AXANG-2");
  const Real nan = ScalarTraits<Real>::nan();
  EXPECT_EQ(AXANG_2_from_axis_angle(Real(1), Vec3<Real>{0, 0, 0}).status, Status::domain_error);
  EXPECT_EQ(AXANG_2_from_axis_angle(Real(1), Vec3<Real>{0, nan, 1}).status, Status::domain_error);
  EXPECT_EQ(AXANG_2_from_axis_angle(nan, Vec3<Real>{0, 0, 1}).status, Status::domain_error);
  EXPECT_EQ(AXANG_2_from_axis_angle(std::numeric_limits<double>::infinity(), Vec3<double>{0, 0, 1}).status,
            Status::domain_error);
  // Huge axes in double do not overflow.
  const QD q = AXANG_2_from_axis_angle(1.0, Vec3<double>{1e300, 1e300, 0}).value;
  EXPECT_LE(METRIC_1_rotation_distance(to_real(q), AXANG_2_from_axis_angle(Real(1), Vec3<Real>{1, 1, 0}).value),
            binary64_bar("eps16"));
}

// ---- LOG-1, LOG-2, EXP-1, EXP-2, EXPSERIES-1 ---------------------------------------------

RC_GTEST_PROP(LogExp, LogIsHalfAngleTimesAxis, ()) {
  RC_CLAUSE("LOG-1");
  const Q q = unit(*quaternion());
  const Real vn = sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
  const Real f = atan2(vn, q.w) / vn;
  const Vec3<Real> l = LOG_1_log(q).value;
  RC_ASSERT(diff(l, Vec3<Real>{f * q.x, f * q.y, f * q.z}) <= ref_class_bar());
  RC_ASSERT(vnorm(l) <= ScalarTraits<Real>::pi() * (1 + ref_class_bar()));  // |B| in [0, pi]
}

TEST(LogExp, LogOfIdentityIsExactlyZero) {
  RC_CLAUSE("LOG-1");
  const Vec3<Real> l = LOG_1_log(Q{7, 0, 0, 0}).value;
  for (const Real& c : l) EXPECT_TRUE(c == 0 && !signbit(c));
}

TEST(LogExp, LogOfMinusOneIsPiAboutZ) {
  RC_CLAUSE("LOG-2");
  for (const Q& q : {Q{-1, 0, 0, 0}, Q{-4, 0, 0, 0}}) {
    const Vec3<Real> l = LOG_1_log(q).value;
    EXPECT_TRUE(l[0] == 0 && l[1] == 0 && l[2] == ScalarTraits<Real>::pi());
  }
  // The rotor view: log(-1) = -pi e12.
  const std::array<Real, 3> b = cl3::log_rotor(MV(Real(-1)));
  EXPECT_TRUE(b[0] == 0 && b[1] == 0 && b[2] == -ScalarTraits<Real>::pi());
  EXPECT_EQ(LOG_1_log(Quaternion<double>{-1, 0, 0, 0}).value[2], M_PI);
}

RC_GTEST_PROP(LogExp, ExpIsCosPlusSinTimesAxis, ()) {
  RC_CLAUSE("EXP-1");
  const Vec3<Real> v = *vector3();
  const Real n = vnorm(v);
  RC_PRE(n > 0);
  const Real s = sin(n) / n;
  RC_ASSERT(diff(EXP_1_exp(v).value, Q{cos(n), s * v[0], s * v[1], s * v[2]}) <= ref_class_bar());
}

TEST(LogExp, ExpOfZeroIsExactlyOne) {
  RC_CLAUSE("EXP-1");
  EXPECT_TRUE(identical(EXP_1_exp(Vec3<Real>{0, 0, 0}).value, Q{1, 0, 0, 0}));
  EXPECT_TRUE(identical(EXP_1_exp(Vec3<double>{0, 0, 0}).value, QD{1, 0, 0, 0}));
}

RC_GTEST_PROP(LogExp, ExpLogAndLogExpAreInverse, ()) {
  RC_CLAUSE("EXP-2");
  const Q q = *quaternion();
  RC_ASSERT(diff(EXP_1_exp(LOG_1_log(q).value).value, unit(q)) <= ref_class_bar());
  const Vec3<Real> v = *vector3(1);  // |v| <= sqrt(3) < pi
  RC_ASSERT(diff(LOG_1_log(EXP_1_exp(v).value).value, v) <= ref_class_bar());
}

RC_GTEST_PROP(LogExp, ClosedFormsEqualTheGenericSeries, ()) {
  RC_CLAUSE("EXPSERIES-1");
  const Vec3<Real> b = *vector3(2);
  const MV bivector = cl3::bivector(b);
  RC_ASSERT(diff(exp_series(bivector), cl3::exp_bivector(b)) <= ref_class_bar());
  RC_ASSERT(diff(exp_series(bivector), detail::exp(bivector)) <= ref_class_bar());  // the scaled copy
  // The principal log, away from the cut at -1 where the series has no principal value.
  const Q q = unit(*quaternion());
  RC_PRE(q.w > Real("-0.5"));
  const MV r = cl3::rotor_from_quaternion(q);
  const std::optional<MV> series = log_series(r);
  RC_ASSERT(series.has_value());
  RC_ASSERT(diff(*series, cl3::bivector(cl3::log_rotor(r))) <= ref_class_bar());
  RC_ASSERT(diff(*series, detail::log(r)) <= ref_class_bar());
}

// ---- SLERP-1 ... SLERP-5, NLERP-1 ------------------------------------------------------

RC_GTEST_PROP(Slerp, IsAPowerOnTheShorterArc, ()) {
  RC_CLAUSE("SLERP-1");
  const Q a = unit(*quaternion()), b = unit(*quaternion());
  const Real t = *real_in(1);
  const Q bp = dot(a, b) < 0 ? -b : b;
  const Q s = SLERP_1_slerp(a, b, t).value;
  RC_ASSERT(diff(s, power_form(a, bp, t)) <= ref_class_bar());
  RC_ASSERT(METRIC_6_norm_defect(s) <= ref_class_bar());
}

RC_GTEST_PROP(Slerp, RotorInterpolationEqualsSlerp, ()) {
  RC_CLAUSE("SLERP-2");
  RC_CLAUSE("SLERP-4");
  const Q a = *quaternion(), b = *quaternion();
  const Real t = *real_in(3);  // t in [-3, 3]: inside and outside [0, 1]
  RC_ASSERT(diff(SLERP_2_rotor_interpolation(a, b, t).value, SLERP_1_slerp(a, b, t).value) <= ref_class_bar());
}

RC_GTEST_PROP(Slerp, Endpoints, ()) {
  RC_CLAUSE("SLERP-3");
  const Q a = *quaternion(), b = *quaternion();
  const Q bp = dot(a, b) < 0 ? -unit(b) : unit(b);
  RC_ASSERT(diff(SLERP_1_slerp(a, b, Real(0)).value, unit(a)) <= ref_class_bar());
  RC_ASSERT(diff(SLERP_1_slerp(a, b, Real(1)).value, bp) <= ref_class_bar());
  RC_ASSERT(diff(SLERP_2_rotor_interpolation(a, b, Real(1)).value, bp) <= ref_class_bar());
}

RC_GTEST_PROP(Slerp, ExtrapolatesAlongTheSameGreatCircle, ()) {
  RC_CLAUSE("SLERP-4");
  const Q a = unit(*quaternion()), b = unit(*quaternion());
  const Q bp = dot(a, b) < 0 ? -b : b;
  const Real t = *real_in(4);
  RC_ASSERT(diff(SLERP_1_slerp(a, b, t).value, power_form(a, bp, t)) <= ref_class_bar());
  // t = 2: a (a^-1 b')^2 = b' a^-1 b'; t = -1: a (a^-1 b')^-1 = a b'^-1 a.
  RC_ASSERT(diff(SLERP_1_slerp(a, b, Real(2)).value, bp * conj(a) * bp) <= ref_class_bar());
  RC_ASSERT(diff(SLERP_1_slerp(a, b, Real(-1)).value, a * conj(bp) * a) <= ref_class_bar());
}

RC_GTEST_PROP(Slerp, ConstantAngularVelocity, ()) {
  RC_CLAUSE("SLERP-5");
  const Q a = *quaternion(), b = *quaternion();
  // t1, t2 in [0, 1]: the rotation between them is at most the whole, <= pi, so METRIC-1 does not wrap.
  const Real t1 = abs(*real_in(1)), t2 = abs(*real_in(1));
  const Real whole = METRIC_1_rotation_distance(a, b);  // = distance(a, b'), <= pi
  const Real part = METRIC_1_rotation_distance(SLERP_1_slerp(a, b, t1).value, SLERP_1_slerp(a, b, t2).value);
  RC_ASSERT(abs(part - abs(t1 - t2) * whole) <= ref_class_bar());
}

RC_GTEST_PROP(Nlerp, NormalisedLinearBlendOnTheShorterArc, ()) {
  RC_CLAUSE("NLERP-1");
  const Q a = *quaternion(), b = *quaternion();
  const Real t = *real_in(2);
  const Q ua = unit(a), ub = unit(b);
  const Q bp = dot(ua, ub) < 0 ? -ub : ub;
  const Result<Q> n = NLERP_1_nlerp(a, b, t);
  RC_ASSERT(n.status == Status::ok);
  RC_ASSERT(diff(n.value, unit((1 - t) * ua + t * bp)) <= ref_class_bar());
  RC_ASSERT(METRIC_6_norm_defect(n.value) <= ref_class_bar());
  // Slerp and nlerp coincide at 0, 1/2 (the chord's midpoint points at the arc's midpoint), 1.
  for (const Real& s : {Real(0), Real("0.5"), Real(1)})
    RC_ASSERT(diff(NLERP_1_nlerp(a, b, s).value, SLERP_1_slerp(a, b, s).value) <= ref_class_bar());
}

TEST(Nlerp, NeverZeroEvenForAntipodesAndHugeT) {
  RC_CLAUSE("NLERP-1");
  const Q a = unit(Q{1, 2, 3, 4});
  for (const Real& t : {Real(0), Real("0.5"), Real(1), Real("1e30")})
    EXPECT_LE(diff(NLERP_1_nlerp(a, -a, t).value, a), ref_class_bar());  // b' = a
  const Result<QD> huge = NLERP_1_nlerp(QD{1, 0, 0, 0}, QD{0, 1, 0, 0}, DBL_MAX);
  EXPECT_EQ(huge.status, Status::ok);
  EXPECT_TRUE(finite(huge.value));
  EXPECT_LE(METRIC_1_rotation_distance(to_real(huge.value), Q{-1, 1, 0, 0}), binary64_bar("eps16"));
}

// ---- EDGE-1 ... EDGE-8 -----------------------------------------------------------------------

template <class T>
void expect_identity_exactly() {
  const Quaternion<T> one{T(1), T(0), T(0), T(0)};
  auto same = [](const Quaternion<T>& a, const Quaternion<T>& b) {
    return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z && !signbit(a.x) && !signbit(a.y) && !signbit(a.z);
  };
  EXPECT_TRUE(same(COMPOSE_1_compose(one, one).value, one));
  EXPECT_TRUE(same(NORM_1_normalize(one).value, one));
  EXPECT_TRUE(same(INV_1_inverse(one).value, one));
  for (const T& t : {T(0), T(0.25), T(0.5), T(1), T(-3), T(7)}) {
    EXPECT_TRUE(same(SLERP_1_slerp(one, one, t).value, one));
    EXPECT_TRUE(same(SLERP_2_rotor_interpolation(one, one, t).value, one));
    EXPECT_TRUE(same(NLERP_1_nlerp(one, one, t).value, one));
  }
  for (const T& c : LOG_1_log(one).value) EXPECT_TRUE(c == 0 && !signbit(c));
  EXPECT_TRUE(same(EXP_1_exp(Vec3<T>{T(0), T(0), T(0)}).value, one));
  const Quaternion<T> blend[] = {one, one};
  const T w[] = {T(1), T(2)};
  EXPECT_TRUE(same(QLB_1_blend<T>(blend, w).value, one));
  EXPECT_TRUE(same(LOGBLEND_1_blend<T>(blend, w).value, one));
  EXPECT_TRUE(same(KARCHER_1_mean<T>(blend, w).value, one));
}

TEST(Edge, IdentityInIdentityOutExactly) {
  RC_CLAUSE("EDGE-1");
  expect_identity_exactly<Real>();
  expect_identity_exactly<double>();
}

TEST(Edge, SmallAnglesAreAccurate) {
  RC_CLAUSE("EDGE-2");
  const Vec3<Real> axis = {Real(2) / 7, Real(-3) / 7, Real(6) / 7};  // unit
  for (const char* angle_text : {"1e-9", "1e-7", "1e-5", "1e-3"}) {
    const Real angle(angle_text);
    const Q q = AXANG_2_from_axis_angle(angle, axis).value;
    const Q one{1, 0, 0, 0};
    // Reference, 256 bits.
    EXPECT_LE(diff(LOG_1_log(q).value, Vec3<Real>{angle / 2 * axis[0], angle / 2 * axis[1], angle / 2 * axis[2]}), ref_class_bar());
    EXPECT_LE(abs(AXANG_1_to_axis_angle(q).value.angle - angle), ref_class_bar());
    const Real t("0.3");
    const Q expected = AXANG_2_from_axis_angle(t * angle, axis).value;
    EXPECT_LE(diff(SLERP_1_slerp(one, q, t).value, expected), ref_class_bar());
    EXPECT_LE(diff(SLERP_2_rotor_interpolation(one, q, t).value, expected), ref_class_bar());
    EXPECT_LE(METRIC_1_rotation_distance(one, q) - angle, ref_class_bar());
    // Double: no NaN, within the clause class of the reference.
    const QD qd = to_double(q), oned{1, 0, 0, 0};
    const QD sd = SLERP_1_slerp(oned, qd, 0.3).value;
    ASSERT_TRUE(finite(sd)) << angle_text;
    EXPECT_LE(METRIC_1_rotation_distance(to_real(sd), SLERP_1_slerp(one, to_real(qd), t).value), binary64_bar("eps16"));
    const QD s2 = SLERP_2_rotor_interpolation(oned, qd, 0.3).value;
    ASSERT_TRUE(finite(s2)) << angle_text;
    EXPECT_LE(METRIC_1_rotation_distance(to_real(s2), SLERP_1_slerp(one, to_real(qd), t).value), binary64_bar("eps16"));
    const Vec3<double> ld = LOG_1_log(qd).value;
    EXPECT_LE(METRIC_5_bivector_error(to_real(ld), LOG_1_log(to_real(qd)).value), binary64_bar("eps16"));
    // Relative accuracy too: the log of a tiny rotation keeps its digits.
    EXPECT_LE(METRIC_5_bivector_error(to_real(ld), LOG_1_log(to_real(qd)).value) / (angle / 2), binary64_bar("eps16"));
    const AxisAngle<double> aad = AXANG_1_to_axis_angle(qd).value;
    EXPECT_LE(abs(Real(aad.angle) - AXANG_1_to_axis_angle(to_real(qd)).value.angle) / angle, binary64_bar("eps16"));
    const QD ed = EXP_1_exp(ld).value;
    EXPECT_LE(METRIC_1_rotation_distance(to_real(ed), to_real(qd)), binary64_bar("eps16"));
  }
}

template <class T>
void expect_tie_rule() {
  using Qt = Quaternion<T>;
  // dot = +0: no flip, slerp at t = 1 reaches b itself, not -b.
  const Qt a{T(1), T(0), T(0), T(0)}, b{T(0), T(1), T(0), T(0)};
  const Qt s = SLERP_1_slerp(a, b, T(1)).value;
  EXPECT_TRUE(s.x > 0);
  EXPECT_TRUE(SLERP_2_rotor_interpolation(a, b, T(1)).value.x > 0);
  EXPECT_TRUE(NLERP_1_nlerp(a, b, T(1)).value.x > 0);
  // dot = -0 (every product -0): still no flip.
  const Qt c{T(-0.0), T(-1), T(-0.0), T(-0.0)};
  ASSERT_TRUE(dot(a, c) == 0 && signbit(dot(a, c)));
  EXPECT_TRUE(SLERP_1_slerp(a, c, T(1)).value.x < 0);
  EXPECT_TRUE(SLERP_2_rotor_interpolation(a, c, T(1)).value.x < 0);
  EXPECT_TRUE(NLERP_1_nlerp(a, c, T(1)).value.x < 0);
  // Exact antipodes: dot = -1 < 0 flips, b' = a, every t gives a.
  const Qt d{T(0.5), T(-0.5), T(0.5), T(0.5)};
  for (const T& t : {T(0), T(0.5), T(1), T(2)}) {
    const Qt r = SLERP_1_slerp(d, -d, t).value;
    EXPECT_TRUE(r.w == d.w && r.x == d.x && r.y == d.y && r.z == d.z);
  }
}

TEST(Edge, TieRuleAndAntipodes) {
  RC_CLAUSE("EDGE-3");
  expect_tie_rule<Real>();
  expect_tie_rule<double>();
  // Half turns: log at the rotor angle pi is (pi/2) u; at rotor -1 the cut of LOG-2.
  EXPECT_LE(diff(LOG_1_log(Q{0, 1, 0, 0}).value, Vec3<Real>{ScalarTraits<Real>::pi() / 2, 0, 0}), ref_class_bar());
  EXPECT_EQ(LOG_1_log(Q{-1, 0, 0, 0}).value[2], ScalarTraits<Real>::pi());
}

RC_GTEST_PROP(Edge, QAndMinusQAreOneRotation, ()) {
  RC_CLAUSE("EDGE-4");
  const Q a = *quaternion(), b = *quaternion();
  const Vec3<Real> v = *vector3();
  const Real t = *real_in(1);
  RC_ASSERT(METRIC_1_rotation_distance(COMPOSE_1_compose(-a, b).value, COMPOSE_1_compose(a, b).value) <= ref_class_bar());
  RC_ASSERT(METRIC_1_rotation_distance(INV_1_inverse(-a).value, INV_1_inverse(a).value) <= ref_class_bar());
  RC_ASSERT(METRIC_1_rotation_distance(SLERP_1_slerp(-a, b, t).value, SLERP_1_slerp(a, b, t).value) <= ref_class_bar());
  RC_ASSERT(METRIC_1_rotation_distance(SLERP_1_slerp(a, -b, t).value, SLERP_1_slerp(a, b, t).value) <= ref_class_bar());
  RC_ASSERT(METRIC_1_rotation_distance(NLERP_1_nlerp(a, -b, t).value, NLERP_1_nlerp(a, b, t).value) <= ref_class_bar());
  RC_ASSERT(METRIC_1_rotation_distance(SLERP_2_rotor_interpolation(-a, -b, t).value, SLERP_1_slerp(a, b, t).value) <=
            ref_class_bar());
  RC_ASSERT(diff(APPLY_1_apply_vector(-a, v).value, APPLY_1_apply_vector(a, v).value) <= ref_class_bar());
  RC_ASSERT(diff(APPLY_2_apply_bivector(-a, v).value, APPLY_2_apply_bivector(a, v).value) <= ref_class_bar());
  RC_ASSERT(diff(MAT_1_to_matrix(-a).value, MAT_1_to_matrix(a).value) <= ref_class_bar());
  const AxisAngle<Real> p = AXANG_1_to_axis_angle(a).value, m = AXANG_1_to_axis_angle(-a).value;
  RC_ASSERT(METRIC_1_rotation_distance(AXANG_2_from_axis_angle(p.angle, p.axis).value,
                                       AXANG_2_from_axis_angle(m.angle, m.axis).value) <= ref_class_bar());
}

RC_GTEST_PROP(Edge, ScaleDoesNotMatter, ()) {
  RC_CLAUSE("EDGE-5");
  const Q a = *quaternion(), b = *quaternion();
  const Real s = *rc::gen::element(Real("1e-30"), Real("3e-7"), Real(5), Real("1e30"));
  const Vec3<Real> v = *vector3();
  const Q sa = s * a;
  RC_ASSERT(diff(NORM_1_normalize(sa).value, NORM_1_normalize(a).value) <= ref_class_bar());
  // COMPOSE-1 is defined on the unnormalised inputs: scaling a scales the product, the rotation stays.
  RC_ASSERT(METRIC_1_rotation_distance(COMPOSE_1_compose(sa, b).value, COMPOSE_1_compose(a, b).value) <= ref_class_bar());
  RC_ASSERT(diff(SLERP_1_slerp(sa, b, Real("0.3")).value, SLERP_1_slerp(a, b, Real("0.3")).value) <= ref_class_bar());
  RC_ASSERT(diff(APPLY_1_apply_vector(sa, v).value, APPLY_1_apply_vector(a, v).value) <= ref_class_bar());
  RC_ASSERT(diff(MAT_1_to_matrix(sa).value, MAT_1_to_matrix(a).value) <= ref_class_bar());
  RC_ASSERT(diff(LOG_1_log(sa).value, LOG_1_log(a).value) <= ref_class_bar());
}

TEST(Edge, NormaliseAnyScaleInDouble) {
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("NORM-1");
  const QD base{0.5, -0.25, 0.75, 1.0};
  const Q expected = unit(to_real(base));
  for (int e = -1074 + 3; e <= 1023; e += 7) {
    const double s = std::ldexp(1.0, e);
    const QD q{base.w * s, base.x * s, base.y * s, base.z * s};
    if (!finite(q)) continue;
    const Result<QD> n = NORM_1_normalize(q);
    ASSERT_EQ(n.status, Status::ok) << e;
    if (e >= -1070) {  // the components are exactly the scaled base
      EXPECT_LE(diff(to_real(n.value), expected), binary64_bar("eps4")) << e;
    }
    EXPECT_LE(METRIC_6_norm_defect(to_real(n.value)), binary64_bar("eps4")) << e;
  }
  for (double s : {1e-30, 1e-10, 1.0, 1e10, 1e30, 1e300, DBL_MAX / 2}) {
    const QD q{s, s, s, s};
    EXPECT_LE(diff(to_real(NORM_1_normalize(q).value), Q{Real("0.5"), Real("0.5"), Real("0.5"), Real("0.5")}),
              binary64_bar("eps4"))
        << s;
    EXPECT_LE(METRIC_1_rotation_distance(to_real(SLERP_1_slerp(q, QD{1, 0, 0, 0}, 0.5).value),
                                         SLERP_1_slerp(Q{1, 1, 1, 1}, Q{1, 0, 0, 0}, Real("0.5")).value),
              binary64_bar("eps16"))
        << s;
  }
}

template <class T> bool all_nan(const T& x) { return ScalarTraits<T>::is_nan(x); }
template <class T> bool all_nan(const Quaternion<T>& q) { return all_nan(q.w) && all_nan(q.x) && all_nan(q.y) && all_nan(q.z); }
template <class T, std::size_t N> bool all_nan(const std::array<T, N>& a) {
  for (const T& x : a)
    if (!all_nan(x)) return false;
  return true;
}
template <class T> bool all_nan(const AxisAngle<T>& a) { return all_nan(a.angle) && all_nan(a.axis); }
template <class T> bool all_nan(const cl3::MV<T>& m) { return all_nan(m.c); }

template <class V>
void expect_domain_error(const Result<V>& r, const std::string& what) {
  EXPECT_EQ(r.status, Status::domain_error) << what;
  EXPECT_TRUE(all_nan(r.value)) << what;
}

/// Every function that takes a quaternion, with `bad` in each quaternion position.
template <class T>
void expect_every_function_rejects(const Quaternion<T>& bad, const std::string& what) {
  using Qt = Quaternion<T>;
  const Qt good{T(1), T(2), T(-3), T(4)};
  const Vec3<T> v{T(1), T(2), T(3)};
  const T t(0.25);
  expect_domain_error(NORM_1_normalize(bad), what + " NORM_1");
  expect_domain_error(COMPOSE_1_compose(bad, good), what + " COMPOSE_1 a");
  expect_domain_error(COMPOSE_1_compose(good, bad), what + " COMPOSE_1 b");
  expect_domain_error(INV_1_inverse(bad), what + " INV_1");
  expect_domain_error(APPLY_1_apply_vector(bad, v), what + " APPLY_1");
  expect_domain_error(APPLY_2_apply_bivector(bad, v), what + " APPLY_2");
  expect_domain_error(APPLY_3_apply_trivector(bad, t), what + " APPLY_3");
  expect_domain_error(MAT_1_to_matrix(bad), what + " MAT_1");
  expect_domain_error(AXANG_1_to_axis_angle(bad), what + " AXANG_1");
  expect_domain_error(LOG_1_log(bad), what + " LOG_1");
  expect_domain_error(SLERP_1_slerp(bad, good, t), what + " SLERP_1 a");
  expect_domain_error(SLERP_1_slerp(good, bad, t), what + " SLERP_1 b");
  expect_domain_error(SLERP_2_rotor_interpolation(bad, good, t), what + " SLERP_2 a");
  expect_domain_error(SLERP_2_rotor_interpolation(good, bad, t), what + " SLERP_2 b");
  expect_domain_error(NLERP_1_nlerp(bad, good, t), what + " NLERP_1 a");
  expect_domain_error(NLERP_1_nlerp(good, bad, t), what + " NLERP_1 b");
  // Blends: a bad influence is rejected even with weight 0.
  for (const T& w_bad : {T(1), T(0)}) {
    const Qt q[] = {good, bad};
    const T w[] = {T(1), w_bad};
    expect_domain_error(QLB_1_blend<T>(q, w), what + " QLB_1");
    expect_domain_error(LOGBLEND_1_blend<T>(q, w), what + " LOGBLEND_1");
    expect_domain_error(KARCHER_1_mean<T>(q, w), what + " KARCHER_1");
    expect_domain_error(BLENDQ_1_deviation<T>(q, w, BlendMethod::qlb), what + " BLENDQ_1");
  }
}

template <class T>
void expect_zero_rejected() {
  expect_every_function_rejects(Quaternion<T>{T(0), T(0), T(0), T(0)}, "zero");
  expect_every_function_rejects(Quaternion<T>{T(-0.0), T(0), T(-0.0), T(0)}, "signed zero");
}

TEST(Edge, ZeroQuaternionIsADomainError) {
  RC_CLAUSE("EDGE-6");
  expect_zero_rejected<Real>();
  expect_zero_rejected<double>();
}

template <class T>
void expect_non_finite_rejected() {
  const T nan = ScalarTraits<T>::nan(), inf = T(1) / T(0);
  for (int k = 0; k < 4; ++k)
    for (const T& bad : {nan, inf, T(-inf)}) {
      std::array<T, 4> c{T(1), T(2), T(3), T(4)};
      c[k] = bad;
      expect_every_function_rejects(Quaternion<T>::from_xyzw(c), "non-finite component " + std::to_string(k));
    }
  const Quaternion<T> good{T(1), T(2), T(-3), T(4)};
  for (const T& bad : {nan, inf, T(-inf)}) {
    const Vec3<T> v{T(1), bad, T(3)};
    expect_domain_error(SLERP_1_slerp(good, good, bad), "t SLERP_1");
    expect_domain_error(SLERP_2_rotor_interpolation(good, good, bad), "t SLERP_2");
    expect_domain_error(NLERP_1_nlerp(good, good, bad), "t NLERP_1");
    expect_domain_error(APPLY_1_apply_vector(good, v), "v APPLY_1");
    expect_domain_error(APPLY_2_apply_bivector(good, v), "v APPLY_2");
    expect_domain_error(APPLY_3_apply_trivector(good, bad), "s APPLY_3");
    expect_domain_error(EXP_1_exp(v), "v EXP_1");
    expect_domain_error(AXANG_2_from_axis_angle(bad, Vec3<T>{T(0), T(0), T(1)}), "angle AXANG_2");
    expect_domain_error(AXANG_2_from_axis_angle(T(1), v), "axis AXANG_2");
    expect_domain_error(Q2R_4_method1(bad, Vec3<T>{T(0), T(0), T(1)}), "angle Q2R_4");
    expect_domain_error(Q2R_4_method1(T(1), v), "axis Q2R_4");
    Mat3<T> m{T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};
    m[4] = bad;
    expect_domain_error(MAT_2_from_matrix(m), "matrix MAT_2");
  }
}

TEST(Edge, NonFiniteInputIsADomainError) {
  RC_CLAUSE("EDGE-7");
  expect_non_finite_rejected<Real>();
  expect_non_finite_rejected<double>();
}

TEST(Edge, SubnormalsAreOrdinaryValuesAndMinusZeroIsZero) {
  RC_CLAUSE("EDGE-8");
  const double d = std::numeric_limits<double>::denorm_min();
  // (w, x) = (3, 4) * 2^-1074: the unit quaternion (0.6, 0.8).
  const Result<QD> n = NORM_1_normalize(QD{3 * d, 4 * d, 0.0, -0.0});
  ASSERT_EQ(n.status, Status::ok);
  EXPECT_LE(diff(to_real(n.value), Q{Real("0.6"), Real("0.8"), 0, 0}), binary64_bar("eps4"));
  // A subnormal next to a normal component is kept, not flushed.
  const QD mixed{1.0, 0.0, 0.0, 1e-310};
  EXPECT_GT(NORM_1_normalize(mixed).value.z, 0.0);
  EXPECT_LE(diff(LOG_1_log(mixed).value, Vec3<double>{0, 0, 1e-310}), 0.0) << "log of a subnormal rotation is itself";
  // Huge and tiny logs in double neither overflow nor flush (exp of a finite v is finite).
  const QD big = EXP_1_exp(Vec3<double>{1e200, -1e200, 0}).value;
  EXPECT_TRUE(finite(big));
  EXPECT_LE(METRIC_6_norm_defect(to_real(big)), binary64_bar("eps4"));
  EXPECT_GT(EXP_1_exp(Vec3<double>{0, 0, 1e-310}).value.z, 0.0);
  // The smallest subnormal alone is the rotation (1, 0, 0, 0) after normalisation.
  EXPECT_TRUE(identical(NORM_1_normalize(QD{d, 0, 0, 0}).value, QD{1, 0, 0, 0}));
  // -0 equals +0: the same results bit for bit where the sign of zero does not leak.
  const QD plus{0.5, 0.0, 0.5, 0.0}, minus{0.5, -0.0, 0.5, -0.0};
  EXPECT_TRUE(MAT_1_to_matrix(plus).value == MAT_1_to_matrix(minus).value);
  EXPECT_TRUE(APPLY_1_apply_vector(plus, Vec3<double>{1, 2, 3}).value == APPLY_1_apply_vector(minus, Vec3<double>{1, 2, 3}).value);
}

}  // namespace
