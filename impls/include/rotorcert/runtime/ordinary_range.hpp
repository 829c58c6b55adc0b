// The cheap test that lets the built-ins skip their robustness scaling on ordinary inputs.
//
// NORM-1, EDGE-5 and DQ-4 ask every normalisation to be accurate at any scale, from subnormal to
// near-overflow components, so the built-ins scale a vector by the power of two of its largest
// component (ilogb, scalbn: exact) before squaring it. That costs several libm calls per vector.
// Yet the sum of squares computed without scaling answers whether scaling was needed: if
//
//     2^-2W <= |v|^2 (as computed) <= 2^2W,   W = emax / 4 (32 for binary32, 256 for binary64),
//
// then no component exceeded 2^W (no square overflowed, and products of two such vectors stay
// 2^(emax/2) below overflow), and what underflowed is negligible: each square below the smallest
// normal loses at most 2^(emin - p) of itself, relative to |v|^2 >= 2^-2W below 2^-60 (binary32)
// or 2^-500 (binary64), far under the unit roundoff. The unscaled formula is then as accurate as
// the scaled one (the scaling is exact, so apart from those underflows the two compute the same
// values), and the test costs two comparisons on a value the formula needs anyway. NaN and
// infinity fail it, so they take the scaled path as before.
#pragma once

#include <limits>

namespace rotorcert::runtime {

template <class S>
struct OrdinaryRange {
  static constexpr int kW = std::numeric_limits<S>::max_exponent / 4;

  static constexpr S power_of_two(int e) {
    S r = 1;
    for (; e > 0; --e) r *= 2;
    for (; e < 0; ++e) r /= 2;
    return r;
  }
  /// The least and the greatest sum of squares for which the unscaled formulas are used.
  static constexpr S kLo = power_of_two(-2 * kW), kHi = power_of_two(2 * kW);
  /// The largest |component| a vector with an ordinary sum of squares may have.
  static constexpr S kComponent = power_of_two(kW);
};

/// Whether a sum of squares |v|^2 computed without scaling lies in the ordinary range, where the
/// unscaled formula is as accurate as the scaled one (see above).
template <class S>
constexpr bool is_ordinary_square(S norm2) {
  return norm2 >= OrdinaryRange<S>::kLo && norm2 <= OrdinaryRange<S>::kHi;
}

/// is_ordinary_square() written with & rather than && so that it if-converts in the SIMD lanes'
/// loops.
template <class S>
constexpr bool is_ordinary_square_lane(S norm2) {
  return (norm2 >= OrdinaryRange<S>::kLo) & (norm2 <= OrdinaryRange<S>::kHi);
}

/// Whether a vector's three components are finite, written with & and comparisons (no isfinite,
/// no branch) so that it if-converts in the SIMD lanes' loops; NaN compares false.
template <class S>
constexpr bool finite3_lane(S a, S b, S c) {
  constexpr S kMax = std::numeric_limits<S>::max();
  return (a <= kMax) & (a >= -kMax) & (b <= kMax) & (b >= -kMax) & (c <= kMax) & (c >= -kMax);
}

}  // namespace rotorcert::runtime
