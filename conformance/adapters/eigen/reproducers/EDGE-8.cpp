// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-8.
// EDGE-8: subnormal components are ordinary nonzero values; AXANG-4's axis of a unit quaternion
// is the unit vector v/|v| (eps16). AngleAxisd(q) of the unit quaternion (w, x, y, z) =
// (-1, 2^-1073, -0, 2^-1074), a rotation a few ulp short of a full turn, returns an axis that is
// not unit: the norm of the subnormal vector part comes out as its largest component.
// (normalized() of a subnormal quaternion, which Dot.h documents to return a copy of its input
// where norm() == 0, is not reproduced.)
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-8.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

int main() {
  const Eigen::Quaterniond q(-1.0, 0x1p-1073, -0.0, 0x1p-1074);  // (w, x, y, z), |q| = 1 in double
  const Eigen::AngleAxisd aa(q);
  const Eigen::Vector3d u = aa.axis();
  const long double len = std::sqrt((long double)u.x() * u.x() + (long double)u.y() * u.y() + (long double)u.z() * u.z());
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-8: AngleAxisd(q).axis() of a unit quaternion with a subnormal "
              "vector part is not unit\n");
  std::printf("call:    Eigen::AngleAxisd(Eigen::Quaterniond(w, x, y, z)).axis()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w(), q.x(), q.y(), q.z());
  std::printf("library: axis = (%a, %a, %a), angle = %a\n", u.x(), u.y(), u.z(), aa.angle());
  std::printf("correct: axis = +-(2, 0, 1)/sqrt(5) = +-(0x1.c9f25c5bfedd9p-1, 0, 0x1.c9f25c5bfedd9p-2), unit   [closed form]\n");
  std::printf("error:   axis norm defect | |u| - 1 | = %.3Lg = %.3Lg eps (eps = 2^-52; EDGE-8 on to_axis is eps16, loose "
              "bar 256 eps)\n",
              std::fabs(len - 1), std::fabs(len - 1) / 0x1p-52L);
  if (!(std::fabs(len - 1) > 256 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
