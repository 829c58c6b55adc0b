// The exact sign of a dot product, for the hemisphere rules of the spec (SLERP-1, QLB-1, DQ-5,
// DQ-6; EDGE-3: flip iff the dot of the inputs as given is < 0 strictly). A dot product rounded
// in the format can turn an exact 0 (a half turn between the inputs: no flip) into +-tiny in
// either direction, and a dot of separately normalised copies always can; so runtime code decides
// the flip here, on the inputs as given.
//
// Two paths. The filter computes the dot in S with a rigorous error bound and answers whenever
// the rounded dot lies outside it: every ordinary input. Otherwise the exact path sums the
// products exactly in a wider format. It does not scale the inputs: scaling each vector so that
// its largest component is near 1 keeps products from overflowing but flushes small components
// to zero, and where the large products cancel exactly those components decide the sign (the
// float pair a = (0, 0, -M, -M), b = (-M, -M, 2^-141, 0x1.7b18ap-94) with M near FLT_MAX has
// a.b = -1.3e10 < 0; scaled copies give a dot of exactly 0, and dq's dq_sclerp took the wrong
// hemisphere: fuzz/corpus/rigid/regression-dq-sclerp-hemisphere-underflow).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace rotorcert::runtime {

namespace detail {

/// A non-overlapping expansion in W (Shewchuk's grow-expansion with zero elimination): the sum
/// of its components is exactly the sum of the terms added, provided no sum overflows; the sign
/// of that sum is the sign of its largest nonzero component.
template <class W, std::size_t Capacity>
struct Expansion {
  W e[Capacity];
  std::size_t m = 0;

  void add(W x) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const W s = x + e[i], bv = s - x, err = (x - (s - bv)) + (e[i] - bv);  // TwoSum
      x = s;
      if (err != 0) e[k++] = err;
    }
    if (x != 0) e[k++] = x;
    m = k;
  }
  int sign() const { return m == 0 ? 0 : (e[m - 1] > 0 ? 1 : -1); }
};

/// x with the low 27 bits of its stored significand cleared: at most 26 significant bits, and
/// x - high_part(x) (at most 27 bits) is exact. Bits, not Veltkamp's split, because Veltkamp's
/// C * x overflows near DBL_MAX.
inline double high_part(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits &= ~((std::uint64_t{1} << 27) - 1);
  std::memcpy(&x, &bits, sizeof bits);
  return x;
}

/// binary32: a product of two floats has at most 48 significant bits and a binary exponent in
/// [-298, 256], so it is exact in binary64, and the sums of N of them never overflow.
template <std::size_t N>
int exact_dot_sign_wide(const std::array<float, N>& a, const std::array<float, N>& b) {
  Expansion<double, N + 1> sum;
  for (std::size_t i = 0; i < N; ++i) sum.add(double(a[i]) * double(b[i]));
  return sum.sign();
}

/// binary64: each factor split into two parts of at most 27 bits; the four partial products have
/// at most 54 bits and binary exponents in [-2148, 2048], exact in the x87 extended format (64-bit
/// significand, exponents to -16382) or binary128.
template <std::size_t N>
int exact_dot_sign_wide(const std::array<double, N>& a, const std::array<double, N>& b) {
  using W = long double;
  static_assert(std::numeric_limits<W>::digits >= 64 && std::numeric_limits<W>::max_exponent >= 4200 &&
                    std::numeric_limits<W>::min_exponent <= -4200,
                "exact_dot_sign<double> needs a long double with a 64-bit significand and a 15-bit exponent");
  Expansion<W, 4 * N + 1> sum;
  for (std::size_t i = 0; i < N; ++i) {
    const double ah = high_part(a[i]), bh = high_part(b[i]);
    const W a_hi = ah, a_lo = a[i] - ah, b_hi = bh, b_lo = b[i] - bh;
    sum.add(a_hi * b_hi);
    sum.add(a_hi * b_lo);
    sum.add(a_lo * b_hi);
    sum.add(a_lo * b_lo);
  }
  return sum.sign();
}

}  // namespace detail

/// The exact sign (-1, 0, +1) of sum a_i b_i of finite a, b, whatever the scale, order or
/// cancellation. S is float or double.
///
/// Filter: each product and each sum in S rounds once (relative error <= u) and an underflowing
/// product loses at most half the smallest subnormal, so |dot - a.b| <= N u s + N denorm_min / 2
/// with s the sum of |a_i b_i|; twice that is the bound. Where s overflows or the rounded dot is
/// within the bound, the exact path decides.
///
/// filtered_dot_sign() is the filter alone (inline, a few operations): it returns 2 where only the
/// exact path can decide, so that a caller's fast path can leave those inputs to its slow path.
template <class S, std::size_t N>
inline int filtered_dot_sign(const std::array<S, N>& a, const std::array<S, N>& b) {
  static_assert(std::is_same_v<S, float> || std::is_same_v<S, double>, "exact_dot_sign: float or double");
  S dot = 0, size = 0;
  for (std::size_t i = 0; i < N; ++i) {
    const S p = a[i] * b[i];
    dot += p;
    size += std::abs(p);
  }
  if (size <= std::numeric_limits<S>::max()) {
    constexpr S u = std::numeric_limits<S>::epsilon() / 2;
    const S bound = S(2 * N) * u * size + S(2 * N) * std::numeric_limits<S>::denorm_min();
    if (dot > bound) return 1;
    if (dot < -bound) return -1;
  }
  return 2;
}

template <class S, std::size_t N>
int exact_dot_sign(const std::array<S, N>& a, const std::array<S, N>& b) {
  if (const int s = filtered_dot_sign(a, b); s != 2) return s;
  return detail::exact_dot_sign_wide(a, b);
}

/// filtered_dot_sign<S, 4> without branches, for SIMD lanes (dq/dlb_lanes.hpp,
/// motor_pga/motor_lanes.hpp): the same operations in the same order. Returns whether the filter
/// decides; `negative` is then whether a.b < 0.
template <class S>
[[gnu::always_inline]] inline bool filtered_dot4_lane(S a0, S a1, S a2, S a3, S b0, S b1, S b2, S b3, bool& negative) {
  const S p0 = a0 * b0, p1 = a1 * b1, p2 = a2 * b2, p3 = a3 * b3;
  const S dot = S(0) + p0 + p1 + p2 + p3;
  const S size = S(0) + std::abs(p0) + std::abs(p1) + std::abs(p2) + std::abs(p3);
  constexpr S u = std::numeric_limits<S>::epsilon() / 2;
  const S bound = S(2 * 4) * u * size + S(2 * 4) * std::numeric_limits<S>::denorm_min();
  negative = dot < -bound;
  return (size <= std::numeric_limits<S>::max()) & ((dot > bound) | negative);
}

/// The sign of a . b of two quaternions (or any 4-vectors) as given, decided exactly.
template <class S>
int hemisphere_sign(const std::array<S, 4>& a, const std::array<S, 4>& b) {
  return exact_dot_sign<S, 4>(a, b);
}

}  // namespace rotorcert::runtime
