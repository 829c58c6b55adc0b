// rotor_simd, shared scalar code (compiled once, not per target): the dispatch table type, the
// exact sign of a dot product, and binary64 fallbacks for the rare far-out lanes (|t| > 4 in
// slerp, |v| > 8 in exp) where a binary32 polynomial would lose accuracy in proportion to the
// argument.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <vector>

#include <rotorcert/impl_table.hpp>
#include <rotorcert/runtime/exact_sign.hpp>

/// Forces a lambda inline (GCC and Clang attribute syntax for a lambda's call operator).
#define ROTORCERT_SIMD_INLINE __attribute__((always_inline))

namespace rotorcert::rotor_simd {

using Unary = int (*)(std::size_t, const float*, float*, std::uint8_t*);
using Binary = int (*)(std::size_t, const float*, const float*, float*, std::uint8_t*);
using Interp = int (*)(std::size_t, const float*, const float*, const float*, float*, std::uint8_t*);
using Blend = int (*)(std::size_t, std::size_t, const float*, const float*, float*, std::uint8_t*);
using AxisAngleOut = int (*)(std::size_t, const float*, float*, float*, std::uint8_t*);

/// One target's kernels, all with the ABI's batch signatures.
struct Kernels {
  const char* name;  // hwy::TargetName of the target it was compiled for
  std::int64_t target;
  std::size_t lanes;  // floats per vector: elements per block
  Unary normalize;
  Binary compose;
  Binary apply_vector;  // also APPLY-2: bivector coefficients rotate like a vector
  Unary to_matrix;
  Unary inverse;
  AxisAngleOut to_axis_angle;
  Binary from_axis_angle;  // (angle, axis) -> q
  Unary log;
  Unary exp;
  Interp slerp;
  Interp nlerp;
  Blend blend_qlb;
  Blend blend_log;
};

/// Sign (-1, 0, +1) of the exact dot product of two float quaternions ([x, y, z, w] arrays):
/// the hemisphere rules (SLERP-1, QLB-1, EDGE-3) flip iff it is < 0 strictly, and a float dot
/// can turn an exact 0 into +-tiny. The kernels call this only when their float dot is within
/// its error bound of zero.
inline int exact_dot_sign(const float* a, const float* b) {
  return rotorcert::runtime::hemisphere_sign<float>({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]});
}

/// q/|q| in double with the largest component scaled out first.
inline void normalized_double(const float* q, double out[4]) {
  double m = 0;
  for (int i = 0; i < 4; ++i) m = std::max(m, std::fabs(static_cast<double>(q[i])));
  double s[4], n2 = 0;
  for (int i = 0; i < 4; ++i) {
    s[i] = q[i] / m;
    n2 += s[i] * s[i];
  }
  const double n = std::sqrt(n2);
  for (int i = 0; i < 4; ++i) out[i] = s[i] / n;
}

/// SLERP-1 in binary64 for one valid lane ([x, y, z, w] arrays): the formula of the spec with
/// Omega from the chord lengths. Used for |t| > 4, where the binary32 argument t * Omega of
/// sin would carry an absolute error proportional to |t|.
inline void slerp_double(const float* qa, const float* qb, float t, float* out) {
  double a[4], b[4];
  normalized_double(qa, a);
  normalized_double(qb, b);
  if (exact_dot_sign(qa, qb) < 0)
    for (double& x : b) x = -x;
  double d2 = 0, s2 = 0;
  for (int i = 0; i < 4; ++i) {
    d2 += (a[i] - b[i]) * (a[i] - b[i]);
    s2 += (a[i] + b[i]) * (a[i] + b[i]);
  }
  const double omega = 2 * std::atan2(std::sqrt(d2), std::sqrt(s2));
  if (omega == 0) {
    for (int i = 0; i < 4; ++i) out[i] = static_cast<float>(a[i]);
    return;
  }
  const double sa = std::sin((1 - static_cast<double>(t)) * omega), sb = std::sin(t * omega), s = std::sin(omega);
  for (int i = 0; i < 4; ++i) out[i] = static_cast<float>((sa * a[i] + sb * b[i]) / s);
}

/// AXANG-2 in binary64 for one lane: (sin(angle/2) u, cos(angle/2)), u = axis/|axis|. Used
/// for |angle| > 16, where the binary32 polynomials' error grows with the argument.
inline void from_axis_angle_double(float angle, const float* axis, float* out) {
  const double x = axis[0], y = axis[1], z = axis[2];
  const double m = std::max({std::fabs(x), std::fabs(y), std::fabs(z)});
  const double n = std::sqrt((x / m) * (x / m) + (y / m) * (y / m) + (z / m) * (z / m));
  const double h = static_cast<double>(angle) / 2, k = std::sin(h) / n;
  out[0] = static_cast<float>(k * (x / m));
  out[1] = static_cast<float>(k * (y / m));
  out[2] = static_cast<float>(k * (z / m));
  out[3] = static_cast<float>(std::cos(h));
}

/// EXP-1 in binary64 for one lane: (sin|v| v/|v|, cos|v|). Used for |v| > 8.
inline void exp_double(const float* v, float* out) {
  const double x = v[0], y = v[1], z = v[2];
  const double m = std::max({std::fabs(x), std::fabs(y), std::fabs(z)});
  const double theta = m * std::sqrt((x / m) * (x / m) + (y / m) * (y / m) + (z / m) * (z / m));
  const double k = std::sin(theta) / theta;
  out[0] = static_cast<float>(k * x);
  out[1] = static_cast<float>(k * y);
  out[2] = static_cast<float>(k * z);
  out[3] = static_cast<float>(std::cos(theta));
}

}  // namespace rotorcert::rotor_simd
