// rotorcert reproducer, Assimp 5.2.5 (Debian libassimp-dev 5.2.5~ds0-1+b1), clause EDGE-7.
// EDGE-7 (spec/SPEC.md 9, outcome class): NaN or +-Inf in any input is DOMAIN_ERROR, every output a
// quiet NaN (an adapter without a status channel reads "all outputs NaN" as DOMAIN_ERROR). Assimp
// propagates NaN by policy (https://github.com/assimp/assimp/pull/485, "Assimp has always propagated
// NaN"), but Inf does not propagate: Normalize (quaternion.inl:266) of [x, y, z, w] = [0, Inf, 0, 1]
// computes mag = Inf, invMag = 1/Inf = 0, and returns [0, NaN, 0, 0]: three finite components that
// look like a valid (zero) quaternion. Rotate, operator*, GetMatrix, Interpolate and the axis-angle
// constructor likewise mix finite and non-finite outputs.
// Upstream: no issue found in the assimp tracker.
// Build: g++ -std=c++20 -O1 EDGE-7.cpp   (header-only)   Exit: 0 defect shown, 1 not shown.
#include <assimp/types.h>

#include <cmath>
#include <cstdio>
#include <limits>

int main() {
  const double inf = std::numeric_limits<double>::infinity();
  // The suite's worst input (example EX-EDGE-7-b): [x, y, z, w] = [0, Inf, 0, 1].
  aiQuaterniont<double> q(1.0, 0.0, inf, 0.0);  // (w, x, y, z)
  std::printf("rotorcert reproducer: Assimp 5.2.5 EDGE-7: Normalize of a quaternion with an infinite component "
              "returns three finite components and one NaN\n");
  std::printf("call:    aiQuaterniont<double>(w, x, y, z).Normalize()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  q.Normalize();
  std::printf("library: (%a, %a, %a, %a)\n", q.w, q.x, q.y, q.z);
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (EDGE-7)\n");
  aiQuaterniont<float> f(1.0f, 0.0f, std::numeric_limits<float>::infinity(), 0.0f);  // aiQuaternion
  f.Normalize();
  std::printf("float:   aiQuaternion: (%a, %a, %a, %a)\n", (double)f.w, (double)f.x, (double)f.y, (double)f.z);
  const bool all_nan = std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
  if (all_nan) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   finite components in the output of a non-finite input\nDEFECT SHOWN\n");
  return 0;
}
