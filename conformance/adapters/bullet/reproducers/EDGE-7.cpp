// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause EDGE-7.
// EDGE-7 (spec/SPEC.md 9, outcome class): NaN or +-Inf in any input is DOMAIN_ERROR, every output a
// quiet NaN; status OK with some output NaN or +-Inf (IEEE propagation, e.g. normalized() of
// (0, Inf, 0, 1) = (0, NaN, 0, 0)) is ACCEPTABLE (ACC-1 nonfinite_propagation). An all-finite answer
// to a non-finite input stays a FAIL: the caller can no longer see that the input was not a number.
// Bullet gives one from two calls, with nothing documented:
//   1. slerp(a, b, t) (btQuaternion.h:577): product = dot(q) / magnitude (:582) is NaN when b holds
//      a NaN or +-Inf (Inf/Inf), the test absproduct < 1 - SIMD_EPSILON (:585) fails, and the else
//      branch returns *this (:604): a, unchanged and finite -- the suite's worst input;
//   2. getAngle() (btQuaternion.h:468-472) is 2 btAcos(w) and reads w alone: a NaN or +-Inf in
//      x, y or z gives a finite angle.
// (getAxis() of w = +-Inf returns the "Arbitrary" (1, 0, 0) (:491): the identity's axis, the
// rotation q/|q| tends to, ACCEPTABLE under ACC-1 nonfinite_limit since spec 2.7.0.)
// Upstream: no issue found in the bullet3 tracker.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION); the inputs are the suite's EDGE-7 inputs of each.
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

static btQuaternion quat(const double* q) { return btQuaternion(opaque(q[0]), opaque(q[1]), opaque(q[2]), opaque(q[3])); }

static bool finite(const btQuaternion& q) {
  return std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z()) && std::isfinite(q.w());
}

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::printf("rotorcert reproducer: Bullet 3.24 (%s) EDGE-7: slerp with a NaN in b returns a; getAngle of a NaN y "
              "returns a finite angle\n", is_double ? "double" : "float");

  // 1. The suite's worst input (slerp, "NaN in b"), [x, y, z, w] as the report prints it (the
  // binary32 values are exact in double).
  const double a_float[4] = {-0x1.ae57c2p-1, 0x1.ba53d4p-2, -0x1.1f47ccp-4, 0x1.4715cp-2};
  const double b_float[4] = {0x1.a6500cp-1, nan, -0x1.9ea2e4p-3, -0x1.b5c048p-2};
  const double t_float = 0x1.2a37acp-2;
  const double a_double[4] = {-0x1.ae57c2320e1f7p-1, 0x1.ba53d3534cf54p-2, -0x1.1f47ccc967701p-4, 0x1.4715c09b44951p-2};
  const double b_double[4] = {0x1.a6500b077288bp-1, nan, -0x1.9ea2e461ed636p-3, -0x1.b5c0474abd362p-2};
  const double t_double = 0x1.2a37abeb2956ap-2;
  const btQuaternion a = quat(is_double ? a_double : a_float), b = quat(is_double ? b_double : b_float);
  const btScalar t = opaque(is_double ? t_double : t_float);
  const btQuaternion s = slerp(a, b, t);
  const bool shown1 = !finite(b) && finite(a) && std::isfinite(t) && finite(s);
  std::printf("call:    slerp(btQuaternion(a), btQuaternion(b), t)  (a.slerp(b, t), btQuaternion.h:577)\n");
  std::printf("input:   a (x, y, z, w) = (%a, %a, %a, %a)\n", (double)a.x(), (double)a.y(), (double)a.z(), (double)a.w());
  std::printf("         b (x, y, z, w) = (%a, %a, %a, %a), t = %a\n", (double)b.x(), (double)b.y(), (double)b.z(),
              (double)b.w(), (double)t);
  std::printf("library: (%a, %a, %a, %a)%s\n", (double)s.x(), (double)s.y(), (double)s.z(), (double)s.w(),
              shown1 ? "   <-- a itself: all finite, b's NaN dropped" : "");
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-7), or some component NaN/Inf (ACC-1 nonfinite_propagation)\n");

  // 2. getAngle of a NaN y (the suite's "NaN in q" of to_angle: every finite w gives a finite angle).
  const double q2_float[4] = {-0x1.23e64ep-1, nan, -0x1.04e99ap-2, -0x1.580322p-2};
  const double q2_double[4] = {-0x1.23e64e6838673p-1, nan, -0x1.04e99a3543728p-2, -0x1.5803222154743p-2};
  const btQuaternion r = quat(is_double ? q2_double : q2_float);
  const btScalar angle = r.getAngle();
  const bool shown2 = !finite(r) && std::isfinite(angle);
  std::printf("call:    btQuaternion(x, y, z, w).getAngle()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)\n", (double)r.x(), (double)r.y(), (double)r.z(), (double)r.w());
  std::printf("library: angle = %a%s\n", (double)angle, shown2 ? "   <-- finite: 2 acos(w), y never read" : "");
  std::printf("correct: DOMAIN_ERROR: angle NaN (EDGE-7)\n");

  if (!shown1 && !shown2) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   all-finite answers to non-finite inputs (no NaN or Inf reaches the result)\nDEFECT SHOWN\n");
  return 0;
}
