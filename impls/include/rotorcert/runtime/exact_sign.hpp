// The exact sign of a dot product, for the hemisphere rules of the spec (SLERP-1, QLB-1, DQ-5,
// DQ-6; EDGE-3: flip iff the dot is < 0 strictly). A dot product rounded in the format can turn
// an exact 0 (a half turn between the inputs: no flip) into +-tiny in either direction, and a
// dot of separately normalised copies always can; so runtime code decides the flip here, on the
// inputs as given.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace rotorcert::runtime {

/// The exact sign (-1, 0, +1) of sum a_i b_i, whatever the order or cancellation: each product is
/// split exactly into p + e (fma), and the 2N terms are summed into a non-overlapping expansion
/// (Shewchuk's grow-expansion with zero elimination), whose largest nonzero component has the
/// sign of the exact sum. Precondition: no product overflows (see hemisphere_sign).
template <class S, std::size_t N>
int exact_dot_sign(const std::array<S, N>& a, const std::array<S, N>& b) {
  S e[2 * N + 1];
  int m = 0;
  const auto grow = [&](S x) {
    int k = 0;
    for (int i = 0; i < m; ++i) {
      const S s = x + e[i], bv = s - x, err = (x - (s - bv)) + (e[i] - bv);  // TwoSum
      x = s;
      if (err != 0) e[k++] = err;
    }
    if (x != 0) e[k++] = x;
    m = k;
  };
  for (std::size_t i = 0; i < N; ++i) {
    const S p = a[i] * b[i];
    grow(p);
    grow(std::fma(a[i], b[i], -p));
  }
  return m == 0 ? 0 : (e[m - 1] > 0 ? 1 : -1);
}

/// a scaled by the power of two that brings its largest |component| into [1, 2): exact, and it
/// keeps every product and sum of exact_dot_sign far from overflow. A zero vector stays zero.
template <class S, std::size_t N>
std::array<S, N> unit_scaled(const std::array<S, N>& a) {
  S largest = 0;
  for (const S& x : a) largest = std::max(largest, std::abs(x));
  if (largest == 0 || !std::isfinite(largest)) return a;
  const int e = -std::ilogb(largest);
  std::array<S, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = std::scalbn(a[i], e);
  return r;
}

/// The sign of a . b of two quaternions (or any 4-vectors) as given, decided exactly.
template <class S>
int hemisphere_sign(const std::array<S, 4>& a, const std::array<S, 4>& b) {
  return exact_dot_sign<S, 4>(unit_scaled(a), unit_scaled(b));
}

}  // namespace rotorcert::runtime
