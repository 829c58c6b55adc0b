// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause AXANG-1.
// AXANG-1: the angle-axis of q is theta = 2 atan2(|v|, w) in [0, 2 pi] with a UNIT axis (any unit
// axis when v = 0, e.g. (0, 0, 1)); an angle that is not written, or a zero axis, is a defect.
// When |v| <= DBL_MIN, CQRGetQuaternionAngle returns CQR_SUCCESS WITHOUT writing *angle (the
// caller's variable keeps whatever it held) and CQRGetQuaternionAxis returns the zero axis
// (0, 0, 0), also with CQR_SUCCESS: for q = -1 and q = 1 (and any real q) there is no answer at all.
// (CQRGetQuaternionAngle returns the polar angle phi = atan2(|v|, w), half the rotation angle.)
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 AXANG-1.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <cmath>
#include <cstdio>

int main() {
  CQRQuaternion q;  // {w, x, y, z}
  q.w = -1.0, q.x = 0.0, q.y = 0.0, q.z = 0.0;
  const double sentinel = 12345.0;  // not an angle: shows whether the library wrote *angle
  double phi = sentinel;
  CQRQuaternion axis;
  axis.w = axis.x = axis.y = axis.z = 7.0;
  const int rc_angle = CQRGetQuaternionAngle(&phi, &q);
  const int rc_axis = CQRGetQuaternionAxis(&axis, &q);
  const double alen = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
  std::printf("rotorcert reproducer: CQRlib 1.1.4 AXANG-1: for a real quaternion (v = 0, e.g. q = -1) "
              "CQRGetQuaternionAngle returns CQR_SUCCESS without writing the angle and CQRGetQuaternionAxis "
              "returns the zero axis\n");
  std::printf("call:    double phi = %g; CQRGetQuaternionAngle(&phi, &q); CQRGetQuaternionAxis(&axis, &q);\n",
              sentinel);
  std::printf("input:   q {w, x, y, z} = {%a, %a, %a, %a}\n", q.w, q.x, q.y, q.z);
  std::printf("library: rc = %d, phi = %a (%g, the caller's value); rc = %d, axis {w, x, y, z} = {%a, %a, %a, %a}\n",
              rc_angle, phi, phi, rc_axis, axis.w, axis.x, axis.y, axis.z);
  std::printf("correct: phi = atan2(|v|, w) = atan2(+0, -1) = pi = %a (rotation angle 2 pi), a unit axis, "
              "e.g. {0, 0, 0, 1}   [closed form]\n", std::atan2(0.0, -1.0));
  std::printf("error:   angle not written (rc %d = CQR_SUCCESS); axis length %g instead of 1 (%.3g eps, eps = 2^-52)\n",
              rc_angle, alen, std::fabs(alen - 1) / 0x1p-52);
  if (phi != sentinel && std::fabs(alen - 1) <= 256 * 0x1p-52) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
