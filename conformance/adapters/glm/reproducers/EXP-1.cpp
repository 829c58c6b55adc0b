// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EXP-1 (binary32).
// EXP-1: exp(v) = (cos|v|, sin|v| v/|v|) for every finite v, unit output; "near 0, sin|v|/|v| MUST
// be evaluated without 0/0". glm::exp(q) returns qua<T, Q>() whenever |v| < epsilon<T>(); in the
// default configuration that is the zero quaternion (see EDGE-1.cpp). In binary32 epsilon is
// 2^-23, so every rotation below 2.4e-7 rad (|v| is half the angle) comes out as (0, 0, 0, 0): an
// ordinary small rotation, found by the spec's logarithmic angle sweep (LEVEL-1), not an edge case.
// Build: g++ -std=c++20 -O1 EXP-1.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EXP-1: glm::exp (float) of a rotation vector shorter than "
              "2^-23 returns the zero quaternion\n");
  std::printf("call:    glm::exp(glm::quat(0, x, y, z))\n");
  // The vector of the certificate's worst input (the angle sweep, seed 1), exact binary32 values.
  const float x = -0x1.666c1p-33f, y = -0x1.05354p-31f, z = -0x1.7ad562p-34f;
  const glm::quat e = glm::exp(glm::quat(0.0f, x, y, z));
  std::printf("input:   v = (%a, %a, %a)\n", (double)x, (double)y, (double)z);
  std::printf("library: (w, x, y, z) = (%a, %a, %a, %a)\n", (double)e.w, (double)e.x, (double)e.y, (double)e.z);
  // Reference in long double: |v| ~ 5e-10, so cos|v| = 1 and sin|v|/|v| = 1 to far below 2^-24.
  const long double n = std::sqrt((long double)x * x + (long double)y * y + (long double)z * z);
  const long double s = std::sin(n) / n;
  std::printf("correct: (w, x, y, z) = (%.9Lg, %.9Lg, %.9Lg, %.9Lg)   [cos|v|, sin|v| v/|v| in long double]\n",
              std::cos(n), s * x, s * y, s * z);
  const long double d = std::fabs(std::sqrt((long double)e.w * e.w + (long double)e.x * e.x + (long double)e.y * e.y +
                                            (long double)e.z * e.z) - 1.0L);
  std::printf("error:   norm defect | |q| - 1 | = %Lg = %.3Lg eps (eps = 2^-23; EXP-1 loose bar 256 eps)\n", d,
              d / 0x1p-23L);
  if (d <= 256 * 0x1p-23L) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
