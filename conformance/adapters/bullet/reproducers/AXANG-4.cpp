// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause AXANG-4.
// AXANG-4 (spec/SPEC.md 6, level Extended, eps16: METRIC-3 with s = 1): the axis alone, u = v/|v|
// (any unit axis only for the identity, v = 0; -u for w < 0 is acceptable). btQuaternion::getAxis()
// (btQuaternion.h:486, "Return the axis of the rotation represented by this quaternion") divides v
// by sqrt(1 - w^2), which cancels near w = +-1, and returns the "Arbitrary" (1, 0, 0) whenever
// 1 - w^2 < 10 SIMD_EPSILON (btQuaternion.h:490): for every rotation within ~3e-3 rad (binary32) /
// ~3e-7 rad (binary64) of the identity or of a full turn, although v/|v| is exact there: the axis is
// replaced by x, an axis of another rotation.
// Upstream: no issue found for getAxis' threshold (searched bulletphysics/bullet3).
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION); the input is the suite's worst input of each.
// Build: g++ -std=c++20 -O1 AXANG-4.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 AXANG-4.cpp $(pkg-config --cflags bullet-float64)    (double)
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
  // The suite's worst input, [x, y, z, w] as the report prints it (binary32 values are exact in
  // double): float from the angle sweep 1e-9 .. pi, double from near a full turn.
  const double in_float[4] = {-0x1.1e926cp-23, 0x1.62965ap-28, 0x1.0bc63ap-27, 0x1p+0};
  const double in_double[4] = {-0x1.3292a6807a3c9p-30, -0x1.c973b08ee3e11p-34, -0x1.2d52a5d7c1a42p-33, -0x1p+0};
  const double* in = is_double ? in_double : in_float;
  const btQuaternion q(opaque(in[0]), opaque(in[1]), opaque(in[2]), opaque(in[3]));  // (x, y, z, w)
  const btVector3 axis = q.getAxis();

  // Reference (AXANG-4): u = v/|v|, in long double.
  const LD x = q.x(), y = q.y(), z = q.z(), w = q.w(), nv = std::sqrt(x * x + y * y + z * z);
  const LD u[3] = {x / nv, y / nv, z / nv}, a[3] = {axis.x(), axis.y(), axis.z()};
  LD dm = 0, dp = 0;
  for (int i = 0; i < 3; ++i) dm += (a[i] - u[i]) * (a[i] - u[i]), dp += (a[i] + u[i]) * (a[i] + u[i]);
  // The error against u; -u, the axis of the same rotation by 2 pi - theta (ACC-1 angle_range), is
  // acceptable where w < 0, so the defect is the error against the nearer of the two there.
  const LD e = std::sqrt(dm), e_conv = w < 0 ? std::min(e, std::sqrt(dp)) : e;
  const double err = (double)e / eps, err_conv = (double)e_conv / eps;

  std::printf("rotorcert reproducer: Bullet 3.24 (%s) AXANG-4: getAxis() returns the 'Arbitrary' (1, 0, 0) for a "
              "rotation %.3Lg rad from %s: %.3g eps\n", is_double ? "double" : "float",
              w > 0 ? 2 * std::atan2(nv, w) : 2 * (LD)M_PI - 2 * std::atan2(nv, w), w > 0 ? "the identity" : "a full turn",
              err);
  std::printf("call:    btQuaternion q(x, y, z, w); q.getAxis()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)   (|q| - 1 = %.3Lg)\n", (double)q.x(), (double)q.y(),
              (double)q.z(), (double)q.w(), std::sqrt(w * w + nv * nv) - 1);
  std::printf("library: axis = (%a, %a, %a)\n", (double)axis.x(), (double)axis.y(), (double)axis.z());
  std::printf("correct: axis = (%a, %a, %a)   [v/|v| in long double]\n", (double)u[0], (double)u[1], (double)u[2]);
  std::printf("error:   %.3Lg (METRIC-3) = %.3g eps (eps = %a; loose bar 256 eps)\n", e, err, eps);
  if (w < 0)
    std::printf("         against -u (the axis that goes with 2 pi - theta, acceptable for w < 0): %.3g eps\n", err_conv);
  if (err_conv <= 256) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
