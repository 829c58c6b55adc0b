// rotorcert reproducer, Assimp 5.2.5 (Debian libassimp-dev 5.2.5~ds0-1+b1), clause EDGE-6.
// EDGE-6 (spec/SPEC.md 9, outcome class): a zero quaternion and a zero rotation axis have no rotation:
// DOMAIN_ERROR (every output NaN), or under ACC-1 zero_sentinel an all-zero output or exactly the
// identity's output (Assimp's Normalize, Rotate, GetMatrix and operator* of 0 do that and are not
// held against it). Two calls return something else, with nothing documented:
//   1. Interpolate (quaternion.inl:222) with a zero start key: cos = 0, acos gives pi/2, and the
//      result is sin(t pi/2) * end, e.g. t = 1/2 gives (0.5, 0, 0, 0.5), a non-unit "rotation";
//   2. the axis-angle constructor (quaternion.inl:189) with a zero axis: axis.Normalize() leaves it
//      zero (vector3.inl:100), and the result is (cos(angle/2), 0, 0, 0), not unit unless angle = 0.
// Upstream: no issue found in the assimp tracker.
// Build: g++ -std=c++20 -O1 EDGE-6.cpp   (header-only)   Exit: 0 defect shown, 1 not shown.
#include <assimp/types.h>

#include <cmath>
#include <cstdio>

template <class Q>
static bool acceptable(const Q& q) {  // DOMAIN_ERROR (all NaN), all zero, or exactly the identity
  const bool nan = std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
  const bool zero = q.w == 0 && q.x == 0 && q.y == 0 && q.z == 0;
  const bool identity = q.w == 1 && q.x == 0 && q.y == 0 && q.z == 0;
  return nan || zero || identity;
}

int main() {
  std::printf("rotorcert reproducer: Assimp 5.2.5 EDGE-6: Interpolate from a zero quaternion and the axis-angle "
              "constructor with a zero axis return non-unit quaternions\n");
  // 1. The suite's worst input (example EX-EDGE-6-g): a = 0, b = [x, y, z, w] = [0, 0, sqrt(1/2), sqrt(1/2)], t = 1/2.
  const aiQuaterniont<double> a(0.0, 0.0, 0.0, 0.0), b(0x1.6a09e667f3bcdp-1, 0.0, 0.0, 0x1.6a09e667f3bcdp-1);
  aiQuaterniont<double> out;
  aiQuaterniont<double>::Interpolate(out, a, b, 0.5);
  std::printf("call:    aiQuaterniont<double>::Interpolate(out, a, b, 0.5)\n");
  std::printf("input:   a (w, x, y, z) = (%a, %a, %a, %a), b = (%a, %a, %a, %a)\n", a.w, a.x, a.y, a.z, b.w, b.x, b.y,
              b.z);
  std::printf("library: (%a, %a, %a, %a)\n", out.w, out.x, out.y, out.z);
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-6), or all zero / the identity (ACC-1 zero_sentinel)\n");

  // 2. A zero axis, angle pi/2 (example EX-AXANG-2-g).
  const aiQuaterniont<double> c(aiVector3t<double>(0.0, 0.0, 0.0), 0x1.921fb54442d18p+0);
  std::printf("call:    aiQuaterniont<double>(aiVector3t<double>(0, 0, 0), angle)\n");
  std::printf("input:   axis (0, 0, 0), angle = %a (pi/2)\n", 0x1.921fb54442d18p+0);
  std::printf("library: (w, x, y, z) = (%a, %a, %a, %a), |q| = %g\n", c.w, c.x, c.y, c.z,
              std::sqrt(c.w * c.w + c.x * c.x + c.y * c.y + c.z * c.z));
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-6, AXANG-2: a zero axis has no direction)\n");
  std::printf("error:   finite, non-unit outputs for inputs without a rotation\n");

  if (acceptable(out) && acceptable(c)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
