// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause EDGE-6.
// EDGE-6 (spec/SPEC.md 9, outcome class): a zero quaternion and a zero rotation axis have no rotation:
// DOMAIN_ERROR (every output NaN), or under ACC-1 zero_sentinel an all-zero output or exactly the
// identity's output (Bullet's operator*, inverse(), quatRotate of 0 do that; normalized() and
// btMatrix3x3::setRotation of 0 give all-NaN: both fine). Three calls answer otherwise, with nothing
// documented (the btAssert lines that guard two of them are compiled out of release builds):
//   1. getAngle() / getAxis() of 0 (btQuaternion.h:468, :486): 2 acos(0) = pi about the zero axis
//      (0, 0, 0) -- the suite's worst input;
//   2. setRotation(axis, angle) with a zero axis (btQuaternion.h:108, btAssert(d != 0) at :111):
//      sin(angle/2) / 0 gives (NaN, NaN, NaN, cos(angle/2)): a finite w beside NaNs;
//   3. slerp(a, 0, t) (btQuaternion.h:577, btAssert(magnitude > 0) at :580): the normalised dot is
//      0/0 = NaN, the branch test fails, and a comes back unchanged, as if 0 were a rotation.
// Upstream: no issue found in the bullet3 tracker.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION).
// Build: g++ -std=c++20 -O1 EDGE-6.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 EDGE-6.cpp $(pkg-config --cflags bullet-float64)    (double)
// (header-only: no Bullet library is linked)   Exit: 0 defect shown, 1 not shown.
#include <LinearMath/btQuaternion.h>

#include <cmath>
#include <cstdio>

// Run-time values, as the library meets them in a program (no constant folding of its arithmetic).
static btScalar opaque(double x) {
  volatile double v = x;
  return static_cast<btScalar>(v);
}

static bool all_nan(const btQuaternion& q) {
  return std::isnan(q.x()) && std::isnan(q.y()) && std::isnan(q.z()) && std::isnan(q.w());
}

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  std::printf("rotorcert reproducer: Bullet 3.24 (%s) EDGE-6: getAngle/getAxis of 0 give pi about (0, 0, 0); "
              "setRotation with a zero axis gives NaNs beside a finite w; slerp(a, 0, t) gives a\n",
              is_double ? "double" : "float");
  const btScalar zero = opaque(0.0);
  // 1. The suite's worst input: q = 0.
  const btQuaternion z(zero, zero, zero, zero);
  const btScalar angle = z.getAngle();
  const btVector3 axis = z.getAxis();
  std::printf("call:    btQuaternion(0, 0, 0, 0).getAngle(), .getAxis()\n");
  std::printf("library: angle = %a, axis = (%a, %a, %a)\n", (double)angle, (double)axis.x(), (double)axis.y(),
              (double)axis.z());
  std::printf("correct: DOMAIN_ERROR: angle NaN, axis (nan, nan, nan) (EDGE-6)\n");
  const bool ok1 = std::isnan(angle) && std::isnan(axis.x()) && std::isnan(axis.y()) && std::isnan(axis.z());

  // 2. A zero axis, angle pi/2 (example EX-AXANG-2-g).
  btQuaternion r;
  r.setRotation(btVector3(zero, zero, zero), opaque(1.5707963267948966));
  std::printf("call:    btQuaternion r; r.setRotation(btVector3(0, 0, 0), pi/2)\n");
  std::printf("library: (x, y, z, w) = (%a, %a, %a, %a)\n", (double)r.x(), (double)r.y(), (double)r.z(), (double)r.w());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-6, AXANG-2: a zero axis has no direction)\n");
  const bool ok2 = all_nan(r);

  // 3. slerp from a rotation to the zero quaternion.
  const btQuaternion a(opaque(0.5), opaque(0.5), opaque(0.5), opaque(0.5));
  const btQuaternion s = slerp(a, z, opaque(0.5));
  std::printf("call:    slerp(a, btQuaternion(0, 0, 0, 0), 0.5), a (x, y, z, w) = (0.5, 0.5, 0.5, 0.5)\n");
  std::printf("library: (%a, %a, %a, %a)\n", (double)s.x(), (double)s.y(), (double)s.z(), (double)s.w());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-6), or all zero / the identity (ACC-1 zero_sentinel)\n");
  const bool ok3 = all_nan(s) || (s.x() == 0 && s.y() == 0 && s.z() == 0 && (s.w() == 0 || s.w() == 1));

  if (ok1 && ok2 && ok3) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   outputs that are neither DOMAIN_ERROR nor a zero sentinel\nDEFECT SHOWN\n");
  return 0;
}
