// Hamilton quaternions and the quaternion <-> rotor map (QUAT-1, Q2R-1 ... Q2R-5).
//
// Random quaternions lie on a 2^-20 grid with components of at most 2, so products of a few
// of them are exact at 256 bits: the algebraic identities are checked for exact equality.
// Where transcendentals round (Method 1), the spec's "ref" class bounds the difference.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/cl3.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "prelude.hpp"

namespace {

using MV = cl3::MV<Real>;

/// The spec's "ref" class (spec/clauses.json, tolerance_classes.ref: 1e-60): identities of the
/// reference itself at 256 bits, where rounding happens.

bool same(const MV& a, const MV& b) { return a.c == b.c; }
bool same(const Q& a, const Q& b) { return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z; }

Real max_abs_diff(const MV& a, const MV& b) {
  Real m(0);
  for (int i = 0; i < 8; ++i) m = std::max(m, Real(abs(a.c[i] - b.c[i])));
  return m;
}

MV blade(const char* name) { return blade_from_name<Cl3, Real>(name); }

rc::Gen<MV> even_multivector() {
  return rc::gen::map(rotorcert::testing::multivector<Cl3>(2), [](const MV& m) { return even(m); });
}

// Functions, not globals: a Real made during static initialisation would have 53 bits.
Q one() { return {1, 0, 0, 0}; }
Q qi() { return {0, 1, 0, 0}; }
Q qj() { return {0, 0, 1, 0}; }
Q qk() { return {0, 0, 0, 1}; }

TEST(Quaternion, HamiltonUnitsSquareToMinusOneAndIjkIsMinusOne) {
  RC_CLAUSE("QUAT-1");
  EXPECT_TRUE(same(qi() * qi(), -one()));
  EXPECT_TRUE(same(qj() * qj(), -one()));
  EXPECT_TRUE(same(qk() * qk(), -one()));
  EXPECT_TRUE(same(qi() * qj() * qk(), -one()));
  // The cyclic products follow: ij = k, jk = i, ki = j, and they anticommute.
  EXPECT_TRUE(same(qi() * qj(), qk()));
  EXPECT_TRUE(same(qj() * qk(), qi()));
  EXPECT_TRUE(same(qk() * qi(), qj()));
  EXPECT_TRUE(same(qj() * qi(), -qk()));
}

RC_GTEST_PROP(Quaternion, ProductIsBilinearExpansionOfTheUnitTable, ()) {
  RC_CLAUSE("QUAT-1");
  // (sum a_m e_m)(sum b_n e_n) = sum a_m b_n (e_m e_n): the product formula agrees with the
  // multiplication table above, term by term.
  const Q a = *quaternion(), b = *quaternion();
  const std::array<Q, 4> unit{one(), qi(), qj(), qk()};
  const std::array<Real, 4> ca{a.w, a.x, a.y, a.z}, cb{b.w, b.x, b.y, b.z};
  Q sum{0, 0, 0, 0};
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) sum = sum + Real(ca[m] * cb[n]) * (unit[m] * unit[n]);
  RC_ASSERT(same(a * b, sum));
}

TEST(QuaternionToRotor, UnitsMapToMinusTheBivectorBasis) {
  RC_CLAUSE("Q2R-1");
  EXPECT_TRUE(same(Q2R_1_rotor_from_quaternion(one()), MV(Real(1))));
  EXPECT_TRUE(same(Q2R_1_rotor_from_quaternion(qi()), -blade("e23")));
  EXPECT_TRUE(same(Q2R_1_rotor_from_quaternion(qj()), -blade("e31")));
  EXPECT_TRUE(same(Q2R_1_rotor_from_quaternion(qk()), -blade("e12")));
  EXPECT_TRUE(same(Q2R_1_quaternion_from_rotor(-blade("e31")), qj()));
}

RC_GTEST_PROP(QuaternionToRotor, MapAndInverseRoundTripExactly, ()) {
  RC_CLAUSE("Q2R-1");
  const Q q = *quaternion();
  RC_ASSERT(same(Q2R_1_quaternion_from_rotor(Q2R_1_rotor_from_quaternion(q)), q));
  const MV r = *even_multivector();
  RC_ASSERT(same(Q2R_1_rotor_from_quaternion(Q2R_1_quaternion_from_rotor(r)), r));
}

RC_GTEST_PROP(QuaternionToRotor, IsAnAlgebraIsomorphism, ()) {
  RC_CLAUSE("Q2R-2");
  const Q p = *quaternion(), q = *quaternion();
  const Real s = *rotorcert::testing::real_in(2);
  const MV rp = Q2R_1_rotor_from_quaternion(p), rq = Q2R_1_rotor_from_quaternion(q);
  RC_ASSERT(same(Q2R_1_rotor_from_quaternion(p * q), gp(rp, rq)));                     // products
  RC_ASSERT(same(Q2R_1_rotor_from_quaternion(p + s * q), rp + s * rq));               // linear
  RC_ASSERT(same(Q2R_1_rotor_from_quaternion(conj(q)), reverse(rq)));                 // q* <-> ~R
  RC_ASSERT(scp(rq, reverse(rq)) == dot(q, q));                                        // |Phi(q)| = |q|
  RC_ASSERT(same(gp(rq, reverse(rq)), MV(dot(q, q))));                                 // R ~R is scalar
}

RC_GTEST_PROP(QuaternionToRotor, RotatesLikeQuaternionConjugation, ()) {
  RC_CLAUSE("Q2R-3");
  // Unnormalised, both sides carry the factor |q|^2, and everything is exact.
  const Q q = *quaternion();
  const std::array<Real, 3> v = *vector3();
  const Q qv = q * Q{0, v[0], v[1], v[2]} * conj(q);
  const MV r = Q2R_1_rotor_from_quaternion(q);
  RC_ASSERT(same(gp(gp(r, cl3::vector(v)), reverse(r)), cl3::vector<Real>({qv.x, qv.y, qv.z})));
  RC_ASSERT(qv.w == 0);
  // And through the clause function, which normalises: APPLY-1 = q v q* / |q|^2.
  const Vec3<Real> applied = APPLY_1_apply_vector(q, v).value;
  for (int k = 0; k < 3; ++k)
    RC_ASSERT(abs(applied[k] - std::array<Real, 3>{qv.x, qv.y, qv.z}[k] / dot(q, q)) <= ref_class_bar());
}

RC_GTEST_PROP(QuaternionToRotor, Method1EqualsMethod2, ()) {
  RC_CLAUSE("Q2R-4");
  const Q q = *unit_quaternion();
  const AxisAngle<Real> aa = AXANG_1_to_axis_angle(q).value;
  const Result<MV> m1 = Q2R_4_method1(aa.angle, aa.axis);
  RC_ASSERT(m1.status == Status::ok);
  RC_ASSERT(max_abs_diff(m1.value, Q2R_1_rotor_from_quaternion(q)) <= ref_class_bar());
}

RC_GTEST_PROP(QuaternionToRotor, Method1FromAnyAngleAndAxisIsPhiOfTheQuaternion, ()) {
  RC_CLAUSE("Q2R-4");
  using std::cos;
  using std::sin;
  const Real angle = *rotorcert::testing::real_in(8);
  const Vec3<Real> axis = *rc::gen::suchThat(vector3(), [](const Vec3<Real>& a) {
    return a[0] * a[0] + a[1] * a[1] + a[2] * a[2] > Real(1) / Real(1024);
  });
  const Real n = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const Real s = sin(angle / 2) / n;
  const Q expected{cos(angle / 2), s * axis[0], s * axis[1], s * axis[2]};
  RC_ASSERT(max_abs_diff(Q2R_4_method1(angle, axis).value, Q2R_1_rotor_from_quaternion(expected)) <= ref_class_bar());
}

TEST(QuaternionToRotor, Method1RotatesRightHandedAboutTheAxis) {
  RC_CLAUSE("Q2R-4");
  // exp(-I e3 theta/2) takes e1 to cos(theta) e1 + sin(theta) e2.
  const Real theta = Real(1) / Real(3);
  const MV r = Q2R_4_method1(theta, Vec3<Real>{0, 0, 2}).value;
  const MV image = cl3::sandwich(r, cl3::vector<Real>({1, 0, 0}));
  EXPECT_LE(abs(image.c[cl3::kE1] - cos(theta)), ref_class_bar());
  EXPECT_LE(abs(image.c[cl3::kE2] - sin(theta)), ref_class_bar());
  EXPECT_EQ(Q2R_4_method1(theta, Vec3<Real>{0, 0, 0}).status, Status::domain_error);
}

TEST(QuaternionToRotor, ExactlyOneOfTheFortyEightSignedMapsIsValid) {
  RC_CLAUSE("Q2R-5");
  EXPECT_EQ(Q2R_5_count_valid_maps(), 1);
  const std::array<MapVerdict, 48> verdicts = Q2R_5_classify_maps();
  int homomorphisms = 0;
  for (const MapVerdict& v : verdicts) {
    if (v.is_homomorphism) ++homomorphisms;
    const bool is_q2r1 = v.map.target == std::array<int, 3>{0, 1, 2} && v.map.sign == std::array<int, 3>{-1, -1, -1};
    EXPECT_EQ(v.is_homomorphism && v.rotates_correctly, is_q2r1);
  }
  // Phi composed with the 24 automorphisms of H that permute +-i, +-j, +-k (the rotation
  // group of the cube): all homomorphisms, only the identity automorphism rotates by q.
  EXPECT_EQ(homomorphisms, 24);
}

TEST(QuaternionToRotor, PrintedMapsFailUniqueness) {
  RC_CLAUSE("Q2R-5");
  // The paper's Method 2 (ERRATUM-2): x e23 + y e31 + z e12, all signs +.
  const MapVerdict printed = Q2R_5_classify(SignedMap{{0, 1, 2}, {+1, +1, +1}});
  EXPECT_FALSE(printed.is_homomorphism);
  EXPECT_FALSE(printed.rotates_correctly);
  // The Appendix B alternative (ERRATUM-4): x e23 - y e31 + z e12.
  const MapVerdict alternative = Q2R_5_classify(SignedMap{{0, 1, 2}, {+1, -1, +1}});
  EXPECT_TRUE(alternative.is_homomorphism);
  EXPECT_FALSE(alternative.rotates_correctly);
  // The classifier sees the map it is given: Q2R-1's own map passes.
  const MapVerdict q2r1 = Q2R_5_classify(SignedMap{});
  EXPECT_TRUE(q2r1.is_homomorphism);
  EXPECT_TRUE(q2r1.rotates_correctly);
}

}  // namespace
