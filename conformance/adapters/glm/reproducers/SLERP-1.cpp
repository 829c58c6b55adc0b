// rotorcert reproducer, GLM 0.9.9.8 (Debian libglm-dev), clause SLERP-1 (rotorcert table glm_mix).
// SLERP-1: slerp(a, b, t) = a (a^-1 b')^t with b' = -b iff a.b < 0; no 0/0; an exact antipode
// interpolates constantly (spec Table 7). glm::mix is GLM's oriented spherical interpolation (it
// takes the long arc by design: "For short path spherical linear interpolation, use the slerp
// function"), but it calls acos on an unclamped dot: for the unit float quaternion a and its
// antipode -a, or a b one bit away from -a, the rounded dot is below -1 and the result is NaN.
// No reading of glm::mix allows a NaN for unit inputs (SLERP-1: no 0/0, b = -a gives a).
// Known upstream: https://github.com/g-truc/glm/issues/901 (open; this input is the issue's).
// Build: g++ -std=c++20 -O1 SLERP-1.cpp   Exit: 0 defect shown, 1 not shown.
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

// SLERP-1 reference in long double: b' = -b iff a.b < 0, theta = 2 atan2(|a - b'|, |a + b'|) on the
// normalised inputs, result (sin((1 - t) theta) a + sin(t theta) b') / sin theta.
static void slerp_ref(const long double* a0, const long double* b0, long double t, long double* out) {
  long double a[4], b[4], na = 0, nb = 0, dot = 0, dm = 0, dp = 0;
  for (int i = 0; i < 4; ++i) na += a0[i] * a0[i], nb += b0[i] * b0[i], dot += a0[i] * b0[i];
  for (int i = 0; i < 4; ++i) a[i] = a0[i] / std::sqrt(na), b[i] = (dot < 0 ? -b0[i] : b0[i]) / std::sqrt(nb);
  for (int i = 0; i < 4; ++i) dm += (a[i] - b[i]) * (a[i] - b[i]), dp += (a[i] + b[i]) * (a[i] + b[i]);
  const long double th = 2 * std::atan2(std::sqrt(dm), std::sqrt(dp));
  for (int i = 0; i < 4; ++i)
    out[i] = th == 0 ? a[i] : (std::sin((1 - t) * th) * a[i] + std::sin(t * th) * b[i]) / std::sin(th);
}

// One case: prints it and returns the METRIC-1 error (NaN if the library gave NaN).
static long double run(const glm::quat& a, const glm::quat& b, float t) {
  const glm::quat m = glm::mix(a, b, t);
  const long double la[4] = {a.w, a.x, a.y, a.z}, lb[4] = {b.w, b.x, b.y, b.z}, lib[4] = {m.w, m.x, m.y, m.z};
  long double ref[4];
  slerp_ref(la, lb, t, ref);
  const long double err = rdist(lib, ref);
  std::printf("input:   a (w, x, y, z) = (%a, %a, %a, %a), b = (%a, %a, %a, %a), t = %a; float dot(a, b) = %a\n",
              (double)a.w, (double)a.x, (double)a.y, (double)a.z, (double)b.w, (double)b.x, (double)b.y, (double)b.z,
              (double)t, (double)glm::dot(a, b));
  std::printf("library: (%a, %a, %a, %a)\n", (double)m.w, (double)m.x, (double)m.y, (double)m.z);
  std::printf("correct: (%a, %a, %a, %a)   [SLERP-1 in long double; for b = -a it is a itself]\n", (double)ref[0],
              (double)ref[1], (double)ref[2], (double)ref[3]);
  std::printf("error:   %Lg rad (METRIC-1; NaN = FAIL; eps = 2^-23, SLERP-1 is eps16, loose bar 256 eps)\n", err);
  return err;
}

int main() {
  std::printf("rotorcert reproducer: GLM 0.9.9.8 SLERP-1: glm::mix of two unit quaternions returns NaN when "
              "their rounded dot is below -1 (unclamped acos), e.g. a and its antipode -a\n");
  std::printf("call:    glm::mix(glm::quat a, glm::quat b, float t)\n");
  // a = 90 degrees about x, with sqrt(2)/2 rounded to float (0x1.6a09e8p-1 = 0.707106829f).
  const glm::quat a(0x1.6a09e8p-1f, 0x1.6a09e8p-1f, 0.0f, 0.0f);  // (w, x, y, z)
  const float t = 0x1.47ae14p-7f;                                 // 0.01f
  // Case 1 (the input of glm issue #901): the exact antipode b = -a.
  const long double e1 = run(a, -a, t);
  // Case 2: not an antipode (b differs from -a in the last bit of w and x): the long arc that
  // glm::mix documents is well defined here, yet the result is NaN as well.
  const long double e2 = run(a, glm::quat(-0x1.6a09e6p-1f, -0x1.6a09eap-1f, 0.0f, 0.0f), t);
  if (!(std::isnan(e1) || std::isnan(e2) || e1 > 256 * 0x1p-23L || e2 > 256 * 0x1p-23L)) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
