// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-8.
// EDGE-8: subnormal components are ordinary nonzero values: "normalize((2^-1074, -0, 0, 0)) =
// (1, -0, 0, 0)" (spec layout [x, y, z, w]), eps4. glm::normalize squares the components, the sum
// underflows to 0 and it returns the identity: a half turn about x becomes no rotation (pi rad).
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-8.cpp   Exit: 0 defect shown, 1 not shown.
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
  const glm::dquat q(0.0, 0x1p-1074, -0.0, 0.0);  // (w, x, y, z): x = the smallest subnormal
  const glm::dquat n = glm::normalize(q);
  const long double ref[4] = {0, 1, 0, 0};  // closed form: q/|q| = (w, x, y, z) = (0, 1, -0, 0)
  const long double lib[4] = {n.w, n.x, n.y, n.z};
  const long double err = rdist(lib, ref);
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-8: glm::normalize of a subnormal quaternion returns the "
              "identity (a half turn about x becomes no turn)\n");
  std::printf("call:    glm::normalize(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  std::printf("library: (%a, %a, %a, %a)\n", n.w, n.x, n.y, n.z);
  std::printf("correct: (0x0p+0, 0x1p+0, -0x0p+0, 0x0p+0)   [closed form, spec EDGE-8's own example]\n");
  std::printf("error:   %.6Lg rad (METRIC-1) = %.3Lg eps (eps = 2^-52; EDGE-8 is eps4, loose bar 64 eps)\n", err,
              err / 0x1p-52L);
  if (!(err > 64 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
