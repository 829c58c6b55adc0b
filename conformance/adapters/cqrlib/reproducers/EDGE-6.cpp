// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause EDGE-6.
// EDGE-6: a zero quaternion is DOMAIN_ERROR: an error status, or every output component a quiet
// NaN (RESULT-2: non-finite). ACC-1 zero_sentinel (spec 2.2.0) also accepts status OK with every
// output component +-0, or exactly the identity's output (0, 0, 0, 1). CQRlib has a status channel
// (CQRInverse answers CQR_BAD_ARGUMENT for a zero q), but CPPQR<double>::UnitQ() of the zero
// quaternion returns DBL_MAX in all four components (cqrlib.h:790-792), a finite quaternion that is
// neither of the two sentinels and not an error. (Its zero matrix from CQRQuaternion2Matrix, the
// zero log and the zero axis-angle of 0 are the all-zero sentinel, ACCEPTABLE since 2.2.0.)
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 EDGE-6.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <cfloat>
#include <cmath>
#include <cstdio>

int main() {
  std::printf("rotorcert reproducer: CQRlib 1.1.4 EDGE-6: UnitQ() of the zero quaternion returns DBL_MAX x 4 "
              "(finite, no error), neither DOMAIN_ERROR nor an ACC-1 zero_sentinel\n");
  const CPPQR<double> z(0.0, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const CPPQR<double> n = z.UnitQ();
  const double out[4] = {n.GetW(), n.GetX(), n.GetY(), n.GetZ()};
  std::printf("call:    CPPQR<double>(w, x, y, z).UnitQ()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", z.GetW(), z.GetX(), z.GetY(), z.GetZ());
  std::printf("library: (%a, %a, %a, %a)\n", out[0], out[1], out[2], out[3]);
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-6, outcome class); acceptable instead "
              "(ACC-1 zero_sentinel): (0, 0, 0, 0) or the identity (1, 0, 0, 0)\n");
  bool nonfinite = true, zeros = true;
  for (const double c : out) {
    nonfinite = nonfinite && !std::isfinite(c);
    zeros = zeros && c == 0.0;
  }
  const bool identity = out[0] == 1.0 && out[1] == 0.0 && out[2] == 0.0 && out[3] == 0.0;
  if (nonfinite || zeros || identity) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("error:   four finite components (DBL_MAX = %a) and no error for a zero input\n", DBL_MAX);
  return 0;
}
