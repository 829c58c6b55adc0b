// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-5.
// EDGE-5: a finite nonzero q is the rotation q/|q| at every scale the format holds, and unit-valued
// outputs stay unit (eps16). glm::normalize squares without scaling, so q = (2^1023, 2^1023,
// 2^1023, 2^1023) gives |q| = Inf and the ZERO quaternion. More cases (GLM documents no unit
// precondition for these): q * v with a non-unit q is neither the rotation nor |q|^2 times it, and
// glm::angle of 2 * (unit q) is asin(1.2) = NaN.
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-5.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-5: glm::normalize of (2^1023, 2^1023, 2^1023, 2^1023) "
              "returns the zero quaternion; q * v and glm::angle of a non-unit q are wrong (glm::angle: NaN)\n");
  // Case 1: huge q. Correct (closed form): q/|q| = (0.5, 0.5, 0.5, 0.5).
  const glm::dquat q(0x1p1023, 0x1p1023, 0x1p1023, 0x1p1023);  // (w, x, y, z)
  const glm::dquat n = glm::normalize(q);
  const double norm = std::sqrt((long double)n.w * n.w + (long double)n.x * n.x + (long double)n.y * n.y +
                                (long double)n.z * n.z);
  std::printf("call:    glm::normalize(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  std::printf("library: (%a, %a, %a, %a)\n", n.w, n.x, n.y, n.z);
  std::printf("correct: (0x1p-1, 0x1p-1, 0x1p-1, 0x1p-1)   [closed form]\n");
  std::printf("error:   norm defect | |n| - 1 | = %g = %.3g eps (eps = 2^-52; EDGE-5 is eps16, loose bar 256 eps)\n",
              std::fabs(norm - 1), std::fabs(norm - 1) / 0x1p-52);
  // Case 2: q = 2 * (half turn about z) = (w, x, y, z) = (0, 0, 0, 2), v = (1, 0, 0).
  // Correct: q/|q| = (0, 0, 0, 1) turns (1, 0, 0) to (-1, 0, 0) (closed form).
  const glm::dquat q2(0.0, 0.0, 0.0, 2.0);
  const glm::dvec3 v(1.0, 0.0, 0.0);
  const glm::dvec3 r = q2 * v;
  const double e2 = std::sqrt((r.x + 1) * (r.x + 1) + r.y * r.y + r.z * r.z);  // METRIC-3, |v_ref| = 1
  std::printf("call:    glm::dquat q(w, x, y, z); glm::dvec3 r = q * v;\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a), v = (%a, %a, %a)\n", q2.w, q2.x, q2.y, q2.z, v.x, v.y, v.z);
  std::printf("library: (%a, %a, %a)\n", r.x, r.y, r.z);
  std::printf("correct: (-0x1p+0, 0x0p+0, 0x0p+0)   [closed form]\n");
  std::printf("error:   |r - r_ref| / |r_ref| = %g = %.3g eps\n", e2, e2 / 0x1p-52);
  // Case 3: q = 2 * (0.8, 0.6, 0, 0). Correct: theta = 2 atan2(|v|, w), here in long double (~1.287).
  const glm::dquat q3(1.6, 1.2, 0.0, 0.0);
  const double a3 = glm::angle(q3);
  const double ref3 = (double)(2 * std::atan2((long double)q3.x, (long double)q3.w));
  std::printf("call:    glm::angle(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q3.w, q3.x, q3.y, q3.z);
  std::printf("library: %a\n", a3);
  std::printf("correct: %a (= 2 atan2(x, w), about 1.287)\n", ref3);
  if (!(std::fabs(norm - 1) > 256 * 0x1p-52 || e2 > 256 * 0x1p-52 || !(std::fabs(a3 - ref3) <= 256 * 0x1p-52))) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
