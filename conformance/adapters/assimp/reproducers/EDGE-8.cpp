// rotorcert reproducer, Assimp 5.2.5 (Debian libassimp-dev 5.2.5~ds0-1+b1), clause EDGE-8.
// EDGE-8 (spec/SPEC.md 9, eps4): subnormal components are ordinary nonzero values, e.g.
// normalize((2^-1074, -0, 0, 0)) = (1, -0, 0, 0). Normalize (quaternion.inl:266) squares without
// scaling: x^2 + y^2 + z^2 + w^2 underflows to 0, "if (mag)" is false, and the quaternion comes back
// unchanged, not unit. Interpolate (quaternion.inl:225) of subnormal keys: the dot underflows to 0,
// acos(0) = pi/2, and the result is a subnormal combination of the keys, not a unit quaternion
// (the suite's worst input, below); Rotate and GetMatrix of subnormal q return 0 and the identity.
// Upstream: no issue found in the assimp tracker.
// Build: g++ -std=c++20 -O1 EDGE-8.cpp   (header-only)   Exit: 0 defect shown, 1 not shown.
#include <assimp/types.h>

#include <cmath>
#include <cstdio>

int main() {
  std::printf("rotorcert reproducer: Assimp 5.2.5 EDGE-8: Normalize and Interpolate of subnormal quaternions "
              "return subnormal quaternions, not unit ones\n");
  // 1. Example EX-EDGE-8-a: [x, y, z, w] = [2^-1074, -0, 0, 0].
  aiQuaterniont<double> q(0.0, 0x0.0000000000001p-1022, -0.0, 0.0);  // (w, x, y, z)
  std::printf("call:    aiQuaterniont<double>(w, x, y, z).Normalize()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  q.Normalize();
  std::printf("library: (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  std::printf("correct: (0x0p+0, 0x1p+0, -0x0p+0, 0x0p+0)   [closed form]\n");

  // 2. The suite's worst input (worst-case search from subnormal and -0 components).
  const aiQuaterniont<double> a(0x0.000000000001p-1022, -0.0, 0x0.000000000003p-1022, 0x0.0000000000008p-1022);
  const aiQuaterniont<double> b(0x0.0000000000ap-1022, -0.0, 0x0.0000000000001p-1022, 0x0.00000000018p-1022);
  const double t = 0x1.8a80638284748p-4;
  aiQuaterniont<double> out;
  aiQuaterniont<double>::Interpolate(out, a, b, t);
  std::printf("call:    aiQuaterniont<double>::Interpolate(out, a, b, t)\n");
  std::printf("input:   a (w, x, y, z) = (%a, %a, %a, %a)\n         b (w, x, y, z) = (%a, %a, %a, %a), t = %a\n", a.w,
              a.x, a.y, a.z, b.w, b.x, b.y, b.z, t);
  std::printf("library: (%a, %a, %a, %a)\n", out.w, out.x, out.y, out.z);
  std::printf("correct: (w, x, y, z) ~ (0.349094240233, -0, 0.897526704476, 0.269404948338)   [rotorcert's 256-bit "
              "reference, rounded: a unit quaternion]\n");
  const double n1 = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  const double n2 = std::sqrt(out.w * out.w + out.x * out.x + out.y * out.y + out.z * out.z);
  std::printf("error:   |Normalize(q)| = %g, |Interpolate| = %g: norm defects ~1, i.e. ~4.5e15 eps (loose bar 64 eps)\n",
              n1, n2);
  if (std::fabs(n1 - 1) <= 64 * 0x1p-52 && std::fabs(n2 - 1) <= 256 * 0x1p-52) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
