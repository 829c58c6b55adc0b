// runtime::exact_dot_sign, the predicate behind every built-in hemisphere rule (EDGE-3: flip iff
// the dot of the inputs as given is < 0 strictly), against the exact sign from MPFR.
//
// The inputs that matter are those where large products cancel exactly and components tens of
// binades smaller decide the sign: a predicate that first scales each vector (as this one did
// until the rigid fuzzer found dq's dq_sclerp in the wrong hemisphere) flushes those to zero.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <mpreal.h>

#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

using rotorcert::runtime::exact_dot_sign;
using rotorcert::runtime::hemisphere_sign;

/// The exact sign: products of two doubles need 106 bits, and the terms span binary exponents
/// from 2^2048 down to 2^-2148, so 4400 bits hold every sum exactly.
template <class S, std::size_t N>
int mpfr_dot_sign(const std::array<S, N>& a, const std::array<S, N>& b) {
  const mpfr_prec_t prec = 4400;
  mpfr::mpreal sum(0, prec);
  for (std::size_t i = 0; i < N; ++i) sum += mpfr::mpreal(a[i], prec) * mpfr::mpreal(b[i], prec);
  return sgn(sum);
}

template <class S> S from_bits(std::uint64_t bits) {
  if constexpr (sizeof(S) == 4)
    return std::bit_cast<float>(static_cast<std::uint32_t>(bits));
  else
    return std::bit_cast<double>(bits);
}

/// A finite value of any binade, subnormals and zeros included.
template <class S> S any_finite(std::mt19937_64& rng) {
  for (;;) {
    const S x = from_bits<S>(rng());
    if (std::isfinite(x)) return x;
  }
}

/// A value whose binary exponent is uniform over the format's whole range.
template <class S> S any_binade(std::mt19937_64& rng) {
  using L = std::numeric_limits<S>;
  std::uniform_int_distribution<int> exponent(L::min_exponent - L::digits, L::max_exponent - 1);
  std::uniform_real_distribution<S> mantissa(1, 2);
  const S m = std::bernoulli_distribution(0.5)(rng) ? -mantissa(rng) : mantissa(rng);
  const S x = std::ldexp(m, exponent(rng));
  return std::isfinite(x) ? x : L::max();
}

/// A value whose products with another such value are normal numbers far from overflow.
template <class S> S moderate_binade(std::mt19937_64& rng) {
  using L = std::numeric_limits<S>;
  std::uniform_int_distribution<int> exponent(L::min_exponent / 2 + L::digits, L::max_exponent / 2 - 2);
  std::uniform_real_distribution<S> mantissa(1, 2);
  const S m = std::bernoulli_distribution(0.5)(rng) ? -mantissa(rng) : mantissa(rng);
  return std::ldexp(m, exponent(rng));
}

template <class S> void check_random(const char* scalar) {
  const std::uint64_t seed = 20261126;
  std::mt19937_64 rng(seed);
  int cancelling = 0, near_cancelling = 0;
  for (int n = 0; n < 20000; ++n) {
    std::array<S, 4> a, b;
    switch (n % 4) {
      case 0:  // raw bit patterns: mostly the filter's business
        for (int i = 0; i < 4; ++i) a[i] = any_finite<S>(rng), b[i] = any_finite<S>(rng);
        break;
      case 1:  // every binade
        for (int i = 0; i < 4; ++i) a[i] = any_binade<S>(rng), b[i] = any_binade<S>(rng);
        break;
      case 2: {  // x y - x' y' with x' = next(x), y' = x y / x' rounded: the rounded products
                 // cancel or nearly so, the exact ones do not; a third term of about the size of
                 // their rounding error decides, so the rounded dot often has the wrong sign
        const S x = moderate_binade<S>(rng), y = moderate_binade<S>(rng);
        const S x2 = std::nextafter(x, S(0)), y2 = x * y / x2;
        const int e = std::ilogb(x * y) - std::numeric_limits<S>::digits - 4 + int(rng() % 9);
        const S sign = std::bernoulli_distribution(0.5)(rng) ? S(-1) : S(1);
        a = {x, x2, std::ldexp(S(1.5), e / 2), 0};
        b = {y, -y2, sign * std::ldexp(S(1.25), e - e / 2), 0};
        ++near_cancelling;
        break;
      }
      default: {  // x y - y x cancels exactly; the other two terms, of any size, decide
        const S x = any_binade<S>(rng), y = any_binade<S>(rng);
        a = {x, y, any_binade<S>(rng), any_binade<S>(rng)};
        b = {y, -x, any_binade<S>(rng), std::bernoulli_distribution(0.25)(rng) ? S(0) : any_binade<S>(rng)};
        ++cancelling;
      }
    }
    const int want = mpfr_dot_sign(a, b);
    ASSERT_EQ(exact_dot_sign(a, b), want) << "mpfr " << want
        << scalar << " seed " << seed << " case " << n << std::hexfloat << ": a = (" << a[0] << ", " << a[1]
        << ", " << a[2] << ", " << a[3] << "), b = (" << b[0] << ", " << b[1] << ", " << b[2] << ", " << b[3] << ")";
  }
  EXPECT_GT(cancelling, 4000);
  EXPECT_GT(near_cancelling, 4000);
}

TEST(ExactSign, FloatAgreesWithMpfrOnEveryBinadeAndExactCancellation) {
  RC_CLAUSE("EDGE-3");
  check_random<float>("float");
}

TEST(ExactSign, DoubleAgreesWithMpfrOnEveryBinadeAndExactCancellation) {
  RC_CLAUSE("EDGE-3");
  check_random<double>("double");
}

// The rigid fuzzer's finding, as dq saw it: real parts near FLT_MAX whose dot is decided by
// components 2^-94 and 2^-141 (a.b = -1.3e10, relative 2e-67).
TEST(ExactSign, FloatFltMaxScaleDecidedByTinyComponents) {
  RC_CLAUSE("EDGE-3");
  const float m = -0x1.fdfdfcp+126f;
  const std::array<float, 4> a{0, 0, m, m}, b{m, m, 0x1.fcp-142f, 0x1.7b18ap-94f};
  EXPECT_EQ(hemisphere_sign(a, b), -1);
  EXPECT_EQ(hemisphere_sign(b, a), -1);
}

// Products that overflow double cancel exactly; the subnormal one decides.
TEST(ExactSign, DoubleOverflowingProductsCancelSubnormalDecides) {
  RC_CLAUSE("EDGE-3");
  const double big = 0x1.8p+1000, tiny = 0x1p-1074;
  EXPECT_EQ(hemisphere_sign<double>({big, big, tiny, 0}, {big, -big, tiny, 0}), 1);
  EXPECT_EQ(hemisphere_sign<double>({big, big, tiny, 0}, {big, -big, -tiny, 0}), -1);
  EXPECT_EQ(hemisphere_sign<double>({big, big, 0, 0}, {big, -big, -0.0, 0}), 0);
}

// A true tie stays a tie (EDGE-3: a dot of +-0 does not flip), at every scale.
TEST(ExactSign, HalfTurnIsZero) {
  RC_CLAUSE("EDGE-3");
  EXPECT_EQ(hemisphere_sign<float>({1, 0, 0, 0}, {0, 1, 0, 0}), 0);
  EXPECT_EQ(hemisphere_sign<float>({0x1p-149f, 0, 0, 0}, {0, 0x1p127f, 0, 0}), 0);
  EXPECT_EQ(hemisphere_sign<double>({0x1p1023, 0x1p-1074, 0, 0}, {0x1p-1074, -0x1p1023, 0, 0}), 0);
}

}  // namespace
