// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause EDGE-2.
// EDGE-2 (spec/SPEC.md 9): for rotation angles from 1e-9 to 1e-3 rad the result is within the
// operation's class (AXANG-1's eps16 here), "acos-based angles fail here". btQuaternion::getAngle()
// (btQuaternion.h:468) is 2 btAcos(w) and getAxis() (btQuaternion.h:486) is v / sqrt(1 - w^2), or the
// "Arbitrary" (1, 0, 0) when 1 - w^2 < 10 SIMD_EPSILON (btQuaternion.h:490): small rotations lose
// their angle and axis (binary32: all below ~4.9e-4 rad read as angle 0 about x).
// Upstream: getAngle's acos is https://github.com/bulletphysics/bullet3/issues/2555 (closed,
// labelled "new feature", not changed); no issue found for getAxis' threshold.
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION); the input is the suite's worst input of each.
// Build: g++ -std=c++20 -O1 EDGE-2.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 EDGE-2.cpp $(pkg-config --cflags bullet-float64)    (double)
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
  // The suite's worst input (angle 1e-9 .. 1e-3 and its worst-case search), [x, y, z, w] as the report prints it (binary32 values are
  // exact in double).
  const double in_float[4] = {-0x1.a0ac64p-15, -0x1.d1afc6p-19, -0x1.4932c2p-19, 0x1p+0};
  const double in_double[4] = {-0x1.7181e72f122fdp-27, -0x1.182834a6abd5fp-34, -0x1.29231358a4178p-34, 0x1.fffffffffffffp-1};
  const double* in = is_double ? in_double : in_float;
  const btQuaternion q(opaque(in[0]), opaque(in[1]), opaque(in[2]), opaque(in[3]));  // (x, y, z, w)
  const btScalar angle = q.getAngle();
  const btVector3 axis = q.getAxis();

  // Reference (AXANG-1): theta = 2 atan2(|v|, w), u = v/|v|, in long double.
  const LD x = q.x(), y = q.y(), z = q.z(), w = q.w(), nv = std::sqrt(x * x + y * y + z * z);
  const LD theta = 2 * std::atan2(nv, w), u[3] = {x / nv, y / nv, z / nv};
  const LD ea = std::fabs((LD)angle - theta);
  const LD eu = std::sqrt(((LD)axis.x() - u[0]) * ((LD)axis.x() - u[0]) + ((LD)axis.y() - u[1]) * ((LD)axis.y() - u[1]) +
                          ((LD)axis.z() - u[2]) * ((LD)axis.z() - u[2]));
  // The rotation the pair (angle, axis) describes, against the true one (METRIC-1): wrong even when
  // read under any angle-range or identity-axis convention.
  const LD gh = (LD)angle / 2, gq[4] = {std::cos(gh), std::sin(gh) * axis.x(), std::sin(gh) * axis.y(), std::sin(gh) * axis.z()};
  const LD n = std::sqrt(w * w + nv * nv), rq[4] = {w / n, x / n, y / n, z / n};
  LD dm = 0, dp = 0;
  for (int i = 0; i < 4; ++i) dm += (gq[i] - rq[i]) * (gq[i] - rq[i]), dp += (gq[i] + rq[i]) * (gq[i] + rq[i]);
  dm = std::sqrt(dm), dp = std::sqrt(dp);
  const double rot = (double)(4 * std::atan2(std::min(dm, dp), std::max(dm, dp)));
  const double err = (double)std::max(ea, eu) / eps;

  std::printf("rotorcert reproducer: Bullet 3.24 (%s) EDGE-2: getAngle() = 2 acos(w) and getAxis() = v / sqrt(1 - w^2) "
              "lose a rotation of %.3Lg rad: %.3g eps\n", is_double ? "double" : "float", theta, err);
  std::printf("call:    btQuaternion q(x, y, z, w); q.getAngle(); q.getAxis()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)   (|q| - 1 = %.3Lg)\n", (double)q.x(), (double)q.y(), (double)q.z(),
              (double)q.w(), n - 1);
  std::printf("library: angle = %a, axis = (%a, %a, %a)\n", (double)angle, (double)axis.x(), (double)axis.y(), (double)axis.z());
  std::printf("correct: angle = %a, axis = (%a, %a, %a)   [2 atan2(|v|, w), v/|v| in long double]\n", (double)theta,
              (double)u[0], (double)u[1], (double)u[2]);
  std::printf("error:   angle %.3Lg rad, axis %.3Lg (METRIC-3): %.3g eps (eps = %a; loose bar 256 eps); the rotation "
              "(angle, axis) is %.3g rad = %.3g eps off\n", ea, eu, err, eps, rot, rot / eps);
  if (err <= 256 && rot / eps <= 256) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
