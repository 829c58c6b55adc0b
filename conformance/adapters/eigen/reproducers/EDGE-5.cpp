// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-5.
// EDGE-5: a finite nonzero q is the rotation q/|q| at every scale the format holds, and unit-valued
// outputs stay unit (eps16). Quaternion::normalized() divides by sqrt(squaredNorm()) with no
// scaling: for q = (2^1023, 2^1023, 2^1023, 2^1023) the squared norm overflows to Inf and the
// result is the ZERO quaternion. Second case: AngleAxisd(q), documented to "implicitly normalize the
// quaternion q" (AngleAxis.h), returns angle pi with the ZERO axis for the same q (|v| overflows).
// (Non-unit q in _transformVector / toRotationMatrix / slerp is outside Eigen's documented
// precondition "Operations interpreting the quaternion as rotation have undefined behavior if the
// quaternion is not normalized" (Quaternion.h) and is not reproduced.)
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-5.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

int main() {
  const Eigen::Quaterniond q(0x1p1023, 0x1p1023, 0x1p1023, 0x1p1023);  // (w, x, y, z)
  const Eigen::Quaterniond n = q.normalized();
  const long double norm = std::sqrt((long double)n.w() * n.w() + (long double)n.x() * n.x() +
                                     (long double)n.y() * n.y() + (long double)n.z() * n.z());
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-5: Quaterniond::normalized() of (2^1023, 2^1023, 2^1023, "
              "2^1023) returns the zero quaternion (|q|^2 overflows); AngleAxisd of it has a zero axis\n");
  std::printf("call:    Eigen::Quaterniond(w, x, y, z).normalized()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w(), q.x(), q.y(), q.z());
  std::printf("library: (%a, %a, %a, %a)\n", n.w(), n.x(), n.y(), n.z());
  std::printf("correct: (0x1p-1, 0x1p-1, 0x1p-1, 0x1p-1)   [closed form]\n");
  std::printf("error:   norm defect | |n| - 1 | = %.3Lg = %.3Lg eps "
              "(eps = 2^-52; EDGE-5 is eps16, loose bar 256 eps)\n",
              std::fabs(norm - 1), std::fabs(norm - 1) / 0x1p-52L);
  // Case 2: the angle-axis of the same q. Correct (closed form): 2 pi / 3 about (1, 1, 1)/sqrt(3).
  const Eigen::AngleAxisd aa(q);
  const long double alen = std::sqrt((long double)aa.axis().squaredNorm());
  std::printf("call:    Eigen::AngleAxisd aa(Eigen::Quaterniond(w, x, y, z)); aa.angle(); aa.axis();\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w(), q.x(), q.y(), q.z());
  std::printf("library: angle = %a, axis = (%a, %a, %a)\n", aa.angle(), aa.axis().x(), aa.axis().y(), aa.axis().z());
  std::printf("correct: angle = %a (2 pi / 3), axis = (%a, %a, %a) = (1, 1, 1)/sqrt(3)   [closed form]\n",
              (double)(2 * 3.141592653589793238462643383279502884L / 3), (double)(1 / std::sqrt(3.0L)),
              (double)(1 / std::sqrt(3.0L)), (double)(1 / std::sqrt(3.0L)));
  std::printf("error:   axis norm defect | |u| - 1 | = %.3Lg = %.3Lg eps (a zero axis is no rotation)\n",
              std::fabs(alen - 1), std::fabs(alen - 1) / 0x1p-52L);
  if (!(std::fabs(norm - 1) > 256 * 0x1p-52L || std::fabs(alen - 1) > 256 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
