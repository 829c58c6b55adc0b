// rotorcert reproducer, Bullet 3.24 (Debian libbullet-dev 3.24+dfsg-2), clause AXANG-3.
// AXANG-3 (spec/SPEC.md 6, level Extended, eps16: absolute error in radians): the angle alone,
// theta = 2 atan2(|v|, w) in [0, 2 pi], the theta of AXANG-1; an angle of the same rotation (2 pi -
// theta, or signed) is acceptable, so the error is |rho(angle) - rho(theta)| with rho(x) =
// 2 atan2(|sin x/2|, |cos x/2|) in [0, pi]. btQuaternion::getAngle() (btQuaternion.h:468, "Return
// the angle [0, 2Pi] of rotation represented by this quaternion") is 2 btAcos(w): w = cos(theta/2)
// is flat near theta = 0 and 2 pi, so acos gives back only about half of its digits there; the
// angle of a rotation 1e-9 .. 1e-2 rad from the identity or from a full turn is off by up to
// sqrt(eps) (binary32: every angle below ~4.9e-4 rad reads 0).
// Upstream: https://github.com/bulletphysics/bullet3/issues/2555 (getAngle's acos; closed,
// labelled "new feature", not changed).
// Both of Debian's builds: the float one (bullet.pc, the default) and the double one
// (bullet-float64.pc, -DBT_USE_DOUBLE_PRECISION); the input is the suite's worst input of each.
// Build: g++ -std=c++20 -O1 AXANG-3.cpp $(pkg-config --cflags bullet)            (float)
//        g++ -std=c++20 -O1 AXANG-3.cpp $(pkg-config --cflags bullet-float64)    (double)
// (header-only: no Bullet library is linked)   Exit: 0 defect shown, 1 not shown.
#include <LinearMath/btQuaternion.h>

#include <cmath>
#include <cstdio>

using LD = long double;  // reference arithmetic: 64-bit mantissa (x86)

// Run-time values, as the library meets them in a program (no constant folding of its arithmetic).
static btScalar opaque(double x) {
  volatile double v = x;
  return static_cast<btScalar>(v);
}

// The angle in [0, pi] of the rotation by x about some axis (ACC-1 angle_range).
static LD rho(LD x) { return 2 * std::atan2(std::fabs(std::sin(x / 2)), std::fabs(std::cos(x / 2))); }

int main() {
  constexpr bool is_double = sizeof(btScalar) == sizeof(double);
  const double eps = is_double ? 0x1p-52 : 0x1p-23;
  // The suite's worst input (worst-case search from "near a full turn: 2 pi - 1e-9 .. 1e-1"),
  // [x, y, z, w] as the report prints it (binary32 values are exact in double).
  const double in_float[4] = {-0x1.e1421ep-13, -0x1.a423bap-15, 0x1.0e2ab6p-16, -0x1p+0};
  const double in_double[4] = {-0x1.437afb887df37p-28, 0x1.40127017d17bbp-27, -0x1.805dfec37a965p-32, -0x1p+0};
  const double* in = is_double ? in_double : in_float;
  const btQuaternion q(opaque(in[0]), opaque(in[1]), opaque(in[2]), opaque(in[3]));  // (x, y, z, w)
  const btScalar angle = q.getAngle();

  // Reference (AXANG-3): theta = 2 atan2(|v|, w), in long double.
  const LD x = q.x(), y = q.y(), z = q.z(), w = q.w(), nv = std::sqrt(x * x + y * y + z * z);
  const LD theta = 2 * std::atan2(nv, w);
  const LD e = std::fabs(rho((LD)angle) - rho(theta));  // under any angle range
  const double err = (double)e / eps;

  std::printf("rotorcert reproducer: Bullet 3.24 (%s) AXANG-3: getAngle() = 2 acos(w) loses the angle near a full "
              "turn: %.3g eps\n", is_double ? "double" : "float", err);
  std::printf("call:    btQuaternion q(x, y, z, w); q.getAngle()\n");
  std::printf("input:   q (x, y, z, w) = (%a, %a, %a, %a)   (|q| - 1 = %.3Lg, %.3Lg rad short of a full turn)\n",
              (double)q.x(), (double)q.y(), (double)q.z(), (double)q.w(), std::sqrt(w * w + nv * nv) - 1,
              2 * (LD)M_PI - theta);
  std::printf("library: angle = %a = %.12g\n", (double)angle, (double)angle);
  std::printf("correct: angle = %a = %.12Lg   [2 atan2(|v|, w) in long double]\n", (double)theta, theta);
  std::printf("error:   %.3Lg rad = %.3g eps (eps = %a; loose bar 256 eps), read under any angle range (2 pi - "
              "theta, signed)\n", e, err, eps);
  if (err <= 256) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
