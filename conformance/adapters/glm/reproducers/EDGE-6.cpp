// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-6.
// EDGE-6: a zero quaternion has no rotation: DOMAIN_ERROR (every output NaN, or with no status
// channel every output non-finite), or one of ACC-1's sentinels (all zero, or exactly the
// identity's answer: angle 0). glm::angle and glm::axis of the zero quaternion answer angle pi
// about the axis (0, 0, 0): a finite, non-identity answer that no check can tell from a rotation
// angle, with a zero "unit" axis. (normalize(0) = identity and log(0) = Inf are acceptable since
// spec 2.2.0: the identity sentinel and an in-band error.)
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-6.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-6: glm::angle/glm::axis of the zero quaternion return "
              "angle pi about the zero axis, with no error\n");
  const glm::dquat z(0.0, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const double angle = glm::angle(z);
  const glm::dvec3 axis = glm::axis(z);
  std::printf("call:    glm::angle(q); glm::axis(q)\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", z.w, z.x, z.y, z.z);
  std::printf("library: angle = %a, axis = (%a, %a, %a)\n", angle, axis.x, axis.y, axis.z);
  std::printf("correct: DOMAIN_ERROR (NaN or non-finite outputs), or the identity's answer angle 0 with a unit axis "
              "(spec EDGE-6, ACC-1 zero_sentinel)\n");
  const bool finite = std::isfinite(angle) && std::isfinite(axis.x) && std::isfinite(axis.y) && std::isfinite(axis.z);
  const bool identity = angle == 0 && std::fabs(glm::length(axis) - 1) < 1e-12;
  const bool zero = angle == 0 && axis == glm::dvec3(0);
  if (!finite || identity || zero) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   a finite answer that is neither an error nor a sentinel: angle %g rad, |axis| = %g\n", angle,
              glm::length(axis));
  return 0;
}
