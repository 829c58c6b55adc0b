// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-7.
// EDGE-7: NaN or +-Inf in any input component is DOMAIN_ERROR with every output component a quiet
// NaN, "even if the result would be mathematically defined (normalize((Inf, 0, 0, 1)) is
// DOMAIN_ERROR, not (1, 0, 0, 0))". glm::log of (w, x, y, z) = (NaN, 0, 0, 0) returns (Inf, Inf,
// Inf, Inf): the NaN is lost (its |v| < epsilon branch tests w > 0, w < 0, else returns Inf).
// glm::normalize of (w, x, y, z) = (1, Inf, 0, 0) returns (0, NaN, 0, 0): three finite components.
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-7.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

static bool all_nan(const glm::dquat& q) {
  return std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
}

int main() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-7: glm::log of a NaN quaternion returns (Inf, Inf, Inf, "
              "Inf), no NaN; glm::normalize of (1, Inf, 0, 0) returns three finite components\n");
  const glm::dquat q1(nan, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const glm::dquat l = glm::log(q1);
  std::printf("call:    glm::log(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q1.w, q1.x, q1.y, q1.z);
  std::printf("library: (%a, %a, %a, %a)\n", l.w, l.x, l.y, l.z);
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-7, outcome class)\n");
  const glm::dquat q2(1.0, inf, 0.0, 0.0);
  const glm::dquat n = glm::normalize(q2);
  std::printf("call:    glm::normalize(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q2.w, q2.x, q2.y, q2.z);
  std::printf("library: (%a, %a, %a, %a)\n", n.w, n.x, n.y, n.z);
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-7's own example)\n");
  std::printf("error:   non-NaN components in the output of a non-finite input\n");
  if (all_nan(l) && all_nan(n)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
