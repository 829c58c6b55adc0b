// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause EDGE-5.
// EDGE-5: a finite nonzero q is the rotation q/|q| at every scale, unit-valued outputs stay unit
// (eps16). CQRHLERP documents "linear interpolation between the radii" of non-unit inputs, but it
// divides q2 by sqrt(norm1sq), the norm of q1 (a typo for norm2sq): for a unit q1 and |q2| = 2 it
// interpolates towards an unnormalised q2 and leaves the great circle, so even the DIRECTION is
// wrong (126.87 degrees instead of 90 degrees for the midpoint of 0 and 180 degrees about z).
// (The header's C++ twin CPPQR::HLERP shows the line: cqrlib.h:1043 "r2 = sqrt(norm1sq);"; the C
// function behaves identically, checked here.)
// Second case: CQRInverse of q = 2^-900 (a finite nonzero q whose inverse 2^900 is representable)
// returns CQR_BAD_ARGUMENT because its squared norm underflows. Third: CQRQuaternion2Matrix ("Form the
// 3x3 rotation matrix from a quaternion") of q = 2 returns 4 I, not a rotation matrix.
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 EDGE-5.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

// METRIC-1: 4 atan2(min(|a-b|, |a+b|), max(|a-b|, |a+b|)) of the normalised quaternions.
static long double rdist(const long double* a, const long double* b) {
  long double na = 0, nb = 0, dm = 0, dp = 0;
  for (int i = 0; i < 4; ++i) na += a[i] * a[i], nb += b[i] * b[i];
  for (int i = 0; i < 4; ++i) {
    const long double x = a[i] / std::sqrt(na), y = b[i] / std::sqrt(nb);
    dm += (x - y) * (x - y), dp += (x + y) * (x + y);
  }
  dm = std::sqrt(dm), dp = std::sqrt(dp);
  return 4 * std::atan2(std::min(dm, dp), std::max(dm, dp));
}

int main() {
  std::printf("rotorcert reproducer: CQRlib 1.1.4 EDGE-5: CQRHLERP of a unit and a non-unit quaternion leaves the "
              "great circle (q2 is divided by |q1|); CQRInverse of 2^-900 fails; the matrix of q = 2 is 4 I\n");
  CQRQuaternion a, b, out;  // {w, x, y, z}
  a.w = 1.0, a.x = 0.0, a.y = 0.0, a.z = 0.0;  // identity
  b.w = 0.0, b.x = 0.0, b.y = 0.0, b.z = 2.0;  // 2 * (180 degrees about z)
  const int rc = CQRHLERP(&out, &a, &b, 0.5, 0.5);  // weights w1 = w2 = 1/2: the midpoint
  // Correct direction (closed form): the midpoint of 0 and 180 degrees about z, 90 degrees about z:
  // (cos 45, 0, 0, sin 45); CQRlib's own radius rule gives it the length (1 + 2)/2 = 1.5.
  const long double h = 3.141592653589793238462643383279502884L / 4;
  const long double ref[4] = {std::cos(h), 0, 0, std::sin(h)};
  const long double lib[4] = {out.w, out.x, out.y, out.z};
  const long double err = rdist(lib, ref);
  std::printf("call:    CQRHLERP(&out, &q1, &q2, 0.5, 0.5)\n");
  std::printf("input:   q1 {w, x, y, z} = {%a, %a, %a, %a}, q2 = {%a, %a, %a, %a}, w1 = w2 = %a\n", a.w, a.x, a.y,
              a.z, b.w, b.x, b.y, b.z, 0.5);
  std::printf("library: rc = %d, {%a, %a, %a, %a} (a turn of %.6g degrees about z, length %.6g)\n", rc, out.w, out.x,
              out.y, out.z, 2 * std::atan2(out.z, out.w) * 180 / 3.141592653589793,
              std::sqrt(out.w * out.w + out.z * out.z));
  std::printf("correct: direction {%a, 0, 0, %a} (90 degrees about z), length 1.5 by CQRlib's radius rule, 1 by "
              "EDGE-5   [closed form]\n", (double)ref[0], (double)ref[3]);
  std::printf("error:   %.6Lg rad (METRIC-1) = %.3Lg eps (eps = 2^-52; EDGE-5 is eps16, loose bar 256 eps)\n", err,
              err / 0x1p-52L);
  // Case 2: the inverse of a small finite q: q^-1 = q*/|q|^2 = 2^900 (closed form).
  CQRQuaternion s, si;
  s.w = 0x1p-900, s.x = 0.0, s.y = 0.0, s.z = 0.0;
  const int rc2 = CQRInverse(&si, &s);
  std::printf("call:    CQRInverse(&inv, &q)\n");
  std::printf("input:   q {w, x, y, z} = {%a, %a, %a, %a}\n", s.w, s.x, s.y, s.z);
  std::printf("library: rc = %d (CQR_BAD_ARGUMENT = %d), inv = {%a, %a, %a, %a}\n", rc2, CQR_BAD_ARGUMENT, si.w, si.x,
              si.y, si.z);
  std::printf("correct: rc = CQR_SUCCESS, inv = {0x1p+900, -0x0p+0, -0x0p+0, -0x0p+0}   [closed form]\n");
  // Case 3: the matrix of q = 2 (the identity rotation, scaled). Correct: I (closed form).
  CQRQuaternion d;
  d.w = 2.0, d.x = 0.0, d.y = 0.0, d.z = 0.0;
  double m[3][3];
  const int rc3 = CQRQuaternion2Matrix(m, &d);
  double e3 = 0;  // METRIC-4: max |M_ij - I_ij|
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) e3 = std::fmax(e3, std::fabs(m[r][c] - (r == c ? 1.0 : 0.0)));
  std::printf("call:    double m[3][3]; CQRQuaternion2Matrix(m, &q)\n");
  std::printf("input:   q {w, x, y, z} = {%a, %a, %a, %a}\n", d.w, d.x, d.y, d.z);
  std::printf("library: rc = %d, diag(m) = (%a, %a, %a)\n", rc3, m[0][0], m[1][1], m[2][2]);
  std::printf("correct: the identity matrix   [closed form]\n");
  std::printf("error:   max |m - I| = %g = %.3g eps\n", e3, e3 / 0x1p-52);
  if (!(err > 256 * 0x1p-52L || rc2 != CQR_SUCCESS || si.w != 0x1p900 || e3 > 256 * 0x1p-52)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
