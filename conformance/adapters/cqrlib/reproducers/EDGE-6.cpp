// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause EDGE-6.
// EDGE-6: a zero quaternion is DOMAIN_ERROR: an error status, or every output component a quiet
// NaN. CQRlib has a status channel (CQRInverse answers CQR_BAD_ARGUMENT for a zero q), but
// CPPQR<double>::UnitQ() of the zero quaternion returns DBL_MAX in all four components, and
// CQRQuaternion2Matrix ("Form the 3x3 rotation matrix from a quaternion") returns the zero matrix
// with CQR_SUCCESS.
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 EDGE-6.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <cmath>
#include <cstdio>

int main() {
  std::printf("rotorcert reproducer: CQRlib 1.1.4 EDGE-6: the zero quaternion is accepted: UnitQ() returns "
              "DBL_MAX x 4, CQRQuaternion2Matrix returns the zero matrix with CQR_SUCCESS\n");
  const CPPQR<double> z(0.0, 0.0, 0.0, 0.0);  // (w, x, y, z)
  const CPPQR<double> n = z.UnitQ();
  std::printf("call:    CPPQR<double>(w, x, y, z).UnitQ()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", z.GetW(), z.GetX(), z.GetY(), z.GetZ());
  std::printf("library: (%a, %a, %a, %a)\n", n.GetW(), n.GetX(), n.GetY(), n.GetZ());
  std::printf("correct: DOMAIN_ERROR: (nan, nan, nan, nan) (spec EDGE-6, outcome class)\n");
  CQRQuaternion q;  // {w, x, y, z}
  q.w = q.x = q.y = q.z = 0.0;
  double m[3][3];
  const int rc = CQRQuaternion2Matrix(m, &q);
  std::printf("call:    double m[3][3]; CQRQuaternion2Matrix(m, &q)\n");
  std::printf("input:   q {w, x, y, z} = {%a, %a, %a, %a}\n", q.w, q.x, q.y, q.z);
  std::printf("library: rc = %d (CQR_SUCCESS = %d), m = [%a %a %a; %a %a %a; %a %a %a]\n", rc, CQR_SUCCESS, m[0][0],
              m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]);
  std::printf("correct: DOMAIN_ERROR: an error status (as CQRInverse gives) or an all-NaN matrix\n");
  std::printf("error:   finite outputs and CQR_SUCCESS for a zero input\n");
  const bool unitq_ok = std::isnan(n.GetW()) && std::isnan(n.GetX()) && std::isnan(n.GetY()) && std::isnan(n.GetZ());
  if (unitq_ok && (rc != CQR_SUCCESS || std::isnan(m[0][0]))) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
