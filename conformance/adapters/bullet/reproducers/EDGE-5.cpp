// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause EDGE-5.
// EDGE-5 (spec/SPEC.md 9, eps16): a finite nonzero q is the rotation q/|q| at every scale the format
// holds, and unit-valued outputs stay unit. btQuaternion.h states no unit-length requirement, but:
//   1. normalized() (btQuaternion.h:442) is *this / length(), length() = sqrt(length2()) squares
//      without scaling: at scale 2^-100 (binary32) or 2^-999 (binary64) length2() underflows to 0
//      and the "normalised" quaternion is Inf/NaN (the suite's worst input);
//   2. quatRotate (btQuaternion.h:926) is (q * v) * q.inverse() with no division by |q|^2: for
//      q = 2 (quarter turn about z) it turns x into 4 y, not y;
//   3. getAngle() = 2 acos(w) (btQuaternion.h:468) clamps w > 1 to 1: 2 (quarter turn about z) reads
//      as angle 0 about the "Arbitrary" (1, 0, 0).
// (setRotation(q) of btMatrix3x3 divides by length2() and is right at moderate scales; it overflows
// and underflows at the extreme ones.)
// Upstream: no issue found in the bullet3 tracker.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION).
// Build: g++ -std=c++20 -O1 EDGE-5.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 EDGE-5.cpp $(pkg-config --cflags bullet-float64)    (double)
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
  std::printf("rotorcert reproducer: Bullet 3.24 (%s) EDGE-5: normalized() underflows to Inf/NaN, quatRotate "
              "scales by |q|^2, getAngle/getAxis of a non-unit q name another rotation\n", is_double ? "double" : "float");
  bool shown = false;

  // 1. The suite's worst input: binary32 non-unit scale 2^-100; binary64 example EX-NORM-1-h.
  const double in_float[4] = {0x1.b8f03cp-102, 0x1.875a4cp-111, -0x1.b04b1ep-104, 0x1.fa16f6p-101};  // [x, y, z, w]
  const double in_double[4] = {0x1.8p-999, 0x0p+0, 0x0p+0, 0x1p-998};
  const double* in = is_double ? in_double : in_float;
  const btQuaternion q1(opaque(in[0]), opaque(in[1]), opaque(in[2]), opaque(in[3]));
  const btQuaternion n1 = q1.normalized();
  std::printf("call:    btQuaternion(x, y, z, w).normalized()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)\n", (double)q1.x(), (double)q1.y(), (double)q1.z(), (double)q1.w());
  std::printf("library: (%a, %a, %a, %a)\n", (double)n1.x(), (double)n1.y(), (double)n1.z(), (double)n1.w());
  const long double m = std::sqrt((long double)in[0] * in[0] + (long double)in[1] * in[1] + (long double)in[2] * in[2] +
                                  (long double)in[3] * in[3]);
  std::printf("correct: (%a, %a, %a, %a)   [q/|q| in long double]\n", (double)(in[0] / m), (double)(in[1] / m),
              (double)(in[2] / m), (double)(in[3] / m));
  const double len1 = std::sqrt((double)n1.x() * n1.x() + (double)n1.y() * n1.y() + (double)n1.z() * n1.z() +
                                (double)n1.w() * n1.w());
  shown = shown || !(std::fabs(len1 - 1) <= 256 * eps);

  // 2. and 3. A moderate scale: 2 (cos 45, 0, 0, sin 45) (x, y, z, w), the quarter turn about z.
  const btScalar h = opaque(std::sqrt(2.0));  // 2 sin 45 = 2 cos 45
  const btQuaternion q2(btScalar(0), btScalar(0), h, h);
  const btVector3 r2 = quatRotate(q2, btVector3(1, 0, 0));
  std::printf("call:    quatRotate(q, btVector3(1, 0, 0))\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)   (2 x the quarter turn about z)\n", (double)q2.x(),
              (double)q2.y(), (double)q2.z(), (double)q2.w());
  std::printf("library: (%a, %a, %a)\n", (double)r2.x(), (double)r2.y(), (double)r2.z());
  std::printf("correct: (0x0p+0, 0x1p+0, 0x0p+0)   [closed form: the rotation of q/|q| maps x to y]\n");
  const double e2 = std::sqrt((double)r2.x() * r2.x() + ((double)r2.y() - 1) * ((double)r2.y() - 1) + (double)r2.z() * r2.z());
  std::printf("error:   |out - (0, 1, 0)| = %g = %.3g eps (METRIC-3; loose bar 256 eps)\n", e2, e2 / eps);
  shown = shown || !(e2 / eps <= 256);
  const btScalar angle = q2.getAngle();
  const btVector3 axis = q2.getAxis();
  std::printf("call:    q.getAngle(), q.getAxis()\n");
  std::printf("library: angle = %a, axis = (%a, %a, %a)\n", (double)angle, (double)axis.x(), (double)axis.y(),
              (double)axis.z());
  std::printf("correct: angle = %a (pi/2), axis = (0x0p+0, 0x0p+0, 0x1p+0)   [closed form]\n", 1.5707963267948966);

  if (!shown) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
