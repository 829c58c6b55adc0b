// The dual part of a DQ-4 normalisation without cancellation.
//
// DQ-4 (and MOTOR-1's motor normalisation, the same map) keeps the part of the dual 4-vector d
// perpendicular to the real 4-vector r: d' = (d - (r'.d) r') / |r| with r' = r / |r|. Written that
// way it subtracts the parallel part of d from d. Where d is mostly parallel to r (a non-unit
// input: a dual quaternion scaled by (1 + eps c), whose d gains c r), the difference cancels and
// d' keeps an error of about eps |d| along r, so the result breaks DQ-4's r'.d' = 0 by far more
// than eps |d'| (fuzz finding rigid/regression-dq-sclerp-subnormal-real-part-f64: 5829 eps).
//
// Component i of |r|^2 (d - (r'.d) r') is sum_{j != i} r_j (r_j d_i - r_i d_j): no parallel part
// is ever formed, and each 2x2 term with an fma is accurate to 1.5 ulp (Kahan), so the
// perpendicular part comes out to a few ulp of itself. It takes 12 such terms (24 products, 24
// fmas) where the subtraction takes 4 products and 4 differences, so the callers use it only where
// the cheap test below says the subtraction would cancel.
#pragma once

#include <array>
#include <cmath>
#include <limits>

namespace rotorcert::runtime {

/// r_j d_i - r_i d_j to 1.5 ulp: the rounding error of r_i d_j is recovered by an fma.
template <class S>
S difference_of_products(S rj, S di, S ri, S dj) {
  const S p = ri * dj;
  return std::fma(rj, di, -p) + std::fma(-ri, dj, p);
}

/// |r|^2 (d - (r.d / |r|^2) r), componentwise as sum_{j != i} r_j (r_j d_i - r_i d_j).
/// Precondition: squares and products of the components are finite (the callers have scaled r
/// into [1, 2) where they had to).
template <class S>
std::array<S, 4> perpendicular_times_norm2(const std::array<S, 4>& r, const std::array<S, 4>& d) {
  std::array<S, 4> out{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (j != i) out[i] += r[j] * difference_of_products(r[j], d[i], r[i], d[j]);
  return out;
}

/// The cheap test, asked before the subtraction: with r' unit, |d|^2 = along^2 + |d'|^2, so
/// along^2 > 15/16 |d|^2 means |d'| < |d|/4: the subtraction d - along r' would lose more than two
/// bits of d', whose parallel part then errs by more than DQ-4's bars allow relative to |d'|.
/// |d|^2 comes from the input alone, so it is computed beside the normalisation's sqrt and
/// division rather than after them. A |d|^2 that overflowed (or is not finite) answers yes.
template <class S>
bool projection_cancels(S along, S d_norm2) {
  return !(d_norm2 <= std::numeric_limits<S>::max()) || along * along > S(0.9375) * d_norm2;
}

}  // namespace rotorcert::runtime
