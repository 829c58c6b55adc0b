// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-7.
// EDGE-7: NaN or +-Inf in any input component is DOMAIN_ERROR with every output component a quiet
// NaN; since spec 2.7.0 status OK is ACCEPTABLE when at least one output component is NaN or +-Inf
// (ACC-1 nonfinite_propagation: glm::normalize of (1, Inf, 0, 0) = (0, NaN, 0, 0) is no defect) or
// is the answer for the rotation an infinite quaternion tends to (nonfinite_limit: glm::axis of a
// w = +-Inf quaternion, (0, 0, 1), is the identity's axis). What stays a FAIL is any other
// all-finite answer: glm::angle (ext/quaternion_trigonometric.inl:5-14) reads only w where
// |w| <= cos(1/2) and returns 2 acos(w), so a NaN in x, y or z is dropped and a finite angle comes
// back. Input: the suite's failing to_angle [NaN in q] input of the binary64 table.
// Upstream: no issue found in the GLM tracker.
// Build: g++ -std=c++20 -O1 EDGE-7.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

static bool finite(const glm::dquat& q) {
  return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

int main() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-7: glm::angle of a quaternion with a NaN in y returns a "
              "finite angle\n");
  // to_angle [NaN in q]: q (x, y, z, w) = [-0x1.23e64e6838673p-1, -nan, -0x1.04e99a3543728p-2, -0x1.5803222154743p-2]
  const glm::dquat q(-0x1.5803222154743p-2, -0x1.23e64e6838673p-1, -nan, -0x1.04e99a3543728p-2);  // (w, x, y, z)
  const double a = glm::angle(q);
  std::printf("call:    glm::angle(glm::dquat(w, x, y, z))\n");
  std::printf("input:   q (x, y, z, w) = [%a, %a, %a, %a]\n", q.x, q.y, q.z, q.w);
  std::printf("library: %a (%.12g rad = 2 acos(w): the NaN in y is not read)\n", a, a);
  std::printf("correct: DOMAIN_ERROR: nan (spec EDGE-7); ACCEPTABLE: a NaN or infinite angle (ACC-1 "
              "nonfinite_propagation)\n");
  if (finite(q) || !std::isfinite(a)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   an all-finite answer to a non-finite input (the NaN is lost)\n");
  return 0;
}
