// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause EDGE-8.
// EDGE-8 (spec/SPEC.md 9, eps4): subnormal components are ordinary nonzero values, e.g.
// normalize((2^-1074, -0, 0, 0)) = (1, -0, 0, 0). btQuaternion::normalized() (btQuaternion.h:442)
// divides by length() = sqrt(length2()) computed without scaling: length2() of subnormal (or tiny)
// components underflows to 0, 1/0 = Inf, and the result is Inf and NaN (0 * Inf) -- the suite's
// worst inputs, below. quatRotate of a subnormal q returns 0, btMatrix3x3::setRotation (s = 2/0)
// returns Inf/NaN, slerp returns subnormal quaternions.
// Upstream: no issue found in the bullet3 tracker.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION).
// Build: g++ -std=c++20 -O1 EDGE-8.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 EDGE-8.cpp $(pkg-config --cflags bullet-float64)    (double)
// (header-only: no Bullet library is linked)   Exit: 0 defect shown, 1 not shown.
#include <LinearMath/btQuaternion.h>

#include <cmath>
#include <cstdio>

// Run-time values, as the library meets them in a program (no constant folding of its arithmetic).
static btScalar opaque(double x) {
  volatile double v = x;
  return static_cast<btScalar>(v);
}

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  const double eps = is_double ? 0x1p-52 : 0x1p-23;
  // binary32: example EX-NORM-1-i, [0, 0, 3 2^-141, 2^-139] -> [0, 0, 0.6, 0.8];
  // binary64: example EX-EDGE-8-a, [2^-1074, -0, 0, 0] -> [1, -0, 0, 0].
  const double in_float[4] = {0x0p+0, 0x0p+0, 0x1.8p-140, 0x1p-139};
  const double in_double[4] = {0x0.0000000000001p-1022, -0x0p+0, 0x0p+0, 0x0p+0};
  const double want_float[4] = {0, 0, 0.6, 0.8}, want_double[4] = {1, -0.0, 0, 0};
  const double *in = is_double ? in_double : in_float, *want = is_double ? want_double : want_float;
  const btQuaternion q(opaque(in[0]), opaque(in[1]), opaque(in[2]), opaque(in[3]));
  const btQuaternion n = q.normalized();
  std::printf("rotorcert reproducer: Bullet 3.24 (%s) EDGE-8: normalized() of a subnormal quaternion returns "
              "Inf/NaN (length2() underflows to 0)\n", is_double ? "double" : "float");
  std::printf("call:    btQuaternion(x, y, z, w).normalized()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)\n", (double)q.x(), (double)q.y(), (double)q.z(), (double)q.w());
  std::printf("library: (%a, %a, %a, %a)   (length2() = %a)\n", (double)n.x(), (double)n.y(), (double)n.z(),
              (double)n.w(), (double)q.length2());
  std::printf("correct: (%a, %a, %a, %a)   [closed form]\n", want[0], want[1], want[2], want[3]);
  double e = 0;
  const double got[4] = {(double)n.x(), (double)n.y(), (double)n.z(), (double)n.w()};
  for (int i = 0; i < 4; ++i) e = std::isnan(got[i]) || std::isinf(got[i]) ? INFINITY : std::fmax(e, std::fabs(got[i] - want[i]));
  std::printf("error:   %g (%.3g eps; EDGE-8 is eps4, loose bar 64 eps)\n", e, e / eps);
  if (e / eps <= 64) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
