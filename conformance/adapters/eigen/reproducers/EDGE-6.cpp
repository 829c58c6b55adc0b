// rotorcert reproducer, Eigen 3.4.0 (Debian libeigen3-dev), clause EDGE-6.
// EDGE-6: a zero quaternion is DOMAIN_ERROR: every output component a quiet NaN (Eigen has no
// error channel, so NaN is the only way to say it). Quaternion::normalized() returns the zero
// quaternion unchanged (documented, Dot.h: "returns a copy of the input" when norm() == 0) and
// inverse() returns the zero quaternion ("an invalid result to flag the error", a comment in
// Quaternion.h's code, not in its documentation): both look like numbers, not like an error.
// Upstream: no issue found.
// Build: g++ -std=c++20 -O1 -I/usr/include/eigen3 EDGE-6.cpp   Exit: 0 defect shown, 1 not shown.
#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "written against Eigen 3.4");

static bool all_nan(const Eigen::Quaterniond& q) {
  return std::isnan(q.w()) && std::isnan(q.x()) && std::isnan(q.y()) && std::isnan(q.z());
}

int main() {
  const Eigen::Quaterniond z(0.0, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const Eigen::Quaterniond n = z.normalized();
  const Eigen::Quaterniond i = z.inverse();
  std::printf("rotorcert reproducer: Eigen 3.4.0 EDGE-6: Quaterniond::normalized() and inverse() of the zero "
              "quaternion return the zero quaternion, no NaN\n");
  std::printf("call:    Eigen::Quaterniond q(w, x, y, z); q.normalized(); q.inverse();\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", z.w(), z.x(), z.y(), z.z());
  std::printf("library: normalized = (%a, %a, %a, %a), inverse = (%a, %a, %a, %a)\n", n.w(), n.x(), n.y(), n.z(),
              i.w(), i.x(), i.y(), i.z());
  std::printf("correct: DOMAIN_ERROR: every component a quiet NaN (spec EDGE-6, outcome class)\n");
  std::printf("error:   finite components for a zero input\n");
  if (all_nan(n) && all_nan(i)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
