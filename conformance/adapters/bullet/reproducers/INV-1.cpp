// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause INV-1.
// INV-1 (spec/SPEC.md 8.1, eps4, componentwise relative error, loose bar 64 eps): q^-1 = q* / |q|^2
// for every finite nonzero q. btQuaternion::inverse(), documented as "Return the inverse of this
// quaternion" (btQuaternion.h:496), returns the conjugate (-x, -y, -z, w) (btQuaternion.h:503): the
// inverse of a unit quaternion only, and btQuaternion.h states no unit-length requirement. For
// q = (0, 3, 0, 4) (x, y, z, w), |q| = 5, it returns (0, -3, 0, 4) instead of (0, -0.12, 0, 0.16),
// 25 times too long, and q * q.inverse() = 25, not 1. (Either the code -- divide by length2() -- or
// the comment -- "of this unit quaternion" -- would fix it; the certificate holds the comment to its
// word.)
// Upstream: no issue found in the bullet3 tracker.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION); the input is the suite's worst input of each
// (worst-case search from example EX-INV-1-d).
// Build: g++ -std=c++20 -O1 INV-1.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 INV-1.cpp $(pkg-config --cflags bullet-float64)    (double)
// (header-only: no Bullet library is linked)   Exit: 0 defect shown, 1 not shown.
#include <LinearMath/btQuaternion.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using LD = long double;

// Run-time values, as the library meets them in a program (no constant folding of its arithmetic).
static btScalar opaque(double x) {
  volatile double v = x;
  return static_cast<btScalar>(v);
}

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  const double eps = is_double ? 0x1p-52 : 0x1p-23;
  const double in_float[4] = {0x0p+0, 0x1.8010e4p+1, 0x0p+0, 0x1.000bbep+2};  // [x, y, z, w]
  const double in_double[4] = {0x0p+0, 0x1.8000000000872p+1, 0x0p+0, 0x1.00000000005dfp+2};
  const double* in = is_double ? in_double : in_float;
  const btQuaternion q(opaque(in[0]), opaque(in[1]), opaque(in[2]), opaque(in[3]));
  const btQuaternion r = q.inverse();

  const LD Q[4] = {q.x(), q.y(), q.z(), q.w()}, G[4] = {r.x(), r.y(), r.z(), r.w()};
  const LD n2 = Q[0] * Q[0] + Q[1] * Q[1] + Q[2] * Q[2] + Q[3] * Q[3];
  const LD R[4] = {-Q[0] / n2, -Q[1] / n2, -Q[2] / n2, Q[3] / n2};
  const LD nr = std::sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2] + R[3] * R[3]);
  LD e = 0;
  for (int i = 0; i < 4; ++i) e = std::max(e, std::fabs(G[i] - R[i]) / nr);
  const double err = (double)e / eps;

  std::printf("rotorcert reproducer: Bullet 3.24 (%s) INV-1: btQuaternion::inverse() returns the conjugate, not "
              "q*/|q|^2: %.3g eps\n", is_double ? "double" : "float", err);
  std::printf("call:    btQuaternion(x, y, z, w).inverse()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a), |q|^2 = %.17Lg\n", (double)q.x(), (double)q.y(), (double)q.z(),
              (double)q.w(), n2);
  std::printf("library: (%a, %a, %a, %a)\n", (double)r.x(), (double)r.y(), (double)r.z(), (double)r.w());
  std::printf("correct: (%a, %a, %a, %a)   [q* / |q|^2 in long double]\n", (double)R[0], (double)R[1], (double)R[2],
              (double)R[3]);
  std::printf("error:   max |out_i - r_i| / |r| = %.3Lg: %.3g eps (eps = %a; loose bar 64 eps)\n", e, err, eps);
  if (err <= 64) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
