// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-5.
// EDGE-5: a finite nonzero q is invertible at every scale the format holds (INV-1 at an extreme
// scale, eps16). QuaternionBase::inverse() is conjugate().coeffs() / squaredNorm() where
// squaredNorm() > 0, else zero "to flag the error" (Geometry/Quaternion.h:720-731), with no
// scaling: for q = (2^600, 0, 0, 0) the squared norm overflows to Inf and the inverse comes back
// as the ZERO quaternion, although 2^-600 is an ordinary double. Eigen documents no range for
// inverse() (:153 "the quaternion describing the inverse rotation"). (normalized() has the same
// overflow, but Dot.h documents its limit and offers stableNormalized(): not reproduced.)
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-5.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

int main() {
  const Eigen::Quaterniond q(0x1p600, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const Eigen::Quaterniond n = q.inverse();
  // Correct (closed form): q* / |q|^2 = (2^-600, -0, -0, -0); relative error against it.
  const long double err = std::fabs((long double)n.w() - 0x1p-600L) / 0x1p-600L;
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-5: Quaterniond::inverse() of (2^600, 0, 0, 0) returns the zero "
              "quaternion (|q|^2 overflows)\n");
  std::printf("call:    Eigen::Quaterniond(w, x, y, z).inverse()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w(), q.x(), q.y(), q.z());
  std::printf("library: (%a, %a, %a, %a)\n", n.w(), n.x(), n.y(), n.z());
  std::printf("correct: (0x1p-600, -0x0p+0, -0x0p+0, -0x0p+0)   [closed form]\n");
  std::printf("error:   relative error of w = %.3Lg (EDGE-5 is eps16, loose bar 256 eps = %.3Lg)\n", err, 256 * 0x1p-52L);
  if (!(err > 256 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
