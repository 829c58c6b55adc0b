// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause DQ-4.
// DQ-4: normalising r + eps d gives r' = r/|r| and d' = d/|r| - ((r.d)/|r|^3) r, so that |r'| = 1
// and r'.d' = 0 (a unit dual quaternion); eps16 on METRIC-7, METRIC-6 of r' and |r'.d'|.
// glm::normalize(tdualquat) returns q / length(q.real): it never removes the component of d along
// r, so the result is not a unit dual quaternion (spec example EX-DQ-4-b). The same function ends
// every dual-quaternion blend written with GLM (normalize of glm::lerp / a weighted sum), which is
// why DQ-6 and the dq_blend case of EDGE-3 fail too.
// Upstream: no issue in the GLM tracker; the same formula was fixed in gl-matrix,
// https://github.com/toji/gl-matrix/pull/327 (which names GLM's normalize as doing the same).
// Build: g++ -std=c++20 -O1 DQ-4.cpp   Exit: 0 defect shown, 1 not shown.
#define GLM_ENABLE_EXPERIMENTAL  // gtx/dual_quaternion.hpp requires it
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/dual_quaternion.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

int main() {
  // EX-DQ-4-b: r = 1, d = 1 (d parallel to r: it carries no translation).
  const glm::dquat r(1.0, 0.0, 0.0, 0.0), d(1.0, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const glm::tdualquat<double> n = glm::normalize(glm::tdualquat<double>(r, d));
  const double rd = n.real.w * n.dual.w + n.real.x * n.dual.x + n.real.y * n.dual.y + n.real.z * n.dual.z;
  std::printf("rotorcert reproducer: GLM 0.9.9.8 DQ-4: glm::normalize(dualquat) leaves the dual part's component "
              "along the real part: normalize(1 + eps 1) = 1 + eps 1, real.dual = 1 instead of 0\n");
  std::printf("call:    glm::normalize(glm::dualquat(glm::dquat(w, x, y, z), glm::dquat(w, x, y, z)))\n");
  std::printf("input:   real (w, x, y, z) = (%a, %a, %a, %a), dual = (%a, %a, %a, %a)\n", r.w, r.x, r.y, r.z, d.w, d.x,
              d.y, d.z);
  std::printf("library: real = (%a, %a, %a, %a), dual = (%a, %a, %a, %a)\n", n.real.w, n.real.x, n.real.y, n.real.z,
              n.dual.w, n.dual.x, n.dual.y, n.dual.z);
  std::printf("correct: real = (0x1p+0, 0x0p+0, 0x0p+0, 0x0p+0), dual = (0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0)   "
              "[closed form: d/|r| - (r.d/|r|^3) r = 1 - 1 = 0]\n");
  std::printf("error:   |real . dual| = %g = %.3g eps (eps = 2^-52; DQ-4 is eps16, loose bar 256 eps)\n", std::fabs(rd),
              std::fabs(rd) / 0x1p-52);
  if (!(std::fabs(rd) > 256 * 0x1p-52)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
