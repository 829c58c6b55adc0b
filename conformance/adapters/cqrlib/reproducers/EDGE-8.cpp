// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause EDGE-8.
// EDGE-8: subnormal components are ordinary nonzero values: "normalize((2^-1074, -0, 0, 0)) =
// (1, -0, 0, 0)" (spec layout [x, y, z, w]), eps4. CPPQR<double>::UnitQ() squares the components,
// the sum underflows to 0 and it returns its zero sentinel DBL_MAX x 4. CQRHLERP treats an input
// with norm^2 <= DBL_MIN as zero and returns the other input scaled: the midpoint of a (subnormal)
// half turn about x and the identity comes out as the identity, pi/2 rad from the 90-degree turn.
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 EDGE-8.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
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
  std::printf("rotorcert reproducer: CQRlib 1.1.4 EDGE-8: UnitQ() of a subnormal quaternion returns DBL_MAX x 4; "
              "CQRHLERP ignores a subnormal input\n");
  const CPPQR<double> q(0.0, 0x1p-1074, -0.0, 0.0);  // (w, x, y, z): x = the smallest subnormal
  const CPPQR<double> n = q.UnitQ();
  const long double norm = std::sqrt((long double)n.GetW() * n.GetW() + (long double)n.GetX() * n.GetX() +
                                     (long double)n.GetY() * n.GetY() + (long double)n.GetZ() * n.GetZ());
  std::printf("call:    CPPQR<double>(w, x, y, z).UnitQ()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.GetW(), q.GetX(), q.GetY(), q.GetZ());
  std::printf("library: (%a, %a, %a, %a)\n", n.GetW(), n.GetX(), n.GetY(), n.GetZ());
  std::printf("correct: (0x0p+0, 0x1p+0, -0x0p+0, 0x0p+0)   [closed form, spec EDGE-8's own example]\n");
  std::printf("error:   norm defect | |n| - 1 | = %.3Lg (eps = 2^-52; EDGE-8 is eps4, loose bar 64 eps)\n",
              std::fabs(norm - 1));
  CQRQuaternion a, b, out;  // {w, x, y, z}
  a.w = 0.0, a.x = 0x1p-1074, a.y = 0.0, a.z = 0.0;  // (subnormal) half turn about x
  b.w = 1.0, b.x = 0.0, b.y = 0.0, b.z = 0.0;        // identity
  const int rc = CQRHLERP(&out, &a, &b, 0.5, 0.5);
  // Correct direction (closed form): halfway between 180 and 0 degrees about x: 90 degrees about x.
  const long double h = 3.141592653589793238462643383279502884L / 4;
  const long double ref[4] = {std::cos(h), std::sin(h), 0, 0};
  const long double lib[4] = {out.w, out.x, out.y, out.z};
  const long double err = rdist(lib, ref);
  std::printf("call:    CQRHLERP(&out, &q1, &q2, 0.5, 0.5)\n");
  std::printf("input:   q1 {w, x, y, z} = {%a, %a, %a, %a}, q2 = {%a, %a, %a, %a}\n", a.w, a.x, a.y, a.z, b.w, b.x,
              b.y, b.z);
  std::printf("library: rc = %d, {%a, %a, %a, %a}\n", rc, out.w, out.x, out.y, out.z);
  std::printf("correct: direction {%a, %a, 0, 0} (90 degrees about x)   [closed form]\n", (double)ref[0],
              (double)ref[1]);
  std::printf("error:   %.6Lg rad (METRIC-1) = %.3Lg eps\n", err, err / 0x1p-52L);
  if (!(std::fabs(norm - 1) > 64 * 0x1p-52L || err > 64 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
