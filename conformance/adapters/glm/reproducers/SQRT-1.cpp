// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause SQRT-1.
// SQRT-1: for finite nonzero q with q^ = q/|q| != -1, sqrt(q) is the unique s with s^2 = q^ and
// s.w > 0 (half the angle about the same axis); sqrt(-1) = (0, 0, 1, 0) (any unit pure quaternion
// is accepted). glm::sqrt(q) is glm::pow(q, 0.5), which
//  - takes the angle as asin(|v|/|q|) whenever |w|/|q| > cos(1/2), also for w < 0: for a turn
//    theta in (2 pi - 1, 2 pi) it uses pi - theta/2 instead of theta/2, and s^2 is not q
//    (e.g. 6 rad about +z: glm::sqrt squares to a 0.28 rad turn);
//  - returns (pow(w, 0.5), 0, 0, 0) when |v|^2 < epsilon: sqrt(-1) = (NaN, 0, 0, 0), and in
//    binary32 the axis of every rotation below 6.9e-4 rad is lost (the identity is returned).
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 SQRT-1.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 SQRT-1: glm::sqrt (= glm::pow(q, 0.5)) takes the wrong "
              "branch near a full turn and returns NaN for -1\n");
  // 1. A 6 rad turn about +z, as glm::angleAxis computes it: w = cos 3 < -cos(1/2).
  const glm::dquat q(-0x1.fae04be85e5d2p-1, 0.0, 0.0, 0x1.210386db6d55bp-3);  // (w, x, y, z)
  const glm::dquat s = glm::sqrt(q);
  const glm::dquat s2 = s * s;
  const double miss = std::sqrt((s2.w - q.w) * (s2.w - q.w) + (s2.z - q.z) * (s2.z - q.z) + s2.x * s2.x + s2.y * s2.y);
  std::printf("call:    glm::dquat s = glm::sqrt(q);\n");
  std::printf("input:   q (w, x, y, z) = (%a, 0, 0, %a)   [= glm::angleAxis(6.0, (0, 0, 1))]\n", q.w, q.z);
  std::printf("library: s = (%.17g, %.17g, %.17g, %.17g), s*s = (%.17g, %g, %g, %.17g)\n", s.w, s.x, s.y, s.z, s2.w,
              s2.x, s2.y, s2.z);
  std::printf("correct: s = (cos 1.5, 0, 0, sin 1.5) = (%.17g, 0, 0, %.17g): s*s = q\n", std::cos(1.5), std::sin(1.5));
  // 2. -1: pow(-1, 0.5) = NaN.
  const glm::dquat m = glm::sqrt(glm::dquat(-1.0, 0.0, 0.0, 0.0));
  std::printf("input:   q = -1 = (-1, 0, 0, 0)\n");
  std::printf("library: s = (%g, %g, %g, %g)\n", m.w, m.x, m.y, m.z);
  std::printf("correct: s = (0, 0, 0, 1), +z (or any unit pure quaternion)\n");
  const bool shown = miss > 0.1 && std::isnan(m.w);
  std::printf("%s\n", shown ? "defect shown: s*s is a 0.28 rad turn about +z, not q (6 rad); sqrt(-1) = NaN" : "defect NOT shown");
  return shown ? 0 : 1;
}
