// Rotor3 (impls/rotor/rotor3.hpp) against the reference's Cl(3,0): the hand-expanded product
// equals the bitmap-table product, and exp, log, the sandwich, the matrix and the rotor
// interpolation meet their clauses' eps classes in float and double.
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/cl3.hpp>
#include <rotorcert/reference/mat3_domain.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "rotor3.hpp"
#include "rotor_test_support.hpp"

namespace {

using namespace rotor_test;
namespace cl3 = rotorcert::ref::cl3;
namespace clause = rotorcert::ref::clause;
using rotorcert::rotor::Rotor3;
using rotorcert::testing::eps_class_bars;
using MV = cl3::MV<Real>;

template <class S> MV mv(const Rotor3<S>& r) {
  MV m = cl3::bivector<Real>({Real(r.e23), Real(r.e31), Real(r.e12)});
  m.c[0] = Real(r.s);
  return m;
}
/// Phi of Q2R-1 in S (exact) and its inverse.
template <class S> Rotor3<S> phi(const Q<S>& q) { return {q[3], -q[0], -q[1], -q[2]}; }
template <class S> Q<S> phi_inv(const Rotor3<S>& r) { return {-r.e23, -r.e31, -r.e12, r.s}; }

template <class S> Q<S> random_unit() { return round_to<S>(*rotorcert::testing::unit_quaternion()); }

template <class S>
void product_equals_reference() {
  auto g = rotorcert::testing::real_in(2);
  const Rotor3<S> p{round_to<S>(*g), round_to<S>(*g), round_to<S>(*g), round_to<S>(*g)};
  const Rotor3<S> q{round_to<S>(*g), round_to<S>(*g), round_to<S>(*g), round_to<S>(*g)};
  const Rotor3<S> r = rotorcert::rotor::gp(p, q);
  const MV ref = gp(mv(p), mv(q));
  const Real scale = sqrt(scp(mv(p), reverse(mv(p))) * scp(mv(q), reverse(mv(q))));
  const MV d = mv(r) - ref;
  Real worst(0);
  for (const Real& c : d.c) worst = std::max(worst, Real(abs(c)));
  RC_ASSERT(scale == 0 || (worst / scale).toDouble() / eps<S>() <= eps_class_bars("eps8").strict);
  const MV rev = mv(rotorcert::rotor::reverse(p)) - reverse(mv(p));
  for (const Real& c : rev.c) RC_ASSERT(c == 0);
}

RC_GTEST_PROP(Rotor3, ProductEqualsReferenceGeometricProduct, ()) {
  RC_CLAUSE("ALG-2");
  RC_CLAUSE("COMPOSE-1");
  product_equals_reference<float>();
  product_equals_reference<double>();
}

TEST(Rotor3, ProductOfBasisBladesFollowsTable6) {
  RC_CLAUSE("ALG-2");
  // e23 e31 = -e12, e31 e12 = -e23, e12 e23 = -e31, e23 e23 = -1 (Table 6).
  const Rotor3<double> e23{0, 1, 0, 0}, e31{0, 0, 1, 0}, e12{0, 0, 0, 1};
  const auto a = rotorcert::rotor::gp(e23, e31), b = rotorcert::rotor::gp(e31, e12), c = rotorcert::rotor::gp(e12, e23),
             d = rotorcert::rotor::gp(e23, e23);
  EXPECT_EQ(a.e12, -1);
  EXPECT_EQ(b.e23, -1);
  EXPECT_EQ(c.e31, -1);
  EXPECT_EQ(d.s, -1);
}

template <class S>
void sandwich_matches_reference() {
  const Q<S> q = random_unit<S>();
  const RV vr = *rotorcert::testing::vector3();
  const V<S> v = round_to<S>(vr);
  const Rotor3<S> r = rotorcert::rotor::normalized(phi(q));
  const RV x = real(v);
  const auto ref = clause::APPLY_1_apply_vector(real(q), x).value;
  RC_ASSERT(vector_error(rotorcert::rotor::sandwich_vector(r, v), ref, length(x)) <= eps_class_bars("eps8").strict);
  const auto refb = clause::APPLY_2_apply_bivector(real(q), x).value;
  RC_ASSERT(vector_error(rotorcert::rotor::sandwich_bivector(r, v), refb, length(x)) <= eps_class_bars("eps8").strict);
  const auto refm = clause::MAT_1_to_matrix(real(q)).value;
  RC_ASSERT(matrix_error(rotorcert::rotor::to_matrix(r), refm) <= eps_class_bars("eps8").strict);
}

RC_GTEST_PROP(Rotor3, SandwichAndMatrixMatchReference, ()) {
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("APPLY-2");
  RC_CLAUSE("MAT-1");
  sandwich_matches_reference<float>();
  sandwich_matches_reference<double>();
}

TEST(Rotor3, QuarterTurnAboutZMapsXToY) {
  RC_CLAUSE("ALG-6");
  // R = cos(pi/4) - e12 sin(pi/4) (ALG-6's check).
  const double h = std::numbers::pi / 4;
  const Rotor3<double> r{std::cos(h), 0, 0, -std::sin(h)};
  const V<double> y = rotorcert::rotor::sandwich_vector(r, V<double>{1, 0, 0});
  EXPECT_NEAR(y[0], 0, eps_class_bars("eps8").strict * eps<double>());
  EXPECT_NEAR(y[1], 1, eps_class_bars("eps8").strict * eps<double>());
}

/// exp of a bivector b; the reference is EXP-1 of the pure quaternion -b (Phi(v) = -v).
template <class S>
void exp_matches_reference(const RV& b_real) {
  const V<S> b = round_to<S>(b_real);
  const Q<S> got = phi_inv(rotorcert::rotor::exp(b));
  const RQ ref = clause::EXP_1_exp(RV{-Real(b[0]), -Real(b[1]), -Real(b[2])}).value;
  RC_ASSERT(rotation_error(got, ref) <= eps_class_bars("eps16").strict);
}

RC_GTEST_PROP(Rotor3, ExpMatchesReference, ()) {
  RC_CLAUSE("EXP-1");
  const RV b = *rotorcert::testing::vector3();
  exp_matches_reference<float>(b);
  exp_matches_reference<double>(b);
}

RC_GTEST_PROP(Rotor3, ExpOfSmallBivectorsUsesTheSeries, ()) {
  RC_CLAUSE("EXP-1");
  RC_CLAUSE("EDGE-2");
  const RV u = *rotorcert::testing::vector3();
  const int k = *rc::gen::inRange(3, 10);  // |b| around 10^-k
  const Real s = pow(Real(10), -k);
  exp_matches_reference<float>(RV{s * u[0], s * u[1], s * u[2]});
  exp_matches_reference<double>(RV{s * u[0], s * u[1], s * u[2]});
}

/// log of Phi(q) (not normalised: the log is scale-free) against LOG-1 of q.
template <class S>
void log_matches_reference(const Q<S>& q) {
  const V<S> b = rotorcert::rotor::log(phi(q));
  const V<S> view{-b[0], -b[1], -b[2]};
  const RV ref = clause::LOG_1_log(real(q)).value;
  RC_ASSERT(bivector_error(view, ref) <= eps_class_bars("eps16").strict);
}

RC_GTEST_PROP(Rotor3, LogMatchesReference, ()) {
  RC_CLAUSE("LOG-1");
  const RQ q = *rotorcert::testing::quaternion();
  log_matches_reference<float>(round_to<float>(q));
  log_matches_reference<double>(round_to<double>(q));
}

RC_GTEST_PROP(Rotor3, LogOfSmallRotationsUsesTheSeries, ()) {
  RC_CLAUSE("LOG-1");
  RC_CLAUSE("EDGE-2");
  const RV u = *rotorcert::testing::vector3();
  const int k = *rc::gen::inRange(3, 10);
  const Real s = pow(Real(10), -k);
  const bool negative = *rc::gen::arbitrary<bool>();  // near the identity and near -1
  const Real w = negative ? Real(-1) : Real(1);
  log_matches_reference<float>(Q<float>{round_to<float>(s * u[0]), round_to<float>(s * u[1]), round_to<float>(s * u[2]), float(w.toDouble())});
  log_matches_reference<double>(Q<double>{round_to<double>(s * u[0]), round_to<double>(s * u[1]), round_to<double>(s * u[2]), w.toDouble()});
}

TEST(Rotor3, LogCutAndIdentityAreExact) {
  RC_CLAUSE("LOG-2");
  RC_CLAUSE("EDGE-1");
  const V<float> cut = rotorcert::rotor::log(Rotor3<float>{-2, 0, -0.0f, 0});
  EXPECT_EQ(cut, (V<float>{0, 0, -std::numbers::pi_v<float>}));  // -pi e12, view (0, 0, pi)
  const V<double> zero = rotorcert::rotor::log(Rotor3<double>{3, 0, 0, 0});
  EXPECT_EQ(zero, (V<double>{0, 0, 0}));
  const Rotor3<double> one = rotorcert::rotor::exp(V<double>{0, 0, 0});
  EXPECT_EQ(one.s, 1);
  EXPECT_EQ(one.e23, 0);
}

template <class S>
void interpolation_matches_reference() {
  const Q<S> a = random_unit<S>(), b = random_unit<S>();
  const S t = round_to<S>(*rotorcert::testing::real_in(2));
  const Rotor3<S> r = rotorcert::rotor::interpolate(rotorcert::rotor::normalized(phi(a)), rotorcert::rotor::normalized(phi(b)), t);
  const RQ ref = clause::SLERP_2_rotor_interpolation(real(a), real(b), Real(t)).value;
  RC_ASSERT(rotation_error(phi_inv(r), ref) <= eps_class_bars("eps16").strict);
}

RC_GTEST_PROP(Rotor3, InterpolationMatchesReference, ()) {
  RC_CLAUSE("SLERP-2");
  interpolation_matches_reference<float>();
  interpolation_matches_reference<double>();
}

TEST(Rotor3, InterpolationFlipsOnlyOnANegativeScalar) {
  RC_CLAUSE("EDGE-3");
  // slerp(1, i, 1/2) and slerp(1, -i, 1/2): <R_B ~R_A>_0 = +-0, no flip either way.
  const Rotor3<double> one{1, 0, 0, 0};
  const Rotor3<double> i = phi(Q<double>{1, 0, 0, 0}), minus_i = phi(Q<double>{-1, 0, 0, 0});
  const Q<double> half = phi_inv(rotorcert::rotor::interpolate(one, i, 0.5));
  const Q<double> half_minus = phi_inv(rotorcert::rotor::interpolate(one, minus_i, 0.5));
  const double r = std::numbers::sqrt2 / 2, bar = eps_class_bars("eps16").strict * eps<double>();
  EXPECT_NEAR(half[0], r, bar);
  EXPECT_NEAR(half[3], r, bar);
  EXPECT_NEAR(half_minus[0], -r, bar);
  EXPECT_NEAR(half_minus[3], r, bar);
}

/// MAT-3 over the whole exponent range: M = U diag(2^a, 2^b, 2^c) V^T rounded to S, with
/// singular values that may differ by up to 2^(2 max_exp). Where the format can decide the
/// sign of det M (|det M| > 8u per(|M|), MAT-3's note) the status must be the reference's;
/// a rotation result is unit and within inherited-mat's strict bar (TOL-2: 16 eps + 2 delta).
template <class S>
void from_matrix_over_the_exponent_range() {
  namespace rr = rotorcert::ref;
  const int range = std::numeric_limits<S>::max_exponent - 8;
  const bool spread = *rc::gen::arbitrary<bool>();
  const auto exponent = rc::gen::inRange(-range, range + 1);
  const std::array<int, 3> e{spread ? *exponent : 0, spread ? *exponent : 0, spread ? *exponent : 0};
  // U and V random, or with components in {-1, 0, 1} (normalised): these include the 24
  // rotations of the cube, whose matrices keep the scales apart in separate entries (a diagonal
  // M = diag(2^a, 2^b, 2^c) among them), the inputs where range problems show.
  auto rotation = [] {
    if (*rc::gen::arbitrary<bool>()) return clause::MAT_1_to_matrix(*rotorcert::testing::unit_quaternion()).value;
    const auto c = rc::gen::inRange(-1, 2);
    RQ q{Real(*c), Real(*c), Real(*c), Real(*c)};
    if (q.w == 0 && q.x == 0 && q.y == 0 && q.z == 0) q.w = 1;
    const Real n = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    q = {q.w / n, q.x / n, q.y / n, q.z / n};
    return clause::MAT_1_to_matrix(q).value;
  };
  const auto u = rotation(), v = rotation();
  const bool reflect = *rc::gen::arbitrary<bool>();  // det < 0 half the time
  M<S> m;
  std::array<Real, 9> mr;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      Real sum(0);
      for (int k = 0; k < 3; ++k) sum += u[k * 3 + r] * Real(std::ldexp(k == 2 && reflect ? -1.0 : 1.0, e[k])) * v[k * 3 + c];
      m[c * 3 + r] = round_to<S>(sum);
      mr[c * 3 + r] = Real(m[c * 3 + r]);
    }
  // Inside the band either outcome conforms (MAT-3).
  RC_PRE(!clause::MAT_3_numerically_singular(mr, Real(eps<S>() / 2)));
  const std::optional<Rotor3<S>> got = rotorcert::rotor::rotor_from_matrix(m);
  const auto want = clause::MAT_2_from_matrix(mr);
  RC_ASSERT(got.has_value() == (want.status == rr::Status::ok));
  if (!got) return;
  const Real delta = clause::MAT_3_orthogonality_defect(mr);
  const double strict = (Real(16) + Real(2) * delta / Real(eps<S>())).toDouble();
  RC_ASSERT(rotation_error(phi_inv(*got), want.value) <= strict);
}

RC_GTEST_PROP(Rotor3, FromMatrixKeepsItsDomainOverTheExponentRange, ()) {
  RC_CLAUSE("MAT-3");
  from_matrix_over_the_exponent_range<float>();
  from_matrix_over_the_exponent_range<double>();
}

}  // namespace
