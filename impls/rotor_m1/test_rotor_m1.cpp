// rotor_m1: facts of the paper's Method 1 (angle and axis -> exp) and a smoke check of every
// op against the reference. Method 1 must agree with the coefficient map Phi (rotor_m2) within
// eps16 (Q2R-4).
#include <cmath>
#include <cstdint>
#include <numbers>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/testing/clause.hpp>

#include "../rotor/rotor_test_support.hpp"
#include "../tests/rotor_smoke.hpp"

extern "C" const rc_impl* rotorcert_impl_entry_rotor_m1(std::uint32_t abi, std::uint32_t index);
extern "C" const rc_impl* rotorcert_impl_entry_rotor_m2(std::uint32_t abi, std::uint32_t index);

namespace {

using namespace rotor_test;

const Ops<float>& m1f() { return ops_of<float>(&rotorcert_impl_entry_rotor_m1); }
const Ops<double>& m1d() { return ops_of<double>(&rotorcert_impl_entry_rotor_m1); }
const Ops<float>& m2f() { return ops_of<float>(&rotorcert_impl_entry_rotor_m2); }

RC_GTEST_PROP(RotorM1, SmokeAgainstReference, ()) {
  smoke_against_reference(m1f(), m1d());  // names its clauses (../tests/rotor_smoke.hpp)
}

RC_GTEST_PROP(RotorM1, Method1EqualsMethod2InFloat, ()) {
  RC_CLAUSE("Q2R-4");
  // The rotor of q by angle and axis and the rotor Phi(q/|q|), both read out by Phi^-1, and the
  // same rotor interpolation on top of each.
  const Q<float> a = round_to<float>(*rotorcert::testing::quaternion());
  const Q<float> b = round_to<float>(*rotorcert::testing::quaternion());
  const float t = round_to<float>(*rotorcert::testing::real_in(1));
  std::uint8_t st;
  Q<float> q1, q2;
  m1f().normalize(1, a.data(), q1.data(), &st);
  m2f().normalize(1, a.data(), q2.data(), &st);
  RC_ASSERT(rotation_error(q1, real(q2)) <= bar("eps16"));
  m1f().slerp(1, a.data(), b.data(), &t, q1.data(), &st);
  m2f().slerp(1, a.data(), b.data(), &t, q2.data(), &st);
  RC_ASSERT(rotation_error(q1, real(q2)) <= bar("eps16"));
}

TEST(RotorM1, HalfTurnsAreExactSoTiesDoNotFlip) {
  RC_CLAUSE("EDGE-3");
  // cos(float(pi/2)) = -0x1.777a5cp-25: without the exact half turn, Method 1 turns the tie
  // <R_B ~R_A>_0 = 0 of slerp(1, i, 1/2) into a negative scalar and flips to the other arc.
  std::uint8_t st;
  const Q<float> one{0, 0, 0, 1}, i{1, 0, 0, 0}, minus_i{-1, 0, 0, 0};
  const float half = 0.5f;
  Q<float> q;
  m1f().slerp(1, one.data(), i.data(), &half, q.data(), &st);
  const double r = std::numbers::sqrt2 / 2;
  EXPECT_LE(rotation_error(q, RQ{Real(r), Real(r), 0, 0}), bar("eps16"));
  EXPECT_GT(q[0], 0);
  m1f().slerp(1, one.data(), minus_i.data(), &half, q.data(), &st);
  EXPECT_LT(q[0], 0);
  EXPECT_GT(q[3], 0);
}

TEST(RotorM1, NegativeRealQuaternionsAreTheFullTurn) {
  RC_CLAUSE("LOG-2");
  RC_CLAUSE("AXANG-1");
  std::uint8_t st;
  const Q<float> minus{0, -0.0f, 0, -3};
  V<float> l;
  m1f().log(1, minus.data(), l.data(), &st);
  EXPECT_EQ(l, (V<float>{0, 0, std::numbers::pi_v<float>}));
  float angle;
  V<float> axis;
  m1f().to_axis_angle(1, minus.data(), &angle, axis.data(), &st);
  EXPECT_EQ(angle, 2 * std::numbers::pi_v<float>);
  EXPECT_EQ(axis, (V<float>{0, 0, 1}));
}

TEST(RotorM1, IdentityInIdentityOut) {
  RC_CLAUSE("EDGE-1");
  std::uint8_t st;
  const Q<double> one{0, 0, 0, 1};
  const double t = -7.5;
  Q<double> q;
  m1d().compose(1, one.data(), one.data(), q.data(), &st);
  EXPECT_EQ(q, one);
  m1d().slerp(1, one.data(), one.data(), &t, q.data(), &st);
  EXPECT_EQ(q, one);
  const V<double> zero{0, 0, 0};
  m1d().exp(1, zero.data(), q.data(), &st);
  EXPECT_EQ(q, one);
}

TEST(RotorM1, NonOrthonormalMatrixGivesThePolarFactor) {
  RC_CLAUSE("MAT-3");
  // diag(2, 1/2, 3) times a quarter turn about z: the nearest rotation is the quarter turn.
  // Column-major M = R D with R e1 = e2, R e2 = -e1.
  const M<double> m{0, 2, 0, -0.5, 0, 0, 0, 0, 3};
  std::uint8_t st;
  Q<double> q;
  m1d().from_matrix(1, m.data(), q.data(), &st);
  const double r = std::numbers::sqrt2 / 2;
  EXPECT_LE(rotation_error(q, RQ{Real(r), 0, 0, Real(r)}), bar("eps16"));
  const M<double> reflection{1, 0, 0, 0, 1, 0, 0, 0, -1};
  m1d().from_matrix(1, reflection.data(), q.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
}

}  // namespace
