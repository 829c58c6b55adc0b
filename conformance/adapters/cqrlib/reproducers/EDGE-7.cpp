// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause EDGE-7.
// EDGE-7: NaN or +-Inf in any input component (theta and axes included) is DOMAIN_ERROR: an error
// status, or every output component a quiet NaN. CQRAxis2Quaternion checks the axis only for
// norm == 0: an axis with a NaN component gives CQR_SUCCESS and a finite w = cos(theta/2) next to
// NaN x, y, z. CPPQR<double>::UnitQ() of (w, x, y, z) = (1, Inf, 0, 0) gives (0, NaN, 0, 0).
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 EDGE-7.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <cmath>
#include <cstdio>
#include <limits>

int main() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::printf("rotorcert reproducer: CQRlib 1.1.4 EDGE-7: CQRAxis2Quaternion with a NaN axis component returns "
              "CQR_SUCCESS and a finite w; UnitQ() of (1, Inf, 0, 0) returns (0, NaN, 0, 0)\n");
  double axis[3] = {nan, 0.0, 1.0};
  const double theta = 1.0;
  CQRQuaternion q;  // {w, x, y, z}
  q.w = q.x = q.y = q.z = 0.0;
  const int rc = CQRAxis2Quaternion(&q, axis, theta);
  std::printf("call:    CQRAxis2Quaternion(&q, axis, theta)\n");
  std::printf("input:   axis = (%a, %a, %a), theta = %a\n", axis[0], axis[1], axis[2], theta);
  std::printf("library: rc = %d (CQR_SUCCESS = %d), q {w, x, y, z} = {%a, %a, %a, %a}\n", rc, CQR_SUCCESS, q.w, q.x,
              q.y, q.z);
  std::printf("correct: DOMAIN_ERROR: an error status or {nan, nan, nan, nan} (spec EDGE-7, outcome class)\n");
  const CPPQR<double> p(1.0, inf, 0.0, 0.0);  // (w, x, y, z)
  const CPPQR<double> n = p.UnitQ();
  std::printf("call:    CPPQR<double>(w, x, y, z).UnitQ()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", p.GetW(), p.GetX(), p.GetY(), p.GetZ());
  std::printf("library: (%a, %a, %a, %a)\n", n.GetW(), n.GetX(), n.GetY(), n.GetZ());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-7's own example)\n");
  std::printf("error:   finite components (and CQR_SUCCESS) for a non-finite input\n");
  const bool a2q_ok = rc != CQR_SUCCESS || (std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z));
  const bool unitq_ok = std::isnan(n.GetW()) && std::isnan(n.GetX()) && std::isnan(n.GetY()) && std::isnan(n.GetZ());
  if (a2q_ok && unitq_ok) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
