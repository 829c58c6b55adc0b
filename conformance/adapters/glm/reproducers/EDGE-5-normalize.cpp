// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-5 (NORM-1's extreme inputs, judged at Robust by LEVEL-1).
// EDGE-5 (NORM-1 at an extreme scale): normalize is q/|q| "without intermediate overflow or underflow for every finite nonzero
// input of the format"; output unit; eps4. glm::normalize divides by sqrt(dot(q, q)) with no
// scaling: for a tiny q the sum of squares underflows to 0, and glm::normalize then returns the
// identity (its "len <= 0" branch), a different rotation.
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-5-normalize.cpp   Exit: 0 defect shown, 1 not shown.
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
  // q = 2^-999 * (w, x, y, z) = 2^-999 * (2, 1.5, 0, 0): |q| = 2.5 * 2^-999, all components normal numbers.
  const glm::dquat q(0x1p-998, 0x1.8p-999, 0.0, 0.0);  // (w, x, y, z)
  const glm::dquat n = glm::normalize(q);
  // Correct (closed form, 3-4-5): q/|q| = (2, 1.5, 0, 0) / 2.5 = (0.8, 0.6, 0, 0).
  const long double ref[4] = {0.8L, 0.6L, 0, 0};
  const long double lib[4] = {n.w, n.x, n.y, n.z};
  const long double err = rdist(lib, ref);
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-5 (NORM-1 at an extreme scale): glm::normalize of a tiny quaternion returns the "
              "identity (|q|^2 underflows to 0)\n");
  std::printf("call:    glm::normalize(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  std::printf("library: (%a, %a, %a, %a)\n", n.w, n.x, n.y, n.z);
  std::printf("correct: (%a, %a, 0x0p+0, 0x0p+0)   [= (0.8, 0.6, 0, 0), closed form]\n", 0.8, 0.6);
  std::printf("error:   %.4Lg rad (METRIC-1) = %.3Lg eps (eps = 2^-52; NORM-1 is eps4, loose bar 64 eps)\n", err,
              err / 0x1p-52L);
  if (!(err > 64 * 0x1p-52L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
