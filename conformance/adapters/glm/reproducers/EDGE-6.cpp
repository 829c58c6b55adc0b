// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-6.
// EDGE-6: a zero quaternion (and a dual quaternion with a zero real part) is DOMAIN_ERROR: every
// output component a quiet NaN (GLM has no error channel, so NaN is the only way to say it).
// glm::normalize(0) returns the identity, a valid rotation nobody asked for; glm::log(0) returns
// (Inf, Inf, Inf, Inf); glm::dualquat(0, t) returns the zero dual quaternion (the DQ-1 entry).
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-6.cpp   Exit: 0 defect shown, 1 not shown.
#define GLM_ENABLE_EXPERIMENTAL  // gtx/dual_quaternion.hpp requires it
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>
#include <glm/gtx/dual_quaternion.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

static bool all_nan(const glm::dquat& q) {
  return std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
}

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-6: glm::normalize of the zero quaternion returns the "
              "identity rotation instead of NaN\n");
  const glm::dquat z(0.0, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const glm::dquat n = glm::normalize(z);
  const glm::dquat l = glm::log(z);
  const glm::tdualquat<double> d(z, glm::dvec3(1.0, 2.0, 3.0));
  std::printf("call:    glm::normalize(q); glm::log(q); glm::dualquat(q, glm::dvec3(1, 2, 3))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", z.w, z.x, z.y, z.z);
  std::printf("library: normalize = (%a, %a, %a, %a)\n", n.w, n.x, n.y, n.z);
  std::printf("         log       = (%a, %a, %a, %a)\n", l.w, l.x, l.y, l.z);
  std::printf("         dualquat  = real (%a, %a, %a, %a), dual (%a, %a, %a, %a)\n", d.real.w, d.real.x, d.real.y,
              d.real.z, d.dual.w, d.dual.x, d.dual.y, d.dual.z);
  std::printf("correct: DOMAIN_ERROR: every component a quiet NaN (spec EDGE-6, outcome class)\n");
  std::printf("error:   normalize answers a valid unit quaternion (the identity) for a zero input\n");
  if (all_nan(n)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
