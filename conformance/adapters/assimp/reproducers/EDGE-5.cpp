// rotorcert reproducer, Assimp 5.2.5 (Debian libassimp-dev 5.2.5~ds0-1+b1), clause EDGE-5.
// EDGE-5 (spec/SPEC.md 9, eps16): a finite nonzero q is the rotation q/|q| at every scale the format
// holds, and unit-valued outputs stay unit. quaternion.h documents no unit-length requirement, but
// aiQuaterniont::Rotate (quaternion.inl:300) is q (0, v) Conjugate(q) with no division by |q|^2,
// GetMatrix (quaternion.inl:170) is the unit-quaternion formula, Normalize (quaternion.inl:266) and
// Interpolate (quaternion.inl:225) square the components without scaling:
//   1. Rotate of q = 2 (quarter turn about z) turns x into 4 y, not y;
//   2. Rotate of q = (w, x, y, z) = (2^1000, 0, 0, 2^1000) (the suite's worst input, a quarter turn
//      about z) overflows: (NaN, Inf, 0) instead of (0, 1, 0);
//   3. Normalize of (2^1023, 2^1023, 2^1023, 2^1023): the sum of squares overflows, 1/Inf = 0, and the
//      result is the zero quaternion instead of (1/2, 1/2, 1/2, 1/2).
// The float aiQuaternion (ai_real = float in Debian's build) fails the same way from scale 2^64.
// Upstream: no issue found in the assimp tracker.
// Build: g++ -std=c++20 -O1 EDGE-5.cpp   (header-only)   Exit: 0 defect shown, 1 not shown.
#include <assimp/types.h>

#include <cmath>
#include <cstdio>

int main() {
  std::printf("rotorcert reproducer: Assimp 5.2.5 EDGE-5: aiQuaterniont::Rotate scales by |q|^2 and overflows, "
              "Normalize overflows: non-unit quaternions are not the rotation q/|q|\n");
  const double h = std::sqrt(0.5);
  bool shown = false;

  // 1. A moderate scale: 2 (cos 45, 0, 0, sin 45), the quarter turn about z scaled by 2.
  const aiQuaterniont<double> q1(2 * h, 0.0, 0.0, 2 * h);  // (w, x, y, z)
  const aiVector3t<double> r1 = q1.Rotate(aiVector3t<double>(1.0, 0.0, 0.0));
  std::printf("call:    aiQuaterniont<double>(w, x, y, z).Rotate(aiVector3t<double>(1, 0, 0))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)   (2 x the quarter turn about z)\n", q1.w, q1.x, q1.y, q1.z);
  std::printf("library: (%a, %a, %a)\n", r1.x, r1.y, r1.z);
  std::printf("correct: (0x0p+0, 0x1p+0, 0x0p+0)   [closed form: the rotation of q/|q| maps x to y]\n");
  const double e1 = std::hypot(r1.x, r1.y - 1.0, r1.z);
  std::printf("error:   |out - (0, 1, 0)| = %g = %.3g eps (METRIC-3, eps = 2^-52; loose bar 256 eps)\n", e1, e1 / 0x1p-52);
  shown = shown || !(e1 / 0x1p-52 <= 256);

  // 2. The suite's worst input: q = [x, y, z, w] = [0, 0, 2^1000, 2^1000], v = (1, 0, 0).
  const aiQuaterniont<double> q2(0x1p+1000, 0.0, 0.0, 0x1p+1000);
  const aiVector3t<double> r2 = q2.Rotate(aiVector3t<double>(1.0, 0.0, 0.0));
  std::printf("call:    aiQuaterniont<double>(w, x, y, z).Rotate(aiVector3t<double>(1, 0, 0))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q2.w, q2.x, q2.y, q2.z);
  std::printf("library: (%a, %a, %a)\n", r2.x, r2.y, r2.z);
  std::printf("correct: (0x0p+0, 0x1p+0, 0x0p+0)   [closed form]\n");
  shown = shown || !(std::isfinite(r2.x) && std::isfinite(r2.y) && std::fabs(r2.y - 1.0) <= 256 * 0x1p-52);

  // 3. Normalize at the overflow threshold.
  aiQuaterniont<double> q3(0x1p+1023, 0x1p+1023, 0x1p+1023, 0x1p+1023);
  std::printf("call:    aiQuaterniont<double>(w, x, y, z).Normalize()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q3.w, q3.x, q3.y, q3.z);
  q3.Normalize();
  std::printf("library: (%a, %a, %a, %a)\n", q3.w, q3.x, q3.y, q3.z);
  std::printf("correct: (0x1p-1, 0x1p-1, 0x1p-1, 0x1p-1)   [closed form]\n");
  const double n3 = std::sqrt(q3.w * q3.w + q3.x * q3.x + q3.y * q3.y + q3.z * q3.z);
  std::printf("error:   norm defect | |out| - 1 | = %g (METRIC-6)\n", std::fabs(n3 - 1));
  shown = shown || !(std::fabs(n3 - 1) <= 256 * 0x1p-52);

  if (!shown) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
