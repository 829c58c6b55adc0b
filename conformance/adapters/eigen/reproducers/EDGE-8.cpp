// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-8.
// EDGE-8: subnormal components are ordinary nonzero values: "normalize((2^-1074, -0, 0, 0)) =
// (1, -0, 0, 0)" (spec layout [x, y, z, w]), eps4. Quaterniond::normalized() squares the
// components, the squared norm underflows to 0 and the subnormal input comes back unchanged, not
// unit (documented, Dot.h: "returns a copy of the input" when norm() == 0; the quaternion class
// has no stableNormalized()).
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-8.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

int main() {
  const Eigen::Quaterniond q(0.0, 0x1p-1074, -0.0, 0.0);  // (w, x, y, z): x = the smallest subnormal
  const Eigen::Quaterniond n = q.normalized();
  const long double norm = std::sqrt((long double)n.w() * n.w() + (long double)n.x() * n.x() +
                                     (long double)n.y() * n.y() + (long double)n.z() * n.z());
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-8: Quaterniond::normalized() of a subnormal quaternion "
              "returns it unchanged, not unit\n");
  std::printf("call:    Eigen::Quaterniond(w, x, y, z).normalized()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w(), q.x(), q.y(), q.z());
  std::printf("library: (%a, %a, %a, %a)\n", n.w(), n.x(), n.y(), n.z());
  std::printf("correct: (0x0p+0, 0x1p+0, -0x0p+0, 0x0p+0)   [closed form, spec EDGE-8's own example]\n");
  std::printf("error:   norm defect | |n| - 1 | = %.3Lg = %.3Lg eps (eps = 2^-52; EDGE-8 is eps4, loose bar 64 eps)\n",
              std::fabs(norm - 1), std::fabs(norm - 1) / 0x1p-52L);
  if (!(std::fabs(norm - 1) > 64 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
