// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause EDGE-5 (NORM-1's extreme inputs, judged at Robust by LEVEL-1).
// EDGE-5 (NORM-1 at an extreme scale): normalize is q/|q| "without intermediate overflow or underflow for every finite nonzero
// input of the format"; output unit; eps4. CQRlib's C API has no normalize; its header's C++
// template CPPQR<double>::UnitQ() ("Get a unit quaternion from a general one") divides by
// sqrt(Normsq()) with no scaling: for a tiny q the squared norm underflows to 0 and UnitQ returns
// its zero sentinel, DBL_MAX in all four components.
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 EDGE-5-normalize.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <cmath>
#include <cstdio>

int main() {
  // q = 2^-999 * (w, x, y, z) = 2^-999 * (2, 1.5, 0, 0): |q| = 2.5 * 2^-999, all components normal numbers.
  const CPPQR<double> q(0x1p-998, 0x1.8p-999, 0.0, 0.0);  // (w, x, y, z)
  const CPPQR<double> n = q.UnitQ();
  const long double norm = std::sqrt((long double)n.GetW() * n.GetW() + (long double)n.GetX() * n.GetX() +
                                     (long double)n.GetY() * n.GetY() + (long double)n.GetZ() * n.GetZ());
  std::printf("rotorcert reproducer: CQRlib 1.1.4 EDGE-5 (NORM-1 at an extreme scale): CPPQR<double>::UnitQ() of a tiny quaternion returns "
              "DBL_MAX x 4 (|q|^2 underflows to 0)\n");
  std::printf("call:    CPPQR<double>(w, x, y, z).UnitQ()\n");
  std::printf("input:   q (w, x, y, z) = (%a, %a, %a, %a)\n", q.GetW(), q.GetX(), q.GetY(), q.GetZ());
  std::printf("library: (%a, %a, %a, %a)\n", n.GetW(), n.GetX(), n.GetY(), n.GetZ());
  std::printf("correct: (%a, %a, 0x0p+0, 0x0p+0)   [= (0.8, 0.6, 0, 0), closed form]\n", 0.8, 0.6);
  std::printf("error:   norm defect | |n| - 1 | = %.3Lg (eps = 2^-52; NORM-1 is eps4, loose bar 64 eps)\n",
              std::fabs(norm - 1));
  if (!(std::fabs(norm - 1) > 64 * 0x1p-52L)) {  // Inf (DBL_MAX squared) also counts
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  return 0;
}
