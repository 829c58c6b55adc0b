// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause EDGE-7.
// EDGE-7 (spec/SPEC.md 9, outcome class): NaN or +-Inf in any input is DOMAIN_ERROR, every output a
// quiet NaN (an adapter without a status channel reads "all outputs NaN" as DOMAIN_ERROR).
// btQuaternion::normalized() (btQuaternion.h:442) of [x, y, z, w] = [0, Inf, 0, 1] (the suite's
// worst input, example EX-EDGE-7-b) computes length() = Inf and multiplies by 1/Inf = 0: the result
// is [0, NaN, 0, 0], three finite components. operator*, quatRotate, setRotation, getAngle/getAxis
// and slerp likewise mix finite and non-finite outputs.
// Upstream: no issue found in the bullet3 tracker.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION).
// Build: g++ -std=c++20 -O1 EDGE-7.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 EDGE-7.cpp $(pkg-config --cflags bullet-float64)    (double)
// (header-only: no Bullet library is linked)   Exit: 0 defect shown, 1 not shown.
#include <LinearMath/btQuaternion.h>

#include <cmath>
#include <cstdio>
#include <limits>

// Run-time values, as the library meets them in a program (no constant folding of its arithmetic).
static btScalar opaque(double x) {
  volatile double v = x;
  return static_cast<btScalar>(v);
}

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  const btQuaternion q(opaque(0.0), opaque(std::numeric_limits<double>::infinity()), opaque(0.0), opaque(1.0));
  const btQuaternion n = q.normalized();
  std::printf("rotorcert reproducer: Bullet 3.24 (%s) EDGE-7: normalized() of a quaternion with an infinite "
              "component returns three finite components and one NaN\n", is_double ? "double" : "float");
  std::printf("call:    btQuaternion(x, y, z, w).normalized()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)\n", (double)q.x(), (double)q.y(), (double)q.z(), (double)q.w());
  std::printf("library: (%a, %a, %a, %a)\n", (double)n.x(), (double)n.y(), (double)n.z(), (double)n.w());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-7)\n");
  if (std::isnan(n.x()) && std::isnan(n.y()) && std::isnan(n.z()) && std::isnan(n.w())) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   finite components in the output of a non-finite input\nDEFECT SHOWN\n");
  return 0;
}
