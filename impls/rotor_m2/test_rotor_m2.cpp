// rotor_m2: facts of the corrected Method 2 (Phi, exact, no trigonometry) and a smoke check
// of every op against the reference.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/testing/clause.hpp>

#include "../rotor/rotor_test_support.hpp"

extern "C" const rc_impl* rotorcert_impl_entry_rotor_m2(std::uint32_t abi, std::uint32_t index);

namespace {

using namespace rotor_test;

const Ops<float>& m2f() { return ops_of<float>(&rotorcert_impl_entry_rotor_m2); }
const Ops<double>& m2d() { return ops_of<double>(&rotorcert_impl_entry_rotor_m2); }

RC_GTEST_PROP(RotorM2, SmokeAgainstReference, ()) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("INV-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("APPLY-2");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("MAT-2");
  RC_CLAUSE("AXANG-1");
  RC_CLAUSE("AXANG-2");
  RC_CLAUSE("LOG-1");
  RC_CLAUSE("EXP-1");
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("QLB-1");
  RC_CLAUSE("LOGBLEND-1");
  RC_CLAUSE("SKIN-1");
  smoke<float>(m2f());
  smoke<double>(m2d());
}

TEST(RotorM2, ComposeIsThePlainProduct) {
  RC_CLAUSE("COMPOSE-1");
  // EX-COMPOSE-1-h: (0,0,0,2) (0,0,1,1) = (0,0,2,2), no normalisation; EX-COMPOSE-1-e: i i = -1.
  std::uint8_t st;
  const Q<double> a{0, 0, 0, 2}, b{0, 0, 1, 1}, i{1, 0, 0, 0};
  Q<double> q;
  m2d().compose(1, a.data(), b.data(), q.data(), &st);
  EXPECT_EQ(q, (Q<double>{0, 0, 2, 2}));
  m2d().compose(1, i.data(), i.data(), q.data(), &st);
  EXPECT_EQ(q[3], -1);
}

TEST(RotorM2, IdentityInIdentityOut) {
  RC_CLAUSE("EDGE-1");
  std::uint8_t st;
  const Q<float> one{0, 0, 0, 1};
  const V<float> v{0.1f, -3, 7};
  const float t = 0.3f;
  Q<float> q;
  V<float> w;
  M<float> m;
  m2f().slerp(1, one.data(), one.data(), &t, q.data(), &st);
  EXPECT_EQ(q, one);
  m2f().nlerp(1, one.data(), one.data(), &t, q.data(), &st);
  EXPECT_EQ(q, one);
  m2f().apply_vector(1, one.data(), v.data(), w.data(), &st);
  EXPECT_EQ(w, v);
  m2f().to_matrix(1, one.data(), m.data(), &st);
  EXPECT_EQ(m, (M<float>{1, 0, 0, 0, 1, 0, 0, 0, 1}));
  m2f().log(1, one.data(), w.data(), &st);
  EXPECT_EQ(w, (V<float>{0, 0, 0}));
}

TEST(RotorM2, SubnormalAndHugeInputsAreRotations) {
  RC_CLAUSE("EDGE-8");
  RC_CLAUSE("EDGE-5");
  std::uint8_t st;
  const Q<float> tiny{0x1p-149f, -0.0f, 0, 0}, huge{0x1p127f, 0x1p127f, 0x1p127f, 0x1p127f};
  Q<float> q;
  m2f().normalize(1, tiny.data(), q.data(), &st);
  EXPECT_EQ(st, RC_OK);
  EXPECT_EQ(q, (Q<float>{1, 0, 0, 0}));
  m2f().normalize(1, huge.data(), q.data(), &st);
  EXPECT_EQ(q, (Q<float>{0.5f, 0.5f, 0.5f, 0.5f}));
}

/// NORM-1, COMPOSE-1, APPLY-1, EDGE-5..8: a batch runs its ordinary elements in SIMD lanes
/// (rotor_lanes.hpp) and must give, bit for bit and status for status, what the element function
/// gives for each element alone (a one-element call takes RotorOps, the checked path). 61
/// elements: 3 blocks of 16, 3 of 4 and one alone; among ordinary quaternions of sizes 1/4 .. 4
/// (EDGE-5) sit ones scaled by 2^+-E beyond the ordinary range, zeros, subnormals, NaN and
/// infinities (EDGE-6..8), so lanes of one block take different paths. Any difference between
/// the lanes' arithmetic and RotorOps' shows as a bit.
template <class S>
void batch_lanes_give_the_element_bits(const Ops<S>& ops) {
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;
  constexpr std::size_t kCases = 61;
  std::mt19937_64 gen(61);
  std::uniform_real_distribution<double> unit(-1, 1), size(0.25, 4);
  std::vector<S> a(4 * kCases), b(4 * kCases), v(3 * kCases);
  for (std::size_t i = 0; i < kCases; ++i) {
    for (std::size_t c = 0; c < 4; ++c) a[4 * i + c] = S(unit(gen) * size(gen)), b[4 * i + c] = S(unit(gen) * size(gen));
    for (std::size_t c = 0; c < 3; ++c) v[3 * i + c] = S(unit(gen) * 10);
    switch (i % 11) {  // the specials, spread over blocks and lanes
      case 2: for (std::size_t c = 0; c < 4; ++c) a[4 * i + c] = std::ldexp(a[4 * i + c], E); break;
      case 5: for (std::size_t c = 0; c < 4; ++c) b[4 * i + c] = std::ldexp(b[4 * i + c], -E); break;
      case 7: a[4 * i] = a[4 * i + 1] = a[4 * i + 2] = a[4 * i + 3] = S(i % 2 ? -0.0 : 0.0); break;
      case 8: a[4 * i + 1] = std::numeric_limits<S>::denorm_min(), a[4 * i] = a[4 * i + 2] = a[4 * i + 3] = 0; break;
      case 9: v[3 * i + 2] = std::numeric_limits<S>::infinity(); b[4 * i + 3] = std::numeric_limits<S>::quiet_NaN(); break;
      default: break;
    }
  }
  const auto same = [](const S* x, const S* y, std::size_t count) { return std::memcmp(x, y, count * sizeof(S)) == 0; };
  std::vector<S> batch(4 * kCases), one(4);
  std::vector<std::uint8_t> st(kCases);
  std::uint8_t st1;
  ASSERT_EQ(ops.normalize(kCases, a.data(), batch.data(), st.data()), 0);
  for (std::size_t i = 0; i < kCases; ++i) {
    ops.normalize(1, &a[4 * i], one.data(), &st1);
    EXPECT_EQ(st[i], st1) << "normalize " << i;
    EXPECT_TRUE(same(&batch[4 * i], one.data(), 4)) << "normalize element " << i;
  }
  ASSERT_EQ(ops.compose(kCases, a.data(), b.data(), batch.data(), st.data()), 0);
  for (std::size_t i = 0; i < kCases; ++i) {
    ops.compose(1, &a[4 * i], &b[4 * i], one.data(), &st1);
    EXPECT_EQ(st[i], st1) << "compose " << i;
    EXPECT_TRUE(same(&batch[4 * i], one.data(), 4)) << "compose element " << i;
  }
  ASSERT_EQ(ops.apply_vector(kCases, a.data(), v.data(), batch.data(), st.data()), 0);
  for (std::size_t i = 0; i < kCases; ++i) {
    ops.apply_vector(1, &a[4 * i], &v[3 * i], one.data(), &st1);
    EXPECT_EQ(st[i], st1) << "apply_vector " << i;
    EXPECT_TRUE(same(&batch[3 * i], one.data(), 3)) << "apply_vector element " << i;
  }
}

TEST(RotorM2, BatchLanesGiveTheElementFunctionsBits) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-8");
  batch_lanes_give_the_element_bits<float>(m2f());
  batch_lanes_give_the_element_bits<double>(m2d());
}

TEST(RotorM2, BadInputsAreDomainErrors) {
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-9");
  std::uint8_t st;
  const Q<double> zero{0, -0.0, 0, 0}, nan{0, 0, std::nan(""), 1}, one{0, 0, 0, 1};
  Q<double> q;
  m2d().normalize(1, zero.data(), q.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
  EXPECT_TRUE(std::isnan(q[0]) && std::isnan(q[3]));
  V<double> l;
  m2d().log(1, nan.data(), l.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
  EXPECT_TRUE(std::isnan(l[2]));
  const std::array<Q<double>, 2> qs{one, zero};
  const std::array<double, 2> w{1, 0};  // a zero quaternion with weight 0 is still an error
  m2d().blend_qlb(1, 2, qs[0].data(), w.data(), q.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
  const std::array<Q<double>, 2> good{one, one};
  const std::array<double, 2> neg{1, -1}, zeros{0, -0.0};
  m2d().blend_log(1, 2, good[0].data(), neg.data(), q.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
  m2d().blend_log(1, 2, good[0].data(), zeros.data(), q.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
}

}  // namespace
