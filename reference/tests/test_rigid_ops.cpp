// Dual quaternions (DQ-1 .. DQ-6), rotation about an off-origin line (AXIS-1), and the edge
// cases of the rigid-transform functions (EDGE-5, EDGE-6, EDGE-7, EDGE-9).
//
// The DQ functions are checked against plain formulas written here (rotation matrix MAT-1,
// Rodrigues' formula, screws built from translations and rotations), not against themselves.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/near.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "prelude.hpp"

namespace {

// ---- tolerance: the spec's "ref" class, relative to max(1, |expected|) per component ----------

/// The same rigid transform: sigma and -sigma.
bool same_motion(const DQ& a, const DQ& b) { return near(a, b) || near(a, DQ{-b.real, -b.dual}); }

// ---- plain formulas ------------------------------------------------------------------------

/// MAT-1 of a unit quaternion applied to v (rows as in the spec).
template <class T>
Vec3<T> matrix_rotate(const Quaternion<T>& q, const Vec3<T>& v) {
  const T w = q.w, x = q.x, y = q.y, z = q.z;
  const T m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                     {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                     {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Q unit_of(const Q& q) { return (Real(1) / norm(q)) * q; }
V3 add(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 scale(const Real& s, const V3& a) { return {s * a[0], s * a[1], s * a[2]}; }
Real dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Rotation by theta about the unit axis u: (cos(theta/2), sin(theta/2) u).
Q about(const Real& theta, const V3& u) {
  const Real h = theta / Real(2);
  return {cos(h), sin(h) * u[0], sin(h) * u[1], sin(h) * u[2]};
}

/// Rodrigues: v cos + (u x v) sin + u (u.v)(1 - cos), u unit.
V3 rodrigues(const V3& u, const Real& theta, const V3& v) {
  return add(add(scale(cos(theta), v), scale(sin(theta), cross(u, v))), scale(dot3(u, v) * (1 - cos(theta)), u));
}

// ---- generators ------------------------------------------------------------------------------

rc::Gen<V3> translation() { return rc::gen::weightedOneOf<V3>({{3, vector3(1000)}, {1, vector3(1000000)}}); }

rc::Gen<DQ> rigid_dq() {
  return rc::gen::apply(
      [](const Q& q, const V3& v) { return DQ{q, (Real(1) / Real(2)) * (Q{Real(0), v[0], v[1], v[2]} * q)}; },
      unit_quaternion(), translation());
}
DQ disturbed(const DQ& d, const Real& k, const Real& lambda) { return {k * d.real, k * (d.dual + lambda * d.real)}; }
rc::Gen<Real> nonzero_scale() {
  return rc::gen::suchThat(real_in(8), [](const Real& k) { return abs(k) > Real(1) / Real(64); });
}
rc::Gen<Real> positive_scale() { return rc::gen::map(nonzero_scale(), [](const Real& k) { return abs(k); }); }
rc::Gen<V3> unit_vector() {
  return rc::gen::map(rc::gen::suchThat(vector3(2), [](const V3& v) { return dot3(v, v) > Real(1) / Real(16); }),
                      [](const V3& v) { return scale(Real(1) / sqrt(dot3(v, v)), v); });
}
/// t in [-2, 3]: inside and outside [0, 1].
rc::Gen<Real> interpolation_parameter() {
  return rc::gen::map(real_in(2), [](const Real& x) { return x * Real(5) / Real(4) + Real(1) / Real(2); });
}

// ---- DQ-1 ----------------------------------------------------------------------------------

TEST(DualQuaternion, FromRotationTranslationMovesPointsByRotationThenTranslation) {
  RC_CLAUSE("DQ-1");
  RC_CLAUSE("DQ-3");
  check_cases(100, [] {
    const Q q = *quaternion();  // not unit: stands for q/|q|
    const V3 t = *translation(), p = *translation();
    const auto d = DQ_1_from_rotation_translation(q, t);
    RC_ASSERT(d.status == Status::ok);
    RC_ASSERT(near(d.value.real, unit_of(q)));
    const auto moved = DQ_3_apply_point(d.value, p);
    RC_ASSERT(moved.status == Status::ok);
    RC_ASSERT(near(moved.value, add(matrix_rotate(unit_of(q), p), t)));
    // t = 2 q_d q_r*, also of a non-unit representative.
    RC_ASSERT(near(DQ_1_translation(d.value).value, t));
    RC_ASSERT(near(DQ_1_translation(disturbed(d.value, *nonzero_scale(), *real_in(4))).value, t));
  });
}

TEST(DualQuaternion, PureTranslationHasHalfTranslationAsDualPart) {
  RC_CLAUSE("DQ-1");
  const auto d = DQ_1_from_rotation_translation<Real>(Q::identity(), {Real(2), Real(-4), Real(6)});
  EXPECT_EQ(d.value.real.xyzw(), Q::identity().xyzw());
  EXPECT_EQ(d.value.dual.xyzw(), (std::array<Real, 4>{Real(1), Real(-2), Real(3), Real(0)}));
  // Quarter turn about z, then translation: q_d = (1/2) t q_r by hand.
  const Real h = sqrt(Real(1) / Real(2));
  const auto e = DQ_1_from_rotation_translation<Real>({h, Real(0), Real(0), h}, {Real(2), Real(0), Real(0)});
  EXPECT_TRUE(near(e.value.dual, Q{Real(0), h, -h, Real(0)}));  // (1/2)(2i)(h + h k) = h i + h ik = h i - h j
}

// ---- DQ-2 ----------------------------------------------------------------------------------

TEST(DualQuaternion, ComposeAppliesTheRightOperandFirst) {
  RC_CLAUSE("DQ-2");
  check_cases(100, [] {
    const DQ a = *rigid_dq(), b = *rigid_dq(), c = *rigid_dq();
    const V3 p = *translation();
    const auto ab = DQ_2_compose(a, b);
    RC_ASSERT(ab.status == Status::ok);
    RC_ASSERT(near(DQ_3_apply_point(ab.value, p).value, DQ_3_apply_point(a, DQ_3_apply_point(b, p).value).value));
    // Associative, and the product of unit dual quaternions is unit.
    RC_ASSERT(near(DQ_2_compose(ab.value, c).value, DQ_2_compose(a, DQ_2_compose(b, c).value).value));
    RC_ASSERT(near(norm(ab.value.real), Real(1)));
    RC_ASSERT(abs(dot(ab.value.real, ab.value.dual)) <= rotorcert::testing::ref_class_bar() * Real(1000000));
  });
  // Translate by x, then quarter turn about z: the origin goes to (0, 1, 0).
  const Real h = sqrt(Real(1) / Real(2));
  const DQ turn{{h, Real(0), Real(0), h}, {}};
  const DQ shift = DQ_1_from_rotation_translation<Real>(Q::identity(), {Real(1), Real(0), Real(0)}).value;
  EXPECT_TRUE(near(DQ_3_apply_point<Real>(DQ_2_compose(turn, shift).value, {}).value, V3{Real(0), Real(1), Real(0)}));
  EXPECT_TRUE(near(DQ_3_apply_point<Real>(DQ_2_compose(shift, turn).value, {}).value, V3{Real(1), Real(0), Real(0)}));
}

/// QUAT-1's component formulas, written out here (not the reference's operator*).
Q hamilton(const Q& a, const Q& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

TEST(DualQuaternion, ComposeIsTheProductOfTheInputsAsGiven) {
  RC_CLAUSE("DQ-2");
  RC_CLAUSE("MOTOR-3");
  RC_CLAUSE("METRIC-7");
  check_cases(100, [] {
    // Non-unit inputs whose dual part is not orthogonal to the real part: DQ-2 says "No
    // normalisation", so the result is (a_r b_r, a_r b_d + a_d b_r) of these very inputs.
    const DQ a = disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4));
    const DQ b = disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4));
    const DQ expected{hamilton(a.real, b.real), hamilton(a.real, b.dual) + hamilton(a.dual, b.real)};
    const auto ab = DQ_2_compose(a, b);
    RC_ASSERT(ab.status == Status::ok);
    RC_ASSERT(near(ab.value, expected));
    RC_ASSERT(near(MOTOR_3_compose(a, b).value, expected));  // MOTOR-3: the same product in the algebra
    // The dual norm is multiplicative, so DQ-4 of the product is the product of the DQ-4
    // normalisations: METRIC-7 (both sides DQ-4 normalised) accepts either for the same motion.
    RC_ASSERT(near(DQ_4_normalize(ab.value).value,
                   DQ_2_compose(DQ_4_normalize(a).value, DQ_4_normalize(b).value).value));
  });
}

// ---- DQ-4 ----------------------------------------------------------------------------------

TEST(DualQuaternion, NormaliseMakesRealPartUnitAndDualPartOrthogonal) {
  RC_CLAUSE("DQ-4");
  RC_CLAUSE("EDGE-5");
  check_cases(100, [] {
    const auto c = *rc::gen::container<std::array<Real, 8>>(real_in(1000));
    const DQ d{{c[3], c[0], c[1], c[2]}, {c[7], c[4], c[5], c[6]}};
    RC_PRE(!is_zero(d.real));
    const auto n = DQ_4_normalize(d);
    RC_ASSERT(n.status == Status::ok);
    // The clause's formula, unscaled.
    const Real r = norm(d.real);
    const DQ expected{(Real(1) / r) * d.real, (Real(1) / r) * d.dual - (dot(d.real, d.dual) / (r * r * r)) * d.real};
    RC_ASSERT(near(n.value, expected));
    RC_ASSERT(near(norm(n.value.real), Real(1)));
    RC_ASSERT(abs(dot(n.value.real, n.value.dual)) <= rotorcert::testing::ref_class_bar() * Real(1000));
    RC_ASSERT(near(DQ_4_normalize(n.value).value, n.value));  // idempotent
    // EDGE-5: k sigma + lambda (0, k q_r) normalise to the same (k > 0).
    const Real k = *positive_scale(), lambda = *real_in(4);
    RC_ASSERT(near(DQ_4_normalize(disturbed(n.value, k, lambda)).value, n.value));
  });
}

// ---- DQ-5 ----------------------------------------------------------------------------------

/// The screw motion about the line through c with unit direction u: rotation by s theta and
/// translation by s pitch along u, built from DQ-1 and DQ-2 only: T_c T_(s pitch u) R(s theta) T_-c.
DQ screw(const V3& c, const V3& u, const Real& theta, const Real& pitch, const Real& s) {
  const DQ to_c = DQ_1_from_rotation_translation(Q::identity(), c).value;
  const DQ from_c = DQ_1_from_rotation_translation(Q::identity(), scale(Real(-1), c)).value;
  const DQ move = DQ_1_from_rotation_translation(about(s * theta, u), scale(s * pitch, u)).value;
  return DQ_2_compose(to_c, DQ_2_compose(move, from_c).value).value;
}

TEST(DualQuaternion, ScLERPFollowsTheScrew) {
  RC_CLAUSE("DQ-5");
  check_cases(100, [] {
    const DQ a = *rigid_dq();
    const V3 c = *translation(), u = *unit_vector();
    const Real theta = *real_in(3), pitch = *real_in(1000), t = *interpolation_parameter();  // |theta| <= 3 < pi
    const DQ b = DQ_2_compose(a, screw(c, u, theta, pitch, Real(1))).value;
    const DQ expected = DQ_2_compose(a, screw(c, u, theta, pitch, t)).value;
    const Real k = *nonzero_scale();
    const auto got = DQ_5_sclerp(a, disturbed(b, k, *real_in(4)), t);  // b and -b: the same motion
    RC_ASSERT(got.status == Status::ok);
    RC_ASSERT(near(got.value, expected));
  });
}

TEST(DualQuaternion, ScLERPEndpointsAndHemisphere) {
  RC_CLAUSE("DQ-5");
  check_cases(100, [] {
    const DQ a = *rigid_dq(), b = *rigid_dq();
    const DQ b_aligned = dot(a.real, b.real) < 0 ? DQ{-b.real, -b.dual} : b;
    RC_ASSERT(near(DQ_5_sclerp(a, b, Real(0)).value, a));
    RC_ASSERT(near(DQ_5_sclerp(a, b, Real(1)).value, b_aligned));
    // Constant velocity of the rotation: at t = 1/2 the rotation is halfway (real part bisects).
    const Q mid = DQ_5_sclerp(a, b, Real(1) / Real(2)).value.real;
    RC_ASSERT(near(mid, unit_of(a.real + b_aligned.real)));
  });
}

template <class T>
void check_sclerp_tie_rule() {
  // dot(a_r, b_r) = 0 exactly: no flip. a = 1, b = half turn about z: halfway is +90 deg about z.
  const DualQuaternion<T> a{Quaternion<T>::identity(), {}};
  const DualQuaternion<T> b{{T(0), T(0), T(0), T(1)}, {}};
  for (const T& zero : {T(0), -T(0)}) {
    DualQuaternion<T> bz = b;
    bz.real.w = zero;
    const auto r = DQ_5_sclerp(a, bz, T(1) / T(2));
    using std::sqrt;
    const T h = sqrt(T(1) / T(2));
    EXPECT_NEAR(ScalarTraits<T>::to_double(r.value.real.w), ScalarTraits<T>::to_double(h), 1e-15);
    EXPECT_NEAR(ScalarTraits<T>::to_double(r.value.real.z), ScalarTraits<T>::to_double(h), 1e-15);
  }
}

TEST(DualQuaternion, ScLERPFlipsOnlyOnStrictlyNegativeDot) {
  RC_CLAUSE("DQ-5");
  RC_CLAUSE("EDGE-3");
  check_sclerp_tie_rule<Real>();
  check_sclerp_tie_rule<double>();
}

// ---- DQ-6 ----------------------------------------------------------------------------------

rc::Gen<std::vector<Real>> weights(int n) {
  return rc::gen::map(rc::gen::container<std::vector<Real>>(std::size_t(n), real_in(4)), [](std::vector<Real> w) {
    for (auto& x : w) x = abs(x);
    w[0] += Real(1) / Real(8);
    return w;
  });
}

TEST(DualQuaternion, DLBIsSignInvariantAndIgnoresZeroWeights) {
  RC_CLAUSE("DQ-6");
  check_cases(100, [] {
    const int n = *rc::gen::inRange(1, 5);
    std::vector<DQ> d;
    for (int i = 0; i < n; ++i) d.push_back(*rigid_dq());
    const std::vector<Real> w = *weights(n);
    const auto base = DQ_6_dlb<Real>(d, w);
    RC_ASSERT(base.status == Status::ok);
    RC_ASSERT(near(norm(base.value.real), Real(1)));
    // s_i: negating an influence changes nothing (not even the sign: that follows the pivot).
    for (int i = 1; i < n; ++i) {
      std::vector<DQ> flipped = d;
      flipped[i] = disturbed(d[i], *nonzero_scale(), *real_in(4));
      RC_ASSERT(near(DQ_6_dlb<Real>(flipped, w).value, base.value));
    }
    // The pivot is the first positive weight: influences of weight 0 in front change nothing.
    std::vector<DQ> d0 = d;
    std::vector<Real> w0 = w;
    d0.insert(d0.begin(), *rigid_dq());
    w0.insert(w0.begin(), *rc::gen::element(Real(0), -Real(0)));
    RC_ASSERT(near(DQ_6_dlb<Real>(d0, w0).value, base.value));
    // Only the ratios of the weights matter.
    std::vector<Real> w2 = w;
    const Real k = *positive_scale();
    for (auto& x : w2) x *= k;
    RC_ASSERT(near(DQ_6_dlb<Real>(d, w2).value, base.value));
    // The result's sign is the pivot's hemisphere.
    RC_ASSERT(dot(base.value.real, d[0].real) >= 0);
  });
}

TEST(DualQuaternion, DLBOfTwoPointsOnOneScrewIsTheMidpoint) {
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("DQ-5");
  check_cases(100, [] {
    const V3 c = *translation(), u = *unit_vector();
    const Real theta = *real_in(3), pitch = *real_in(1000);
    // |theta (s1 - s2)| <= 3 < pi: the two rotations lie in one hemisphere, no flip.
    const Real s1 = *real_in(1) / Real(2), s2 = *real_in(1) / Real(2);
    const std::vector<DQ> d{screw(c, u, theta, pitch, s1), screw(c, u, theta, pitch, s2)};
    const std::vector<Real> w{Real(1), Real(1)};
    const DQ mid = screw(c, u, theta, pitch, (s1 + s2) / Real(2));
    RC_ASSERT(same_motion(DQ_6_dlb<Real>(d, w).value, mid));
    RC_ASSERT(same_motion(DQ_5_sclerp(d[0], d[1], Real(1) / Real(2)).value, mid));
  });
}

TEST(DualQuaternion, DLBOfOneInfluenceIsItsNormalisation) {
  RC_CLAUSE("DQ-6");
  check_cases(50, [] {
    const DQ d = *rigid_dq();
    const DQ x = disturbed(d, *positive_scale(), *real_in(4));
    const std::vector<DQ> one{x};
    const std::vector<Real> w{*positive_scale()};
    RC_ASSERT(near(DQ_6_dlb<Real>(one, w).value, d));
  });
}

// ---- AXIS-1 --------------------------------------------------------------------------------

TEST(Axis, RotationAboutLineEqualsPlainFormula) {
  RC_CLAUSE("AXIS-1");
  RC_CLAUSE("EDGE-5");
  check_cases(100, [] {
    const V3 c = *translation(), p = *translation(), u = *unit_vector();
    const Real theta = *real_in(7), k = *positive_scale();
    const V3 expected = add(rodrigues(u, theta, sub(p, c)), c);
    const auto got = AXIS_1_rotate_about_line(c, scale(k, u), theta, p);  // u need not be unit
    RC_ASSERT(got.status == Status::ok);
    RC_ASSERT(near(got.value, expected));
    // Points of the line stay put.
    const V3 on_line = add(c, scale(*real_in(100), u));
    RC_ASSERT(near(AXIS_1_rotate_about_line(c, u, theta, on_line).value, on_line));
  });
  // Right-handed: a quarter turn about +z through (1, 0, 0) takes (2, 0, 0) to (1, 1, 0).
  const auto r = AXIS_1_rotate_about_line<Real>({Real(1), Real(0), Real(0)}, {Real(0), Real(0), Real(3)},
                                                ScalarTraits<Real>::pi() / Real(2), {Real(2), Real(0), Real(0)});
  EXPECT_TRUE(near(r.value, V3{Real(1), Real(1), Real(0)}));
}

// ---- EDGE-6, EDGE-7, EDGE-9: defined outcomes ---------------------------------------------------

template <class T> bool all_nan(const T& x) { return ScalarTraits<T>::is_nan(x); }
template <class T> bool all_nan(const Quaternion<T>& q) { return all_nan(q.w) && all_nan(q.x) && all_nan(q.y) && all_nan(q.z); }
template <class T, std::size_t N> bool all_nan(const std::array<T, N>& a) {
  return std::all_of(a.begin(), a.end(), [](const T& x) { return all_nan(x); });
}
template <class T> bool all_nan(const DualQuaternion<T>& d) { return all_nan(d.real) && all_nan(d.dual); }
template <class T> bool all_nan(const RotationTranslation<T>& r) { return all_nan(r.q) && all_nan(r.t); }

template <class V>
bool is_domain_error(const Result<V>& r) { return r.status == Status::domain_error && all_nan(r.value); }

template <class T> T& component(DualQuaternion<T>& d, int k) {
  Quaternion<T>& q = k < 4 ? d.real : d.dual;
  switch (k % 4) {
    case 0: return q.x;
    case 1: return q.y;
    case 2: return q.z;
    default: return q.w;
  }
}

/// Every function of rigid_ops.hpp that takes dual quaternions, on (a, b, p, t, weights).
template <class T>
std::vector<bool> all_rigid_calls_fail(const DualQuaternion<T>& a, const DualQuaternion<T>& b, const Vec3<T>& p,
                                       const T& t, const std::vector<T>& w) {
  const std::vector<DualQuaternion<T>> ds{a, b};
  return {is_domain_error(DQ_1_translation(a)),          is_domain_error(DQ_2_compose(a, b)),
          is_domain_error(DQ_2_compose(b, a)),           is_domain_error(DQ_3_apply_point(a, p)),
          is_domain_error(DQ_4_normalize(a)),            is_domain_error(DQ_5_sclerp(a, b, t)),
          is_domain_error(DQ_5_sclerp(b, a, t)),         is_domain_error(DQ_6_dlb<T>(ds, w)),
          is_domain_error(MOTOR_2_apply_point(a, p)),    is_domain_error(MOTOR_3_compose(a, b)),
          is_domain_error(MOTOR_3_compose(b, a)),        is_domain_error(MOTOR_4_interpolate(a, b, t)),
          is_domain_error(MOTOR_4_interpolate(b, a, t)), is_domain_error(MOTOR_5_blend<T>(ds, w))};
}

template <class T>
struct Valid {
  DualQuaternion<T> a{{T(1) / T(2), T(1) / T(2), T(1) / T(2), T(1) / T(2)}, {T(1), T(-2), T(3), T(0)}};
  DualQuaternion<T> b{{T(0), T(0), T(3) / T(5), T(4) / T(5)}, {T(5), T(0), T(0), T(0)}};
  Vec3<T> p{T(1), T(2), T(3)};
  T t = T(1) / T(3);
  std::vector<T> w{T(1), T(2)};
};

template <class T>
void check_zero_real_part() {
  const Valid<T> v;
  // Sanity: the valid inputs succeed everywhere.
  for (bool failed : all_rigid_calls_fail(v.a, v.b, v.p, v.t, v.w)) EXPECT_FALSE(failed);
  for (const T& zero : {T(0), -T(0)}) {
    DualQuaternion<T> z = v.a;
    z.real = {zero, T(0), -T(0), zero};
    int i = 0;
    for (bool failed : all_rigid_calls_fail(z, v.b, v.p, v.t, v.w)) EXPECT_TRUE(failed) << "call " << i++;
  }
  EXPECT_TRUE(is_domain_error(DQ_1_from_rotation_translation(Quaternion<T>{T(0), -T(0), T(0), T(0)}, v.p)));
}

TEST(RigidEdge, ZeroRealPartIsDomainError) {
  RC_CLAUSE("EDGE-6");
  check_zero_real_part<Real>();
  check_zero_real_part<double>();
}

template <class T>
void check_nonfinite() {
  const Valid<T> v;
  for (const T& bad : {ScalarTraits<T>::nan(), T(std::numeric_limits<double>::infinity()),
                      T(-std::numeric_limits<double>::infinity())}) {
    for (int k = 0; k < 8; ++k) {
      DualQuaternion<T> a = v.a, b = v.b;
      component(a, k) = bad;
      component(b, k) = bad;
      for (bool failed : all_rigid_calls_fail(a, v.b, v.p, v.t, v.w)) EXPECT_TRUE(failed) << k;
      for (bool failed : all_rigid_calls_fail(b, v.a, v.p, v.t, v.w)) EXPECT_TRUE(failed) << k;
      Quaternion<T> q = a.real;  // k >= 4: a valid real part with a bad translation
      EXPECT_TRUE(is_domain_error(DQ_1_from_rotation_translation(k < 4 ? q : v.a.real, k < 4 ? v.p : Vec3<T>{bad, T(0), T(0)})));
    }
    for (int k = 0; k < 3; ++k) {
      Vec3<T> p = v.p, c{T(0), T(0), T(0)}, u{T(0), T(0), T(1)};
      p[k] = bad;
      EXPECT_TRUE(is_domain_error(DQ_3_apply_point(v.a, p)));
      EXPECT_TRUE(is_domain_error(MOTOR_2_apply_point(v.a, p)));
      EXPECT_TRUE(is_domain_error(DQ_1_from_rotation_translation(v.a.real, p)));
      EXPECT_TRUE(is_domain_error(AXIS_1_rotate_about_line(c, u, v.t, p)));
      EXPECT_TRUE(is_domain_error(AXIS_1_rotate_about_line(p, u, v.t, v.p)));
      EXPECT_TRUE(is_domain_error(AXIS_1_rotate_about_line(c, p, v.t, v.p)));
    }
    EXPECT_TRUE(is_domain_error(DQ_5_sclerp(v.a, v.b, bad)));
    EXPECT_TRUE(is_domain_error(MOTOR_4_interpolate(v.a, v.b, bad)));
    EXPECT_TRUE(is_domain_error(AXIS_1_rotate_about_line<T>({}, {T(0), T(0), T(1)}, bad, v.p)));
  }
}

TEST(RigidEdge, NonFiniteInputIsDomainError) {
  RC_CLAUSE("EDGE-7");
  check_nonfinite<Real>();
  check_nonfinite<double>();
}

template <class T>
void check_axis_zero_direction() {
  EXPECT_TRUE(is_domain_error(AXIS_1_rotate_about_line<T>({T(1), T(2), T(3)}, {T(0), -T(0), T(0)}, T(1), {T(4), T(5), T(6)})));
  // A subnormal direction is a direction (EDGE-8): no domain error, and the rotation is about z.
  const auto r = AXIS_1_rotate_about_line<T>({}, {T(0), T(0), T(0x1p-1074)}, T(1), {T(1), T(0), T(0)});
  EXPECT_EQ(r.status, Status::ok);
  using std::cos;
  EXPECT_NEAR(ScalarTraits<T>::to_double(r.value[0]), std::cos(1.0), 1e-15);
}

TEST(RigidEdge, AxisWithoutDirectionIsDomainError) {
  RC_CLAUSE("AXIS-1");
  RC_CLAUSE("EDGE-6");
  check_axis_zero_direction<Real>();
  check_axis_zero_direction<double>();
}

template <class T>
void check_weights() {
  const Valid<T> v;
  const std::vector<DualQuaternion<T>> two{v.a, v.b}, none;
  const T nan = ScalarTraits<T>::nan(), inf = T(std::numeric_limits<double>::infinity());
  const std::vector<std::vector<T>> bad{{nan, T(1)}, {T(1), inf}, {-inf, T(1)}, {T(1), T(-1)},
                                        {T(0), T(0)}, {T(0), -T(0)}, {T(1)}, {T(1), T(1), T(1)}};
  for (const auto& w : bad) {
    EXPECT_TRUE(is_domain_error(DQ_6_dlb<T>(two, w)));
    EXPECT_TRUE(is_domain_error(MOTOR_5_blend<T>(two, w)));
  }
  const std::vector<T> empty;
  EXPECT_TRUE(is_domain_error(DQ_6_dlb<T>(none, empty)));
  EXPECT_TRUE(is_domain_error(MOTOR_5_blend<T>(none, empty)));
  // -0 counts as 0: valid, and the pivot is the second influence.
  const std::vector<T> w{-T(0), T(2)};
  const auto r = DQ_6_dlb<T>(two, w);
  EXPECT_EQ(r.status, Status::ok);
  const auto only_b = DQ_4_normalize(v.b).value;
  EXPECT_NEAR(ScalarTraits<T>::to_double(r.value.real.w), ScalarTraits<T>::to_double(only_b.real.w), 1e-15);
  EXPECT_NEAR(ScalarTraits<T>::to_double(r.value.dual.x), ScalarTraits<T>::to_double(only_b.dual.x), 1e-14);
  EXPECT_EQ(MOTOR_5_blend<T>(two, w).status, Status::ok);
}

TEST(RigidEdge, BadWeightsAreDomainError) {
  RC_CLAUSE("EDGE-9");
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("MOTOR-5");
  check_weights<Real>();
  check_weights<double>();
}

TEST(RigidEdge, NonUnitRealPartIsNormalised) {
  RC_CLAUSE("EDGE-5");
  check_cases(50, [] {
    const DQ a = *rigid_dq(), b = *rigid_dq();
    const V3 p = *translation();
    const Real t = *interpolation_parameter();
    const DQ an = disturbed(a, *nonzero_scale(), *real_in(4)), bn = disturbed(b, *nonzero_scale(), *real_in(4));
    RC_ASSERT(near(DQ_3_apply_point(an, p).value, DQ_3_apply_point(a, p).value));
    RC_ASSERT(near(DQ_1_translation(an).value, DQ_1_translation(a).value));
    // DQ-2 is an exception (the product of the inputs as given); its DQ-4 normalisation, which is
    // what METRIC-7 compares, is the composed motion.
    RC_ASSERT(same_motion(DQ_4_normalize(DQ_2_compose(an, bn).value).value, DQ_2_compose(a, b).value));
    RC_ASSERT(same_motion(DQ_4_normalize(an).value, a));
    RC_ASSERT(same_motion(DQ_5_sclerp(an, bn, t).value, DQ_5_sclerp(a, b, t).value));
    const std::vector<DQ> d{a, b}, dn{an, bn};
    const std::vector<Real> w{Real(1), Real(3)};
    RC_ASSERT(same_motion(DQ_6_dlb<Real>(dn, w).value, DQ_6_dlb<Real>(d, w).value));
    // Unit-valued outputs stay unit.
    RC_ASSERT(near(norm(DQ_5_sclerp(an, bn, t).value.real), Real(1)));
  });
  // Double: a dual quaternion at a large and a tiny scale is the same rigid transform.
  const DualQuaternion<double> d{{0.5, 0.5, 0.5, 0.5}, {1, -2, 3, 0}};
  for (double k : {0x1p-1000, 0x1p+1000}) {
    const DualQuaternion<double> s{k * d.real, k * d.dual};
    const auto p = DQ_3_apply_point<double>(s, {1, 2, 3});
    const auto q = DQ_3_apply_point<double>(d, {1, 2, 3});
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.value[i], q.value[i], 1e-13) << k;
  }
}

// ---- DQ-7: DQ-1 read backwards -----------------------------------------------------------------

TEST(DualQuaternion, RotationAndTranslationInvertFromRotationTranslation) {
  RC_CLAUSE("DQ-7");
  check_cases(100, [] {
    const Q q = *quaternion();  // not unit: stands for q/|q|
    RC_PRE(norm(q) > Real(1) / Real(64));
    const V3 t = *translation();
    // A non-unit representative with a part of the dual along the real part (EDGE-5): same q, t.
    const DQ sigma = disturbed(DQ_1_from_rotation_translation(q, t).value, *positive_scale(), *real_in(4));
    const auto r = DQ_7_to_rotation_translation(sigma);
    RC_ASSERT(r.status == Status::ok);
    RC_ASSERT(near(r.value.q, unit_of(q)));
    RC_ASSERT(near(r.value.t, t));
  });
  EXPECT_TRUE(is_domain_error(DQ_7_to_rotation_translation(DQ{Q{Real(0), Real(0), Real(0), Real(0)}, Q::identity()})));  // EDGE-6
  EXPECT_TRUE(is_domain_error(
      DQ_7_to_rotation_translation(DQ{Q::identity(), Q{Real(0), ScalarTraits<Real>::nan(), Real(0), Real(0)}})));  // EDGE-7
}

// ---- RIGID-1 .. RIGID-3: rotation + translation against the matrix formula and DQ-2/DQ-3 --------

TEST(RigidTransform, ApplyRotatesThenTranslates) {
  RC_CLAUSE("RIGID-2");
  check_cases(50, [] {
    const Q q = *quaternion();  // non-unit: the rotation of q/|q| (EDGE-5)
    RC_PRE(norm(q) > Real(1) / Real(64));
    const V3 t = *translation(), p = *translation();
    const auto r = RIGID_2_apply(q, t, p);
    RC_ASSERT(r.status == Status::ok);
    RC_ASSERT(near(r.value, add(matrix_rotate(unit_of(q), p), t)));
    RC_ASSERT(near(r.value, DQ_3_apply_point(DQ_1_from_rotation_translation(q, t).value, p).value));
  });
}

TEST(RigidTransform, ComposeAppliesTheRightOperandFirst) {
  RC_CLAUSE("RIGID-1");
  check_cases(50, [] {
    const Q qa = *unit_quaternion(), qb = *unit_quaternion();
    const V3 ta = *translation(), tb = *translation(), p = *translation();
    const auto c = RIGID_1_compose(qa, ta, qb, tb);
    RC_ASSERT(c.status == Status::ok);
    // (a o b)(p) = a(b(p)), by the matrix formula.
    const V3 twice = add(matrix_rotate(qa, add(matrix_rotate(qb, p), tb)), ta);
    RC_ASSERT(near(RIGID_2_apply(c.value.q, c.value.t, p).value, twice));
    // The same motion as DQ-2's product of the two DQ-1 motions.
    const DQ product = DQ_2_compose(DQ_1_from_rotation_translation(qa, ta).value, DQ_1_from_rotation_translation(qb, tb).value).value;
    RC_ASSERT(same_motion(DQ_1_from_rotation_translation(c.value.q, c.value.t).value, product));
  });
}

TEST(RigidTransform, InverseUndoesTheTransform) {
  RC_CLAUSE("RIGID-3");
  check_cases(50, [] {
    const Q q = *unit_quaternion();
    const V3 t = *translation(), p = *translation();
    const auto inv = RIGID_3_inverse(q, t);
    RC_ASSERT(inv.status == Status::ok);
    RC_ASSERT(near(RIGID_2_apply(inv.value.q, inv.value.t, RIGID_2_apply(q, t, p).value).value, p));
    RC_ASSERT(near(inv.value.q, conj(q)));
  });
  const V3 t{Real(1), Real(2), Real(3)};
  EXPECT_TRUE(is_domain_error(RIGID_3_inverse(Q{Real(0), Real(0), Real(0), Real(0)}, t)));  // EDGE-6
  EXPECT_TRUE(is_domain_error(RIGID_1_compose(Q::identity(), t, Q::identity(), V3{Real(1), Real(std::numeric_limits<double>::infinity()), Real(0)})));  // EDGE-7
  EXPECT_TRUE(is_domain_error(RIGID_2_apply(Q::identity(), t, V3{ScalarTraits<Real>::nan(), Real(0), Real(0)})));
}

}  // namespace
