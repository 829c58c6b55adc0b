// PGA Cl(3,0,1) and its motors (ALG-7, MOTOR-1 .. MOTOR-5): points, translators, the map to
// dual quaternions, and the equivalences between the motor route (geometric products, closed-form
// exp/log) and the dual-quaternion route (quaternion formulas) of rigid_ops.hpp.
//
// Random rigid transforms: unit rotations and translations up to 1e3, a quarter of them up to
// 1e6. MPFR at 256 bits is slow, so the heavier properties run a limited number of cases.
#include <algorithm>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/motor.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/series.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/near.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "prelude.hpp"

namespace {

using PMV = pga::MV<Real>;

// ---- tolerance: the spec's "ref" class, relative to max(1, |expected|) per component ----------

bool near(const PMV& a, const PMV& b) {
  for (int i = 0; i < PGA3::size; ++i)
    if (!near(a.c[i], b.c[i])) return false;
  return true;
}

// ---- generators ------------------------------------------------------------------------------

rc::Gen<V3> translation() { return rc::gen::weightedOneOf<V3>({{3, vector3(1000)}, {1, vector3(1000000)}}); }

/// A unit rigid transform (q, (1/2) t q), written with the quaternion product of quaternion.hpp.
rc::Gen<DQ> rigid_dq(rc::Gen<V3> t = translation()) {
  return rc::gen::apply(
      [](const Quaternion<Real>& q, const V3& v) {
        return DQ{q, (Real(1) / Real(2)) * (Quaternion<Real>{Real(0), v[0], v[1], v[2]} * q)};
      },
      unit_quaternion(), t);
}

/// The same rigid transform as a non-unit dual quaternion: k sigma, plus lambda q_r in the dual
/// part (DQ-4 removes both; EDGE-5).
DQ disturbed(const DQ& d, const Real& k, const Real& lambda) {
  return {k * d.real, k * (d.dual + lambda * d.real)};
}
rc::Gen<Real> nonzero_scale() {
  return rc::gen::suchThat(real_in(8), [](const Real& k) { return abs(k) > Real(1) / Real(64); });
}

PMV named(const char* name) { return blade_from_name<PGA3, Real>(name); }

/// Phi(q) in the even subalgebra of e1, e2, e3 of PGA: w - x e23 - y e31 - z e12.
PMV pga_rotor(const Quaternion<Real>& q) {
  return q.w * named("1") - q.x * named("e23") - q.y * named("e31") - q.z * named("e12");
}

// ---- ALG-7: the algebra of points and translators ------------------------------------------

TEST(PGA, IdealVectorSquaresToZeroAndAnticommutes) {
  RC_CLAUSE("ALG-7");
  const PMV e0 = named("e0");
  EXPECT_EQ(gp(e0, e0).c, PMV().c);
  for (const char* e : {"e1", "e2", "e3"}) {
    EXPECT_EQ(gp(named(e), named(e)).c, PMV(Real(1)).c) << e;
    EXPECT_EQ(gp(e0, named(e)).c, (-gp(named(e), e0)).c) << e;
  }
  // I = e0123 squares to 0 and commutes with the even elements.
  EXPECT_EQ(gp(pga::I<Real>(), pga::I<Real>()).c, PMV().c);
  for (const char* b : {"e01", "e02", "e03", "e12", "e31", "e23"})
    EXPECT_EQ(gp(pga::I<Real>(), named(b)).c, gp(named(b), pga::I<Real>()).c) << b;
  // I turns Euclidean bivectors into ideal ones (motor.hpp's split M = R + I S).
  EXPECT_EQ(gp(pga::I<Real>(), named("e23")).c, (-named("e01")).c);
  EXPECT_EQ(gp(pga::I<Real>(), named("e31")).c, (-named("e02")).c);
  EXPECT_EQ(gp(pga::I<Real>(), named("e12")).c, (-named("e03")).c);
}

RC_GTEST_PROP(PGA, PointEmbeddingIsTheNamedTrivectors, ()) {
  RC_CLAUSE("ALG-7");
  const V3 p = *translation();
  const PMV expected = p[0] * named("e032") + p[1] * named("e013") + p[2] * named("e021") + named("e123");
  RC_ASSERT(pga::point(p).c == expected.c);
  RC_ASSERT(pga::point_coordinates(pga::point(p)) == p);
}

RC_GTEST_PROP(PGA, TranslatorMovesPointsByPlusT, ()) {
  RC_CLAUSE("ALG-7");
  const V3 p = *translation(), t = *translation();
  const PMV moved = pga::sandwich(pga::translator(t), pga::point(p));
  // Grid inputs: exact arithmetic, exact equality.
  RC_ASSERT(moved.c == pga::point(V3{p[0] + t[0], p[1] + t[1], p[2] + t[2]}).c);
  // The translator is the exp of the ideal bivector -(1/2)(tx e01 + ty e02 + tz e03).
  const PMV ideal = (Real(-1) / Real(2)) * (t[0] * named("e01") + t[1] * named("e02") + t[2] * named("e03"));
  RC_ASSERT(MOTOR_4_exp(ideal).c == pga::translator(t).c);
}

RC_GTEST_PROP(PGA, EuclideanRotorActsLikeCl3, ()) {
  RC_CLAUSE("ALG-7");
  const auto q = *unit_quaternion();
  const V3 p = *translation();
  const V3 in_pga = pga::point_coordinates(pga::sandwich(pga_rotor(q), pga::point(p)));
  const V3 in_cl3 = cl3::vector_part(cl3::sandwich(cl3::rotor_from_quaternion(q), cl3::vector(p)));
  RC_ASSERT(near(in_pga, in_cl3));
}

TEST(PGA, MotorsOfUnitDualQuaternionsAreUnit) {
  RC_CLAUSE("ALG-7");
  check_cases(50, [] {
    const DQ d = *rigid_dq();
    const PMV m = MOTOR_1_from_dual_quaternion(d);
    RC_ASSERT(near(gp(m, reverse(m)), PMV(Real(1))));
    RC_ASSERT(even(m).c == m.c);
  });
}

// ---- MOTOR-1: the coefficient map --------------------------------------------------------------

RC_GTEST_PROP(Motor, MapIsTheClauseFormulaExactly, ()) {
  RC_CLAUSE("MOTOR-1");
  const auto c = *rc::gen::container<std::array<Real, 8>>(real_in(4));
  const DQ d{{c[3], c[0], c[1], c[2]}, {c[7], c[4], c[5], c[6]}};
  const PMV expected = d.real.w * named("1") - d.real.x * named("e23") - d.real.y * named("e31") -
                       d.real.z * named("e12") - d.dual.x * named("e01") - d.dual.y * named("e02") -
                       d.dual.z * named("e03") - d.dual.w * named("e0123");
  RC_ASSERT(MOTOR_1_from_dual_quaternion(d).c == expected.c);
  // M = Phi(q_r) - e0123 Phi(q_d).
  RC_ASSERT(expected.c == (pga_rotor(d.real) - gp(pga::I<Real>(), pga_rotor(d.dual))).c);
}

RC_GTEST_PROP(Motor, MapAndInverseAreExact, ()) {
  RC_CLAUSE("MOTOR-1");
  const auto c = *rc::gen::container<std::array<Real, 8>>(real_in(4));
  const DQ d{{c[3], c[0], c[1], c[2]}, {c[7], c[4], c[5], c[6]}};
  const DQ back = MOTOR_1_to_dual_quaternion(MOTOR_1_from_dual_quaternion(d));
  RC_ASSERT(back.real.xyzw() == d.real.xyzw());
  RC_ASSERT(back.dual.xyzw() == d.dual.xyzw());
  const PMV m = even(*rotorcert::testing::multivector<PGA3>());
  RC_ASSERT(MOTOR_1_from_dual_quaternion(MOTOR_1_to_dual_quaternion(m)).c == m.c);
}

TEST(Motor, MotorOfDualQuaternionIsTranslatorTimesRotor) {
  RC_CLAUSE("MOTOR-1");
  RC_CLAUSE("DQ-1");
  check_cases(50, [] {
    const auto q = *unit_quaternion();
    const V3 t = *translation();
    const auto d = DQ_1_from_rotation_translation(q, t);
    RC_ASSERT(d.status == Status::ok);
    RC_ASSERT(near(MOTOR_1_from_dual_quaternion(d.value), gp(pga::translator(t), pga_rotor(q))));
  });
}

// ---- MOTOR-2, MOTOR-3: sandwich and product against the quaternion formulas --------------------

TEST(Motor, SandwichOfPointEqualsDualQuaternionTransform) {
  RC_CLAUSE("MOTOR-2");
  RC_CLAUSE("DQ-3");
  check_cases(50, [] {
    const DQ d = disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4));
    const V3 p = *translation();
    const auto by_motor = MOTOR_2_apply_point(d, p);
    const auto by_dq = DQ_3_apply_point(d, p);
    RC_ASSERT(by_motor.status == Status::ok && by_dq.status == Status::ok);
    RC_ASSERT(near(by_motor.value, by_dq.value));
  });
}

TEST(Motor, ProductCorrespondsToDualQuaternionProduct) {
  RC_CLAUSE("MOTOR-3");
  RC_CLAUSE("DQ-2");
  check_cases(50, [] {
    const DQ a = *rigid_dq(), b = *rigid_dq();
    // The map is a homomorphism: M(a) M(b) = M(a b).
    const DQ ab{a.real * b.real, a.real * b.dual + a.dual * b.real};
    RC_ASSERT(near(gp(MOTOR_1_from_dual_quaternion(a), MOTOR_1_from_dual_quaternion(b)),
                   MOTOR_1_from_dual_quaternion(ab)));
    const DQ an = disturbed(a, *nonzero_scale(), *real_in(4));
    const DQ bn = disturbed(b, *nonzero_scale(), *real_in(4));
    const auto by_motor = MOTOR_3_compose(an, bn);
    const auto by_dq = DQ_2_compose(an, bn);
    RC_ASSERT(by_motor.status == Status::ok && by_dq.status == Status::ok);
    RC_ASSERT(near(by_motor.value, by_dq.value));
    // Apply b first.
    const V3 p = *translation();
    RC_ASSERT(near(MOTOR_2_apply_point(by_motor.value, p).value,
                   MOTOR_2_apply_point(an, MOTOR_2_apply_point(bn, p).value).value));
  });
}

// ---- MOTOR-4: closed-form exp and log against the series ----------------------------------------

rc::Gen<PMV> line_bivector(int range) {
  return rc::gen::apply([](const V3& e, const V3& i) { return pga::bivector<Real>(e, i); }, vector3(range),
                        vector3(range));
}

TEST(Motor, ExpClosedFormEqualsSeries) {
  RC_CLAUSE("MOTOR-4");
  check_cases(50, [] {
    const V3 zero{Real(0), Real(0), Real(0)};
    const int kind = *rc::gen::inRange(0, 4);  // general, pure rotation, pure translation, large
    PMV b;
    if (kind == 0) b = *line_bivector(4);
    if (kind == 1) b = pga::bivector<Real>(*vector3(4), zero);
    if (kind == 2) b = pga::bivector<Real>(zero, *vector3(1000));
    if (kind == 3) b = pga::bivector<Real>(*vector3(4), *vector3(1000));
    const PMV closed = MOTOR_4_exp(b), series = exp_series(b);
    RC_ASSERT(near(closed, series));
    RC_ASSERT(near(gp(closed, reverse(closed)), PMV(Real(1))));  // a unit motor (ALG-7)
  });
}

TEST(Motor, LogClosedFormEqualsSeries) {
  RC_CLAUSE("MOTOR-4");
  check_cases(25, [] {
    // Series log needs a principal log: keep the rotor angle away from 2 pi (w > -0.9).
    const DQ d = *rc::gen::suchThat(rigid_dq(vector3(8)), [](const DQ& x) { return x.real.w > Real(-0.9); });
    const PMV m = MOTOR_1_from_dual_quaternion(d);
    const auto series = log_series(m);
    RC_ASSERT(series.has_value());
    RC_ASSERT(near(MOTOR_4_log(m), *series));
  });
  // Pure rotations and pure translations.
  const Real pi = ScalarTraits<Real>::pi();
  const PMV rotation = MOTOR_4_exp(pga::bivector<Real>({pi / Real(3), Real(-1) / Real(5), Real(1) / Real(7)},
                                                       {Real(0), Real(0), Real(0)}));
  const PMV translation = pga::translator<Real>({Real(3), Real(-5), Real(1) / Real(3)});
  EXPECT_TRUE(near(MOTOR_4_log(rotation), *log_series(rotation)));
  EXPECT_TRUE(near(MOTOR_4_log(translation), *log_series(translation)));
  EXPECT_EQ(MOTOR_4_log(PMV(Real(1))).c, PMV().c);  // log 1 = 0 exactly
}

TEST(Motor, ExpInvertsLogAndLogInvertsExp) {
  RC_CLAUSE("MOTOR-4");
  check_cases(50, [] {
    const DQ d = *rigid_dq();
    const PMV m = MOTOR_1_from_dual_quaternion(d);
    RC_ASSERT(near(MOTOR_4_exp(MOTOR_4_log(m)), m));
    // |beta| < pi: the log is principal and gives the bivector back.
    const V3 e = *vector3(1), i = *translation();
    const PMV b = pga::bivector<Real>(e, i);
    RC_ASSERT(near(MOTOR_4_log(MOTOR_4_exp(b)), b));
  });
}

TEST(Motor, LogOfMinusTranslatorIsDocumentedChoice) {
  RC_CLAUSE("MOTOR-4");
  // R = -1 (b = pi): the axis is taken along the translation and exp(log M) = M.
  const PMV m = -pga::translator<Real>({Real(2), Real(-3), Real(6)});
  const PMV l = MOTOR_4_log(m);
  EXPECT_TRUE(near(MOTOR_4_exp(l), m));
  EXPECT_TRUE(near(pga::norm3(pga::euclidean_bivector(l)), ScalarTraits<Real>::pi()));
  // No translation either: LOG-2's -pi e12.
  const PMV minus_one = MOTOR_4_log(PMV(Real(-1)));
  EXPECT_TRUE(near(minus_one, -ScalarTraits<Real>::pi() * named("e12")));
}

TEST(Motor, InterpolationEqualsScLERP) {
  RC_CLAUSE("MOTOR-4");
  RC_CLAUSE("DQ-5");
  check_cases(50, [] {
    const DQ a = disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4));
    const DQ b = disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4));
    const Real t = *rc::gen::oneOf(real_in(1), rc::gen::map(real_in(3), [](const Real& x) { return x + Real(1) / Real(2); }));
    const auto by_motor = MOTOR_4_interpolate(a, b, t);
    const auto by_dq = DQ_5_sclerp(a, b, t);
    RC_ASSERT(by_motor.status == Status::ok && by_dq.status == Status::ok);
    RC_ASSERT(near(by_motor.value, by_dq.value));
  });
}

// ---- DQ-8, DQ-9: the motor log and exp in dual-quaternion coordinates ----------------------------

/// The motor bivector of a dual vector xi (MOTOR-1 is linear: -(xi_r on e23, e31, e12) -
/// (xi_d on e01, e02, e03)).
PMV motor_bivector(const DualVector<Real>& xi) {
  return pga::bivector<Real>({-xi.real[0], -xi.real[1], -xi.real[2]}, {-xi.dual[0], -xi.dual[1], -xi.dual[2]});
}

TEST(Motor, DualQuaternionExpIsTheMotorExp) {
  RC_CLAUSE("DQ-9");
  check_cases(50, [] {
    const DualVector<Real> xi{*vector3(4), *translation()};
    const auto e = DQ_9_exp(xi);
    RC_ASSERT(e.status == Status::ok);
    // The series of the algebra (EXPSERIES-1), not the closed form the function uses.
    RC_ASSERT(near(MOTOR_1_from_dual_quaternion(e.value), exp_series(motor_bivector(xi))));
  });
  const V3 zero{Real(0), Real(0), Real(0)};
  const V3 t{Real(3), Real(-5), Real(1) / Real(3)};
  const auto translator = DQ_9_exp(DualVector<Real>{zero, t});  // b = 0: 1 + eps xi_d
  EXPECT_TRUE(near(translator.value, DQ{Quaternion<Real>::identity(), {Real(0), t[0], t[1], t[2]}}));
  EXPECT_EQ(DQ_9_exp(DualVector<Real>{{Real(1), ScalarTraits<Real>::nan(), Real(0)}, zero}).status, Status::domain_error);
}

TEST(Motor, DualQuaternionLogIsTheMotorLog) {
  RC_CLAUSE("DQ-8");
  check_cases(50, [] {
    const DQ d = disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4));  // non-unit: DQ-4 first
    const auto l = DQ_8_log(d);
    RC_ASSERT(l.status == Status::ok);
    RC_ASSERT(near(motor_bivector(l.value), MOTOR_4_log(MOTOR_1_from_dual_quaternion(d))));
    // exp(log sigma) = DQ-4(sigma), w < 0 included (no hemisphere flip: |xi_r| in [0, pi]).
    RC_ASSERT(near(DQ_9_exp(l.value).value, DQ_4_normalize(d).value));
    RC_ASSERT(pga::norm3(l.value.real) <= ScalarTraits<Real>::pi());
  });
}

TEST(Motor, DualQuaternionLogAtTheBranchCut) {
  RC_CLAUSE("DQ-8");
  // r = -1: the rotation by 2 pi about the translation's direction, xi = (pi t/|t|, t/2).
  const Real pi = ScalarTraits<Real>::pi();
  const V3 t{Real(2), Real(-3), Real(6)};  // |t| = 7
  const DQ sigma = DQ_1_from_rotation_translation(Quaternion<Real>{Real(-1), Real(0), Real(0), Real(0)}, t).value;
  const auto l = DQ_8_log(sigma);
  EXPECT_TRUE(near(l.value.real, V3{pi * Real(2) / Real(7), pi * Real(-3) / Real(7), pi * Real(6) / Real(7)}));
  EXPECT_TRUE(near(l.value.dual, V3{Real(1), Real(-3) / Real(2), Real(3)}));
  EXPECT_TRUE(near(DQ_9_exp(l.value).value, sigma));
  // No translation either: LOG-2's +z.
  const auto minus_one = DQ_8_log(DQ{{Real(-1), Real(0), Real(0), Real(0)}, {Real(0), Real(0), Real(0), Real(0)}});
  EXPECT_TRUE(near(minus_one.value.real, V3{Real(0), Real(0), pi}));
  EXPECT_TRUE(near(minus_one.value.dual, V3{Real(0), Real(0), Real(0)}));
  // log 1 = 0 exactly; a zero real part is DOMAIN_ERROR (EDGE-6).
  const auto one = DQ_8_log(DQ{Quaternion<Real>::identity(), {Real(0), Real(0), Real(0), Real(0)}});
  EXPECT_TRUE(one.value.real == (V3{Real(0), Real(0), Real(0)}) && one.value.dual == (V3{Real(0), Real(0), Real(0)}));
  EXPECT_EQ(DQ_8_log(DQ{{Real(0), Real(0), Real(0), Real(0)}, {Real(1), Real(0), Real(0), Real(0)}}).status,
            Status::domain_error);
}

TEST(Motor, DualQuaternionLogInvertsExp) {
  RC_CLAUSE("DQ-8");
  RC_CLAUSE("DQ-9");
  check_cases(50, [] {
    // |xi_r| < pi: the principal log gives xi back.
    const V3 e = *rc::gen::suchThat(vector3(2), [](const V3& v) { return pga::norm3(v) < Real(3); });
    const DualVector<Real> xi{e, *translation()};
    const auto back = DQ_8_log(DQ_9_exp(xi).value);
    RC_ASSERT(near(back.value.real, xi.real));
    RC_ASSERT(near(back.value.dual, xi.dual));
  });
}

// ---- MOTOR-5: motor blend against DLB -------------------------------------------------------

TEST(Motor, BlendEqualsDLB) {
  RC_CLAUSE("MOTOR-5");
  RC_CLAUSE("DQ-6");
  check_cases(50, [] {
    const int n = *rc::gen::inRange(1, 5);
    std::vector<DQ> d;
    std::vector<Real> w;
    for (int i = 0; i < n; ++i) {
      d.push_back(disturbed(*rigid_dq(), *nonzero_scale(), *real_in(4)));
      w.push_back(*rc::gen::oneOf(rc::gen::just(Real(0)), rc::gen::map(real_in(4), [](const Real& x) { return abs(x); })));
    }
    w.back() += Real(1) / Real(8);  // a positive sum
    const auto by_motor = MOTOR_5_blend<Real>(d, w);
    const auto by_dq = DQ_6_dlb<Real>(d, w);
    RC_ASSERT(by_motor.status == Status::ok && by_dq.status == Status::ok);
    RC_ASSERT(near(by_motor.value, by_dq.value));
  });
}

}  // namespace
