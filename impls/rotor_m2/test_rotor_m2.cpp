// rotor_m2: facts of the corrected Method 2 (Phi, exact, no trigonometry) and a smoke check
// of every op against the reference.
#include <cmath>
#include <cstdint>
#include <numbers>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/quat_batch_laws.hpp>

#include "../rotor/rotor_test_support.hpp"
#include "../tests/rotor_smoke.hpp"

extern "C" const rc_impl* rotorcert_impl_entry_rotor_m2(std::uint32_t abi, std::uint32_t index);

namespace {

using namespace rotor_test;

const Ops<float>& m2f() { return ops_of<float>(&rotorcert_impl_entry_rotor_m2); }
const Ops<double>& m2d() { return ops_of<double>(&rotorcert_impl_entry_rotor_m2); }

RC_GTEST_PROP(RotorM2, SmokeAgainstReference, ()) {
  smoke_against_reference(m2f(), m2d());  // names its clauses (../tests/rotor_smoke.hpp)
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

TEST(RotorM2, BatchLanesGiveTheElementFunctionsBits) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("INV-1");
  RC_CLAUSE("APPLY-2");
  RC_CLAUSE("APPLY-3");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("EDGE-3");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-8");
  RC_CLAUSE("AXANG-4");
  RC_CLAUSE("QLB-1");
  RC_CLAUSE("EDGE-9");
  RC_CLAUSE("MAT-2");
  RC_CLAUSE("MAT-3");
  RC_CLAUSE("SLERP-2");
  RC_CLAUSE("LOG-1");
  RC_CLAUSE("EXP-1");
  RC_CLAUSE("AXANG-2");
  RC_CLAUSE("AXANG-1");
  RC_CLAUSE("AXANG-3");
  RC_CLAUSE("SKIN-1");
  const rc_impl* f = rotorcert_impl_entry_rotor_m2(RC_ABI_VERSION, 0);
  const rc_impl* d = rotorcert_impl_entry_rotor_m2(RC_ABI_VERSION, 1);
  ASSERT_TRUE(f != nullptr && d != nullptr && f->f32_v3 != nullptr && d->f64_v3 != nullptr);
  rotorcert::testing::quat_batch_laws::batch_gives_the_element_bits<float>(m2f(), f->f32_v3);
  rotorcert::testing::quat_batch_laws::batch_gives_the_element_bits<double>(m2d(), d->f64_v3);
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
