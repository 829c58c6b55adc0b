// DQ-8's logarithm of a dual quaternion whose real part is a scalar: r = (0, 0, 0, w), r_v = 0
// exactly, w != 0. Shared by dq and motor_pga, which both read this case off the input as given.
//
// With r_v = 0 the translation is t = 2 d_v / w (d_w drops out), so t / 2 = d_v / w. Normalising
// first (d / |r|) would underflow d_v for a huge w and leave NaN or a wrong axis in binary32 (fuzz
// findings rigid_transforms/regression-*-log-f32-branch-cut-huge-real-part), so d_v and w are each
// scaled by their own power of two and the quotient scaled back once.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace rotorcert::runtime {

/// [xi_r, xi_d] of DQ-8 for sigma = w + eps (d_v, d_w), w finite and nonzero, d_v finite:
/// w > 0: (0, t / 2); w < 0, the branch cut: (pi t / |t|, t / 2), and (0, 0, pi) for t = 0
/// (LOG-2's axis), with t / 2 = d_v / w.
template <class S>
std::array<S, 6> log_of_scalar_real_part(S w, const std::array<S, 3>& dv) {
  using std::abs;
  const S pi = S(3.14159265358979323846264338327950288);
  const S largest = std::max({abs(dv[0]), abs(dv[1]), abs(dv[2])});
  if (largest == 0) return {0, 0, w > 0 ? S(0) : pi, 0, 0, 0};
  const int ed = std::ilogb(largest), ew = std::ilogb(w);
  const std::array<S, 3> v{std::scalbn(dv[0], -ed), std::scalbn(dv[1], -ed), std::scalbn(dv[2], -ed)};
  const S inv_w = S(1) / std::scalbn(w, -ew);
  const S to_pi = -pi / std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);  // w < 0: t points against d_v
  std::array<S, 6> xi{};
  for (int i = 0; i < 3; ++i) {
    if (w < 0) xi[i] = to_pi * v[i];
    xi[3 + i] = std::scalbn(inv_w * v[i], ed - ew);
  }
  return xi;
}

}  // namespace rotorcert::runtime
