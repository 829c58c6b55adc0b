// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-7.
// EDGE-7: NaN or +-Inf in any input component is DOMAIN_ERROR with every output component a quiet
// NaN, "even if the result would be mathematically defined (normalize((Inf, 0, 0, 1)) is
// DOMAIN_ERROR, not (1, 0, 0, 0))". Quaterniond::normalized() of (w, x, y, z) = (1, Inf, 0, 0)
// returns (0, NaN, 0, 0): three finite components; inverse() of (NaN, 0, 0, 1) returns the zero
// quaternion, the NaN is lost. (Rotation operations on a non-finite q are outside Eigen's documented
// precondition that the quaternion be normalized, and are not reproduced.)
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-7.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <limits>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

static bool all_nan(const Eigen::Quaterniond& q) {
  return std::isnan(q.w()) && std::isnan(q.x()) && std::isnan(q.y()) && std::isnan(q.z());
}

int main() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-7: Quaterniond::normalized() of (1, Inf, 0, 0) returns "
              "(0, NaN, 0, 0); inverse() of a NaN quaternion returns (0, 0, 0, 0)\n");
  const Eigen::Quaterniond q1(1.0, inf, 0.0, 0.0);  // (w, x, y, z)
  const Eigen::Quaterniond n = q1.normalized();
  std::printf("call:    Eigen::Quaterniond(w, x, y, z).normalized()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q1.w(), q1.x(), q1.y(), q1.z());
  std::printf("library: (%a, %a, %a, %a)\n", n.w(), n.x(), n.y(), n.z());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-7's own example)\n");
  const Eigen::Quaterniond q2(nan, 0.0, 0.0, 1.0);
  const Eigen::Quaterniond i = q2.inverse();
  std::printf("call:    Eigen::Quaterniond(w, x, y, z).inverse()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q2.w(), q2.x(), q2.y(), q2.z());
  std::printf("library: (%a, %a, %a, %a)\n", i.w(), i.x(), i.y(), i.z());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-7, outcome class)\n");
  std::printf("error:   non-NaN components in the output of a non-finite input\n");
  if (all_nan(n) && all_nan(i)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
