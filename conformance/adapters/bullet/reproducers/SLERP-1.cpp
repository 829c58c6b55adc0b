// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause SLERP-1.
// SLERP-1 (spec/SPEC.md 8.2, eps16; METRIC-1 and METRIC-6): slerp(a, b, t) = (sin((1-t) W) a + sin(t W) b') / sin W
// for every pair of rotations, tending to a without 0/0 as W -> 0.
// btQuaternion::slerp (btQuaternion.h:577) returns *this, the first key, for every t whenever the
// normalised |a.b| >= 1 - SIMD_EPSILON (btQuaternion.h:585, :604): pairs of rotations up to ~9.8e-4 rad
// (binary32) or ~4.2e-8 rad (binary64) apart are not interpolated at all, so slerp(a, b, 1) = a, not
// b; just above that threshold theta = btAcos(|a.b|) (btQuaternion.h:588) loses half its digits.
// Upstream: the threshold came with the fix of NaN results for nearly equal keys,
// https://github.com/bulletphysics/bullet3/issues/64 and pull/446 (merged); no issue found for the
// interpolation it drops.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION); the input is the suite's worst input of each.
// Build: g++ -std=c++20 -O1 SLERP-1.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 SLERP-1.cpp $(pkg-config --cflags bullet-float64)    (double)
// (header-only: no Bullet library is linked)   Exit: 0 defect shown, 1 not shown.
#include <LinearMath/btQuaternion.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using LD = long double;  // reference arithmetic: 64-bit mantissa (x86)

// Run-time values, as the library meets them in a program (no constant folding of its arithmetic).
static btScalar opaque(double x) {
  volatile double v = x;
  return static_cast<btScalar>(v);
}

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  const double eps = is_double ? 0x1p-52 : 0x1p-23;
  // The suite's worst input (worst-case search from near-identical pair), [x, y, z, w] as the report prints it.
  const double af[4] = {0x1.00131p-1, 0x1.94189ap-1, 0x1.0bcd98p-3, 0x1.535ff4p-2};
  const double bf[4] = {0x1.001eb4p-1, 0x1.93f4f6p-1, 0x1.0cd908p-3, 0x1.53b1a4p-2};
  const double tf = 0x1.cd51f6p-1;
  const double ad[4] = {0x1.a13f7edd2d9d5p-2, 0x1.9781c71e9b28fp-5, -0x1.d21db9fbf9215p-1, -0x1.a976882b4fe5p-5};
  const double bd[4] = {0x1.a13f7f25ee0c5p-2, 0x1.9781d4536cc72p-5, -0x1.d21db9de518b1p-1, -0x1.a9768a2bef06ep-5};
  const double td = 0x1.cb139286ba5b8p-1;
  const double *ai = is_double ? ad : af, *bi = is_double ? bd : bf;
  const btQuaternion a(opaque(ai[0]), opaque(ai[1]), opaque(ai[2]), opaque(ai[3]));  // (x, y, z, w)
  const btQuaternion b(opaque(bi[0]), opaque(bi[1]), opaque(bi[2]), opaque(bi[3]));
  const btScalar t = opaque(is_double ? td : tf);
  const btQuaternion out = slerp(a, b, t);

  // Reference in long double: normalise, b' = -b when a.b < 0, W = 2 atan2(|a - b'|, |a + b'|),
  // slerp = (sin((1 - t) W) a + sin(t W) b') / sin W.
  const LD A[4] = {a.x(), a.y(), a.z(), a.w()}, B0[4] = {b.x(), b.y(), b.z(), b.w()}, G[4] = {out.x(), out.y(), out.z(), out.w()};
  LD na = 0, nb = 0, dot = 0, dm = 0, dp = 0, Ah[4], Bh[4], R[4];
  for (int i = 0; i < 4; ++i) na += A[i] * A[i], nb += B0[i] * B0[i], dot += A[i] * B0[i];
  const LD sgn = dot < 0 ? -1.0L : 1.0L;
  for (int i = 0; i < 4; ++i) {
    Ah[i] = A[i] / std::sqrt(na), Bh[i] = sgn * B0[i] / std::sqrt(nb);
    dm += (Ah[i] - Bh[i]) * (Ah[i] - Bh[i]), dp += (Ah[i] + Bh[i]) * (Ah[i] + Bh[i]);
  }
  const LD W = 2 * std::atan2(std::sqrt(dm), std::sqrt(dp)), s = std::sin(W);
  const LD ca = std::sin((1 - (LD)t) * W) / s, cb = std::sin((LD)t * W) / s;
  for (int i = 0; i < 4; ++i) R[i] = ca * Ah[i] + cb * Bh[i];
  LD ng = 0, nr = 0, em = 0, ep = 0;
  for (int i = 0; i < 4; ++i) ng += G[i] * G[i], nr += R[i] * R[i];
  for (int i = 0; i < 4; ++i) {
    const LD g = G[i] / std::sqrt(ng), r = R[i] / std::sqrt(nr);
    em += (g - r) * (g - r), ep += (g + r) * (g + r);
  }
  em = std::sqrt(em), ep = std::sqrt(ep);
  const double d = (double)(4 * std::atan2(std::min(em, ep), std::max(em, ep)));
  const double norm_defect = (double)std::fabs(std::sqrt(ng) - 1);
  const double err = std::max(d, norm_defect) / eps;
  const bool returned_a = out.x() == a.x() && out.y() == a.y() && out.z() == a.z() && out.w() == a.w();

  std::printf("rotorcert reproducer: Bullet 3.24 (%s) SLERP-1: slerp of two rotations %.3Lg rad apart returns %s: "
              "%.3g eps\n", is_double ? "double" : "float", 2 * W, returned_a ? "its first argument for every t" : "a wrong result", err);
  std::printf("call:    slerp(a, b, t)   (btQuaternion.h:920, a.slerp(b, t))\n");
  std::printf("input:   a (x, y, z, w) = (%a, %a, %a, %a)\n", (double)a.x(), (double)a.y(), (double)a.z(), (double)a.w());
  std::printf("         b (x, y, z, w) = (%a, %a, %a, %a)\n         t = %a   (|a.b| / (|a| |b|) = %.17Lg, "
              "1 - SIMD_EPSILON = %.17g)\n", (double)b.x(), (double)b.y(), (double)b.z(), (double)b.w(), (double)t,
              std::fabs(dot) / std::sqrt(na * nb), (double)(btScalar(1.0) - SIMD_EPSILON));
  std::printf("library: (%a, %a, %a, %a)%s\n", (double)out.x(), (double)out.y(), (double)out.z(), (double)out.w(),
              returned_a ? "   (= a)" : "");
  std::printf("correct: (%a, %a, %a, %a)   [slerp in long double]\n", (double)R[0], (double)R[1], (double)R[2], (double)R[3]);
  std::printf("error:   %.3g rad (METRIC-1), norm defect %.3g (METRIC-6): %.3g eps (eps = %a; loose bar 256 eps)\n", d,
              norm_defect, err, eps);
  if (err <= 256) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
