// Skinning of one vertex (SKIN-1 .. SKIN-3): linear blend skinning against the plain matrix
// formula, dual-quaternion skinning against DLB + DQ-3, the rigid cases, the candy-wrapper
// effect, and the defined outcomes for bad input (EDGE-6, EDGE-7, EDGE-9).
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

// ---- plain formulas ------------------------------------------------------------------------

/// MAT-1 of q/|q| applied to v.
V3 matrix_rotate(const Q& q_in, const V3& v) {
  const Q q = (Real(1) / norm(q_in)) * q_in;
  const Real w = q.w, x = q.x, y = q.y, z = q.z;
  const Real m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                        {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}
V3 add(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 scale(const Real& s, const V3& a) { return {s * a[0], s * a[1], s * a[2]}; }
Real dot3(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Real length(const V3& a) { return sqrt(dot3(a, a)); }

// ---- generators ------------------------------------------------------------------------------

rc::Gen<V3> translation() { return rc::gen::weightedOneOf<V3>({{3, vector3(1000)}, {1, vector3(1000000)}}); }

struct Influences {
  std::vector<Q> q;
  std::vector<V3> t;
  std::vector<Real> w;
};

/// 1 to 4 influences: non-unit rotations, translations, nonnegative weights with a positive sum.
rc::Gen<Influences> influences() {
  return rc::gen::exec([] {
    Influences r;
    const int n = *rc::gen::inRange(1, 5);
    for (int i = 0; i < n; ++i) {
      r.q.push_back(*quaternion());
      r.t.push_back(*translation());
      r.w.push_back(*rc::gen::oneOf(rc::gen::just(Real(0)), rc::gen::map(real_in(4), [](const Real& x) { return abs(x); })));
    }
    r.w[std::size_t(*rc::gen::inRange(0, n))] += Real(1) / Real(8);
    return r;
  });
}

Real total(const std::vector<Real>& w) {
  Real s(0);
  for (const auto& x : w) s += x;
  return s;
}

// ---- SKIN-1 ----------------------------------------------------------------------------------

TEST(Skinning, LinearBlendIsTheWeightedAverageOfRigidTransforms) {
  RC_CLAUSE("SKIN-1");
  check_cases(100, [] {
    const Influences in = *influences();
    const V3 v = *translation();
    V3 expected{Real(0), Real(0), Real(0)};
    for (std::size_t i = 0; i < in.q.size(); ++i)
      expected = add(expected, scale(in.w[i] / total(in.w), add(matrix_rotate(in.q[i], v), in.t[i])));
    const auto got = SKIN_1_linear_blend<Real>(in.q, in.t, in.w, v);
    RC_ASSERT(got.status == Status::ok);
    RC_ASSERT(near(got.value, expected));
  });
}

// ---- SKIN-2 ----------------------------------------------------------------------------------

TEST(Skinning, DualQuaternionSkinningIsDLBThenApply) {
  RC_CLAUSE("SKIN-2");
  RC_CLAUSE("DQ-6");
  check_cases(100, [] {
    const Influences in = *influences();
    const V3 v = *translation(), v2 = *translation();
    std::vector<DQ> d;
    for (std::size_t i = 0; i < in.q.size(); ++i) d.push_back(DQ_1_from_rotation_translation(in.q[i], in.t[i]).value);
    const auto blended = DQ_6_dlb<Real>(d, in.w);
    const auto got = SKIN_2_dual_quaternion<Real>(in.q, in.t, in.w, v);
    RC_ASSERT(got.status == Status::ok);
    RC_ASSERT(near(got.value, DQ_3_apply_point(blended.value, v).value));
    // q and -q are the same bone rotation.
    Influences flipped = in;
    for (auto& q : flipped.q)
      if (*rc::gen::arbitrary<bool>()) q = -q;
    RC_ASSERT(near(SKIN_2_dual_quaternion<Real>(flipped.q, flipped.t, flipped.w, v).value, got.value));
    // One rigid transform per set of weights: distances between vertices are kept.
    const auto got2 = SKIN_2_dual_quaternion<Real>(in.q, in.t, in.w, v2);
    RC_ASSERT(near(length(sub(got.value, got2.value)), length(sub(v, v2))));
  });
}

TEST(Skinning, DualQuaternionSkinningDecidesTheHemisphereTieOnTheGivenRotations) {
  RC_CLAUSE("SKIN-2");
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("EDGE-3");
  // q_0 . q_1 = 0 exactly, with different norms: the real parts q_i/|q_i| of DQ-1 are rounded
  // at the reference precision, and their dot can come out as +-tiny. DQ-6 flips iff
  // real_1 . real_0 < 0, whose sign is that of q_1 . q_0 = 0: no flip, for q_1 and for -q_1.
  const std::vector<std::pair<Q, Q>> ties = {
      {Q{Real(0), Real(1), Real(2), Real(3)}, Q{Real(0), Real(3), Real(0), Real(-1)}},
      {Q{Real(7), Real(2), Real(3), Real(5)}, Q{Real(0), Real(3), Real(-2), Real(0)}},
      {Q{Real(1), Real(1), Real(1), Real(1)}, Q{Real(0), Real(1), Real(2), Real(-3)}},
      {Q{Real(11), Real(3), Real(5), Real(7)}, Q{Real(5), Real(0), Real(-11), Real(0)}}};
  const std::vector<V3> t{{Real(1), Real(0), Real(0)}, {Real(0), Real(1), Real(0)}};
  const std::vector<Real> w{Real(1), Real(1)};
  const V3 v{Real(1), Real(2), Real(3)};
  for (const auto& [q0, q1_in] : ties)
    for (const Real& sign : {Real(1), Real(-1)}) {
      const Q q1 = sign * q1_in;
      ASSERT_TRUE(dot(q0, q1) == 0);
      const DQ s0 = DQ_1_from_rotation_translation(q0, t[0]).value, s1 = DQ_1_from_rotation_translation(q1, t[1]).value;
      const DQ unflipped = DQ_4_normalize(DQ{s0.real + s1.real, s0.dual + s1.dual}).value;
      const std::vector<Q> q{q0, q1};
      EXPECT_TRUE(near(SKIN_2_dual_quaternion<Real>(q, t, w, v).value, DQ_3_apply_point(unflipped, v).value))
          << "q1 = " << q1.w << " " << q1.x << " " << q1.y << " " << q1.z;
    }
}

// ---- SKIN-3 ----------------------------------------------------------------------------------

TEST(Skinning, RigidCasesEqualTheRigidTransform) {
  RC_CLAUSE("SKIN-3");
  check_cases(100, [] {
    const Q q = *quaternion();
    const V3 t = *translation(), v = *translation();
    const V3 rigid = add(matrix_rotate(q, v), t);
    // A single influence (any positive weight).
    const std::vector<Q> q1{q};
    const std::vector<V3> t1{t};
    const std::vector<Real> w1{abs(*real_in(4)) + Real(1) / Real(8)};
    RC_ASSERT(near(SKIN_1_linear_blend<Real>(q1, t1, w1, v).value, rigid));
    RC_ASSERT(near(SKIN_2_dual_quaternion<Real>(q1, t1, w1, v).value, rigid));
    // All influences equal: the same rotation (scaled by nonzero k_i, sign included).
    const int n = *rc::gen::inRange(2, 5);
    std::vector<Q> qs;
    std::vector<V3> ts(std::size_t(n), t);
    std::vector<Real> ws;
    for (int i = 0; i < n; ++i) {
      const Real k = *rc::gen::suchThat(real_in(4), [](const Real& x) { return abs(x) > Real(1) / Real(16); });
      qs.push_back(k * q);
      ws.push_back(abs(*real_in(4)));
    }
    ws[0] += Real(1) / Real(8);
    RC_ASSERT(near(SKIN_1_linear_blend<Real>(qs, ts, ws, v).value, rigid));
    RC_ASSERT(near(SKIN_2_dual_quaternion<Real>(qs, ts, ws, v).value, rigid));
  });
}

/// Candy wrapper: two bones twisting by +theta and -theta about the same axis line (through c,
/// direction u), equal weights. With w = v - c split into w_par (along u) and w_perp:
///   R(+theta) w + R(-theta) w = 2 (w_par + cos(theta) w_perp)   (the sin terms cancel),
/// so LBS moves the vertex to c + w_par + cos(theta) w_perp: its distance from the axis shrinks by
/// exactly |cos theta|. The DLB of the two twists is the identity (or, when cos theta < 0 and the
/// second is flipped, the half turn about the axis): DQS keeps the distance.
TEST(Skinning, CandyWrapperLBSShrinksByCosineDQSPreserves) {
  RC_CLAUSE("SKIN-1");
  RC_CLAUSE("SKIN-2");
  check_cases(100, [] {
    const V3 c = *translation(), v = *translation();
    const V3 u0 = *rc::gen::suchThat(vector3(2), [](const V3& x) { return dot3(x, x) > Real(1) / Real(16); });
    const V3 u = scale(Real(1) / length(u0), u0);
    const Real theta = *real_in(3);
    const Real h = theta / Real(2);
    const Q plus{cos(h), sin(h) * u[0], sin(h) * u[1], sin(h) * u[2]};
    const Q minus{cos(h), -sin(h) * u[0], -sin(h) * u[1], -sin(h) * u[2]};
    // Rotation about the line through c: x -> R (x - c) + c, translation c - R c.
    const std::vector<Q> q{plus, minus};
    const std::vector<V3> t{sub(c, matrix_rotate(plus, c)), sub(c, matrix_rotate(minus, c))};
    const std::vector<Real> w{Real(1), Real(1)};
    const auto distance_from_axis = [&](const V3& x) {
      const V3 d = sub(x, c);
      return length(sub(d, scale(dot3(d, u), u)));
    };
    const Real rho = distance_from_axis(v);
    const V3 lbs = SKIN_1_linear_blend<Real>(q, t, w, v).value;
    const V3 dqs = SKIN_2_dual_quaternion<Real>(q, t, w, v).value;
    RC_ASSERT(near(distance_from_axis(lbs), abs(cos(theta)) * rho));
    RC_ASSERT(near(distance_from_axis(dqs), rho));
    // Neither moves the vertex along the axis.
    RC_ASSERT(near(dot3(sub(lbs, c), u), dot3(sub(v, c), u)));
    RC_ASSERT(near(dot3(sub(dqs, c), u), dot3(sub(v, c), u)));
  });
}

// ---- EDGE-6, EDGE-7, EDGE-9 ---------------------------------------------------------------

template <class T>
bool is_domain_error(const Result<Vec3<T>>& r) {
  return r.status == Status::domain_error &&
         std::all_of(r.value.begin(), r.value.end(), [](const T& x) { return ScalarTraits<T>::is_nan(x); });
}

template <class T>
struct Skin {
  std::vector<Quaternion<T>> q{{T(1), T(0), T(0), T(0)}, {T(0), T(0), T(3), T(4)}};
  std::vector<Vec3<T>> t{{T(1), T(2), T(3)}, {T(-1), T(0), T(5)}};
  std::vector<T> w{T(1), T(3)};
  Vec3<T> v{T(2), T(-1), T(1)};
  bool both_fail() const {
    return is_domain_error(SKIN_1_linear_blend<T>(q, t, w, v)) && is_domain_error(SKIN_2_dual_quaternion<T>(q, t, w, v));
  }
  bool both_ok() const {
    return SKIN_1_linear_blend<T>(q, t, w, v).status == Status::ok &&
           SKIN_2_dual_quaternion<T>(q, t, w, v).status == Status::ok;
  }
};

template <class T>
void check_skin_edges() {
  const Skin<T> valid;
  EXPECT_TRUE(valid.both_ok());
  // EDGE-6: a zero rotation quaternion (signed zeros included).
  {
    Skin<T> s = valid;
    s.q[1] = {-T(0), T(0), -T(0), T(0)};
    EXPECT_TRUE(s.both_fail());
  }
  // EDGE-7: NaN or +-Inf in any component of q, t, v or w.
  for (const T& bad : {ScalarTraits<T>::nan(), T(std::numeric_limits<double>::infinity()),
                       T(-std::numeric_limits<double>::infinity())}) {
    for (int k = 0; k < 4; ++k) {
      Skin<T> s = valid;
      (k == 0 ? s.q[1].w : k == 1 ? s.q[1].x : k == 2 ? s.q[1].y : s.q[1].z) = bad;
      EXPECT_TRUE(s.both_fail()) << k;
    }
    for (int k = 0; k < 3; ++k) {
      Skin<T> s = valid, r = valid;
      s.t[0][k] = bad;
      r.v[k] = bad;
      EXPECT_TRUE(s.both_fail()) << k;
      EXPECT_TRUE(r.both_fail()) << k;
    }
    Skin<T> s = valid;
    s.w[1] = bad;
    EXPECT_TRUE(s.both_fail());
  }
  // EDGE-9: negative weight, zero sum, empty set, mismatched sizes.
  for (const std::vector<T>& w : {std::vector<T>{T(1), T(-1)}, std::vector<T>{T(0), -T(0)}, std::vector<T>{T(1)},
                                  std::vector<T>{T(1), T(1), T(1)}}) {
    Skin<T> s = valid;
    s.w = w;
    EXPECT_TRUE(s.both_fail());
  }
  {
    Skin<T> s = valid;
    s.t.pop_back();
    EXPECT_TRUE(s.both_fail());
    Skin<T> e;
    e.q.clear();
    e.t.clear();
    e.w.clear();
    EXPECT_TRUE(e.both_fail());
  }
  // -0 counts as 0: valid, the result is the second influence alone.
  {
    Skin<T> s = valid;
    s.w = {-T(0), T(5)};
    EXPECT_TRUE(s.both_ok());
    const auto lbs = SKIN_1_linear_blend<T>(s.q, s.t, s.w, s.v).value;
    const auto dqs = SKIN_2_dual_quaternion<T>(s.q, s.t, s.w, s.v).value;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(ScalarTraits<T>::to_double(lbs[k]), ScalarTraits<T>::to_double(dqs[k]), 1e-14);
  }
}

TEST(Skinning, BadInputIsDomainError) {
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-9");
  check_skin_edges<Real>();
  check_skin_edges<double>();
}

}  // namespace
