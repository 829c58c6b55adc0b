// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-5 (NORM-1's extreme inputs, judged at Robust by LEVEL-1).
// EDGE-5 (NORM-1 at an extreme scale): normalize is q/|q| "without intermediate overflow or underflow for every finite nonzero
// input of the format"; output unit; eps4. Quaternion::normalized() is coeffs().normalized(),
// which divides by sqrt(squaredNorm()) with no scaling: for a tiny q the squared norm underflows to
// 0 and the input comes back unchanged, not unit. (Eigen documents the norm() == 0 case, Dot.h:
// "If the input vector is too small (i.e., this->norm()==0), then this function returns a copy of
// the input", and offers stableNormalized(); the quaternion class has no stable variant.)
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-5-normalize.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

int main() {
  // q = 2^-999 * (w, x, y, z) = 2^-999 * (2, 1.5, 0, 0): |q| = 2.5 * 2^-999, all components normal numbers.
  const Eigen::Quaterniond q(0x1p-998, 0x1.8p-999, 0.0, 0.0);  // (w, x, y, z)
  const Eigen::Quaterniond n = q.normalized();
  // Correct (closed form, 3-4-5): (0.8, 0.6, 0, 0). The output is unit-valued: its norm defect
  // (METRIC-6) and its distance from the reference are both judged.
  const long double norm = std::sqrt((long double)n.w() * n.w() + (long double)n.x() * n.x() +
                                     (long double)n.y() * n.y() + (long double)n.z() * n.z());
  const long double err = std::max(std::fabs(norm - 1), std::fabs(n.w() - 0.8L) + std::fabs(n.x() - 0.6L));
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-5 (NORM-1 at an extreme scale): Quaterniond::normalized() of a tiny quaternion returns "
              "it unchanged (|q|^2 underflows to 0), not unit\n");
  std::printf("call:    Eigen::Quaterniond(w, x, y, z).normalized()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w(), q.x(), q.y(), q.z());
  std::printf("library: (%a, %a, %a, %a)\n", n.w(), n.x(), n.y(), n.z());
  std::printf("correct: (%a, %a, 0x0p+0, 0x0p+0)   [= (0.8, 0.6, 0, 0), closed form]\n", 0.8, 0.6);
  std::printf("error:   norm defect | |n| - 1 | = %.3Lg = %.3Lg eps (eps = 2^-52; NORM-1 is eps4, loose bar 64 eps)\n",
              std::fabs(norm - 1), std::fabs(norm - 1) / 0x1p-52L);
  if (!(err > 64 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
