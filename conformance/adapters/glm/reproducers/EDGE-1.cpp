// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause EDGE-1.
// EDGE-1: identity in gives identity out exactly; exp(0) = 1 (EXP-1: "exp(0) = 1 exactly").
// glm::exp(q) returns qua<T, Q>() when |v| < epsilon; in GLM's default configuration (no
// GLM_FORCE_CTOR_INIT) that default constructor is "= default", so qua<T, Q>() is value-initialised
// to (0, 0, 0, 0): exp of the zero vector is the zero quaternion, not the identity. The same happens
// for every |v| < epsilon (2^-52 double, 2^-23 float), i.e. also inside EDGE-2's angle range.
// (Only in the default configuration: with GLM_FORCE_CTOR_INIT defined, qua() is the identity.)
// Upstream: no issue found (https://github.com/g-truc/glm/issues/988 is a different exp defect).
// Build: g++ -std=c++20 -O1 EDGE-1.cpp   Exit: 0 defect shown, 1 not shown.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>

#include <cmath>
#include <cstdio>

static_assert(GLM_VERSION == 998, "written against GLM 0.9.9.8");

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 EDGE-1: glm::exp of the zero vector returns the zero "
              "quaternion (0, 0, 0, 0) instead of the identity\n");
  std::printf("call:    glm::exp(glm::dquat(0, x, y, z))   (and glm::quat for float)\n");
  const glm::dquat v(0.0, 0.0, 0.0, 0.0);  // (w, x, y, z): the pure quaternion of the zero vector
  const glm::dquat e = glm::exp(v);
  const glm::quat ef = glm::exp(glm::quat(0.0f, 0.0f, 0.0f, 0.0f));
  // A small nonzero vector, 2^-57 rad about +x (below double epsilon): exp is (cos 2^-57, sin 2^-57, 0, 0).
  const glm::dquat vs(0.0, 0x1p-57, 0.0, 0.0);
  const glm::dquat es = glm::exp(vs);
  std::printf("input:   v (w, x, y, z) = (%a, %a, %a, %a)\n", v.w, v.x, v.y, v.z);
  std::printf("library: double exp = (w, x, y, z) = (%a, %a, %a, %a); float exp = (%a, %a, %a, %a)\n", e.w, e.x, e.y,
              e.z, (double)ef.w, (double)ef.x, (double)ef.y, (double)ef.z);
  std::printf("correct: (0x1p+0, 0x0p+0, 0x0p+0, 0x0p+0)   [closed form: exp(0) = 1]\n");
  std::printf("input:   v (w, x, y, z) = (%a, %a, %a, %a)\n", vs.w, vs.x, vs.y, vs.z);
  std::printf("library: (%a, %a, %a, %a)\n", es.w, es.x, es.y, es.z);
  std::printf("correct: (0x1p+0, %a, 0x0p+0, 0x0p+0)   [cos|v| = 1 and sin|v| = |v| in binary64]\n", vs.x);
  // The error: the output is not unit at all (METRIC-6 norm defect 1 = 2^52 eps); EDGE-1 is exact.
  const double nd = std::fabs(std::sqrt(e.w * e.w + e.x * e.x + e.y * e.y + e.z * e.z) - 1.0);
  std::printf("error:   norm defect | |exp(0)| - 1 | = %g = %.3g eps (eps = 2^-52; EDGE-1 is exact)\n", nd,
              nd / 0x1p-52);
  if (e.w == 1.0 && e.x == 0.0 && e.y == 0.0 && e.z == 0.0) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
