// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause AXANG-1.
// AXANG-1: the angle-axis of q is theta = 2 atan2(|v|, w) in [0, 2 pi] with u = v/|v|; any pair
// (theta, u) of the SAME rotation is accepted. glm::angle returns 2 asin|v| whenever |w| > cos(1/2),
// also for w < 0, so for a turn theta in (2 pi - 1, 2 pi) it returns 2 pi - theta while glm::axis
// returns +u: together they name the inverse rotation.
// Known upstream: https://github.com/g-truc/glm/pull/1038 (fix merged after 0.9.9.8; also reported
// as https://github.com/Zuzu-Typ/PyGLM/issues/90).
// Build: g++ -std=c++20 -O1 AXANG-1.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

// METRIC-1: 4 atan2(min(|a-b|, |a+b|), max(|a-b|, |a+b|)) of the normalised quaternions.
static long double rdist(const long double* a, const long double* b) {
  long double na = 0, nb = 0, dm = 0, dp = 0;
  for (int i = 0; i < 4; ++i) na += a[i] * a[i], nb += b[i] * b[i];
  for (int i = 0; i < 4; ++i) {
    const long double x = a[i] / std::sqrt(na), y = b[i] / std::sqrt(nb);
    dm += (x - y) * (x - y), dp += (x + y) * (x + y);
  }
  dm = std::sqrt(dm), dp = std::sqrt(dp);
  return 4 * std::atan2(std::min(dm, dp), std::max(dm, dp));
}

int main() {
  // q = glm::angleAxis(6.0, glm::dvec3(0, 0, 1)) as GLM computes it: a 6 rad turn about +z, w = cos 3 < 0.
  const glm::dquat q(-0x1.fae04be85e5d2p-1, 0.0, 0.0, 0x1.210386db6d55bp-3);  // (w, x, y, z)
  const double angle = glm::angle(q);
  const glm::dvec3 axis = glm::axis(q);

  // Correct value from q alone, in long double: theta = 2 atan2(|v|, w), u = v/|v| = (0, 0, 1).
  const long double vn = std::sqrt((long double)q.x * q.x + (long double)q.y * q.y + (long double)q.z * q.z);
  const long double theta = 2 * std::atan2(vn, (long double)q.w);
  // The two answers as rotations (w, x, y, z), compared by METRIC-1.
  const long double h = (long double)angle / 2;
  const long double lib[4] = {std::cos(h), std::sin(h) * axis.x, std::sin(h) * axis.y, std::sin(h) * axis.z};
  const long double ref[4] = {q.w, q.x, q.y, q.z};
  const long double err = rdist(lib, ref);

  std::printf("rotorcert reproducer: GLM 0.9.9.8 AXANG-1: glm::angle returns 2*pi - theta for a turn "
              "theta in (2*pi - 1, 2*pi) while glm::axis keeps +u: the inverse rotation\n");
  std::printf("call:    glm::dquat q(w, x, y, z); double a = glm::angle(q); glm::dvec3 u = glm::axis(q);\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)   [= glm::angleAxis(6.0, (0, 0, 1))]\n", q.w, q.x, q.y, q.z);
  std::printf("library: angle = %a (%.17g), axis = (%a, %a, %a)\n", angle, angle, axis.x, axis.y, axis.z);
  std::printf("correct: angle = %a (%.17g), axis = (0, 0, 1)   [or %.17g about (0, 0, -1)]\n", (double)theta,
              (double)theta, (double)(2 * 3.141592653589793238462643383279502884L - theta));
  std::printf("error:   %.3Lg rad between the two rotations = %.3Lg eps "
              "(eps = 2^-52; AXANG-1 is eps16, loose bar 256 eps)\n",
              err, err / 0x1p-52L);
  if (!(err > 256 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
