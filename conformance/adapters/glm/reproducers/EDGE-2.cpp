// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-2.
// EDGE-2: rotations by angles from 1e-9 to 1e-3 rad must come out within the operation's class
// (AXANG-1: eps16), no 0/0, no NaN. glm::axis computes v / sqrt(1 - w*w): for small angles w*w
// rounds to 1 and the axis is lost: it returns (0, 0, 1) for a 1.9e-9 rad turn about +x (another
// rotation), and a non-unit axis (length 1.0004) for a 2e-7 rad turn.
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-2.cpp   Exit: 0 defect shown, 1 not shown.
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

// One case: q = (w, x, 0, 0), a small turn about +x. Returns the rotation error in eps.
static long double run(double w, double x) {
  const glm::dquat q(w, x, 0.0, 0.0);
  const double angle = glm::angle(q);
  const glm::dvec3 u = glm::axis(q);
  // Correct, from q in long double: theta = 2 atan2(|v|, w), u = (1, 0, 0).
  const long double theta = 2 * std::atan2((long double)x, (long double)w);
  const long double h = (long double)angle / 2;
  const long double lib[4] = {std::cos(h), std::sin(h) * u.x, std::sin(h) * u.y, std::sin(h) * u.z};
  const long double ref[4] = {w, x, 0, 0};
  const long double err = rdist(lib, ref);
  const long double ulen = std::sqrt((long double)u.x * u.x + (long double)u.y * u.y + (long double)u.z * u.z);
  std::printf("input:   q (w, x, y, z) = (%a, %a, 0, 0)\n", q.w, q.x);
  std::printf("library: angle = %a (%.6g), axis = (%a, %a, %a), |axis| - 1 = %.3Lg\n", angle, angle, u.x, u.y, u.z,
              ulen - 1);
  std::printf("correct: angle = %a (%.6g), axis = (1, 0, 0)\n", (double)theta, (double)theta);
  const long double e = std::max(err, std::fabs(ulen - 1)) / 0x1p-52L;
  std::printf("error:   %.3Lg rad between the rotations, axis norm defect %.3Lg: %.3Lg eps "
              "(eps = 2^-52; loose bar 256 eps)\n",
              err, std::fabs(ulen - 1), e);
  return e;
}

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-2: glm::axis loses the axis of small rotations "
              "(1 - w*w cancels): (0, 0, 1) for a 1.9e-9 rad turn about x, a non-unit axis at 2e-7 rad\n");
  std::printf("call:    glm::dquat q(w, x, y, z); glm::angle(q); glm::axis(q);\n");
  // 2^-29 rad about +x: w rounds to 1 exactly (q is glm::angleAxis(0x1p-29, (1, 0, 0)) up to rounding).
  const long double e1 = run(1.0, 0x1p-30);
  // glm::angleAxis(2e-7, (1, 0, 0)) as GLM computes it: (cos 1e-7, sin 1e-7, 0, 0).
  const long double e2 = run(0x1.fffffffffffd3p-1, 0x1.ad7f29abcaf3bp-24);
  if (!(std::max(e1, e2) > 256)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
